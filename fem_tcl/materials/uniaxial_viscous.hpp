#pragma once
// `uniaxialMaterial Viscous tag C alpha <minVel>` (OpenSees 3.8 SRC/material/uniaxial/ViscousMaterial.cpp):
// a nonlinear dashpot, stress = C |rate|^alpha sign(rate) (sign(0) = +, i.e. 0 for alpha > 0), tangent 0,
// damping tangent alpha C max(|rate|, minVel)^(alpha - 1). OpenSees' quirks kept: minVel (default 1e-11,
// |minVel| taken, 0 -> 1e-21 with a warning) bounds only the damping tangent, not the stress; alpha < 0
// is set to 1 with a warning. alpha = 1 is the linear dashpot of a Lysmer-Kuhlemeyer boundary
// (Lysmer & Kuhlemeyer 1969, J. Eng. Mech. Div. ASCE 95(EM4):859-877: C = rho Vs A for shear waves).
#include "fem_tcl/materials/uniaxial_material.hpp"

namespace fem::materials {

class UniaxialViscous final : public UniaxialMaterial {
 public:
  UniaxialViscous(int tag, double c, double alpha, double min_vel)
      : UniaxialMaterial(tag), c_(c), alpha_(alpha), min_vel_(min_vel) {}
  std::string type_name() const override { return "Viscous"; }
  std::unique_ptr<UniaxialMaterial> copy() const override {
    return std::make_unique<UniaxialViscous>(tag(), c_, alpha_, min_vel_);
  }
  void set_trial_strain(double strain, double rate) override { strain_ = strain; rate_ = rate; }
  double strain() const override { return strain_; }
  double strain_rate() const override { return rate_; }
  double stress() const override;
  double tangent() const override { return 0.0; }
  double initial_tangent() const override { return 0.0; }
  double damp_tangent() const override;
  bool tangents_fixed() const override { return alpha_ == 1.0; }  // the linear dashpot: C at every rate
  void commit_state() override { committed_strain_ = strain_; committed_rate_ = rate_; }
  void revert_to_last_commit() override { strain_ = committed_strain_; rate_ = committed_rate_; }
  void revert_to_start() override { strain_ = rate_ = committed_strain_ = committed_rate_ = 0.0; }
  nlohmann::ordered_json to_json() const override;

 private:
  double c_, alpha_, min_vel_;
  double strain_ = 0.0, rate_ = 0.0, committed_strain_ = 0.0, committed_rate_ = 0.0;
};

std::unique_ptr<UniaxialMaterial> parse_uniaxial_viscous(common::CommandArgs& args);

}  // namespace fem::materials
