#pragma once
// OpenSees' PressureIndependMultiYield (plane strain): the total-stress multi-surface plasticity of clay in
// site-response analyses. Nested von Mises yield surfaces f_m = 3/2 (s - a_m) : (s - a_m) - M_m^2 = 0 in
// deviatoric stress space, each with its own plastic shear modulus H_m, translated by Mroz's (1967) rule so
// that they touch at the stress point and never intersect: a piecewise-linear hyperbolic backbone under
// monotonic shear and Masing-type hysteresis under cyclic shear (Prevost 1985, Soil Dyn. Earthquake Eng. 4(1);
// Elgamal, Yang, Parra & Ragheb 2003, Int. J. Plasticity 19, 883-905; the OpenSees command manual,
// "PressureIndependMultiYield Material"). The volumetric response is linear elastic, p = p0 + K tr(de).
//
//   nDMaterial PressureIndependMultiYield tag nd rho refShearModul refBulkModul cohesi peakShearStra
//              <frictionAng=0 <refPress=100 <pressDependCoe=0 <noYieldSurf=20 <r1 Gs1 ...>>>>>
//
// Surfaces as OpenSees generates them: with frictionAng = 0 the octahedral shear strength is
// tau_f = 2 sqrt(2) c / 3 and the backbone tau = G g / (1 + g / g_r) (g octahedral shear strain) reaches it at
// peakShearStra; with frictionAng > 0 the surfaces grow with the confinement present when the stage turns
// plastic (a Drucker-Prager cone, sin(phi) as for triaxial compression) and G, K scale with
// ((p' + p_r) / (p_ref + p_r))^pressDependCoe; a negative noYieldSurf gives |n| user points (shear strain,
// G / Gmax). Stress update as OpenSees' (sub-increments of one surface size, stress correction onto the
// active surface, Mroz translation, load reversal re-centring the inner surfaces: the mechanism shared with
// PressureDependMultiYield02, fem_tcl/materials/multi_yield_surfaces.hpp, with a cone height of 1: the
// surfaces are stresses), tangent as OpenSees'.
//
// Stages (`updateMaterialStage`): 0 = linear elastic with G and K (after creation), 1 = plastic; at the first
// plastic step the surfaces are set around the committed (gravity) stress, as OpenSees' elast2Plast does.
// Strain (exx eyy gxy), stress (sxx syy sxy), tension positive; the `stress` response is OpenSees' five
// columns (sxx syy szz sxy, and the stress ratio sqrt(3/2 s:s) / M_failure).
#include <vector>

#include "common/command_args.hpp"
#include "fem_tcl/materials/multi_yield_surfaces.hpp"
#include "fem_tcl/materials/nd_material.hpp"
#include "fem_tcl/materials/reducible_strength.hpp"

namespace fem::materials {

struct PressureIndependMultiYieldParameters {
  double density = 0;             ///< rho
  double shear_modulus = 0;       ///< refShearModul G_r (at refPress when pressDependCoe > 0)
  double bulk_modulus = 0;        ///< refBulkModul B_r
  double cohesion = 0;            ///< cohesi c (>= 0)
  double peak_shear_strain = 0;   ///< peakShearStra, the octahedral shear strain at which the strength is reached
  double friction_deg = 0;        ///< frictionAng (degrees)
  double ref_pressure = 100;      ///< refPress p_ref (> 0, compression)
  double pressure_exponent = 0;   ///< pressDependCoe d
  int surfaces = 20;              ///< number of yield surfaces
  /// User-defined backbone (noYieldSurf < 0): (shear strain, G / Gmax) pairs, one per surface; empty: automatic.
  std::vector<double> backbone;
};

class PressureIndependMultiYield final : public NDMaterial, public ReducibleStrength {
 public:
  /// Validates (common::InputError naming the material) and generates the surfaces.
  PressureIndependMultiYield(int tag, const PressureIndependMultiYieldParameters& params);

  std::string type_name() const override { return "PressureIndependMultiYield"; }
  /// Plane strain only (OpenSees returns no plane-stress copy): plane stress throws common::InputError.
  std::unique_ptr<NDMaterial> copy_for(PlaneType plane) const override;
  std::unique_ptr<NDMaterial> clone() const override { return std::make_unique<PressureIndependMultiYield>(*this); }
  ReducibleStrength* reducible_strength() override { return this; }
  /// c / F, atan(tan phi / F) and the user backbone's G / Gmax / F (reducible_strength.hpp): the surfaces are
  /// generated again for that strength and, once plastic, set around the committed stress as at the switch
  /// (the committed stress brought onto the failure surface where it lies outside it). G and K are kept.
  void set_strength_reduction(double factor) override;
  double strength_reduction() const override { return strength_factor_; }

  void set_trial_strain(const Vector3& strain) override;
  const Vector3& strain() const override { return trial_.strain; }
  const Vector3& stress() const override { return stress_; }
  const Matrix3& tangent() const override { return tangent_; }
  Matrix3 initial_tangent() const override;
  void commit_state() override { committed_ = trial_; }
  void revert_to_last_commit() override;
  void revert_to_start() override;

  double density() const override { return params_.density; }
  Vector6 stress_3d() const override { return trial_.stress; }
  /// updateMaterialStage / materialState, shearModulus, bulkModulus.
  bool set_parameter(std::string_view name, double value) override;
  /// 0 = elastic, 1 = plastic; any other stage throws common::InputError.
  bool update_stage(int stage) override;
  /// stress / stresses: sxx syy szz sxy ratio (OpenSees' getCommittedStress); strain; stress3D.
  std::optional<std::vector<double>> response(std::string_view name) const override;
  nlohmann::json to_json() const override;

  /// One yield surface: centre (deviatoric tensor, sxx syy szz sxy syz sxz), size M (in sqrt(3/2 s:s)),
  /// plastic shear modulus H.
  using Surface = multi_yield::YieldSurface;
  const std::vector<Surface>& surfaces() const { return trial_.surfaces.surfaces(); }
  int active_surface() const { return trial_.surfaces.active(); }

 private:
  /// What one integration point carries between steps (OpenSees' committed / trial members).
  struct State {
    Vector3 strain = Vector3::Zero();  ///< engineering (exx eyy gxy)
    Vector6 stress = Vector6::Zero();  ///< full tensor, tension positive
    multi_yield::MultiYieldSurfaces surfaces;  ///< 1-based as OpenSees' (index 0 unused), and the active one
    double shear_modulus = 0, bulk_modulus = 0;  ///< scaled with the confinement at the plastic switch
    bool plastic_started = false;      ///< OpenSees' e2p
  };

  void set_up_surfaces();
  void start_plastic(State& s) const;                      // elast2Plast
  void place_surfaces(State& s) const;                     // elast2Plast's active-surface search
  void scale_to_confinement(State& s, bool moduli) const;  // paramScaling
  void plastic_update(const Vector6& strain_increment);    // getStress, stage 1
  void form_tangent();

  PressureIndependMultiYieldParameters defined_;  ///< as given (after OpenSees' corrections)
  PressureIndependMultiYieldParameters params_;   ///< in force: reduced by strength_factor_, derived values set
  double strength_factor_ = 1.0;
  double residual_pressure_ = 0;  ///< p_r (OpenSees' residualPress)
  int stage_ = 0;
  State committed_, trial_;
  Vector3 stress_ = Vector3::Zero();
  Matrix3 tangent_ = Matrix3::Zero();
};

/// `nDMaterial PressureIndependMultiYield tag nd rho G B c peakShearStra <phi <pref <d <n <r1 Gs1 ...>>>>>`.
std::unique_ptr<NDMaterial> parse_pressure_independ_multi_yield(common::CommandArgs& args);

}  // namespace fem::materials
