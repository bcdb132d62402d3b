#pragma once
// Tensor-product shape functions on a uniform lattice, evaluated per axis.
//
// Linear (CB-Geo ED2Q4): the bilinear hat functions of the cell that contains the particle
// (Sulsky, Chen & Schreyer 1994, eq. 19): 2 nodes per axis.
//
// uGIMP (CB-Geo ED2Q16G): the generalized interpolation material point functions of Bardenhagen &
// Kober (2004), eq. (32)-(33) (the "uGIMP" variant: the particle's domain keeps its initial size), the
// hat function convolved with the particle's characteristic function of half-width lp. In units of the
// cell size h (r = (x_p - x_i) / h, l = lp / h):
//     |r| >= 1 + l         : 0
//     1 - l < |r| < 1 + l  : (1 + l - |r|)^2 / (4 l)
//     l < |r| <= 1 - l     : 1 - |r|
//     |r| <= l             : 1 - (r^2 + l^2) / (2 l)
// CB-Geo writes the same function in the cell's natural coordinates (element length 2, particle half-
// size nsize/2, include/elements/2d/quadrilateral_gimp_element.tcc), so the physical half-size is
// lp = nsize * h / 4 (nsize = 2/ppd: lp = h / (2 ppd)). For l <= 1/2 (nsize <= 2) the particle touches at
// most the 3 nodes nearest to it per axis: nearest node n and n - 1, n + 1.
#include <cmath>

namespace mpm::core {

/// Bilinear hat functions: `kWidth` = 2 nodes per axis.
struct LinearShape {
  static constexpr int kWidth = 2;
  /// s = (x - x0) / h in lattice units; `max_cell` = last cell index on this axis (cells_on_axis - 1);
  /// `l` unused. Writes the first node index `base` and the weights w and gradients dw (per unit of h).
  static void eval(double s, double /*l*/, int max_cell, int& base, double w[kWidth], double dw[kWidth]) {
    int c = static_cast<int>(std::floor(s));
    c = c < 0 ? 0 : (c > max_cell ? max_cell : c);
    const double t = s - c;
    base = c;
    w[0] = 1.0 - t;
    w[1] = t;
    dw[0] = -1.0;
    dw[1] = 1.0;
  }
};

/// uGIMP (Bardenhagen & Kober 2004): `kWidth` = 3 nodes per axis (the nearest node and its neighbours).
struct GimpShape {
  static constexpr int kWidth = 3;
  /// One node's weight and gradient for the signed distance r (units of h), half-size l (units of h)
  /// and its inverse il = 1 / l (no division in the hot loop).
  static void node(double r, double l, double il, double& w, double& dw) {
    const double a = std::abs(r);
    const double sgn = r < 0.0 ? -1.0 : 1.0;
    if (a >= 1.0 + l) {
      w = 0.0;
      dw = 0.0;
    } else if (a > 1.0 - l) {
      const double d = 1.0 + l - a;
      w = 0.25 * d * d * il;
      dw = -0.5 * sgn * d * il;
    } else if (a > l) {
      w = 1.0 - a;
      dw = -sgn;
    } else {
      w = 1.0 - 0.5 * (r * r + l * l) * il;
      dw = -r * il;
    }
  }
  static void node(double r, double l, double& w, double& dw) { node(r, l, 1.0 / l, w, dw); }
  /// s = (x - x0) / h in lattice units; l = lp / h in (0, 1/2]. `max_cell` unused (the lattice must
  /// hold one node beyond the particle's nearest nodes: CB-Geo's halo ring).
  static void eval(double s, double l, int /*max_cell*/, int& base, double w[kWidth], double dw[kWidth]) {
    const int n = static_cast<int>(std::floor(s + 0.5));
    base = n - 1;
    const double il = 1.0 / l;
    for (int a = 0; a < kWidth; ++a) node(s - static_cast<double>(base + a), l, il, w[a], dw[a]);
  }
};

}  // namespace mpm::core
