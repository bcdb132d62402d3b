#include "fem_tcl/materials/uniaxial_viscous.hpp"

#include <cmath>
#include <iostream>

namespace fem::materials {

double UniaxialViscous::stress() const {
  // OpenSees 3.8 computes a minVel-bounded value and then overwrites it with the unbounded one.
  const double s = c_ * std::pow(std::abs(rate_), alpha_);
  return rate_ < 0.0 ? -s : s;
}

double UniaxialViscous::damp_tangent() const {
  const double v = std::abs(rate_) < min_vel_ ? min_vel_ : std::abs(rate_);
  return alpha_ * c_ * std::pow(v, alpha_ - 1.0);
}

nlohmann::ordered_json UniaxialViscous::to_json() const {
  // OpenSees 3.8 prints plain text here (no JSON branch); this project writes valid JSON.
  nlohmann::ordered_json j;
  j["name"] = std::to_string(tag());
  j["type"] = "Viscous";
  j["C"] = c_;
  j["Alpha"] = alpha_;
  j["minVel"] = min_vel_;
  return j;
}

std::unique_ptr<UniaxialMaterial> parse_uniaxial_viscous(common::CommandArgs& args) {
  const int tag = args.integer("tag");
  const double c = args.number("C");
  double alpha = args.number("alpha");
  double min_vel = 1.0e-11;
  if (!args.empty()) min_vel = args.number("minVel");
  args.expect_end();
  if (!std::isfinite(c) || !std::isfinite(alpha) || !std::isfinite(min_vel)) args.fail("expected finite C, alpha and minVel");
  if (alpha < 0.0) {
    std::cerr << "WARNING " << args.command() << ": alpha < 0, set to 1.0 (as OpenSees)\n";
    alpha = 1.0;
  }
  min_vel = std::abs(min_vel);
  if (min_vel == 0.0) {
    std::cerr << "WARNING " << args.command() << ": minVel == 0, set to 1.0e-21 (as OpenSees)\n";
    min_vel = 1.0e-21;
  }
  return std::make_unique<UniaxialViscous>(tag, c, alpha, min_vel);
}

}  // namespace fem::materials
