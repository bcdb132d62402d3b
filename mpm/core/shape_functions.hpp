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
#include <type_traits>

#include "mpm/core/lanes.hpp"

namespace mpm::core {

/// Bilinear hat functions: `kWidth` = 2 nodes per axis.
struct LinearShape {
  static constexpr int kWidth = 2;
  /// s = (x - x0) / h in lattice units; `max_cell` = last cell index on this axis (cells_on_axis - 1);
  /// `l` unused. Writes the first node index `base` and the weights w and gradients dw (per unit of h).
  static void eval(double s, double /*l*/, int max_cell, int& base, double w[kWidth], double dw[kWidth]) {
    // Truncation, then the clamp to cell 0: the same as floor + clamp, without the floor (a call or a
    // dozen instructions on the SSE2 baseline).
    const int c = cell(s, max_cell);
    const double t = s - c;
    base = c;
    w[0] = 1.0 - t;
    w[1] = t;
    dw[0] = -1.0;
    dw[1] = 1.0;
  }
  /// Every axis of a particle in `dim` dimensions (the engine's weights pass, 2D and 3D): the stencil's
  /// first node per axis and the block wk = [w per axis (W each), then
  /// dw / h per axis (W each)]; node (a_0 .. a_dim-1) of the stencil weighs prod_d w_d[a_d].
  template <int dim>
  static void eval_axes(const double (&s)[dim], const double (&l)[dim], const int (&max_cell)[dim],
                        const double (&ih)[dim], int (&first)[dim], double* wk) {
    for (int d = 0; d < dim; ++d) {
      eval(s[d], l[d], max_cell[d], first[d], wk + d * kWidth, wk + (dim + d) * kWidth);
      for (int a = 0; a < kWidth; ++a) wk[(dim + d) * kWidth + a] *= ih[d];
    }
  }
  /// The stencil's first node (bi, bj), as eval_axes<2> finds it.
  static void first_node(double sx, double sy, int max_i, int max_j, int& bi, int& bj) {
    bi = cell(sx, max_i);
    bj = cell(sy, max_j);
  }
  /// The cell of s: truncation, then the clamp to cell 0 (eval).
  static int cell(double s, int max_cell) {
    const int c = static_cast<int>(s);
    return c < 0 ? 0 : (c > max_cell ? max_cell : c);
  }
};

/// uGIMP (Bardenhagen & Kober 2004): `kWidth` = 3 nodes per axis (the nearest node and its neighbours).
struct GimpShape {
  static constexpr int kWidth = 3;
  /// The node nearest to s, floor(s + 1/2), by truncation (floor is a call or a dozen instructions on
  /// the SSE2 baseline): s + 1/2 > 0 for every particle on the lattice, whose halo ring keeps
  /// s >= 1 - l >= 1/2 (Engine checks the ring and removes particles that leave the region).
  static int nearest_node(double s) { return static_cast<int>(s + 0.5); }
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
    base = nearest_node(s) - 1;
    const double il = 1.0 / l;
    for (int a = 0; a < kWidth; ++a) node(s - static_cast<double>(base + a), l, il, w[a], dw[a]);
  }
  /// node() for two (r, l) pairs at once (the x and y axes of a particle), without branches (the piece
  /// a node falls in changes from particle to particle, which a branch predictor cannot follow): the
  /// pieces a node can reach are evaluated and one is selected per lane, each node()'s expression, so
  /// the values are node()'s bit for bit. For the stencil's middle node (the particle's nearest:
  /// |r| <= 1/2 <= 1 - l): the core or the hat piece.
  template <class V>
  static void middle_node(V r, V l, V il, V& w, V& dw) {
    const V one = splat<V>(1.0);
    const V a = lane_abs(r);
    const auto hat = a > l;
    w = lane_select(hat, one - a, one - 0.5 * (r * r + l * l) * il);
    dw = lane_select(hat, -lane_select(r < splat<V>(0.0), splat<V>(-1.0), one), -r * il);
  }
  /// The same for an outer node of the stencil at distance a = |r| in (1/2, 3/2] (a >= l: never the
  /// core piece) on the side of sign `sgn` (+1: the node before the particle, -1: the one after): the
  /// hat, edge or outside piece.
  template <class V>
  static void outer_node(V a, double sgn, V l, V il, V& w, V& dw) {
    const V one = splat<V>(1.0), zero = splat<V>(0.0);
    const V d = one + l - a;
    const V w_edge = 0.25 * d * d * il, dw_edge = -0.5 * sgn * d * il;
    const auto outside = a >= one + l, edge = a > one - l;
    w = lane_select(outside, zero, lane_select(edge, w_edge, one - a));
    dw = lane_select(outside, zero, lane_select(edge, dw_edge, splat<V>(-sgn)));
  }
  /// Every axis of a particle in `dim` dimensions (see LinearShape::eval_axes) in branch-free lanes: two for
  /// dim = 2, four for dim = 3 (x, y, z and an idle lane). Per axis the same values as eval(): each node takes
  /// only the pieces its position allows (the middle node core or hat, the outer ones hat, edge or
  /// outside), node()'s expressions. The one exception is a particle of l = 1/2 (nsize = 2) within an ulp
  /// of a cell's mid-line, where floor(s + 1/2) rounds across it: eval() then meets the neighbouring
  /// piece, whose value at the shared boundary differs by an ulp.
  template <int dim>
  static void eval_axes(const double (&s)[dim], const double (&l)[dim], const int (&/*max_cell*/)[dim],
                        const double (&ih)[dim], int (&first)[dim], double* wk) {
    static_assert(dim == 2 || dim == 3, "2D or 3D");
    using V = std::conditional_t<dim == 2, Double2, Double4>;
    V sv = splat<V>(1.5), lv = splat<V>(0.5), ihv = splat<V>(1.0), base = splat<V>(0.0);  // the idle lane: any piece
    for (int d = 0; d < dim; ++d) {
      first[d] = nearest_node(s[d]) - 1;
      sv[d] = s[d];
      lv[d] = l[d];
      ihv[d] = ih[d];
      base[d] = static_cast<double>(first[d]);
    }
    const V il = 1.0 / lv;
    V w[kWidth], dw[kWidth];
    outer_node(sv - base, 1.0, lv, il, w[0], dw[0]);
    middle_node(sv - (base + 1.0), lv, il, w[1], dw[1]);
    outer_node(-(sv - (base + 2.0)), -1.0, lv, il, w[2], dw[2]);
    for (int a = 0; a < kWidth; ++a) {
      dw[a] *= ihv;
      for (int d = 0; d < dim; ++d) {
        wk[d * kWidth + a] = w[a][d];
        wk[(dim + d) * kWidth + a] = dw[a][d];
      }
    }
  }
  /// The stencil's first node (bi, bj), as eval_axes<2> finds it.
  static void first_node(double sx, double sy, int /*max_i*/, int /*max_j*/, int& bi, int& bj) {
    bi = nearest_node(sx) - 1;
    bj = nearest_node(sy) - 1;
  }
};

}  // namespace mpm::core
