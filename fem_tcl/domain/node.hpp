#pragma once
// A 2D node with 2 translational dofs (OpenSees Node with ndm = ndf = 2): coordinates, trial and committed
// response (disp, vel, accel), lumped nodal mass, applied (unbalanced) load and the last computed reaction.
#include <Eigen/Core>
#include <array>

namespace fem::domain {

using Vector2 = Eigen::Vector2d;

struct Node {
  int tag = 0;
  Vector2 crd = Vector2::Zero();

  Vector2 disp = Vector2::Zero();   ///< trial displacement
  Vector2 vel = Vector2::Zero();    ///< trial velocity
  Vector2 accel = Vector2::Zero();  ///< trial acceleration
  Vector2 committed_disp = Vector2::Zero();
  Vector2 committed_vel = Vector2::Zero();
  Vector2 committed_accel = Vector2::Zero();
  /// Trial minus committed displacement; zero after a commit (OpenSees Node::commitState), see quirk 5.
  Vector2 incr_disp = Vector2::Zero();

  Vector2 mass = Vector2::Zero();   ///< lumped nodal mass per dof (`mass`, `node -mass`)
  bool has_mass = false;
  /// Mass-proportional Rayleigh factor of this node's mass (`rayleigh`, `region -rayleigh`; OpenSees
  /// Node::alphaM): damping force alphaM m v.
  double rayleigh_alpha_m = 0.0;
  Vector2 load = Vector2::Zero();   ///< applied nodal load of the current step (patterns, inertia of ground motion)
  Vector2 reaction = Vector2::Zero();
  std::array<bool, 2> fixed{false, false};  ///< homogeneous `fix` constraints

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
