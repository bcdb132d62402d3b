#pragma once
// OpenSees' PM4Silt (plane strain): the stress-ratio controlled, critical-state based, bounding-surface plasticity
// model for low-plasticity silts and clays of Boulanger & Ziotopoulou (2018), "PM4Silt (Version 1): a silt
// plasticity model for earthquake engineering applications", Report UCD/CGM-18/01, UC Davis (the manual), built on
// PM4Sand (pm4sand.hpp). Reimplemented from OpenSees 3.8's implementation by L. Chen and P. Arduino
// (SRC/material/nD/UWmaterials/PM4Silt.cpp at commit 2890cb36, the build of the golden files), with its defaults
// and quirks (listed in pm4silt.cpp). The stress integration is the one PM4Sand uses (pm4_integration.hpp).
//
//   nDMaterial PM4Silt tag S_u Su_Rat G_o h_po Den <Su_factor P_atm nu nG h0 eInit lambda phicv nb_wet nb_dry nd
//                                                  Ado ru_max z_max cz ce Cgd Ckaf m_m CG_consol IntScheme
//                                                  TanType TolF TolR>
//
// Optional arguments are positional; a negative value means "the default" (Su_factor: also 0). S_u <= 0 means
// "S_u = Su_Rat sigma'yy at the first initialisation"; ru_max, z_max and ce < 0 are derived then too (see
// initialize()): the model is initialised from the consolidated stress by `setParameter ... FirstCall` (or `reset`).
//
// The model is two-dimensional (pm4_common.hpp): in-plane tensors, p = (sxx + syy) / 2. Strain (exx eyy gxy),
// stress (sxx syy sxy), tension positive at this interface; compression positive inside. Units: stresses in the
// units of P_atm (kPa with the default 101.3).
// Stages (`updateMaterialStage`): 0 = linear elastic with G = G_o P_atm and K from nu (OpenSees GetElasticModuli with
// me2p = 0); 1 = the plastic model, G = G_o P_atm (p / P_atm)^nG C_SR (1 + z_cum / z_max) / (1 + C_GD z_cum / z_max).
#include <string>

#include "common/command_args.hpp"
#include "fem_tcl/materials/pm4_material.hpp"

namespace fem::materials {

/// The command's parameters (OpenSees' names in the comments). As given, a negative optional value means "the
/// default"; after resolve_parameters() every value is the one in force, except S_u (<= 0), ru_max, z_max and ce
/// (< 0), which the first initialisation derives from the stress.
struct PM4SiltParameters {
  double Su = 0;       ///< S_u, undrained shear strength (stress units); <= 0: Su_Rat sigma'yy at initialisation
  double Su_Rat = 0;   ///< Su_Rat, undrained shear strength ratio S_u / sigma'vc
  double G0 = 0;       ///< G_o, shear modulus coefficient: G = G_o P_atm (p / P_atm)^nG
  double hpo = 0;      ///< h_po, contraction rate parameter
  double density = 0;  ///< Den, mass density
  double Su_factor = 1.0, P_atm = 101.3, nu = 0.3, nG = 0.75, h0 = 0.5, e_init = 0.9, lambda = 0.06,
         phi_cv = 32.0, nb_wet = 0.8, nb_dry = 0.5, nd = 0.3, Ado = 0.8, ru_max = -1, z_max = -1, cz = 100.0,
         ce = -1, Cgd = 3.0, Ckaf = 4.0, m = 0.01, CG_consol = 2.0;
  int scheme = 5;        ///< IntScheme (pm4::Scheme; OPS_PM4SiltMaterial's default 5)
  int tangent_type = 0;  ///< TanType: 0 the current elastic matrix, 1 / 2 the one of the last commit
  double tol_f = 1e-7;   ///< TolF, the yield-surface tolerance
  double tol_r = 1e-10;  ///< TolR (stored only, as in OpenSees)
};

/// OpenSees' defaults for the negative (default) entries (OPS_PM4SiltMaterial, the constructor and the checks at
/// the top of initialize(stress)); validates the values (common::InputError naming the argument, `where` first).
PM4SiltParameters resolve_parameters(const PM4SiltParameters& given, const std::string& where);

/// PM4Silt's physics on the shared PM4 material (pm4_material.hpp: the state protocol, stages, commands, responses).
class PM4Silt final : public pm4::Material<PM4SiltParameters> {
 public:
  /// Resolves and validates the parameters (common::InputError naming the argument) and sets the start state:
  /// zero stress, stage 0, moduli at p = P_atm (OpenSees' constructor and initialize()).
  PM4Silt(int tag, const PM4SiltParameters& given);

  std::unique_ptr<NDMaterial> clone() const override { return std::make_unique<PM4Silt>(*this); }

  /// p_cs = 2 S_u / M: the mean effective stress at critical state at e = eInit (0 until initialised).
  double critical_mean_stress() const { return p_cs_; }
  /// Gamma (OpenSees me0): the critical-state line e_cs = Gamma - lambda ln(101.3 p / (P_atm Su_factor)).
  double critical_state_intercept() const { return Gamma_; }
  /// The smallest p the model uses (P_atm / 200 until initialised).
  double minimum_mean_stress() const { return p_min_; }
  /// The state parameter xi = e - e_cs at void ratio e and mean stress p (p not below the minimum).
  double state_parameter(double void_ratio, double p) const;

 private:
  using History = pm4::History;
  using Carried = pm4::Carried;
  using State = pm4::State;
  using Hardening = pm4::Hardening;

  // the model (manual section 2); the pm4::Model hooks of the shared integration (pm4_integration.hpp)
  void elastic_stage_moduli(const Vector3& committed_stress, double& K, double& G) override;
  void elastic_moduli(const Vector3& stress, double& K, double& G) override;
  Hardening state_dependent(const Vector3& stress, const Vector3& alpha, const Vector3& fabric, double G,
                            double void_ratio) override;
  /// Mb (dense of critical: the power law in p / p_cs capped by phi_max = 60 degrees; loose: exp(-nb_wet xi /
  /// lambda)) and Md = min(sqrt(2), M exp(nd xi / lambda)) at state parameter xi and mean stress p.
  void surfaces(double xi, double p, double& Mb, double& Md) const;

  // the pm4::Material hooks: PM4Silt.cpp's departures from PM4Sand.cpp are quirks 5, 6, 9 and 10 (pm4silt.cpp)
  void initialize(const Vector3& stress) override;
  std::unique_ptr<Material> fresh_copy() const override;
  double void_ratio_at_zero_strain() const override { return params_.e_init; }
  void set_void_ratio_at_zero_strain(double e0) override { params_.e_init = e0; }
  bool corrects_at_commit(const Vector3& stress) const override;
  bool set_model_parameter(std::string_view name, double value) override;
  Vector3 tracker() const override { return tracker_; }
  const State& state_reported() const override { return trial_; }
  void add_json(nlohmann::json& entry) const override;

  double Mb_max_ = 0, C_Mb_ = 0;  ///< the bounding ratio at p = 0 (phi_max = 60 degrees) and its constant
  double p_cs_ = 0, Gamma_ = 0;   ///< the critical-state mean stress at eInit and the line's intercept
  Vector3 tracker_ = Vector3::Zero();  ///< OpenSees' mTracker: (0, D of the last GetStateDependent, 0)
};

/// `nDMaterial PM4Silt tag S_u Su_Rat G_o h_po Den <Su_factor P_atm nu nG h0 eInit lambda phicv nb_wet nb_dry nd
/// Ado ru_max z_max cz ce Cgd Ckaf m_m CG_consol IntScheme TanType TolF TolR>`.
std::unique_ptr<NDMaterial> parse_pm4silt(common::CommandArgs& args);

}  // namespace fem::materials
