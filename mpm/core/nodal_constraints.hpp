#pragma once
// The velocity and friction constraints of one grid node in the explicit grid update, in momentum
// form: the constraint changes the node's velocity by an impulse, and the same velocity change is
// what FLIP hands to the particles, so PIC, FLIP and any blend see one constrained nodal field.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "mpm/core/lagged_friction.hpp"

namespace mpm::core {

/// A nodal vector of the `dim`-dimensional engine: one component per axis.
template <int dim>
using Vector = Eigen::Matrix<double, dim, 1>;
using Vec2 = Vector<2>;

/// What constrains one node of the `dim`-dimensional grid (from the deck's velocity_constraints and
/// friction_constraints).
template <int dim>
struct NodeConstraint {
  static_assert(dim >= 1 && dim <= 8, "fixed holds one bit per axis");
  std::uint8_t fixed = 0;  ///< bit d set: velocity component d is prescribed
  Vector<dim> fixed_velocity = Vector<dim>::Zero();
  int friction_dir = -1;   ///< the wall's normal axis d < dim (0 = x, 1 = y, 2 = z); -1: no friction
  double sign_n = -1.0;    ///< outward normal sign along friction_dir (+1 / -1)
  double mu = 0.0;         ///< Coulomb coefficient
  NormalLag lag;           ///< the strength's lag behind the normal force (lagged_friction.hpp); default none
  bool constrained() const { return fixed != 0 || friction_dir >= 0; }
  /// A frictional wall with a free normal: it stops an approach and never pulls (a one-sided contact).
  bool one_sided() const { return friction_dir >= 0 && !((fixed >> friction_dir) & 1u); }
};

/// The normal velocity of a frictional node's wall: the prescribed one, else 0 (a wall at rest).
template <int dim>
inline double wall_velocity(const NodeConstraint<dim>& c) {
  const int dn = c.friction_dir;
  return ((c.fixed >> dn) & 1u) ? c.fixed_velocity[dn] : 0.0;
}

/// The prescribed velocity components take their value.
template <int dim>
inline void apply_prescribed(Vector<dim>& v, const NodeConstraint<dim>& c) {
  for (int d = 0; d < dim; ++d)
    if ((c.fixed >> d) & 1u) v[d] = c.fixed_velocity[d];
}

/// The constrained end-of-step nodal velocity and the velocity change it makes over the step.
template <int dim>
struct ConstrainedVelocity {
  Vector<dim> velocity;  ///< v_new
  Vector<dim> rate;      ///< (v_new - v_old) / dt: the FLIP increment rate handed to the particles
};

/// Grid update of a constrained node (Bardenhagen, Brackbill & Sulsky 2000, "The material-point method
/// for granular materials", CMAME 187, 529-541, section 3, eqs. 19-25, the contact algorithm, with the
/// wall as the rigid body). v_old = p / m is the node's velocity from the mapped momentum before any
/// constraint, a = f / m its acceleration (after damping), v* = v_old + a dt the trial velocity.
/// - Friction (friction_dir = d, any axis d < dim; outward sign s, coefficient mu): the wall pushes only
///   when the node approaches it, w_n = s (v*_d - v_wall) > 0, with v_wall the prescribed normal velocity
///   (0 when the normal is free: then the wall is a one-sided contact that stops the approach). The
///   normal reaction over the step is the impulse that stops that approach, m w_n (a force m w_n / dt:
///   the normal nodal momentum plus the normal force, so it cannot be inflated by a rectified force
///   alone), and the Coulomb limit caps the tangential impulse at mu m w_n: the tangential velocity v*_t
///   (v* without its component d: a vector over the other dim - 1 axes, a line in 2D, the wall's plane in
///   3D) is reduced along its own direction by min(|v*_t|, mu w_n), never reversed (stick when
///   |v*_t| <= mu w_n: the limit is on the magnitude of the tangential vector, as the paper's contact
///   algorithm takes it in any dimension).
/// - Prescribed components then take their value.
/// A one-sided contact acts only where the material touches the wall (the engine's gap test,
/// wall_contact.cpp); elsewhere the node is free.
/// With a lag (c.lag, `memory` the node's NormalMemory, `mass` its mass) the Coulomb limit is mu N_s dt / m
/// with N_s the lagged normal force (lagged_friction.hpp; N = m max(w_n, 0) / dt, slip speed |v*_t|), and
/// on a wall that also holds the normal (bilateral) friction acts while N_s > 0 even where the wall pulls.
/// The rate (v_new - v_old) / dt is what the particles get under FLIP: at a wall it removes the
/// particles' normal velocity into the wall together with the nodal one (as Uintah's MPM does,
/// SerialMPM::setGridBoundaryConditions: "recompute acceleration as the difference between the velocity
/// interpolated to the grid (no bcs applied) and the new velocity_star"). CB-Geo hands FLIP a = 0 in a
/// constrained direction and mu |a_n| from the force alone (include/node.tcc); mpm/README.md.
template <int dim>
inline ConstrainedVelocity<dim> constrained_velocity(const Vector<dim>& v_old, const Vector<dim>& a, double dt,
                                                    const NodeConstraint<dim>& c, NormalMemory* memory = nullptr,
                                                    double mass = 0.0) {
  Vector<dim> v = v_old + dt * a;
  if (c.friction_dir >= 0) {
    const int dn = c.friction_dir;
    const double v_wall = wall_velocity(c);
    const double approach = c.sign_n * (v[dn] - v_wall);
    const bool lagged = memory && c.lag.active();
    if (approach > 0.0 || lagged) {  // else a node leaving a wall without a lag: free
      Vector<dim> vt = v;  // v*_t: the tangential velocity, over every axis but dn
      vt[dn] = 0.0;
      const double slip = vt.norm();
      double limit = c.mu * approach;  // the tangential velocity change Coulomb allows
      if (lagged) {
        const double N = mass * std::max(approach, 0.0) / dt;
        limit = c.mu * lag_normal_force(*memory, N, slip, dt, c.lag, mass) * dt / mass;
      }
      if (approach > 0.0 || (lagged && ((c.fixed >> dn) & 1u))) {
        const double v_n = approach > 0.0 ? v_wall : v[dn];  // the approach is stopped
        v = slip <= limit ? Vector<dim>::Zero() : Vector<dim>((1.0 - limit / slip) * vt);
        v[dn] = v_n;
      }
    }
  }
  apply_prescribed(v, c);
  return {v, (v - v_old) / dt};
}

/// The velocity of a constrained node that the strain rate reads (USF from the mapped momentum, MUSL from
/// the remapped one): the prescribed components, and at a frictional wall no approach into it. The wall
/// stops that approach in the grid update (constrained_velocity), so the particles never move into it; a
/// strain rate that read it would store compression the motion never makes, and on a one-sided contact
/// under FLIP that stored compression pushes the body off the wall a little more every step (a block at
/// rest on a slope hopped and crept down it: 0.125 m in 1 s, mpm/README.md "Friction and flutter"). USL reads
/// the constrained end-of-step velocity itself. Friction is left to the grid update: it needs the normal
/// impulse of the step.
template <int dim>
inline Vector<dim> strain_rate_velocity(Vector<dim> v, const NodeConstraint<dim>& c) {
  if (c.friction_dir >= 0) {
    const int dn = c.friction_dir;
    const double v_wall = wall_velocity(c);
    if (c.sign_n * (v[dn] - v_wall) > 0.0) v[dn] = v_wall;
  }
  apply_prescribed(v, c);
  return v;
}

}  // namespace mpm::core
