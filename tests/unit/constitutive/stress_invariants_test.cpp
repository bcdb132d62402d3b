// Unit tests of constitutive/stress_invariants.hpp against hand-computed values in CB-Geo's conventions
// (CB-Geo include/materials/mohr_coulomb.tcc: epsilon = sqrt(3) p, rho = sqrt(2 J2), cosine-convention
// Lode angle in [0, pi/3]).
#include "constitutive/stress_invariants.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/tolerance.hpp"

namespace {

TEST(StressInvariants, HydrostaticState) {
  const Eigen::Vector4d s(-3.0, -3.0, -3.0, 0.0);
  EXPECT_CLOSE(constitutive::mean_stress(s), -3.0, 1e-15, 0.0);
  EXPECT_CLOSE(constitutive::haigh_epsilon(s), -3.0 * std::sqrt(3.0), 1e-14, 0.0);
  EXPECT_CLOSE(constitutive::haigh_rho(s), 0.0, 1e-15, 0.0);
  EXPECT_CLOSE(constitutive::lode_angle(s), M_PI / 6.0, 1e-15, 0.0);  // J2 = 0: acos(0) / 3
}

TEST(StressInvariants, TriaxialCompressionAndExtension) {
  // s1 = s2 = -1 > s3 = -4 (tension positive): triaxial compression, theta = pi/3.
  const Eigen::Vector4d tc(-1.0, -4.0, -1.0, 0.0);
  EXPECT_CLOSE(constitutive::lode_angle(tc), M_PI / 3.0, 1e-7, 0.0);
  // J2 = (0 + 9 + 9) / 6 = 3, rho = sqrt(6).
  EXPECT_CLOSE(constitutive::j2_invariant(tc), 3.0, 1e-14, 0.0);
  EXPECT_CLOSE(constitutive::haigh_rho(tc), std::sqrt(6.0), 1e-14, 0.0);
  // s1 = 2 > s2 = s3 = -1: triaxial extension, theta = 0.
  const Eigen::Vector4d te(2.0, -1.0, -1.0, 0.0);
  EXPECT_CLOSE(constitutive::lode_angle(te), 0.0, 1e-7, 0.0);
}

TEST(StressInvariants, ShearInvariantUnderRotation) {
  // Pure shear sxy = 2 equals principal (2, -2, 0): J3 = 0, theta = pi/6, J2 = 4.
  const Eigen::Vector4d s(0.0, 0.0, 0.0, 2.0);
  EXPECT_CLOSE(constitutive::j2_invariant(s), 4.0, 1e-14, 0.0);
  EXPECT_CLOSE(constitutive::j3_invariant(s), 0.0, 1e-14, 0.0);
  EXPECT_CLOSE(constitutive::lode_angle(s), M_PI / 6.0, 1e-14, 0.0);
  const Eigen::Vector4d p(2.0, -2.0, 0.0, 0.0);
  EXPECT_CLOSE(constitutive::j3_invariant(p), 0.0, 1e-14, 0.0);
}

}  // namespace
