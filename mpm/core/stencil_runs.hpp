#pragma once
// Stencil runs: four consecutive particles (in iteration order) on one stencil, which the engine forms
// where it can (Engine::evaluate_shape_functions: the sort key puts the particles of a cell's stencil
// quadrant together) and maps four at a time: one particle per lane of a Double4, the x and y
// components in separate vectors, each nodal value loaded once and broadcast to the four.
//
// Every lane evaluates its particle's expressions of the one-particle kernels (shape_functions.hpp,
// stencil_kernels.hpp, velocity_transfer.hpp) in the same order, and every node sums the four particles'
// contributions in particle order, so a particle's results are the same whichever path takes it, bit
// for bit (tests/unit/mpm/core_stencil_runs_test.cpp); what changes is the instruction count
// (mpm/README.md, Performance).
#include <cstddef>
#include <cstdint>

#include "mpm/core/lanes.hpp"
#include "mpm/core/shape_functions.hpp"
#include "mpm/core/stencil_kernels.hpp"

namespace mpm::core {

// Shape functions of a run, one axis at a time.

/// eval_axes<2> for the four particles of a stencil run (one stencil, first node base on this axis): one
/// axis, the particle l in lane l, each lane eval_axes<2>'s expressions (its values bit for bit). s, l:
/// the particles' lattice coordinates and half-sizes on the axis; weights and gradients (times ih)
/// to w[a], dw[a].
inline void eval_run_axis(GimpShape, Double4 s, Double4 l, int base, double ih, Double4 w[GimpShape::kWidth],
                          Double4 dw[GimpShape::kWidth]) {
  const Double4 b = splat4(static_cast<double>(base)), il = 1.0 / l;
  GimpShape::outer_node(s - b, 1.0, l, il, w[0], dw[0]);
  GimpShape::middle_node(s - (b + 1.0), l, il, w[1], dw[1]);
  GimpShape::outer_node(-(s - (b + 2.0)), -1.0, l, il, w[2], dw[2]);
  for (int a = 0; a < GimpShape::kWidth; ++a) dw[a] *= ih;
}

/// eval_axes<2> for the four particles of a stencil run (one cell, first node `base` on this axis), lane
/// by lane eval's expressions: see eval_run_axis(GimpShape).
inline void eval_run_axis(LinearShape, Double4 s, Double4 /*l*/, int base, double ih, Double4 w[LinearShape::kWidth],
                          Double4 dw[LinearShape::kWidth]) {
  const Double4 t = s - splat4(static_cast<double>(base));
  w[0] = 1.0 - t;
  w[1] = t;
  dw[0] = splat4(-1.0 * ih);
  dw[1] = splat4(1.0 * ih);
}

/// The weights of a run of four particles, interleaved by lane: entry e of lane l at wk[4 e + l].
template <int W>
struct StencilWeights4 {
  Double4 wx[W], wy[W], dwx[W], dwy[W];
  explicit StencilWeights4(const double* wk) {
    for (int a = 0; a < W; ++a) {
      wx[a] = load4(wk + 4 * a);
      wy[a] = load4(wk + 4 * (W + a));
      dwx[a] = load4(wk + 4 * (2 * W + a));
      dwy[a] = load4(wk + 4 * (3 * W + a));
    }
  }
};

/// Adds the four lanes of v to *g in lane (particle) order, as four one-particle kernels would.
inline void add_lanes(double* g, Double4 v) { *g = *g + v[0] + v[1] + v[2] + v[3]; }

/// add_lanes for the consecutive nodal values g[0], g[1] with the particles' contributions v0, v1: a
/// 4 x 2 transpose puts particle l's pair in one Double2, so the pair takes each particle's sum in one
/// operation, in particle order: each value is add_lanes' bit for bit.
inline void add_lanes(double* g, Double4 v0, Double4 v1) {
  const Double4 even = __builtin_shufflevector(v0, v1, 0, 4, 2, 6);  // particles 0 and 2
  const Double4 odd = __builtin_shufflevector(v0, v1, 1, 5, 3, 7);   // particles 1 and 3
  Double2 sum;
  __builtin_memcpy(&sum, g, sizeof sum);
  sum = sum + __builtin_shufflevector(even, even, 0, 1) + __builtin_shufflevector(odd, odd, 0, 1) +
        __builtin_shufflevector(even, even, 2, 3) + __builtin_shufflevector(odd, odd, 2, 3);
  __builtin_memcpy(g, &sum, sizeof sum);
}

/// add_lanes for the consecutive nodal values g[0..2] (a node's mass and momentum) with v0, v1, v2: a
/// 4 x 3 transpose, each particle's three contributions in one Double4 (its fourth lane reads g[3] and is
/// not written back); each value add_lanes' bit for bit.
inline void add_lanes(double* g, Double4 v0, Double4 v1, Double4 v2) {
  const Double4 even = __builtin_shufflevector(v0, v1, 0, 4, 2, 6);  // v0, v1 of particles 0 and 2
  const Double4 odd = __builtin_shufflevector(v0, v1, 1, 5, 3, 7);   // of particles 1 and 3
  Double4 sum = load4(g);
  sum = sum + __builtin_shufflevector(even, v2, 0, 1, 4, 4) + __builtin_shufflevector(odd, v2, 0, 1, 5, 5) +
        __builtin_shufflevector(even, v2, 2, 3, 6, 6) + __builtin_shufflevector(odd, v2, 2, 3, 7, 7);
  __builtin_memcpy(g, &sum, 2 * sizeof(double));
  g[2] = sum[2];
}

/// scatter_mass_momentum for the four particles of a run, FLIP / PIC (momentum m v N): m, and
/// mvx = m vx, mvy = m vy per lane.
template <int W>
inline void scatter_mass_momentum4(double* band_row, std::size_t row_stride, const StencilWeights4<W>& w, Double4 m,
                                   Double4 mvx, Double4 mvy) {
  for (int b = 0; b < W; ++b, band_row += row_stride) {
    double* gn = band_row;
    for (int a = 0; a < W; ++a, gn += 5) {
      const Double4 N = w.wx[a] * w.wy[b];
      add_lanes(gn, m * N, mvx * N, mvy * N);
    }
  }
}

/// scatter_momentum for the four particles of a run, FLIP / PIC: mvx = m vx, mvy = m vy per lane.
template <int W>
inline void scatter_momentum4(double* band_row, std::size_t row_stride, const StencilWeights4<W>& w, Double4 mvx,
                              Double4 mvy) {
  for (int b = 0; b < W; ++b, band_row += row_stride) {
    double* gn = band_row;
    for (int a = 0; a < W; ++a, gn += 5) {
      const Double4 N = w.wx[a] * w.wy[b];
      add_lanes(gn + 1, mvx * N, mvy * N);
    }
  }
}

/// scatter_forces for the four particles of a run: per lane mg = (m gx, m gy) as mgx, mgy, the volume V
/// and the stress sxx, syy, sxy.
template <int W>
inline void scatter_forces4(double* band_row, std::size_t row_stride, const StencilWeights4<W>& w, Double4 mgx,
                            Double4 mgy, Double4 V, Double4 sxx, Double4 syy, Double4 sxy) {
  Double4 with_wy_x[W], with_wy_y[W], with_dwy_x[W], with_dwy_y[W];
  for (int a = 0; a < W; ++a) {
    const Double4 V_dwx = V * w.dwx[a], V_wx = V * w.wx[a];
    with_wy_x[a] = mgx * w.wx[a] - V_dwx * sxx;
    with_wy_y[a] = mgy * w.wx[a] - V_dwx * sxy;
    with_dwy_x[a] = V_wx * sxy;
    with_dwy_y[a] = V_wx * syy;
  }
  for (int b = 0; b < W; ++b, band_row += row_stride) {
    double* gn = band_row;
    for (int a = 0; a < W; ++a, gn += 5) {
      add_lanes(gn + 3, w.wy[b] * with_wy_x[a] - w.dwy[b] * with_dwy_x[a],
                w.wy[b] * with_wy_y[a] - w.dwy[b] * with_dwy_y[a]);
    }
  }
}

/// The velocity gradients of four particles (gather_velocity_gradient per lane).
struct VelocityGradient4 {
  Double4 dvx_dx = splat4(0.0), dvy_dx = splat4(0.0), dvx_dy = splat4(0.0), dvy_dy = splat4(0.0);
  void add_row(Double4 wx_vx, Double4 wx_vy, Double4 dwx_vx, Double4 dwx_vy, Double4 wy, Double4 dwy) {
    dvx_dx += wy * dwx_vx;
    dvy_dx += wy * dwx_vy;
    dvx_dy += dwy * wx_vx;
    dvy_dy += dwy * wx_vy;
  }
  /// Lane l as VelocityGradient.
  VelocityGradient lane(int l) const {
    VelocityGradient L;
    L.d_dx = Double2{dvx_dx[l], dvy_dx[l]};
    L.d_dy = Double2{dvx_dy[l], dvy_dy[l]};
    return L;
  }
};

/// gather_velocity_gradient for the four particles of a run.
template <int W>
inline VelocityGradient4 gather_velocity_gradient4(const double* field, std::size_t stride, std::size_t first,
                                                   std::size_t row_nodes, const StencilWeights4<W>& w) {
  VelocityGradient4 L;
  for (int b = 0; b < W; ++b, first += row_nodes) {
    const double* v = field + stride * first;
    Double4 wx_vx = splat4(0.0), wx_vy = splat4(0.0), dwx_vx = splat4(0.0), dwx_vy = splat4(0.0);
    for (int a = 0; a < W; ++a, v += stride) {
      const Double4 vx = splat4(v[0]), vy = splat4(v[1]);
      wx_vx += w.wx[a] * vx;
      wx_vy += w.wx[a] * vy;
      dwx_vx += w.dwx[a] * vx;
      dwx_vy += w.dwx[a] * vy;
    }
    L.add_row(wx_vx, wx_vy, dwx_vx, dwx_vy, w.wy[b], w.dwy[b]);
  }
  return L;
}

/// GridSums of the four particles of a run, particle l in lane l of each value.
struct GridSums4 {
  Double4 vx = splat4(0.0), vy = splat4(0.0), ax = splat4(0.0), ay = splat4(0.0);
  Double4 bdx_x = splat4(0.0), bdx_y = splat4(0.0), bdy_x = splat4(0.0), bdy_y = splat4(0.0);
  VelocityGradient4 L;
  /// Lane l as GridSums.
  GridSums lane(int l) const {
    GridSums s;
    s.v = Double2{vx[l], vy[l]};
    s.a = Double2{ax[l], ay[l]};
    s.b_dx = Double2{bdx_x[l], bdx_y[l]};
    s.b_dy = Double2{bdy_x[l], bdy_y[l]};
    s.L = L.lane(l);
    return s;
  }
};

/// gather_updated<W, false> (FLIP / PIC: v, a and with `gradient` the velocity gradient of v) for the
/// four particles of a run.
template <int W>
inline GridSums4 gather_updated4(const double* updated, std::size_t first, std::size_t row_nodes,
                                 const StencilWeights4<W>& w, bool gradient) {
  GridSums4 s;
  Double4 &vx = s.vx, &vy = s.vy, &ax = s.ax, &ay = s.ay;
  VelocityGradient4& L = s.L;
  for (int b = 0; b < W; ++b, first += row_nodes) {
    const double* u = updated + 4 * first;
    Double4 wx_vx = splat4(0.0), wx_vy = splat4(0.0), wx_ax = splat4(0.0), wx_ay = splat4(0.0);
    Double4 dwx_vx = splat4(0.0), dwx_vy = splat4(0.0);
    for (int a = 0; a < W; ++a, u += 4) {
      const Double4 ux = splat4(u[0]), uy = splat4(u[1]);
      wx_vx += w.wx[a] * ux;
      wx_vy += w.wx[a] * uy;
      wx_ax += w.wx[a] * splat4(u[2]);
      wx_ay += w.wx[a] * splat4(u[3]);
      if (gradient) {
        dwx_vx += w.dwx[a] * ux;
        dwx_vy += w.dwx[a] * uy;
      }
    }
    vx += w.wy[b] * wx_vx;
    vy += w.wy[b] * wx_vy;
    ax += w.wy[b] * wx_ax;
    ay += w.wy[b] * wx_ay;
    if (gradient) L.add_row(wx_vx, wx_vy, dwx_vx, dwx_vy, w.wy[b], w.dwy[b]);
  }
  return s;
}

/// gather_updated<W, true> (APIC: v, B and with `gradient` the velocity gradient of v) for the four
/// particles of a run; dxs, dys: node minus particle per stencil column / row.
template <int W>
inline GridSums4 gather_updated_affine4(const double* updated, std::size_t first, std::size_t row_nodes,
                                        const StencilWeights4<W>& w, const Double4* dxs, const Double4* dys,
                                        bool gradient) {
  GridSums4 s;
  Double4 &vx = s.vx, &vy = s.vy, &bdy_x = s.bdy_x, &bdy_y = s.bdy_y;
  Double4 column_x[W], column_y[W];
  for (int a = 0; a < W; ++a) column_x[a] = column_y[a] = splat4(0.0);
  VelocityGradient4& L = s.L;
  for (int b = 0; b < W; ++b, first += row_nodes) {
    const double* u = updated + 4 * first;
    Double4 row_x = splat4(0.0), row_y = splat4(0.0);
    Double4 wx_vx = splat4(0.0), wx_vy = splat4(0.0), dwx_vx = splat4(0.0), dwx_vy = splat4(0.0);
    for (int a = 0; a < W; ++a, u += 4) {
      const Double4 ux = splat4(u[0]), uy = splat4(u[1]);
      const Double4 N = w.wx[a] * w.wy[b];
      const Double4 Nvx = N * ux, Nvy = N * uy;
      row_x += Nvx;
      row_y += Nvy;
      column_x[a] += Nvx;
      column_y[a] += Nvy;
      if (gradient) {
        wx_vx += w.wx[a] * ux;
        wx_vy += w.wx[a] * uy;
        dwx_vx += w.dwx[a] * ux;
        dwx_vy += w.dwx[a] * uy;
      }
    }
    vx += row_x;
    vy += row_y;
    bdy_x += row_x * dys[b];
    bdy_y += row_y * dys[b];
    if (gradient) L.add_row(wx_vx, wx_vy, dwx_vx, dwx_vy, w.wy[b], w.dwy[b]);
  }
  for (int a = 0; a < W; ++a) {
    s.bdx_x += column_x[a] * dxs[a];
    s.bdx_y += column_y[a] * dxs[a];
  }
  return s;
}

/// affine_weights for the four particles of a stencil run, one axis (the particle l in lane l): w the
/// axis's weights, dw its gradients (per metre), o the first node minus the particles (m), h the cell
/// size; the affine weights to a[W]. Each lane affine_weights' expressions, its values bit for bit.
inline void affine_weights_run_axis(GimpShape, const Double4* w, const Double4* /*dw*/, Double4 o, double h,
                                    Double4* a) {
  constexpr int W = GimpShape::kWidth;
  Double4 wd[W], d[W];
  Double4 D = splat4(0.0);
  for (int k = 0; k < W; ++k) {
    d[k] = o + static_cast<double>(k) * h;
    wd[k] = w[k] * d[k];
    D += wd[k] * d[k];
  }
  const Double4 inv_D = splat4(1.0) / D;
  for (int k = 0; k < W; ++k) a[k] = wd[k] * inv_D;
}
inline void affine_weights_run_axis(LinearShape, const Double4* /*w*/, const Double4* dw, Double4 /*o*/,
                                    double /*h*/, Double4* a) {
  for (int k = 0; k < LinearShape::kWidth; ++k) a[k] = dw[k];
}

/// MomentumContribution for the four particles of a run, APIC, per component x and y: the column
/// terms (m v wx_a + m B (ax_a, 0)^T) and row terms (m B (0, ay_b)^T) of each lane's particle. `a`: the
/// run's affine weights, interleaved (entry e of lane l at a[4 e + l]: ax[W] then ay[W]).
template <int W>
struct AffineMomentum4 {
  Double4 column_x[W], column_y[W], row_x[W], row_y[W];
  /// mvx = m vx, mvy = m vy; mB = m times the matrix entries xx, xy, yx, yy of each lane's particle.
  AffineMomentum4(Double4 mvx, Double4 mvy, const Double4 mB[4], const double* a, const StencilWeights4<W>& w) {
    for (int k = 0; k < W; ++k) {
      const Double4 ax = load4(a + 4 * k), ay = load4(a + 4 * (W + k));
      column_x[k] = mvx * w.wx[k] + mB[0] * ax;
      column_y[k] = mvy * w.wx[k] + mB[2] * ax;
      row_x[k] = mB[1] * ay;
      row_y[k] = mB[3] * ay;
    }
  }
};

/// APIC's momentum of a run into its stencil (MomentumContribution::xy per lane), and with `mass` the
/// mass m N as well; each node's sums in particle order.
template <int W>
inline void scatter_affine_momentum4(double* band_row, std::size_t row_stride, const StencilWeights4<W>& w,
                                     const AffineMomentum4<W>& momentum, const Double4* mass) {
  for (int b = 0; b < W; ++b, band_row += row_stride) {
    double* gn = band_row;
    for (int a = 0; a < W; ++a, gn += 5) {
      const Double4 px = momentum.column_x[a] * w.wy[b] + momentum.row_x[b] * w.wx[a];
      const Double4 py = momentum.column_y[a] * w.wy[b] + momentum.row_y[b] * w.wx[a];
      if (mass)
        add_lanes(gn, *mass * (w.wx[a] * w.wy[b]), px, py);
      else
        add_lanes(gn + 1, px, py);
    }
  }
}

}  // namespace mpm::core
