// CB-Geo's Mohr-Coulomb state variables (cb-geo/mpm include/materials/mohr_coulomb.tcc and
// material_utility: epsilon = sqrt(3) p, rho = sqrt(2 J2), Lode angle theta = acos(3 sqrt(3) J3 / (2 J2^1.5)) / 3).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "bridge/particle_mapping.hpp"
#include "support/tolerance.hpp"

namespace {

TEST(MohrCoulombState, InvariantsOfKnownStresses) {
  bridge::MpmMaterial m;
  m.type = bridge::MpmMaterial::Type::MohrCoulomb2D;
  m.friction = 0.4;
  m.dilation = 0.1;
  m.cohesion = 7;
  double sv[20] = {};
  // Axial tension-like deviator diag(2,-1,-1) k + p: J3 > 0, theta = 0.
  const double k = 10, p = -50;
  ASSERT_EQ(bridge::mohr_coulomb_state(m, {p + 2 * k, p - k, p - k, 0, 0, 0}, sv), 7u);
  EXPECT_CLOSE(sv[0], 0.4, 0, 0);
  EXPECT_CLOSE(sv[1], 0.1, 0, 0);
  EXPECT_CLOSE(sv[2], 7, 0, 0);
  EXPECT_CLOSE(sv[3], std::sqrt(3.0) * p, 1e-12, 1e-14);
  EXPECT_CLOSE(sv[4], std::sqrt(2 * 3 * k * k), 1e-12, 1e-14);  // J2 = 3 k^2
  EXPECT_CLOSE(sv[5], 0, 1e-6, 0);
  EXPECT_CLOSE(sv[6], 0, 0, 0);
  // diag(-2,1,1) k: J3 < 0, theta = pi/3.
  bridge::mohr_coulomb_state(m, {-2 * k, k, k, 0, 0, 0}, sv);
  EXPECT_CLOSE(sv[5], std::numbers::pi / 3, 1e-6, 0);
  // Pure shear: J3 = 0, theta = pi/6; rho = sqrt(2) tau.
  bridge::mohr_coulomb_state(m, {0, 0, 0, 5, 0, 0}, sv);
  EXPECT_CLOSE(sv[5], std::numbers::pi / 6, 1e-12, 0);
  EXPECT_CLOSE(sv[4], std::sqrt(2.0) * 5, 1e-12, 1e-14);
  // Isotropic stress: J2 = 0, CB-Geo sets cos(3 theta) = 0, so theta = pi/6.
  bridge::mohr_coulomb_state(m, {-3, -3, -3, 0, 0, 0}, sv);
  EXPECT_CLOSE(sv[5], std::acos(0.0) / 3, 1e-12, 0);
}

}  // namespace
