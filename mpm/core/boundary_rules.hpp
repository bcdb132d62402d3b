#pragma once
// Nodal boundary rules of the explicit grid update, as pure functions (unit-tested on their own).
#include <cmath>

namespace mpm::core {

/// CB-Geo's friction constraint (include/node.tcc apply_friction_constraints; FORMATS.md section 5) on a
/// node with boundary normal along `dir` (0 = x, 1 = y), outward sign `sign_n` (+1 / -1) and Coulomb
/// coefficient `mu`. Acts only while the normal acceleration pushes into the boundary
/// (a_n * sign_n > 0). Moving node (v_t != 0, kinetic): a_t is reduced by mu |a_n| against the net
/// tangential velocity v_t + a_t dt, and set to -v_t / dt if that would reverse v_t. Node at rest
/// (static): a_t = 0 if |a_t| <= mu |a_n|, else reduced by mu |a_n|.
inline void apply_friction_rule(int dir, double sign_n, double mu, double dt, double& ax, double& ay, double vx,
                                double vy) {
  const double an = dir == 0 ? ax : ay;
  double at = dir == 0 ? ay : ax;
  const double vt = dir == 0 ? vy : vx;
  if (!(an * sign_n > 0.0)) return;
  const double limit = mu * std::abs(an);
  const auto sgn = [](double v) { return v > 0.0 ? 1.0 : -1.0; };
  if (vt != 0.0) {
    const double v_net = vt + dt * at;
    if (std::abs(v_net) <= dt * limit)
      at = -vt / dt;
    else
      at -= sgn(v_net) * limit;
  } else if (std::abs(at) <= limit) {
    at = 0.0;
  } else {
    at -= sgn(at) * limit;
  }
  (dir == 0 ? ay : ax) = at;
}

/// Cundall's local non-viscous damping of the unbalanced nodal force (Cundall 1987; CB-Geo
/// compute_acceleration_velocity_cundall): f_i - alpha |f| sign(v_i), per component, |f| the norm.
inline void apply_cundall_damping(double alpha, double& fx, double& fy, double vx, double vy) {
  const auto sign_of = [](double v) { return v > 0.0 ? 1.0 : (v < 0.0 ? -1.0 : 0.0); };
  const double fn = std::sqrt(fx * fx + fy * fy);
  fx -= alpha * fn * sign_of(vx);
  fy -= alpha * fn * sign_of(vy);
}

}  // namespace mpm::core
