#pragma once
// Linear isotropic elasticity in 2D (OpenSees ElasticIsotropicPlaneStrain2D / ElasticIsotropicPlaneStress2D).
//   plane strain: D = E / ((1+nu)(1-2nu)) [[1-nu, nu, 0], [nu, 1-nu, 0], [0, 0, (1-2nu)/2]]
//   plane stress: D = E / (1-nu^2)        [[1, nu, 0], [nu, 1, 0], [0, 0, (1-nu)/2]]
// (e.g. Zienkiewicz & Taylor, The Finite Element Method, vol. 1, 6th ed., eqs. 6.19 and 6.23).
// Strain (exx, eyy, gxy), stress (sxx, syy, sxy), tension positive.
#include "common/command_args.hpp"
#include "fem_tcl/materials/nd_material.hpp"

namespace fem::materials {

class ElasticIsotropic final : public NDMaterial {
 public:
  /// Throws common::InputError unless E > 0 and -1 < nu < 0.5 and rho >= 0.
  ElasticIsotropic(int tag, double E, double nu, double rho, PlaneType plane = PlaneType::PlaneStrain);

  std::string type_name() const override { return "ElasticIsotropic"; }
  std::unique_ptr<NDMaterial> copy_for(PlaneType plane) const override;
  std::unique_ptr<NDMaterial> clone() const override { return std::make_unique<ElasticIsotropic>(*this); }

  void set_trial_strain(const Vector3& strain) override;
  const Vector3& strain() const override { return strain_; }
  const Vector3& stress() const override { return stress_; }
  const Matrix3& tangent() const override { return D_; }
  Matrix3 initial_tangent() const override { return D_; }
  bool initial_tangent_fixed() const override { return true; }
  void commit_state() override {}
  void revert_to_last_commit() override {}
  void revert_to_start() override;

  double density() const override { return rho_; }
  Vector6 stress_3d() const override;
  bool set_parameter(std::string_view name, double value) override;
  /// Elastic materials accept any stage silently (OpenSees' ElasticIsotropic ignores updateMaterialStage).
  bool update_stage(int stage) override { (void)stage; return true; }
  nlohmann::json to_json() const override;

  double youngs_modulus() const { return E_; }
  double poisson_ratio() const { return nu_; }
  PlaneType plane() const { return plane_; }

 private:
  void update_tangent();

  double E_;
  double nu_;
  double rho_;
  PlaneType plane_;
  Matrix3 D_ = Matrix3::Zero();
  Vector3 strain_ = Vector3::Zero();
  Vector3 stress_ = Vector3::Zero();
};

/// `nDMaterial ElasticIsotropic tag E nu <rho>` (args start at the tag).
std::unique_ptr<NDMaterial> parse_elastic_isotropic(common::CommandArgs& args);

}  // namespace fem::materials
