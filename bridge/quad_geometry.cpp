#include "bridge/quad_geometry.hpp"

#include <cassert>
#include <cmath>
#include <numbers>

namespace bridge {

GaussRule gauss_legendre(int n) {
  assert(n >= 1);
  GaussRule rule;
  rule.points.resize(static_cast<std::size_t>(n));
  rule.weights.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    // Initial guess (A&S 1964, 22.16.6), then Newton on P_n(x) = 0 with the three-term recurrence.
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double dp = 1;
    for (int iter = 0; iter < 100; ++iter) {
      double p0 = 1, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      const double pn = n == 1 ? x : p1;
      const double pnm1 = n == 1 ? 1 : p0;
      dp = n * (x * pn - pnm1) / (x * x - 1);
      const double dx = pn / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    // Ascending order, symmetric weights (A&S 25.4.29).
    rule.points[static_cast<std::size_t>(n - 1 - i)] = x;
    rule.weights[static_cast<std::size_t>(n - 1 - i)] = 2 / ((1 - x * x) * dp * dp);
  }
  if (n % 2 == 1) rule.points[static_cast<std::size_t>(n / 2)] = 0;  // exact centre
  return rule;
}

std::vector<Vec2> opensees_gauss_points(int count) {
  if (count == 1) return {Vec2(0, 0)};
  assert(count == 4);
  const double g = 1 / std::sqrt(3.0);
  return {Vec2(-g, -g), Vec2(g, -g), Vec2(g, g), Vec2(-g, g)};
}

}  // namespace bridge
