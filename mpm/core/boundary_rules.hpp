#pragma once
// Nodal rules of the explicit grid update, as pure functions (unit-tested on their own); the velocity
// and friction constraints are in nodal_constraints.hpp.
#include <cmath>

namespace mpm::core {

/// Cundall's local non-viscous damping of the unbalanced nodal force (Cundall 1987; CB-Geo
/// compute_acceleration_velocity_cundall): f_i - alpha |f| sign(v_i), per component, |f| the norm.
inline void apply_cundall_damping(double alpha, double& fx, double& fy, double vx, double vy) {
  const auto sign_of = [](double v) { return v > 0.0 ? 1.0 : (v < 0.0 ? -1.0 : 0.0); };
  const double fn = std::sqrt(fx * fx + fy * fy);
  fx -= alpha * fn * sign_of(vx);
  fy -= alpha * fn * sign_of(vy);
}

}  // namespace mpm::core
