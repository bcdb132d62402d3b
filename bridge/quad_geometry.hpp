#pragma once
// Bilinear four-node quadrilateral geometry and Gauss-Legendre rules, shared by the stress recovery,
// the particle generation and the transfer report. Node order counter-clockwise: (-1,-1) (1,-1) (1,1) (-1,1)
// (OpenSees quad / SSPquad; Zienkiewicz, Taylor & Zhu 2013, "The Finite Element Method", 7th ed., sec. 6.3).
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <utility>
#include <vector>

namespace bridge {

using Vec2 = Eigen::Vector2d;
/// The four corner positions of one element, in element node order.
using QuadNodes = std::array<Vec2, 4>;

/// Bilinear shape functions N_a(xi, eta) = (1 + xi_a xi)(1 + eta_a eta)/4 (Zienkiewicz et al. 2013, eq. 6.9).
inline std::array<double, 4> shape_functions(double xi, double eta) {
  return {0.25 * (1 - xi) * (1 - eta), 0.25 * (1 + xi) * (1 - eta), 0.25 * (1 + xi) * (1 + eta),
          0.25 * (1 - xi) * (1 + eta)};
}

/// x(xi, eta) = sum_a N_a x_a.
inline Vec2 map_point(const QuadNodes& x, double xi, double eta) {
  const auto n = shape_functions(xi, eta);
  return n[0] * x[0] + n[1] * x[1] + n[2] * x[2] + n[3] * x[3];
}

/// The columns of J = dx/dxi of the bilinear map at (xi, eta): (dx/dxi, dx/deta).
inline std::pair<Vec2, Vec2> map_derivatives(const QuadNodes& x, double xi, double eta) {
  return {0.25 * ((1 - eta) * (x[1] - x[0]) + (1 + eta) * (x[2] - x[3])),
          0.25 * ((1 - xi) * (x[3] - x[0]) + (1 + xi) * (x[2] - x[1]))};
}

/// det(dx/dxi) of the bilinear map at (xi, eta); linear in xi and eta, so its minimum over the
/// element is at a corner.
inline double jacobian_determinant(const QuadNodes& x, double xi, double eta) {
  const auto [dxi, deta] = map_derivatives(x, xi, eta);
  return dxi.x() * deta.y() - dxi.y() * deta.x();
}

/// The shape-function gradients dN_a/dx (a = 0..3) of the bilinear map at (xi, eta): J^-T dN_a/dxi, with
/// J = dx/dxi (Zienkiewicz et al. 2013, eq. 6.12). The element must not be degenerate there (det J != 0).
inline std::array<Vec2, 4> shape_function_gradients(const QuadNodes& x, double xi, double eta) {
  const auto [dxi, deta] = map_derivatives(x, xi, eta);
  const double det = dxi.x() * deta.y() - dxi.y() * deta.x();
  constexpr double xi_a[4] = {-1, 1, 1, -1}, eta_a[4] = {-1, -1, 1, 1};
  std::array<Vec2, 4> g;
  for (int a = 0; a < 4; ++a) {
    const double n_xi = 0.25 * xi_a[a] * (1 + eta_a[a] * eta), n_eta = 0.25 * eta_a[a] * (1 + xi_a[a] * xi);
    // J^-T (n_xi, n_eta) with J = [dxi deta] (columns)
    g[a] = Vec2(deta.y() * n_xi - dxi.y() * n_eta, -deta.x() * n_xi + dxi.x() * n_eta) / det;
  }
  return g;
}

/// Smallest det J over the element (the minimum of the corner values).
inline double min_jacobian_determinant(const QuadNodes& x) {
  const double a = jacobian_determinant(x, -1, -1), b = jacobian_determinant(x, 1, -1);
  const double c = jacobian_determinant(x, 1, 1), d = jacobian_determinant(x, -1, 1);
  return std::min(std::min(a, b), std::min(c, d));
}

/// Area of the quadrilateral (shoelace formula; equals the integral of det J).
inline double quad_area(const QuadNodes& x) {
  double twice = 0;
  for (int a = 0; a < 4; ++a) {
    const Vec2& p = x[a];
    const Vec2& q = x[(a + 1) % 4];
    twice += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * twice;
}

/// One-dimensional Gauss-Legendre rule on [-1, 1].
struct GaussRule {
  std::vector<double> points;
  std::vector<double> weights;  ///< sum to 2
};

/// n-point Gauss-Legendre rule (n >= 1), nodes from Newton iterations on P_n (Abramowitz & Stegun
/// 1964, eq. 25.4.29); accurate to round-off.
GaussRule gauss_legendre(int n);

/// Natural coordinates of OpenSees' Gauss points for an element with `count` points: 1 -> the
/// centre (SSPquad); 4 -> (-,-), (+,-), (+,+), (-,+) at +-1/sqrt(3) (FourNodeQuad; FORMATS.md sec. 2).
std::vector<Vec2> opensees_gauss_points(int count);

}  // namespace bridge
