#pragma once
// The per-particle loops over a particle's node stencil (W x W nodes of tensor-product weights), shared
// by the engine's phases: scatter into a chunk's band (p2g: mass, momentum, forces) and gather from the
// nodal fields (g2p: velocity, acceleration, APIC matrix, velocity gradient).
//
// Written for the compiler: the particle's weights are copied into a local StencilWeights first (the
// band and the weight arrays can then not alias, so no runtime alias checks per particle), and the x
// and y components of each nodal vector go through one Double2 (lanes.hpp: one SSE2 instruction for
// both). Every lane computes the scalar expression of the component, in the same order, and each node's
// sums are accumulated in the same particle order as before: the results are the scalar loops' bit for
// bit. The sums over the stencil use the tensor-product structure N_ab = wx_a wy_b: what does not
// depend on the row is formed once per stencil column (the forces), and gathers sum over a row first and
// weight the row sum by wy_b (or dwy_b) once; APIC sums by stencil row and column (gather_updated) and
// forms its momentum per column (MomentumContribution). Fewer operations per node, equal to the
// node-by-node sums up to round-off.
//
// Band layout (engine.hpp): 5 values per node (m, px, py, fx, fy), rows `row_stride` values apart.
#include <cstddef>
#include <cstring>

#include "mpm/core/lanes.hpp"

namespace mpm::core {

/// Unaligned load / store of two consecutive doubles.
inline Double2 load2(const double* p) {
  Double2 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
inline void store2(double* p, Double2 v) { std::memcpy(p, &v, sizeof v); }

/// Copies N doubles as register moves: std::copy_n of a short block becomes a memcpy call (about 30
/// instructions for a particle's stress or state variables).
template <std::size_t N>
inline void copy_doubles(const double* from, double* to) {
  std::size_t i = 0;
  for (; i + 2 <= N; i += 2) store2(to + i, load2(from + i));
  if constexpr (N % 2 == 1) to[N - 1] = from[N - 1];
}

/// A particle's weights block [wx, wy, dwx, dwy] (W each; gradients per metre) in registers; entry e
/// of the block at wk[e * stride], stride 1 (a block of its own) or 4 (the blocks of a full stencil
/// run interleaved, Engine::weights_), each a constant offset for the compiler.
template <int W>
struct StencilWeights {
  double wx[W], wy[W], dwx[W], dwy[W];
  StencilWeights() = default;
  explicit StencilWeights(const double* wk) { read<1>(wk); }
  StencilWeights(const double* wk, int stride) {
    if (stride == 4)
      read<4>(wk);
    else
      read<1>(wk);
  }
  double N(int a, int b) const { return wx[a] * wy[b]; }

 private:
  template <int Stride>
  void read(const double* wk) {
    for (int a = 0; a < W; ++a) {
      wx[a] = wk[a * Stride];
      wy[a] = wk[(W + a) * Stride];
      dwx[a] = wk[(2 * W + a) * Stride];
      dwy[a] = wk[(3 * W + a) * Stride];
    }
  }
};

/// p2g of mass and momentum (Sulsky et al. 1994, eqs. 14-15): m N into slot 0, the momentum
/// `momentum.xy(a, b, N)` (velocity_transfer.hpp MomentumContribution) into slots 1-2.
template <int W, class Momentum>
inline void scatter_mass_momentum(double* band_row, std::size_t row_stride, const StencilWeights<W>& w, double m,
                                  const Momentum& momentum) {
  for (int b = 0; b < W; ++b, band_row += row_stride) {
    double* gn = band_row;
    for (int a = 0; a < W; ++a, gn += 5) {
      const double N = w.N(a, b);
      gn[0] += m * N;
      store2(gn + 1, load2(gn + 1) + momentum.xy(a, b, N));
    }
  }
}

/// Only the momentum (MUSL's remap of the updated particle momentum, Sulsky, Zhou & Schreyer 1995, eq. 20).
template <int W, class Momentum>
inline void scatter_momentum(double* band_row, std::size_t row_stride, const StencilWeights<W>& w,
                             const Momentum& momentum) {
  for (int b = 0; b < W; ++b, band_row += row_stride) {
    double* gn = band_row;
    for (int a = 0; a < W; ++a, gn += 5)
      store2(gn + 1, load2(gn + 1) + momentum.xy(a, b, w.N(a, b)));
  }
}

/// p2g of the force (Sulsky et al. 1994, eq. 16): m N g - V grad N . sigma into slots 3-4, with
/// mg = (m gx, m gy) and the stress sxx, syy, sxy of volume V:
///   fx += m gx N - V (dN/dx sxx + dN/dy sxy),  fy += m gy N - V (dN/dx sxy + dN/dy syy).
/// With N = wx_a wy_b, dN/dx = dwx_a wy_b, dN/dy = wx_a dwy_b it is summed as
///   f_ab = wy_b (mg wx_a - V dwx_a s_dx) - dwy_b (V wx_a s_dy),
/// the two brackets formed once per stencil column.
template <int W>
inline void scatter_forces(double* band_row, std::size_t row_stride, const StencilWeights<W>& w, Double2 mg, double V,
                           double sxx, double syy, double sxy) {
  const Double2 s_dx{sxx, sxy}, s_dy{sxy, syy};  // what dN/dx and dN/dy multiply, per component
  Double2 with_wy[W], with_dwy[W];                // per column a: what wy_b and dwy_b multiply
  for (int a = 0; a < W; ++a) {
    with_wy[a] = mg * w.wx[a] - (V * w.dwx[a]) * s_dx;
    with_dwy[a] = (V * w.wx[a]) * s_dy;
  }
  for (int b = 0; b < W; ++b, band_row += row_stride) {
    double* gn = band_row;
    for (int a = 0; a < W; ++a, gn += 5)
      store2(gn + 3, load2(gn + 3) + (w.wy[b] * with_wy[a] - w.dwy[b] * with_dwy[a]));
  }
}

/// The velocity gradient of a nodal velocity field at the particle, sum_i v_i (x) grad N_i, as the
/// column pairs of L = [[dvx/dx, dvx/dy], [dvy/dx, dvy/dy]]: d_dx = (dvx/dx, dvy/dx), d_dy = (dvx/dy, dvy/dy).
struct VelocityGradient {
  Double2 d_dx = splat2(0.0), d_dy = splat2(0.0);
  /// One stencil row b: wx_v = sum_a wx_a v_ab and dwx_v = sum_a dwx_a v_ab, with the row's wy_b, dwy_b.
  void add_row(Double2 wx_v, Double2 dwx_v, double wy, double dwy) {
    d_dx += wy * dwx_v;
    d_dy += dwy * wx_v;
  }
  /// The strain increment (dexx, deyy, dgxy) = dt (dvx/dx, dvy/dy, dvx/dy + dvy/dx) (CB-Geo compute_strain_rate).
  void strain_increment(double dt, double* de) const {
    de[0] = dt * d_dx[0];
    de[1] = dt * d_dy[1];
    de[2] = dt * (d_dy[0] + d_dx[1]);
  }
};

/// The velocity gradient of `field` (2 values per node, nodes `row_nodes` apart per row) at the particle
/// whose stencil starts at node `first`; `stride` values per node (2 for velocity_, 4 for updated_).
/// Summed by stencil row: d_dx = sum_b wy_b (sum_a dwx_a v_ab), d_dy = sum_b dwy_b (sum_a wx_a v_ab).
template <int W>
inline VelocityGradient gather_velocity_gradient(const double* field, std::size_t stride, std::size_t first,
                                                 std::size_t row_nodes, const StencilWeights<W>& w) {
  VelocityGradient L;
  for (int b = 0; b < W; ++b, first += row_nodes) {
    const double* v = field + stride * first;
    Double2 wx_v = splat2(0.0), dwx_v = splat2(0.0);
    for (int a = 0; a < W; ++a, v += stride) {
      const Double2 va = load2(v);
      wx_v += w.wx[a] * va;
      dwx_v += w.dwx[a] * va;
    }
    L.add_row(wx_v, dwx_v, w.wy[b], w.dwy[b]);
  }
  return L;
}

/// What g2p sums over the stencil of the updated nodal field (4 values per node: v_new x, y, then the
/// FLIP rate a x, y): v = sum N v_i; FLIP: a = sum N a_i; APIC: B = sum N v_i (x_i - x_p)^T as its
/// columns b_dx = (Bxx, Byx), b_dy = (Bxy, Byy) (Jiang et al. 2015); with `gradient` (USL) also the
/// velocity gradient of v_new at the particle.
struct GridSums {
  Double2 v = splat2(0.0), a = splat2(0.0);
  Double2 b_dx = splat2(0.0), b_dy = splat2(0.0);
  VelocityGradient L;
};

/// The sums are taken per stencil row b, then weighted by the row's wy_b (and dwy_b): FLIP
/// v = sum_b wy_b (sum_a wx_a v_ab), a alike, and the gradient as gather_velocity_gradient. `dxs`,
/// `dys`: APIC only, node minus particle per stencil column / row (m). APIC sums N v_i per stencil row
/// and per column, one add each per node: v = sum_b row_b, b_dy = sum_b dy_b row_b, b_dx = sum_a dx_a
/// column_a.
template <int W, bool Affine>
inline GridSums gather_updated(const double* updated, std::size_t first, std::size_t row_nodes,
                               const StencilWeights<W>& w, const double* dxs, const double* dys, bool gradient) {
  GridSums s;
  Double2 column[W] = {};  // APIC: sum_b N v_ab per column a
  for (int b = 0; b < W; ++b, first += row_nodes) {
    const double* u = updated + 4 * first;
    Double2 row = splat2(0.0);  // APIC: sum_a N v_ab
    Double2 wx_v = splat2(0.0), wx_a = splat2(0.0), dwx_v = splat2(0.0);  // sum_a of wx_a v, wx_a a, dwx_a v
    for (int a = 0; a < W; ++a, u += 4) {
      const Double2 v = load2(u);
      if constexpr (Affine) {
        const Double2 Nv = w.N(a, b) * v;
        row += Nv;
        column[a] += Nv;
        if (gradient) wx_v += w.wx[a] * v;
      } else {
        wx_v += w.wx[a] * v;
        wx_a += w.wx[a] * load2(u + 2);
      }
      if (gradient) dwx_v += w.dwx[a] * v;
    }
    if constexpr (Affine) {
      s.v += row;
      s.b_dy += row * dys[b];
    } else {
      s.v += w.wy[b] * wx_v;
      s.a += w.wy[b] * wx_a;
    }
    if (gradient) s.L.add_row(wx_v, dwx_v, w.wy[b], w.dwy[b]);
  }
  if constexpr (Affine)
    for (int a = 0; a < W; ++a) s.b_dx += column[a] * dxs[a];
  return s;
}

}  // namespace mpm::core
