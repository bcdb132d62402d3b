// Unit tests of mpm/core/nodal_constraints.hpp (velocity and friction constraints in momentum form,
// Bardenhagen, Brackbill & Sulsky 2000) and mpm/core/boundary_rules.hpp (Cundall's local damping).
#include <gtest/gtest.h>

#include <cmath>

#include "mpm/core/boundary_rules.hpp"
#include "mpm/core/nodal_constraints.hpp"
#include "support/tolerance.hpp"

namespace {

using mpm::core::apply_cundall_damping;
using mpm::core::constrained_velocity;
using mpm::core::strain_rate_velocity;
using mpm::core::Vec2;
using NodeConstraint = mpm::core::NodeConstraint<2>;
using Vec3 = mpm::core::Vector<3>;

/// A base node (friction normal -y, dir 1) with a fixed zero normal velocity.
NodeConstraint base(double mu) {
  NodeConstraint c;
  c.fixed = 2u;
  c.friction_dir = 1;
  c.sign_n = -1.0;
  c.mu = mu;
  return c;
}

TEST(NodalConstraints, FixedComponentHandsTheWholeVelocityChangeToFlip) {
  NodeConstraint c;
  c.fixed = 2u;
  c.fixed_velocity = Vec2(0.0, 0.5);
  const auto r = constrained_velocity(Vec2(1.0, -2.0), Vec2(3.0, -10.0), 0.01, c);
  EXPECT_EQ(r.velocity[1], 0.5);
  EXPECT_CLOSE(r.rate[1], (0.5 - -2.0) / 0.01, 1e-9, 0);  // not 0: the particles lose their -2 m/s too
  EXPECT_CLOSE(r.velocity[0], 1.0 + 0.03, 1e-15, 0);
  EXPECT_CLOSE(r.rate[0], 3.0, 1e-12, 0);
}

TEST(NodalConstraints, KineticFrictionTakesMuTimesTheNormalImpulse) {
  // v* = (2 + 0.01 * 1, -0.5 - 0.01 * 10) = (2.01, -0.6): the wall stops 0.6 m/s of approach, friction
  // takes mu * 0.6 = 0.18 m/s of the slip.
  const auto r = constrained_velocity(Vec2(2.0, -0.5), Vec2(1.0, -10.0), 0.01, base(0.3));
  EXPECT_CLOSE(r.velocity[0], 2.01 - 0.18, 1e-12, 0);
  EXPECT_EQ(r.velocity[1], 0.0);
  EXPECT_CLOSE(r.rate[0], (2.01 - 0.18 - 2.0) / 0.01, 1e-9, 0);
}

TEST(NodalConstraints, StaticFrictionSticks) {
  const auto r = constrained_velocity(Vec2(0.0, 0.0), Vec2(2.0, -10.0), 0.01, base(0.3));  // 0.02 <= 0.3 * 0.1
  EXPECT_EQ(r.velocity[0], 0.0);
  EXPECT_CLOSE(r.rate[0], 0.0, 1e-15, 0);
}

TEST(NodalConstraints, FrictionNeverReversesTheSlip) {
  const auto r = constrained_velocity(Vec2(0.01, -1.0), Vec2(0.0, 0.0), 0.01, base(0.3));  // 0.01 < 0.3
  EXPECT_EQ(r.velocity[0], 0.0);
}

TEST(NodalConstraints, NoFrictionWhenMovingOffTheWall) {
  const auto r = constrained_velocity(Vec2(2.0, 0.5), Vec2(0.0, -10.0), 0.01, base(0.3));  // v*_y = 0.4 > 0
  EXPECT_CLOSE(r.velocity[0], 2.0, 1e-15, 0);
  EXPECT_EQ(r.velocity[1], 0.0);  // the velocity constraint still holds the node
}

TEST(NodalConstraints, WallWithNormalAlongX) {
  NodeConstraint c;  // right wall: outward +x, free normal (one-sided contact)
  c.friction_dir = 0;
  c.sign_n = 1.0;
  c.mu = 0.5;
  const auto r = constrained_velocity(Vec2(1.0, -3.0), Vec2(0.0, 0.0), 0.01, c);
  EXPECT_EQ(r.velocity[0], 0.0);           // the approach is stopped
  EXPECT_CLOSE(r.velocity[1], -2.5, 1e-15, 0);  // slip reduced by 0.5 * 1
  const auto away = constrained_velocity(Vec2(-1.0, -3.0), Vec2(0.0, 0.0), 0.01, c);
  EXPECT_EQ(away.velocity[0], -1.0);       // leaving the wall: free
  EXPECT_EQ(away.velocity[1], -3.0);
}

TEST(NodalConstraints, StrainRateSeesNoApproachIntoAOneSidedWall) {
  NodeConstraint c;  // floor: outward -y, free normal (one-sided contact)
  c.friction_dir = 1;
  c.sign_n = -1.0;
  c.mu = 0.5;
  const Vec2 into = strain_rate_velocity(Vec2(0.3, -0.2), c);
  EXPECT_EQ(into[1], 0.0);  // the approach the grid update will stop
  EXPECT_EQ(into[0], 0.3);  // friction is the grid update's (it needs the step's normal impulse)
  const Vec2 off = strain_rate_velocity(Vec2(0.3, 0.2), c);
  EXPECT_EQ(off[1], 0.2);  // leaving the wall: free
  c.fixed = 1u;  // and a prescribed x velocity
  c.fixed_velocity = Vec2(-0.1, 0.0);
  EXPECT_EQ(strain_rate_velocity(Vec2(0.3, 0.2), c)[0], -0.1);
}

// --- Friction with a lag (mpm/core/lagged_friction.hpp, the simplified Prakash-Clifton law) ---------

TEST(LaggedFriction, StrengthCatchesUpWithTheNormalForceOverTheSlipDistance) {
  // N steps from 1 to 2 at slip speed V (V* = 0): dN_s/ds = -(N_s - N) / L in slip s, so after a slip of
  // L the strength has covered 1 - 1/e of the step (implicit Euler: 1 - (1 + V dt / L)^-(L / V dt)).
  const mpm::core::NormalLag lag{0.1, 0.0};
  mpm::core::NormalMemory memory;
  EXPECT_EQ(mpm::core::lag_normal_force(memory, 1.0, 2.0, 1e-5, lag, 1.0), 1.0);  // first touch: N itself
  const double V = 2.0, dt = 1e-5;
  const int steps = static_cast<int>(lag.slip_distance / (V * dt));
  double Ns = 0.0;
  for (int k = 0; k < steps; ++k) Ns = mpm::core::lag_normal_force(memory, 2.0, V, dt, lag, 1.0);
  EXPECT_CLOSE(Ns, 2.0 - std::exp(-1.0), 1e-3, 0);
  // No slip and V* = 0: the strength holds whatever the normal force does.
  EXPECT_EQ(mpm::core::lag_normal_force(memory, 5.0, 0.0, dt, lag, 1.0), Ns);
  // Material leaving the node (its mass halves): the strength falls in proportion at once.
  EXPECT_CLOSE(mpm::core::lag_normal_force(memory, 5.0, 0.0, dt, lag, 0.5), 0.5 * Ns, 1e-15, 0);
  // A lag so short that r = dt (|V| + V*) / L overflows: the instantaneous N, finite (not inf / inf).
  const mpm::core::NormalLag instant{1e-300, 1e300};
  mpm::core::NormalMemory fresh;
  mpm::core::lag_normal_force(fresh, 1.0, 0.0, 1.0, instant, 1.0);
  EXPECT_EQ(mpm::core::lag_normal_force(fresh, 3.0, 1e308, 1.0, instant, 1.0), 3.0);
}

TEST(LaggedFriction, BilateralWallRubsWhileItsStrengthLasts) {
  // A base that holds the normal, pulling this step (v*_y = +0.4: no approach). Instantaneous Coulomb: no
  // friction; with a lag the strength of the earlier pressing still acts: mu N_s dt / m = 0.3 * 10 * 0.01.
  NodeConstraint c = base(0.3);
  EXPECT_CLOSE(constrained_velocity(Vec2(2.0, 0.5), Vec2(0.0, -10.0), 0.01, c).velocity[0], 2.0, 1e-15, 0);
  c.lag = mpm::core::NormalLag{0.1, 1.0};
  mpm::core::NormalMemory memory;
  memory.force = 10.0;  // N_s (N) of a node of 1 kg
  memory.mass = 1.0;
  const auto r = constrained_velocity(Vec2(2.0, 0.5), Vec2(0.0, -10.0), 0.01, c, &memory, 1.0);
  const double r_lag = 0.01 * (2.0 + 1.0) / 0.1;  // dt (|V| + V*) / L, N = 0 this step
  EXPECT_CLOSE(r.velocity[0], 2.0 - 0.3 * (10.0 / (1.0 + r_lag)) * 0.01, 1e-12, 0);
  EXPECT_EQ(r.velocity[1], 0.0);  // the prescribed normal
}

TEST(CundallDamping, ReducesForceAgainstVelocity) {
  Vec2 f(3.0, -4.0);  // |f| = 5
  apply_cundall_damping(0.1, f, Vec2(1.0, -2.0));
  EXPECT_CLOSE(f[0], 3.0 - 0.5, 1e-15, 0);
  EXPECT_CLOSE(f[1], -4.0 + 0.5, 1e-15, 0);
  Vec2 g(3.0, -4.0);
  apply_cundall_damping(0.1, g, Vec2(0.0, 0.0));  // at rest: no damping force
  EXPECT_EQ(g[0], 3.0);
  EXPECT_EQ(g[1], -4.0);
}

TEST(CundallDamping, InThreeDimensionsTakesTheNormOfTheWholeForce) {
  Vec3 f(2.0, 3.0, -6.0);  // |f| = 7
  apply_cundall_damping(0.1, f, Vec3(-1.0, 0.0, 5.0));
  EXPECT_CLOSE(f[0], 2.0 + 0.7, 1e-15, 0);
  EXPECT_EQ(f[1], 3.0);  // no velocity along y: no damping there
  EXPECT_CLOSE(f[2], -6.0 - 0.7, 1e-15, 0);
}

// --- The constraints in 3D: a normal along any axis, the tangential velocity a vector in the wall's plane
// (Bardenhagen, Brackbill & Sulsky 2000: the Coulomb limit on the magnitude of the tangential velocity) ---

const Vec3 kNoAcceleration(0.0, 0.0, 0.0);

/// A one-sided floor of the 3D grid: outward normal -y (dir 1), free normal.
mpm::core::NodeConstraint<3> floor_3d(double mu) {
  mpm::core::NodeConstraint<3> c;
  c.friction_dir = 1;
  c.sign_n = -1.0;
  c.mu = mu;
  return c;
}

TEST(NodalConstraints3D, KineticFrictionReducesTheTangentialVectorAlongItself) {
  // v* = (3, -1, 4): the floor stops 1 m/s of approach; the slip (3, 0, 4) has |v_t| = 5 and loses
  // mu * 1 = 0.5 m/s of its magnitude, keeping its direction: (1 - 0.5 / 5) (3, 0, 4).
  const auto r = constrained_velocity(Vec3(3.0, -1.0, 4.0), kNoAcceleration, 0.01, floor_3d(0.5));
  EXPECT_EQ(r.velocity[1], 0.0);
  EXPECT_CLOSE(r.velocity[0], 2.7, 1e-15, 0);
  EXPECT_CLOSE(r.velocity[2], 3.6, 1e-15, 0);
  EXPECT_CLOSE(r.rate[0], (2.7 - 3.0) / 0.01, 1e-12, 0);
  EXPECT_CLOSE(r.rate[1], 1.0 / 0.01, 1e-12, 0);  // the approach removed from the particles too
  EXPECT_CLOSE(r.rate[2], (3.6 - 4.0) / 0.01, 1e-12, 0);
  // Per component the limit would have taken 0.5 from each, turning the slip: the magnitude is what counts.
  EXPECT_CLOSE(r.velocity[2] / r.velocity[0], 4.0 / 3.0, 1e-15, 0);
}

TEST(NodalConstraints3D, SticksWhenTheSlipMagnitudeIsWithinTheLimit) {
  // |v_t| = 5 <= mu w_n = 5 * 1: the Coulomb cone holds the node.
  const auto r = constrained_velocity(Vec3(3.0, -1.0, 4.0), kNoAcceleration, 0.01, floor_3d(5.0));
  EXPECT_EQ(r.velocity, Vec3::Zero());
  // Just above the limit it slides: mu w_n = 4.9 < 5.
  const auto s = constrained_velocity(Vec3(3.0, -1.0, 4.0), kNoAcceleration, 0.01, floor_3d(4.9));
  EXPECT_CLOSE(s.velocity.norm(), 0.1, 1e-12, 0);
  // Leaving the floor: free, with its whole tangential velocity.
  const auto off = constrained_velocity(Vec3(3.0, 1.0, 4.0), kNoAcceleration, 0.01, floor_3d(5.0));
  EXPECT_EQ(off.velocity, Vec3(3.0, 1.0, 4.0));
}

TEST(NodalConstraints3D, WallWithNormalAlongZAndAPrescribedNormalVelocity) {
  // A lid with outward normal +z moving at 0.2 m/s (bilateral: the normal is prescribed); v* = (0, -0.6, 1):
  // the approach w_n = 1 - 0.2 = 0.8 is stopped, friction mu 0.25 takes 0.2 m/s of the slip along -y.
  mpm::core::NodeConstraint<3> c;
  c.fixed = 4u;
  c.fixed_velocity = Vec3(0.0, 0.0, 0.2);
  c.friction_dir = 2;
  c.sign_n = 1.0;
  c.mu = 0.25;
  const auto r = constrained_velocity(Vec3(0.0, -0.5, 1.0), Vec3(0.0, -10.0, 0.0), 0.01, c);
  EXPECT_EQ(r.velocity[2], 0.2);
  EXPECT_EQ(r.velocity[0], 0.0);
  EXPECT_CLOSE(r.velocity[1], -0.6 + 0.2, 1e-15, 0);
  // The strain rate sees no approach into it, and the tangential velocity untouched.
  const Vec3 seen = strain_rate_velocity(Vec3(0.3, -0.5, 1.0), c);
  EXPECT_EQ(seen, Vec3(0.3, -0.5, 0.2));
}

TEST(NodalConstraints3D, LaggedStrengthActsOnTheSlipMagnitude) {
  // A lagged floor: the slip speed in the lag is |v*_t| = 5, and the strength mu N_s dt / m caps the
  // magnitude of the tangential change.
  mpm::core::NodeConstraint<3> c = floor_3d(0.5);
  c.lag = mpm::core::NormalLag{0.1, 0.0};
  mpm::core::NormalMemory memory;
  memory.force = 40.0;  // N_s (N) of a node of 1 kg
  memory.mass = 1.0;
  const auto r = constrained_velocity(Vec3(3.0, -1.0, 4.0), kNoAcceleration, 0.01, c, &memory, 1.0);
  const double keep = 1.0 / (1.0 + 0.01 * 5.0 / 0.1);  // r = dt |V| / L
  const double Ns = keep * 40.0 + (1.0 - keep) * 1.0 * 1.0 / 0.01;  // N = m w_n / dt = 100 N
  const double limit = 0.5 * Ns * 0.01 / 1.0;
  EXPECT_CLOSE(memory.force, Ns, 1e-12, 0);
  EXPECT_CLOSE(r.velocity.norm(), 5.0 - limit, 1e-12, 0);
  EXPECT_CLOSE(r.velocity[2] / r.velocity[0], 4.0 / 3.0, 1e-15, 0);
}

}  // namespace
