#pragma once
// The body force per unit mass of a step (Sulsky et al. 1994, eq. 16's m N b): gravity, and with a base
// acceleration a_g(t) (the deck's external_loading_conditions.base_acceleration) the inertial force of
// the frame that moves with the shaken base: b(t) = g - a_g(t) e_dir (d'Alembert). Velocities and
// displacements are then relative to the base, as OpenSees' UniformExcitation responses are.
#include <optional>

#include "mpm/core/nodal_constraints.hpp"
#include "mpm/problem/deck.hpp"

namespace mpm::core {

struct BodyForce {
  Vec2 gravity = Vec2::Zero();
  std::optional<BaseAcceleration> base;
  /// b at time t (s): an explicit step from t_n uses b(t_n).
  Vec2 at(double t) const {
    Vec2 b = gravity;
    if (base) b[base->dir] -= base->at(t);
    return b;
  }
};

}  // namespace mpm::core
