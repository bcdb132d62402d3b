#pragma once
// A small limit-equilibrium reference for the strength-reduction tests: Bishop's simplified method of slices
// (Bishop 1955, "The use of the slip circle in the stability analysis of slopes", Geotechnique 5(1):7-17,
// eq. 13 with zero pore pressure and the interslice shear forces neglected):
//   F = sum[(c b + W tan phi) / m_a] / sum[W sin a],   m_a = cos a + sin a tan phi / F   (iterated on F)
// for a slope facing -x (toe on the left, crest on the right), over circles that stay above a rigid base,
// searched on a grid of centres and radii and refined by a pattern search.
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

namespace bishop {

struct Soil {
  double cohesion;      ///< c (kPa)
  double friction_deg;  ///< phi (degrees)
};

struct Slope {
  std::vector<double> surface_x, surface_y;  ///< ground surface, piecewise linear, x increasing
  double base_y = 0.0;                       ///< rigid base: circles may not go below it
  double unit_weight = 20.0;                 ///< gamma (kN/m3)
  /// The soil at a point of the slip surface (layers).
  std::function<Soil(double x, double y)> soil;

  double ground(double x) const {
    if (x <= surface_x.front()) return surface_y.front();
    for (std::size_t i = 1; i < surface_x.size(); ++i) {
      if (x <= surface_x[i]) {
        const double t = (x - surface_x[i - 1]) / (surface_x[i] - surface_x[i - 1]);
        return surface_y[i - 1] + t * (surface_y[i] - surface_y[i - 1]);
      }
    }
    return surface_y.back();
  }
};

struct Circle {
  double xc, yc, r;
};

/// Bishop's F for one circle; +infinity when the circle is not admissible (misses the ground, leaves the model
/// sideways, goes below the base, or has m_a <= 0.2 somewhere, the usual guard against the exit-end singularity).
inline double factor_of_safety(const Slope& s, const Circle& c, int slices = 200) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (!(c.r > 0.0)) return kInf;
  if (c.yc - c.r < s.base_y - 1e-9) return kInf;
  const auto arc = [&](double x) { return c.yc - std::sqrt(std::max(0.0, c.r * c.r - (x - c.xc) * (x - c.xc))); };
  // entry / exit: the one interval where the arc is below the ground, found on a fine scan then bisected
  const int scan = 2000;
  const double x0 = std::max(c.xc - c.r, s.surface_x.front()), x1 = std::min(c.xc + c.r, s.surface_x.back());
  if (!(x1 > x0)) return kInf;
  double a = kInf, b = -kInf;
  bool inside = false, closed = false;
  for (int i = 0; i <= scan; ++i) {
    const double x = x0 + (x1 - x0) * i / scan;
    const bool below = arc(x) < s.ground(x) - 1e-9;
    if (below && closed) return kInf;  // two separate intervals
    if (below) { a = std::min(a, x); b = std::max(b, x); inside = true; }
    if (!below && inside) closed = true;
  }
  if (!inside || !(b > a)) return kInf;
  // a circle that would cut the model's side boundaries is not admissible
  if (a <= s.surface_x.front() + 1e-9 || b >= s.surface_x.back() - 1e-9) return kInf;
  const auto refine = [&](double out, double in) {
    for (int k = 0; k < 50; ++k) {
      const double m = 0.5 * (out + in);
      (arc(m) < s.ground(m) ? in : out) = m;
    }
    return 0.5 * (out + in);
  };
  const double dx = (x1 - x0) / scan;
  a = refine(std::max(x0, a - dx), a);
  b = refine(std::min(x1, b + dx), b);
  std::vector<double> width(slices), weight(slices), sin_a(slices), cos_a(slices), c_b(slices), tan_phi(slices);
  double driving = 0.0;
  for (int i = 0; i < slices; ++i) {
    const double xl = a + (b - a) * i / slices, xr = a + (b - a) * (i + 1) / slices, xm = 0.5 * (xl + xr);
    const double ybase = arc(xm);
    const double h = std::max(0.0, s.ground(xm) - ybase);
    width[i] = xr - xl;
    weight[i] = s.unit_weight * h * width[i];
    sin_a[i] = (xm - c.xc) / c.r;
    cos_a[i] = std::sqrt(std::max(0.0, 1.0 - sin_a[i] * sin_a[i]));
    const Soil soil = s.soil(xm, ybase);
    c_b[i] = soil.cohesion * width[i];
    tan_phi[i] = std::tan(soil.friction_deg * 3.14159265358979323846 / 180.0);
    driving += weight[i] * sin_a[i];
  }
  if (!(driving > 0.0)) return kInf;
  double f = 1.0;
  for (int it = 0; it < 200; ++it) {
    double resisting = 0.0;
    for (int i = 0; i < slices; ++i) {
      const double m = cos_a[i] + sin_a[i] * tan_phi[i] / f;
      if (m <= 0.2) return kInf;
      resisting += (c_b[i] + weight[i] * tan_phi[i]) / m;
    }
    const double next = resisting / driving;
    if (std::abs(next - f) < 1e-12) return next;
    f = next;
  }
  return f;
}

/// The smallest F over circles: a grid of centres (x in [x_lo, x_hi], y in [y_lo, y_hi]) and radii, then a
/// pattern search from the best grid circle.
inline double critical_factor(const Slope& s, double x_lo, double x_hi, double y_lo, double y_hi, Circle* best_circle = nullptr) {
  Circle best{0, 0, 0};
  double best_f = std::numeric_limits<double>::infinity();
  const int n = 24;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      const double xc = x_lo + (x_hi - x_lo) * i / n, yc = y_lo + (y_hi - y_lo) * j / n;
      const double r_max = yc - s.base_y;
      for (int k = 1; k <= n; ++k) {
        const Circle c{xc, yc, r_max * k / n};
        const double f = factor_of_safety(s, c, 60);
        if (f < best_f) { best_f = f; best = c; }
      }
    }
  }
  best_f = factor_of_safety(s, best);
  double step = 0.05 * (x_hi - x_lo);
  while (step > 1e-4) {
    bool moved = false;
    for (int d = 0; d < 3; ++d) {
      for (double sign : {1.0, -1.0}) {
        Circle c = best;
        (d == 0 ? c.xc : d == 1 ? c.yc : c.r) += sign * step;
        // keep a base-tangent circle tangent while its centre moves down
        if (d == 1 && c.yc - c.r < s.base_y) c.r = c.yc - s.base_y;
        const double f = factor_of_safety(s, c);
        if (f < best_f) { best_f = f; best = c; moved = true; }
      }
    }
    if (!moved) step *= 0.5;
  }
  if (best_circle) *best_circle = best;
  return best_f;
}

}  // namespace bishop
