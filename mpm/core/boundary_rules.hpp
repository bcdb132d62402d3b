#pragma once
// Nodal rules of the explicit grid update, as pure functions (unit-tested on their own); the velocity
// and friction constraints are in nodal_constraints.hpp.
#include <cmath>

#include "mpm/core/nodal_constraints.hpp"

namespace mpm::core {

/// Cundall's local non-viscous damping of the unbalanced nodal force (Cundall 1987; CB-Geo
/// compute_acceleration_velocity_cundall): f_d - alpha |f| sign(v_d) for each axis d, |f| the norm
/// (summed from axis 0 on: in 2D sqrt(fx fx + fy fy), as before the axes).
template <int dim>
inline void apply_cundall_damping(double alpha, Vector<dim>& f, const Vector<dim>& v) {
  const auto sign_of = [](double x) { return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0); };
  double f2 = f[0] * f[0];
  for (int d = 1; d < dim; ++d) f2 += f[d] * f[d];
  const double fn = std::sqrt(f2);
  for (int d = 0; d < dim; ++d) f[d] -= alpha * fn * sign_of(v[d]);
}

}  // namespace mpm::core
