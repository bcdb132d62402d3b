// Unit tests of the bilinear quad helpers and the Gauss-Legendre rule (Abramowitz & Stegun 1964, 25.4.29).
#include <gtest/gtest.h>

#include <cmath>

#include "bridge/quad_geometry.hpp"
#include "support/tolerance.hpp"

namespace {

TEST(GaussLegendre, IntegratesPolynomialsOfDegree2nMinus1Exactly) {
  for (int n = 1; n <= 32; ++n) {  // fem2mpm's --ppd range
    const auto rule = bridge::gauss_legendre(n);
    ASSERT_EQ(rule.points.size(), static_cast<std::size_t>(n));
    for (int degree = 0; degree <= 2 * n - 1; ++degree) {
      double sum = 0;
      for (int i = 0; i < n; ++i) sum += rule.weights[i] * std::pow(rule.points[i], degree);
      const double exact = degree % 2 ? 0.0 : 2.0 / (degree + 1);
      EXPECT_CLOSE(sum, exact, 1e-14, 1e-14) << "n = " << n << ", degree " << degree;
    }
    for (int i = 1; i < n; ++i) EXPECT_LT(rule.points[i - 1], rule.points[i]);
  }
  EXPECT_CLOSE(bridge::gauss_legendre(2).points[1], 1 / std::sqrt(3.0), 0, 1e-15);
}

TEST(QuadGeometry, ShapeFunctionsJacobianAndArea) {
  const bridge::QuadNodes x{bridge::Vec2(0, 0), bridge::Vec2(2, 0.2), bridge::Vec2(2.5, 1.5), bridge::Vec2(-0.3, 1.2)};
  for (double xi : {-0.7, 0.1, 0.9})
    for (double eta : {-0.4, 0.6}) {
      const auto n = bridge::shape_functions(xi, eta);
      EXPECT_CLOSE(n[0] + n[1] + n[2] + n[3], 1.0, 1e-15, 0);
    }
  EXPECT_TRUE((bridge::map_point(x, 1, 1) - x[2]).norm() < 1e-15);
  // Area = integral of det J = 4 det J(0,0) for the 1-point rule (det J is linear).
  EXPECT_CLOSE(bridge::quad_area(x), 4 * bridge::jacobian_determinant(x, 0, 0), 1e-14, 1e-14);
  EXPECT_GT(bridge::min_jacobian_determinant(x), 0);
  const bridge::QuadNodes bow{bridge::Vec2(0, 0), bridge::Vec2(1, 0), bridge::Vec2(0.2, 0.2), bridge::Vec2(0, 1)};
  EXPECT_LT(bridge::min_jacobian_determinant(bow), 0);  // re-entrant corner: det J < 0 at node 3
}

}  // namespace
