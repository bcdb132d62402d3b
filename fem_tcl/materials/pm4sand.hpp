#pragma once
// OpenSees' PM4Sand (plane strain): the stress-ratio controlled, critical-state compatible, bounding-surface
// plasticity model for sands in earthquake engineering of Boulanger & Ziotopoulou (2017), "PM4Sand (Version 3.1):
// a sand plasticity model for earthquake engineering applications", Report UCD/CGM-17/01, UC Davis (the manual),
// building on Dafalias & Manzari (2004, J. Eng. Mech. 130(6)). Reimplemented from OpenSees 3.8's implementation by
// L. Chen and P. Arduino (SRC/material/nD/UWmaterials/PM4Sand.cpp at commit 2890cb36, the build of the golden
// files), with its defaults, explicit integration schemes and quirks (listed in pm4sand.cpp).
//
//   nDMaterial PM4Sand tag Dr G0 hpo Den <P_atm h0 emax emin nb nd Ado z_max cz ce phicv nu Cgd Cdr Ckaf Q R m
//                                         Fsed_min p_sedo IntScheme TanType TolF TolR>
//
// Optional arguments are positional; a negative value means "the default", which for h0, ce, Cdr, Ckaf,
// Fsed_min and p_sedo is derived from Dr and P_atm (see resolve_parameters()) and for Ado and z_max is derived
// from the stress when the model is initialised (`setParameter ... FirstCall`, or `reset`).
//
// The model is two-dimensional (pm4_common.hpp): in-plane tensors, p = (sxx + syy) / 2. Strain (exx eyy gxy),
// stress (sxx syy sxy), tension positive at this interface; compression positive inside.
// Stages (`updateMaterialStage`): 0 = linear elastic with G = G0 P_atm and K from nu, independent of p (OpenSees
// GetElasticModuli with me2p = 0); 1 = the plastic model, G = G0 P_atm sqrt(p / P_atm) C_SR (1 + z_cum / z_max) /
// (1 + C_GD z_cum / z_max). Scripts switch to 1 and then re-initialise the state from the consolidated stress
// with `setParameter -val 0 -ele ... FirstCall <tag>`.
#include <string>

#include "common/command_args.hpp"
#include "fem_tcl/materials/pm4_material.hpp"

namespace fem::materials {

/// The explicit stress-integration schemes of OpenSees' PM4Sand (IntScheme), shared with PM4Silt.
using PM4SandScheme = pm4::Scheme;

/// The command's parameters. As given, a negative optional value means "the default"; after resolve_parameters()
/// every value is the one in force (Ado and z_max stay negative until the first initialisation computes them).
struct PM4SandParameters {
  double Dr = 0;       ///< apparent relative density (fraction, 0..1)
  double G0 = 0;       ///< shear modulus coefficient: G = G0 P_atm sqrt(p / P_atm)
  double hpo = 0;      ///< contraction rate parameter
  double density = 0;  ///< Den, mass density
  double P_atm = 101.3, h0 = -1, emax = 0.8, emin = 0.5, nb = 0.5, nd = 0.1, Ado = -1, z_max = -1, cz = 250.0,
         ce = -1, phi_cv = 33.0, nu = 0.3, Cgd = 2.0, Cdr = -1, Ckaf = -1, Q = 10.0, R = 1.5, m = 0.01,
         Fsed_min = -1, p_sedo = -1;
  int scheme = 5;        ///< IntScheme (PM4SandScheme)
  int tangent_type = 0;  ///< TanType: 0 the current elastic matrix, 1 / 2 the one of the last commit
  double tol_f = 1e-8;   ///< TolF, the yield-surface tolerance
  double tol_r = 1e-8;   ///< TolR (stored only, as in OpenSees)
};

/// OpenSees' defaults for the negative (default) entries, derived from Dr and P_atm (PM4Sand constructor, manual
/// table 3.1 and section 4.1); validates the values (common::InputError naming the argument, `where` first).
PM4SandParameters resolve_parameters(const PM4SandParameters& given, const std::string& where);

/// PM4Sand's physics on the shared PM4 material (pm4_material.hpp: the state protocol, stages, commands, responses).
class PM4Sand final : public pm4::Material<PM4SandParameters> {
 public:
  /// Resolves and validates the parameters (common::InputError naming the argument) and sets the start state:
  /// zero stress, stage 0, moduli at p = P_atm (OpenSees' constructor and initialize()).
  PM4Sand(int tag, const PM4SandParameters& given);

  std::unique_ptr<NDMaterial> clone() const override { return std::make_unique<PM4Sand>(*this); }

  /// e0 = emax - (emax - emin) Dr (or as set by `voidRatio`).
  double initial_void_ratio() const { return e_init_; }

 private:
  using History = pm4::History;
  using Carried = pm4::Carried;
  using Hardening = pm4::Hardening;

  // the model (manual section 2); the pm4::Model hooks of the shared integration (pm4_integration.hpp)
  double state_parameter(double Dr, double p) const;
  void elastic_stage_moduli(const Vector3& committed_stress, double& K, double& G) override;
  void elastic_moduli(const Vector3& stress, double& K, double& G) override;
  Hardening state_dependent(const Vector3& stress, const Vector3& alpha, const Vector3& fabric, double G,
                            double void_ratio) override;
  double relative_density_at(double void_ratio) const { return (params_.emax - void_ratio) / (params_.emax - params_.emin); }

  // the pm4::Material hooks
  void initialize(const Vector3& stress) override;
  std::unique_ptr<Material> fresh_copy() const override;
  double void_ratio_at_zero_strain() const override { return e_init_; }
  void set_void_ratio_at_zero_strain(double e0) override { e_init_ = e0; }
  void add_json(nlohmann::json& entry) const override;

  double e_init_ = 0;
  double p_min2_ = 0;  ///< the p of the dilatancy cut-off
};

/// `nDMaterial PM4Sand tag Dr G0 hpo Den <P_atm h0 emax emin nb nd Ado z_max cz ce phicv nu Cgd Cdr Ckaf Q R m
/// Fsed_min p_sedo IntScheme TanType TolF TolR>`.
std::unique_ptr<NDMaterial> parse_pm4sand(common::CommandArgs& args);

}  // namespace fem::materials
