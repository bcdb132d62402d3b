#pragma once
// Mohr-Coulomb perfect plasticity for plane-strain continuum elements: `nDMaterial MohrCoulomb tag E nu rho phi
// c psi <-tension T>` (this project's command; OpenSees has no plane-strain Mohr-Coulomb). The stress update is
// constitutive::mohr_coulomb_update (exact return in principal stresses onto face / edges / apex + Rankine
// cutoff; de Souza Neto, Peric & Owen 2008, sec. 8.2, Boxes 8.4-8.6), the tangent its consistent tangent.
//
// Stress (sxx syy sxy), strain (exx eyy gxy), tension positive; szz is tracked (plane strain, ezz = 0) and
// recorded through the `stress3D` response (sxx syy szz sxy syz sxz).
//
// Stages (`updateMaterialStage -material tag -stage s`, or `setParameter ... updateMaterialStage|materialState`):
//   0 = linear elastic (the stage after creation, so that a gravity stage builds an elastic geostatic state),
//   1 = Mohr-Coulomb plastic. The stress carries over the switch; the update is incremental from the last
//   committed stress.
#include "common/command_args.hpp"
#include "constitutive/mohr_coulomb.hpp"
#include "fem_tcl/materials/nd_material.hpp"

namespace fem::materials {

struct MohrCoulombParameters {
  double young;              ///< E
  double poisson;            ///< nu
  double density;            ///< rho (mass per volume)
  double friction_deg;       ///< phi, degrees
  double cohesion;           ///< c >= 0
  double dilation_deg;       ///< psi, degrees
  std::optional<double> tension;  ///< Rankine cutoff T on the major principal stress; none when absent
};

class MohrCoulomb final : public NDMaterial, public ReducibleStrength {
 public:
  /// Throws common::InputError: E > 0, -1 < nu < 0.5, rho >= 0, 0 <= phi < 90, c >= 0, 0 <= psi < 90, T >= 0.
  MohrCoulomb(int tag, const MohrCoulombParameters& params);

  std::string type_name() const override { return "MohrCoulomb"; }
  /// Plane strain only; plane stress throws common::InputError.
  std::unique_ptr<NDMaterial> copy_for(PlaneType plane) const override;
  std::unique_ptr<NDMaterial> clone() const override { return std::make_unique<MohrCoulomb>(*this); }
  ReducibleStrength* reducible_strength() override { return this; }
  /// c / F, atan(tan phi / F), atan(tan psi / F) (reducible_strength.hpp); the tension cutoff T / F.
  /// The defined parameters (set_parameter, to_json) are unchanged.
  void set_strength_reduction(double factor) override;
  double strength_reduction() const override { return strength_factor_; }

  void set_trial_strain(const Vector3& strain) override;
  const Vector3& strain() const override { return strain_; }
  const Vector3& stress() const override { return stress_; }
  /// The consistent tangent, evaluated on first request after set_trial_strain (algorithms that iterate on an
  /// elastic or initial matrix never pay for it).
  const Matrix3& tangent() const override;
  Matrix3 initial_tangent() const override { return elastic_tangent(); }
  bool initial_tangent_fixed() const override { return true; }
  void commit_state() override;
  void revert_to_last_commit() override;
  void revert_to_start() override;

  double density() const override { return params_.density; }
  Vector6 stress_3d() const override;
  /// E, nu, rho, phi (deg), c, psi (deg), tension; and updateMaterialStage / materialState (the stage).
  bool set_parameter(std::string_view name, double value) override;
  /// 0 = elastic, 1 = plastic; any other stage throws common::InputError.
  bool update_stage(int stage) override;
  /// stress, strain, stress3D, plus `plasticStrain` (exx eyy ezz gxy, accumulated, committed + this step)
  /// and `yieldRegion` (0 elastic, 1 face, 2 TC edge, 3 TE edge, 4 apex, 5.. tension cutoff sets).
  std::optional<std::vector<double>> response(std::string_view name) const override;
  /// {"name": "<tag>", "type": "MohrCoulomb", "E", "nu", "rho", "phi" (deg), "c", "psi" (deg), "tension" (T or null)}
  nlohmann::json to_json() const override;

  int stage() const { return stage_; }
  constitutive::ReturnRegion region() const { return region_; }
  const Eigen::Vector4d& stress_plane_strain() const { return trial_stress4_; }

 private:
  /// Plane-strain elastic D, formed with the constants (read at every elastic update and assembly).
  const Matrix3& elastic_tangent() const { return elastic_tangent_; }
  void update_constants();
  void validate() const;

  MohrCoulombParameters params_;
  constitutive::IsotropicElasticity elasticity_{};
  constitutive::MohrCoulombStrength strength_{};
  /// The return for elasticity_ and strength_ with its constants formed once (sines, planes, candidate
  /// solves); bit for bit constitutive::mohr_coulomb_return. Copies of a material share it.
  constitutive::MohrCoulombReturnMap return_map_;
  Matrix3 elastic_tangent_ = Matrix3::Zero();
  int stage_ = 0;
  double strength_factor_ = 1.0;  ///< strength reduction factor F in force (1: the defined strength)

  // committed
  Vector3 committed_strain_ = Vector3::Zero();
  Eigen::Vector4d committed_stress4_ = Eigen::Vector4d::Zero();  // sxx syy szz sxy
  Eigen::Vector4d committed_plastic_ = Eigen::Vector4d::Zero();
  // trial
  Vector3 strain_ = Vector3::Zero();
  Eigen::Vector4d trial_stress4_ = Eigen::Vector4d::Zero();
  Eigen::Vector4d trial_plastic_ = Eigen::Vector4d::Zero();
  Vector3 stress_ = Vector3::Zero();
  mutable Matrix3 tangent_ = Matrix3::Zero();
  mutable bool tangent_stale_ = false;        ///< tangent_ still to be evaluated at tangent_trial_
  Eigen::Vector4d tangent_trial_ = Eigen::Vector4d::Zero();  ///< elastic trial stress of the last plastic update
  constitutive::ReturnRegion region_ = constitutive::ReturnRegion::Elastic;
};

/// `nDMaterial MohrCoulomb tag E nu rho phi c psi <-tension T>` (args start at the tag; angles in degrees).
std::unique_ptr<NDMaterial> parse_mohr_coulomb(common::CommandArgs& args);

}  // namespace fem::materials
