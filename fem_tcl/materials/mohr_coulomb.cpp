#include "fem_tcl/materials/mohr_coulomb.hpp"

#include <cmath>
#include <limits>
#include <string>

namespace fem::materials {
namespace {
constexpr double kDegree = 3.14159265358979323846 / 180.0;
}  // namespace

MohrCoulomb::MohrCoulomb(int tag, const MohrCoulombParameters& params) : NDMaterial(tag), params_(params) {
  validate();
  update_constants();
  tangent_ = elastic_tangent();
  tangent_stale_ = false;
}

void MohrCoulomb::validate() const {
  const std::string where = "nDMaterial MohrCoulomb " + std::to_string(tag());
  const auto& p = params_;
  if (!(p.young > 0.0) || !std::isfinite(p.young)) throw common::InputError(where, "expected E > 0, got " + std::to_string(p.young));
  if (!(p.poisson > -1.0 && p.poisson < 0.5)) throw common::InputError(where, "expected -1 < nu < 0.5, got " + std::to_string(p.poisson));
  if (!(p.density >= 0.0) || !std::isfinite(p.density)) throw common::InputError(where, "expected rho >= 0, got " + std::to_string(p.density));
  if (!(p.friction_deg >= 0.0 && p.friction_deg < 90.0))
    throw common::InputError(where, "expected 0 <= phi < 90 (degrees), got " + std::to_string(p.friction_deg));
  if (!(p.cohesion >= 0.0) || !std::isfinite(p.cohesion)) throw common::InputError(where, "expected c >= 0, got " + std::to_string(p.cohesion));
  if (!(p.dilation_deg >= 0.0 && p.dilation_deg < 90.0))
    throw common::InputError(where, "expected 0 <= psi < 90 (degrees), got " + std::to_string(p.dilation_deg));
  if (p.tension && !(*p.tension >= 0.0))
    throw common::InputError(where, "expected -tension T >= 0, got " + std::to_string(*p.tension));
}

void MohrCoulomb::update_constants() {
  elasticity_ = constitutive::IsotropicElasticity::from_young_poisson(params_.young, params_.poisson);
  // Shear strength reduction (Griffiths & Lane 1999, eqs. 1-2): F = 1 leaves the defined strength.
  const double f = strength_factor_;
  const double phi = f == 1.0 ? params_.friction_deg * kDegree : std::atan(std::tan(params_.friction_deg * kDegree) / f);
  const double psi = f == 1.0 ? params_.dilation_deg * kDegree : std::atan(std::tan(params_.dilation_deg * kDegree) / f);
  strength_ = {phi, psi, params_.cohesion / f,
               params_.tension ? *params_.tension / f : std::numeric_limits<double>::infinity()};
  return_map_ = constitutive::MohrCoulombReturnMap(elasticity_, constitutive::MohrCoulombSurface(strength_));
  elastic_tangent_ = plane_strain_elastic_matrix(elasticity_.bulk_modulus, elasticity_.shear_modulus);
}

void MohrCoulomb::set_strength_reduction(double factor) {
  if (!(factor > 0.0) || !std::isfinite(factor)) {
    throw common::InputError("nDMaterial MohrCoulomb " + std::to_string(tag()),
                             "expected a strength reduction factor > 0, got " + std::to_string(factor));
  }
  strength_factor_ = factor;
  update_constants();
}

std::unique_ptr<NDMaterial> MohrCoulomb::copy_for(PlaneType plane) const {
  if (plane != PlaneType::PlaneStrain)
    throw common::InputError("nDMaterial MohrCoulomb " + std::to_string(tag()), "only PlaneStrain elements are supported");
  auto copy = std::make_unique<MohrCoulomb>(tag(), params_);
  copy->stage_ = stage_;
  // the same constants: share the return's data (one copy in cache for every element of this material)
  if (copy->strength_factor_ == strength_factor_) copy->return_map_ = return_map_;
  return copy;
}

void MohrCoulomb::set_trial_strain(const Vector3& strain) {
  strain_ = strain;
  const Vector3 dstrain = strain - committed_strain_;
  const Eigen::Vector4d trial = constitutive::elastic_trial(committed_stress4_, dstrain, elasticity_);
  if (stage_ == 0) {
    trial_stress4_ = trial;
    trial_plastic_ = committed_plastic_;
    region_ = constitutive::ReturnRegion::Elastic;
    tangent_ = elastic_tangent();
    tangent_stale_ = false;
  } else {
    const constitutive::MohrCoulombUpdate up = return_map_.apply(trial);
    trial_stress4_ = up.stress;
    trial_plastic_ = committed_plastic_ + up.plastic_strain_increment;
    region_ = up.region;
    if (up.region == constitutive::ReturnRegion::Elastic) {
      tangent_ = elastic_tangent();
      tangent_stale_ = false;
    } else {
      tangent_trial_ = trial;
      tangent_stale_ = true;
    }
  }
  stress_ << trial_stress4_[0], trial_stress4_[1], trial_stress4_[3];
}

const Matrix3& MohrCoulomb::tangent() const {
  if (tangent_stale_) {
    tangent_ = constitutive::mohr_coulomb_tangent(tangent_trial_, elasticity_, strength_);
    tangent_stale_ = false;
  }
  return tangent_;
}

void MohrCoulomb::commit_state() {
  committed_strain_ = strain_;
  committed_stress4_ = trial_stress4_;
  committed_plastic_ = trial_plastic_;
}

void MohrCoulomb::revert_to_last_commit() {
  strain_ = committed_strain_;
  trial_stress4_ = committed_stress4_;
  trial_plastic_ = committed_plastic_;
  stress_ << trial_stress4_[0], trial_stress4_[1], trial_stress4_[3];
  region_ = constitutive::ReturnRegion::Elastic;
}

void MohrCoulomb::revert_to_start() {
  committed_strain_.setZero();
  committed_stress4_.setZero();
  committed_plastic_.setZero();
  revert_to_last_commit();
  tangent_ = elastic_tangent();
  tangent_stale_ = false;
}

Vector6 MohrCoulomb::stress_3d() const {
  Vector6 s = Vector6::Zero();
  s << trial_stress4_[0], trial_stress4_[1], trial_stress4_[2], trial_stress4_[3], 0.0, 0.0;
  return s;
}

bool MohrCoulomb::update_stage(int stage) {
  if (stage != 0 && stage != 1)
    throw common::InputError("updateMaterialStage -material " + std::to_string(tag()),
                             "MohrCoulomb stages are 0 (elastic) and 1 (plastic), got " + std::to_string(stage));
  stage_ = stage;
  return true;
}

bool MohrCoulomb::set_parameter(std::string_view name, double value) {
  MohrCoulombParameters p = params_;
  if (name == "updateMaterialStage" || name == "materialState") {
    return update_stage(static_cast<int>(value));
  } else if (name == "E") {
    p.young = value;
  } else if (name == "nu" || name == "v") {
    p.poisson = value;
  } else if (name == "rho") {
    p.density = value;
  } else if (name == "phi") {
    p.friction_deg = value;
  } else if (name == "c" || name == "cohesion") {
    p.cohesion = value;
  } else if (name == "psi") {
    p.dilation_deg = value;
  } else if (name == "tension") {
    p.tension = value;
  } else {
    return false;
  }
  const MohrCoulombParameters old = params_;
  params_ = p;
  try {
    validate();
  } catch (...) {
    params_ = old;
    throw;
  }
  update_constants();
  return true;
}

std::optional<std::vector<double>> MohrCoulomb::response(std::string_view name) const {
  if (name == "plasticStrain") return std::vector<double>(trial_plastic_.data(), trial_plastic_.data() + 4);
  if (name == "yieldRegion") return std::vector<double>{static_cast<double>(region_)};
  return NDMaterial::response(name);
}

nlohmann::json MohrCoulomb::to_json() const {
  nlohmann::json j{{"name", std::to_string(tag())}, {"type", "MohrCoulomb"}, {"E", params_.young},
                   {"nu", params_.poisson},         {"rho", params_.density}, {"phi", params_.friction_deg},
                   {"c", params_.cohesion},         {"psi", params_.dilation_deg}};
  j["tension"] = params_.tension ? nlohmann::json(*params_.tension) : nlohmann::json(nullptr);
  return j;
}

std::unique_ptr<NDMaterial> parse_mohr_coulomb(common::CommandArgs& args) {
  const int tag = args.integer("tag");
  MohrCoulombParameters p{};
  p.young = args.number("E");
  p.poisson = args.number("nu");
  p.density = args.number("rho");
  p.friction_deg = args.number("phi");
  p.cohesion = args.number("c");
  p.dilation_deg = args.number("psi");
  if (args.flag("-tension")) p.tension = args.number("T (after -tension)");
  args.expect_end();
  return std::make_unique<MohrCoulomb>(tag, p);
}

}  // namespace fem::materials
