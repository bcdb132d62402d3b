#pragma once
// Drucker-Prager with a tension cutoff, isotropic (linear + saturating) and linear kinematic hardening, and
// non-associated flow: OpenSees 3.8's `nDMaterial DruckerPrager` (UWmaterials/DruckerPrager.cpp with
// DruckerPragerPlaneStrain.cpp; Petek, Mackenzie-Helnwein & Arduino), reproduced so that a script gives
// OpenSees' numbers to round-off.
//
// Model (OpenSees DruckerPrager documentation; Petek 2006, MSc thesis, U. Washington), tension positive,
// stress in 6-component contravariant Voigt form (sxx syy szz sxy syz sxz), strain with engineering shears:
//   f1 = ||s - beta|| + rho I1 - sqrt(2/3) Kiso(alpha1) <= 0     (cone; ||.|| with weight 2 on the shears)
//   f2 = I1 - T(alpha2) <= 0                                      (tension cutoff)
//   Kiso(a) = sigma_y + theta H a + (Kinf - Ko)(1 - exp(-delta1 a)),  T(a) = T0 exp(-delta2 a),
//   T0 = sqrt(2/3) sigma_y / rho (1e10 when rho = 0),  H' = (1 - theta) H (kinematic part),
//   flow: d eps_p = gamma1 (n + rho_bar 1) + gamma2 1.
// The return map, active-set logic and tangent follow OpenSees 3.8 INCLUDING its quirks (documented in
// tests/data/reference_runs/README.md section 3, item 12):
//   - the tangent's 4 G^2 gamma / ||eta|| term uses the deviator norm AFTER the return (not the consistent one);
//   - the tension-cap residual is never assembled (OpenSees tests Jact(i) == 2, which never holds), so a
//     tension-only return solves the cone equation with gamma2 = 0, and a two-surface return keeps R2 = 0;
//   - the elastic moduli update of materialState 1 (K, G ~ sqrt(1 + p/p_atm)) happens after the trial stress
//     was computed with the old moduli, once per switch into state 1;
//   - the back stress moves against the return direction (beta_n+1 = beta_n - 2/3 H' gamma n) while the
//     residual assumes it moves with it, so with kinematic hardening (theta < 1) the returned state lies
//     4/3 H' gamma outside the cone it reports;
//   - revert_to_last_commit() leaves the trial state as it is (OpenSees' revertToLastCommit is a no-op);
//   - initial_tangent() returns the current algorithmic tangent, as DruckerPragerPlaneStrain::getInitialTangent
//     in 3.8 (a copy of getTangent).
// materialState: 0 = elastic, 1 = elastic with pressure-dependent moduli, 2 = elastoplastic (the default
// after creation; a gravity stage sets 0 first: `setParameter -val 0 ... materialState`).
#include <Eigen/Core>

#include "common/command_args.hpp"
#include "fem_tcl/materials/nd_material.hpp"

namespace fem::materials {

struct DruckerPragerParameters {
  double bulk_modulus;         ///< K
  double shear_modulus;        ///< G
  double sigma_y;              ///< cohesive intercept (yield at zero confinement)
  double rho;                  ///< friction term of the cone
  double rho_bar;              ///< dilatancy term of the flow (rho_bar = rho: associated)
  double k_inf;                ///< saturated isotropic hardening stress Kinf
  double k_o;                  ///< initial isotropic hardening stress Ko
  double delta1;               ///< exponential isotropic hardening rate
  double delta2;               ///< tension softening rate
  double hardening;            ///< H, linear hardening modulus
  double theta;                ///< isotropic fraction of H (0: kinematic only, 1: isotropic only)
  double density = 0.0;        ///< mass density
  double p_atm = 101.0;        ///< atmospheric pressure for materialState 1
};

class DruckerPrager final : public NDMaterial, public ReducibleStrength {
 public:
  using Vector6d = Eigen::Matrix<double, 6, 1>;
  using Matrix6d = Eigen::Matrix<double, 6, 6>;
  using Vector5d = Eigen::Matrix<double, 5, 1>;

  /// Throws common::InputError when K or G is not positive or a parameter is not finite.
  DruckerPrager(int tag, const DruckerPragerParameters& params);

  std::string type_name() const override { return "DruckerPrager"; }
  /// Plane strain only (OpenSees' getCopy("PlaneStrain")); plane stress throws common::InputError.
  std::unique_ptr<NDMaterial> copy_for(PlaneType plane) const override;
  std::unique_ptr<NDMaterial> clone() const override { return std::make_unique<DruckerPrager>(*this); }
  ReducibleStrength* reducible_strength() override { return this; }
  /// Strength reduction through the plane-strain Mohr-Coulomb match of the cone (Drucker & Prager 1952,
  /// Q. Appl. Math. 10(2):157-165): rho / sqrt(2) = tan phi / sqrt(9 + 12 tan^2 phi), sigma_y / sqrt(3) =
  /// 3 c / sqrt(9 + 12 tan^2 phi). tan phi and c are divided by F and rho, sigma_y mapped back; rho_bar likewise
  /// with tan psi; the hardening stresses Kinf, Ko and H scale with sigma_y. Throws common::InputError when
  /// rho or rho_bar >= 1/sqrt(6) (no Mohr-Coulomb friction angle matches).
  void set_strength_reduction(double factor) override;
  double strength_reduction() const override { return strength_factor_; }

  void set_trial_strain(const Vector3& strain) override;
  const Vector3& strain() const override { return strain2d_; }
  const Vector3& stress() const override { return stress2d_; }
  const Matrix3& tangent() const override { return tangent2d_; }
  Matrix3 initial_tangent() const override { return tangent2d_; }
  void commit_state() override;
  void revert_to_last_commit() override {}
  void revert_to_start() override;

  double density() const override { return params_.density; }
  Vector6 stress_3d() const override { return sigma_; }
  /// materialState (0|1|2), frictionalStrength (rho), nonassociativeTerm (rho_bar), cohesiveIntercept
  /// (sigma_y), shearModulus, bulkModulus: the names OpenSees' DruckerPrager::setParameter knows.
  bool set_parameter(std::string_view name, double value) override;
  /// OpenSees' DruckerPrager has no stages: `updateMaterialStage` has no effect (the caller warns).
  bool update_stage(int stage) override { (void)stage; return false; }
  /// stress, strain, stress3D, and `state`: (I1, ||s - beta||, tr(eps_p), ||dev eps_p||, ||eps_p||).
  std::optional<std::vector<double>> response(std::string_view name) const override;
  nlohmann::json to_json() const override;

  int material_state() const { return elastic_flag_; }
  const Vector5d& state() const { return state_; }
  const Vector6d& plastic_strain() const { return eps_p_n1_; }

 private:
  void initialize();
  void integrate();
  void update_elastic_parameters();
  void update_tension_strength();
  double k_iso(double alpha1) const;
  double k_iso_prime(double alpha1) const;
  double tension_strength(double alpha2) const;
  void condense();

  DruckerPragerParameters params_;
  double k_ref_, g_ref_;  // reference moduli (materialState 1 scales them)
  double k_, g_;          // current moduli
  double t0_ = 0.0;       // tension cutoff of I1
  double h_prime_ = 0.0;  // kinematic hardening modulus (1 - theta) H
  int elastic_flag_ = 2;
  double strength_factor_ = 1.0;  ///< strength reduction factor in force
  bool modulus_flag_ = true;  // OpenSees' mFlag: the state-1 modulus update is still to do

  Vector6d eps_ = Vector6d::Zero();
  Vector6d eps_p_n_ = Vector6d::Zero(), eps_p_n1_ = Vector6d::Zero();
  Vector6d sigma_ = Vector6d::Zero();
  Vector6d beta_n_ = Vector6d::Zero(), beta_n1_ = Vector6d::Zero();
  double alpha1_n_ = 0.0, alpha1_n1_ = 0.0, alpha2_n_ = 0.0, alpha2_n1_ = 0.0;
  Matrix6d ce_ = Matrix6d::Zero(), cep_ = Matrix6d::Zero();
  Vector5d state_ = Vector5d::Zero();

  Vector3 strain2d_ = Vector3::Zero();
  Vector3 stress2d_ = Vector3::Zero();
  Matrix3 tangent2d_ = Matrix3::Zero();
};

/// `nDMaterial DruckerPrager tag K G sigma_y rho rho_bar Kinf Ko delta1 delta2 H theta <density> <atm>`
/// (args start at the tag).
std::unique_ptr<NDMaterial> parse_drucker_prager(common::CommandArgs& args);

}  // namespace fem::materials
