// Unit tests of mpm/core/boundary_rules.hpp: CB-Geo's nodal friction rule (include/node.tcc,
// apply_friction_constraints; FORMATS.md section 5) and Cundall's local damping.
#include <gtest/gtest.h>

#include "mpm/core/boundary_rules.hpp"
#include "support/tolerance.hpp"

namespace {

using mpm::core::apply_cundall_damping;
using mpm::core::apply_friction_rule;

TEST(FrictionRule, StaticWhenTangentialBelowLimit) {
  double ax = 2.0, ay = -10.0;  // base (dir 1, outward normal -y): pushed into it
  apply_friction_rule(1, -1, 0.3, 1e-3, ax, ay, 0.0, 0.0);
  EXPECT_EQ(ax, 0.0);
  EXPECT_EQ(ay, -10.0);  // the normal component is left to the velocity constraint
}

TEST(FrictionRule, StaticSlipsWhenTangentialAboveLimit) {
  double ax = 5.0, ay = -10.0;
  apply_friction_rule(1, -1, 0.3, 1e-3, ax, ay, 0.0, 0.0);
  EXPECT_CLOSE(ax, 5.0 - 3.0, 1e-15, 0);
}

TEST(FrictionRule, KineticOpposesTheMotion) {
  double ax = 1.0, ay = -10.0;
  apply_friction_rule(1, -1, 0.3, 1e-3, ax, ay, 2.0, 0.0);  // moving in +x
  EXPECT_CLOSE(ax, 1.0 - 3.0, 1e-15, 0);
}

TEST(FrictionRule, KineticNeverReversesTheVelocity) {
  double ax = 0.0, ay = -10.0;
  const double dt = 0.1, vx = 0.05;  // friction would stop it within the step
  apply_friction_rule(1, -1, 0.3, dt, ax, ay, vx, 0.0);
  EXPECT_CLOSE(vx + ax * dt, 0.0, 1e-15, 0);
}

TEST(FrictionRule, InactiveWhenPullingAway) {
  double ax = 5.0, ay = 3.0;  // moving off the base
  apply_friction_rule(1, -1, 0.3, 1e-3, ax, ay, 1.0, 0.0);
  EXPECT_EQ(ax, 5.0);
}

TEST(FrictionRule, WallWithNormalAlongX) {
  double ax = 10.0, ay = -4.0;  // right wall (dir 0, outward +x), pushed into it, sliding down
  apply_friction_rule(0, +1, 0.5, 1e-3, ax, ay, 0.0, -1.0);
  EXPECT_CLOSE(ay, -4.0 + 5.0, 1e-15, 0);
  EXPECT_EQ(ax, 10.0);
}

TEST(CundallDamping, ReducesForceAgainstVelocity) {
  double fx = 3.0, fy = -4.0;  // |f| = 5
  apply_cundall_damping(0.1, fx, fy, 1.0, -2.0);
  EXPECT_CLOSE(fx, 3.0 - 0.5, 1e-15, 0);
  EXPECT_CLOSE(fy, -4.0 + 0.5, 1e-15, 0);
  double gx = 3.0, gy = -4.0;
  apply_cundall_damping(0.1, gx, gy, 0.0, 0.0);  // at rest: no damping force
  EXPECT_EQ(gx, 3.0);
  EXPECT_EQ(gy, -4.0);
}

}  // namespace
