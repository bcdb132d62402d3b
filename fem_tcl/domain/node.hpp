#pragma once
// A 2D node (OpenSees Node with ndm = 2) with ndf = 2 dofs (ux, uy) or 3 (ux, uy and the pore pressure p
// of the u-p elements): coordinates, trial and committed response (disp, vel, accel), lumped nodal mass,
// applied (unbalanced) load and the last computed reaction. Every dof vector has room for three dofs;
// only the first ndf are used (the rest stays zero).
//
// The pore-pressure dof follows OpenSees' u-p elements (SSPquadUP, FourNodeQuadUP): the unknown the
// integrator carries as the dof's *velocity* is p (compression positive), so its "displacement" is the time
// integral of p and its "acceleration" dp/dt; recorders and queries report what OpenSees does
// (`recorder Node -dof 3 vel` is the pore pressure).
#include <Eigen/Core>
#include <array>

namespace fem::domain {

using Vector2 = Eigen::Vector2d;
/// Per-dof values of a node (ux, uy, p); entries past the node's ndf stay zero.
using NodeVector = Eigen::Vector3d;

/// The most dofs a node carries (ux, uy, p).
inline constexpr int kMaxNodeDofs = 3;

struct Node {
  int tag = 0;
  Vector2 crd = Vector2::Zero();
  /// Degrees of freedom: 2 (solid) or 3 (solid + pore pressure), from the `model -ndf` in force at `node`.
  int ndf = 2;

  NodeVector disp = NodeVector::Zero();   ///< trial displacement
  NodeVector vel = NodeVector::Zero();    ///< trial velocity (dof 3: the pore pressure)
  NodeVector accel = NodeVector::Zero();  ///< trial acceleration
  NodeVector committed_disp = NodeVector::Zero();
  NodeVector committed_vel = NodeVector::Zero();
  NodeVector committed_accel = NodeVector::Zero();
  /// Trial minus committed displacement; zero after a commit (OpenSees Node::commitState), see quirk 5.
  NodeVector incr_disp = NodeVector::Zero();

  NodeVector mass = NodeVector::Zero();   ///< lumped nodal mass per dof (`mass`, `node -mass`)
  bool has_mass = false;
  /// Mass-proportional Rayleigh factor of this node's mass (`rayleigh`, `region -rayleigh`; OpenSees
  /// Node::alphaM): damping force alphaM m v.
  double rayleigh_alpha_m = 0.0;
  NodeVector load = NodeVector::Zero();   ///< applied nodal load of the current step (patterns, inertia of ground motion)
  NodeVector reaction = NodeVector::Zero();
  std::array<bool, kMaxNodeDofs> fixed{false, false, false};  ///< homogeneous `fix` constraints

  /// The solid displacement (ux, uy) of the trial state.
  auto solid_disp() const { return disp.head<2>(); }

  void commit() {
    committed_disp = disp;
    committed_vel = vel;
    committed_accel = accel;
    incr_disp.setZero();
  }
  void revert_to_last_commit() {
    disp = committed_disp;
    vel = committed_vel;
    accel = committed_accel;
    incr_disp.setZero();
  }
  void revert_to_start() {
    disp.setZero(); vel.setZero(); accel.setZero();
    committed_disp.setZero(); committed_vel.setZero(); committed_accel.setZero();
    incr_disp.setZero();
  }
};

}  // namespace fem::domain
