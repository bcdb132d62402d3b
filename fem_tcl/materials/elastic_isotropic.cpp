#include "fem_tcl/materials/elastic_isotropic.hpp"

#include <cmath>

namespace fem::materials {

ElasticIsotropic::ElasticIsotropic(int tag, double E, double nu, double rho, PlaneType plane)
    : NDMaterial(tag), E_(E), nu_(nu), rho_(rho), plane_(plane) {
  const std::string where = "nDMaterial ElasticIsotropic " + std::to_string(tag);
  if (!(E > 0.0) || !std::isfinite(E)) throw common::InputError(where, "expected E > 0, got " + std::to_string(E));
  if (!(nu > -1.0 && nu < 0.5)) throw common::InputError(where, "expected -1 < nu < 0.5, got " + std::to_string(nu));
  if (!(rho >= 0.0) || !std::isfinite(rho)) throw common::InputError(where, "expected rho >= 0, got " + std::to_string(rho));
  update_tangent();
}

void ElasticIsotropic::update_tangent() {
  D_.setZero();
  if (plane_ == PlaneType::PlaneStrain) {
    const double c = E_ / ((1.0 + nu_) * (1.0 - 2.0 * nu_));
    D_(0, 0) = D_(1, 1) = c * (1.0 - nu_);
    D_(0, 1) = D_(1, 0) = c * nu_;
    D_(2, 2) = 0.5 * E_ / (1.0 + nu_);
  } else {
    const double c = E_ / (1.0 - nu_ * nu_);
    D_(0, 0) = D_(1, 1) = c;
    D_(0, 1) = D_(1, 0) = c * nu_;
    D_(2, 2) = 0.5 * c * (1.0 - nu_);
  }
  stress_ = D_ * strain_;
}

std::unique_ptr<NDMaterial> ElasticIsotropic::copy_for(PlaneType plane) const {
  return std::make_unique<ElasticIsotropic>(tag(), E_, nu_, rho_, plane);
}

void ElasticIsotropic::set_trial_strain(const Vector3& strain) {
  strain_ = strain;
  stress_ = D_ * strain_;
}

void ElasticIsotropic::revert_to_start() {
  strain_.setZero();
  stress_.setZero();
}

Vector6 ElasticIsotropic::stress_3d() const {
  Vector6 s = Vector6::Zero();
  s[0] = stress_[0];
  s[1] = stress_[1];
  if (plane_ == PlaneType::PlaneStrain) s[2] = nu_ * (stress_[0] + stress_[1]);
  s[3] = stress_[2];
  return s;
}

bool ElasticIsotropic::set_parameter(std::string_view name, double value) {
  if (name == "E") {
    E_ = value;
  } else if (name == "nu" || name == "v") {
    nu_ = value;
  } else if (name == "rho") {
    rho_ = value;
    return true;
  } else {
    return false;
  }
  update_tangent();
  return true;
}

nlohmann::json ElasticIsotropic::to_json() const {
  return nlohmann::json{{"name", std::to_string(tag())}, {"type", "ElasticIsotropicMaterial"},
                        {"E", E_}, {"nu", nu_}, {"rho", rho_}};
}

std::unique_ptr<NDMaterial> parse_elastic_isotropic(common::CommandArgs& args) {
  const int tag = args.integer("tag");
  const double E = args.number("E");
  const double nu = args.number("nu");
  const double rho = args.empty() ? 0.0 : args.number("rho");
  args.expect_end();
  return std::make_unique<ElasticIsotropic>(tag, E, nu, rho);
}

}  // namespace fem::materials
