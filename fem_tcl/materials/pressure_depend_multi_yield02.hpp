#pragma once
// OpenSees' PressureDependMultiYield02 (plane strain): the effective-stress multi-surface plasticity of sand for
// liquefaction analyses (Yang, Elgamal & Parra 2003, "Computational model for cyclic mobility and associated
// shear deformation", J. Geotech. Geoenviron. Eng. 129(12):1119-1127; Elgamal, Yang, Parra & Ragheb 2003,
// "Modeling of cyclic mobility in saturated cohesionless soils", Int. J. Plasticity 19:883-905; the OpenSees
// command manual, "PressureDependMultiYield02 Material"), as OpenSees 3.8 implements it.
//
//   nDMaterial PressureDependMultiYield02 tag nd rho refShearModul refBulkModul frictionAng peakShearStra
//              refPress pressDependCoe PTAng contrac1 contrac3 dilat1 dilat3 <noYieldSurf=20 <r1 Gs1 ...>
//              <contrac2=5 dilat2=3 liquefac1=1 liquefac2=0 e=0.6 cs1=0.9 cs2=0.02 cs3=0.7 pa=101 <c=0.1
//              <Hv=0 Pv=1>>>>>
//
// Shear: nested Drucker-Prager cones f_m = 3/2 (s - (p_r - p) a_m) : (s - (p_r - p) a_m) - ((p_r - p) M_m)^2
// (Elgamal et al. 2003, eq. 1) with their apex at the residual pressure p_r = 2 c / M_f (at least 1e-4 pa),
// sizes M_m on the hyperbolic backbone of refShearModul and frictionAng at refPress (or the user points), Mroz
// translation: the mechanism shared with PressureIndependMultiYield (multi_yield_surfaces.hpp). The moduli scale
// as G = G_r ((p_r - p) / (p_r + p_ref))^d. Flow (non-associated): the deviatoric part normal to the active cone,
// the volumetric part P'' of the phase-transformation rule (Elgamal et al. 2003, the flow rule of the contraction
// and dilation phases; OpenSees getPlasticPotential): contraction below the phase-transformation stress ratio eta_PT = 6 sin(PTAng) /
// (3 - sin(PTAng)) and on unloading, P'' = -(eta/eta_PT * cos - 1)^2 (c1 + eps_d,max c2) ((|p| + p_r) / pa)^c3;
// dilation above it while loading, P'' = ((|p| + p_r) / pa)^-d3 (eta/eta_PT - 1)^2 (d1 + gamma_d^d2), with the
// perfectly-plastic zone (PPZ, liquefac1, liquefac2) of cyclic mobility in between (Yang et al. 2003);
// no volumetric flow where the void ratio crosses the critical-state line e_c = cs1 - cs2 (p / pa)^cs3 (cs3 = 0:
// cs1 - cs2 ln(p / pa)). Hv != 0 adds OpenSees' volumetric hardening under compression beyond the largest
// committed confinement.
//
// Stages (`updateMaterialStage`), as OpenSees: 0 = linear elastic with refShearModul and refBulkModul (no
// pressure dependence; the stage after creation), 1 = plastic (at the first plastic step the surfaces are
// centred around the committed stress, OpenSees' elast2Plast), 2 = linear elastic with the moduli scaled to the
// mean stress at which stage 2 was first used (or that of the plastic switch). Strain (exx eyy gxy, engineering
// shear), stress (sxx syy sxy), tension positive; the `stress` response is OpenSees' five committed values
// (sxx syy szz sxy, and the stress ratio sqrt(3/2 s:s) / (|p| + p_r) / M_failure in stage 1, else 0).
#include <vector>

#include <Eigen/Core>

#include "common/command_args.hpp"
#include "fem_tcl/materials/multi_yield_surfaces.hpp"
#include "fem_tcl/materials/nd_material.hpp"

namespace fem::materials {

struct PressureDependMultiYield02Parameters {
  double density = 0;            ///< rho (>= 0)
  double shear_modulus = 0;      ///< refShearModul G_r at refPress (> 0)
  double bulk_modulus = 0;       ///< refBulkModul B_r at refPress (> 0)
  double friction_deg = 0;       ///< frictionAng (0 < phi < 90), triaxial compression
  double peak_shear_strain = 0;  ///< peakShearStra: octahedral shear strain at which the strength is reached at refPress
  double ref_pressure = 0;       ///< refPress p_ref (> 0, compression)
  double pressure_exponent = 0;  ///< pressDependCoe d
  double pt_deg = 0;             ///< PTAng, the phase-transformation angle (> 0)
  double contraction1 = 0;       ///< contrac1 c1
  double contraction3 = 0;       ///< contrac3 c3
  double dilation1 = 0;          ///< dilat1 d1
  double dilation3 = 0;          ///< dilat3 d3
  int surfaces = 20;             ///< noYieldSurf
  /// User-defined backbone (noYieldSurf < 0): (shear strain, G / Gmax) pairs, one per surface; empty: automatic.
  std::vector<double> backbone;
  double contraction2 = 5.0;   ///< contrac2 c2
  double dilation2 = 3.0;      ///< dilat2 d2
  double liquefaction1 = 1.0;  ///< liquefac1: damage-driven growth of the PPZ (0: no PPZ)
  double liquefaction2 = 0.0;  ///< liquefac2: PPZ translation on reversal
  double void_ratio = 0.6;     ///< e, initial void ratio
  double cs1 = 0.9, cs2 = 0.02, cs3 = 0.7;  ///< critical-state line e_c = cs1 - cs2 (p / pa)^cs3
  double atmospheric = 101.0;  ///< pa
  double cohesion = 0.1;       ///< c: sets the residual pressure p_r = 2 c / M_f
  double hv = 0.0, pv = 1.0;   ///< Hv, Pv: volumetric hardening (OpenSees' undocumented extension)
};

class PressureDependMultiYield02 final : public NDMaterial {
 public:
  /// Validates (common::InputError naming the argument) and generates the surfaces.
  PressureDependMultiYield02(int tag, const PressureDependMultiYield02Parameters& params);

  std::string type_name() const override { return "PressureDependMultiYield02"; }
  /// Plane strain only (OpenSees gives no plane-stress copy): plane stress throws common::InputError.
  std::unique_ptr<NDMaterial> copy_for(PlaneType plane) const override;
  std::unique_ptr<NDMaterial> clone() const override { return std::make_unique<PressureDependMultiYield02>(*this); }

  void set_trial_strain(const Vector3& strain) override;
  const Vector3& strain() const override { return trial_.strain; }
  const Vector3& stress() const override { return stress_; }
  const Matrix3& tangent() const override { return tangent_; }
  Matrix3 initial_tangent() const override;
  void commit_state() override;
  void revert_to_last_commit() override;
  void revert_to_start() override;

  double density() const override { return params_.density; }
  Vector6 stress_3d() const override { return trial_.stress; }
  /// updateMaterialStage, shearModulus, bulkModulus, frictionAngle, cohesion (OpenSees' setParameter list).
  bool set_parameter(std::string_view name, double value) override;
  /// 0 = elastic, 1 = plastic, 2 = pressure-dependent elastic; any other stage throws common::InputError.
  bool update_stage(int stage) override;
  int stage() const { return stage_; }
  /// stress / stresses: sxx syy szz sxy ratio (committed, OpenSees' getCommittedStress); strain / strains
  /// (committed); tangent (9 values, row by row); stress3D.
  std::optional<std::vector<double>> response(std::string_view name) const override;
  nlohmann::json to_json() const override;

  /// OpenSees' `backbone p1 p2 ...` response: for each confinement p_k > 0 (compression) two columns, rows
  /// 1..n the (shear strain, secant shear modulus) of surface m at p_k; row 0 holds p_k in its first column.
  Eigen::MatrixXd backbone(const std::vector<double>& confinements) const;

  const PressureDependMultiYield02Parameters& parameters() const { return params_; }
  double residual_pressure() const { return residual_pressure_; }
  /// eta_PT = 6 sin(PTAng) / (3 - sin(PTAng)).
  double stress_ratio_pt() const { return stress_ratio_pt_; }
  const std::vector<multi_yield::YieldSurface>& surfaces() const { return trial_.surfaces.surfaces(); }
  int active_surface() const { return trial_.surfaces.active(); }

 private:
  /// What one integration point carries between steps (OpenSees' committed / trial members).
  struct State {
    Vector3 strain = Vector3::Zero();          ///< engineering (exx eyy gxy)
    Vector6 stress = Vector6::Zero();          ///< full tensor, tension positive
    multi_yield::MultiYieldSurfaces surfaces;  ///< centres and sizes as stress ratios (cone height p_r - p)
    double pressure_d = 0;                     ///< pressureD
    int on_ppz = -1;             ///< -1 never on the PPZ, 0 below it, 1 on it, 2 above it (dilating)
    double ppz_size = 0;
    double cumu_dilate = 0;      ///< cumuDilateStrainOcta
    double max_cumu_dilate = 0;  ///< maxCumuDilateStrainOcta
    double cumu_translate = 0;   ///< cumuTranslateStrainOcta
    double pre_ppz = 0;          ///< prePPZStrainOcta
    double oppo_pre_ppz = 0;     ///< oppoPrePPZStrainOcta
    Vector6 ppz_pivot = Vector6::Zero();          ///< strain tensor
    Vector6 ppz_center = Vector6::Zero();         ///< strain tensor
    Vector6 pivot_strain_rate = Vector6::Zero();  ///< deviator of the strain increment at the pivot
  };

  multi_yield::Cone cone() const { return multi_yield::Cone{true, residual_pressure_}; }
  double modulus_factor(double p) const;  // getModulusFactor
  double elastic_factor() const;          // stages 0 and 2
  void set_up_surfaces();                 // setUpSurfaces
  void start_plastic();                   // elast2Plast
  void plastic_update();                  // getStress, stage 1
  multi_yield::StressPoint elastic_trial(const multi_yield::StressPoint& from, const Vector6& sub);  // setTrialStress
  bool load_reversal(const multi_yield::StressPoint& at, const multi_yield::StressPoint& trial) const;
  /// The unit normal to the active surface at `stress` (deviator, volume), OpenSees getSurfaceNormal.
  std::pair<Vector6, double> surface_normal(const multi_yield::StressPoint& stress) const;
  void flow(multi_yield::StressPoint& trial, bool crossed);  // stressCorrection's return
  double plastic_potential(const multi_yield::StressPoint& contact, const multi_yield::StressPoint& trial);
  bool critical_state(const multi_yield::StressPoint& contact) const;
  void update_ppz(const multi_yield::StressPoint& contact);
  void translate_ppz();
  void update_damage();
  void form_tangent();

  PressureDependMultiYield02Parameters params_;  ///< as in force (OpenSees' corrections, setParameter)
  double residual_pressure_ = 0;  ///< p_r
  double stress_ratio_pt_ = 0;    ///< eta_PT
  double strain_pt_octa_ = 0;     ///< the backbone's octahedral shear strain at eta_PT
  multi_yield::MultiYieldSurfaces reference_surfaces_;  ///< as generated: centred at the origin, none active
  int stage_ = 0;
  State committed_, trial_;
  bool plastic_started_ = false;  ///< OpenSees' e2p
  double init_press_ = 0;         ///< initPress: the mean stress of stage 2's moduli
  double max_press_ = 0;          ///< maxPress: the most compressive committed mean stress of stage 1
  // Step scratch that OpenSees keeps between calls without committing it.
  Vector6 increment_ = Vector6::Zero();       ///< strainRate: the strain tensor increment from the committed state
  Vector6 sub_increment_ = Vector6::Zero();   ///< subStrainRate
  Vector6 sub_strain_ = Vector6::Zero();      ///< trialStrain: committed strain + the sub-increments so far
  multi_yield::StressPoint trial_stress_;     ///< trialStress: the trial stress of the last update
  multi_yield::StressPoint updated_trial_;    ///< updatedTrialStress: the stress at the start of the sub-increment
  double factor_ = 1.0;                       ///< modulusFactor of the sub-increment
  double damage_ = 0;
  Vector3 stress_ = Vector3::Zero();
  Matrix3 tangent_ = Matrix3::Zero();
};

/// `nDMaterial PressureDependMultiYield02 tag nd rho G B phi gamma_peak pref d PTAng c1 c3 d1 d3 <n <r1 Gs1 ...>
/// <c2 d2 liq1 liq2 e cs1 cs2 cs3 pa <c <Hv Pv>>>>>`.
std::unique_ptr<NDMaterial> parse_pressure_depend_multi_yield02(common::CommandArgs& args);

}  // namespace fem::materials
