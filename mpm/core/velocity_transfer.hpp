#pragma once
// The particle-grid velocity transfers (analysis.transfer): what p2g adds to the nodal momentum and what
// g2p hands back to the particle.
//
// FLIP / PIC / blend (Brackbill & Ruppel 1986; Sulsky, Chen & Schreyer 1994, eqs. 21-22):
//   p2g  m_i v_i = sum_p w_ip m_p v_p
//   g2p  v_p <- (1 - b) (v_p + dt sum_i w_ip a_i) + b sum_i w_ip v_i^new      (b = 0 FLIP, 1 PIC)
// APIC (Jiang, Schroeder, Selle, Teran & Stomakhin 2015, "The affine particle-in-cell method", ACM TOG
// 34(4) 51, the transfers and D_p around their eq. 11; for general weights Jiang, Schroeder & Teran 2017,
// "An angular momentum conserving affine-particle-in-cell method", JCP 338):
//   p2g  m_i v_i = sum_p w_ip m_p (v_p + B_p D_p^-1 (x_i - x_p)),  D_p = sum_i w_ip (x_i - x_p)(x_i - x_p)^T
//   g2p  v_p <- sum_i w_ip v_i^new,  B_p <- sum_i w_ip v_i^new (x_i - x_p)^T   (x_p before the move)
// B_p is the particle's stored affine matrix; D_p (the "inertia-like tensor") is computed afresh at every
// p2g from the particle's current weights, as both papers do for weights whose D_p is not constant.
// With D_p computed this way both transfers conserve linear and angular momentum exactly (the proofs of
// both papers: the particle's angular momentum x_p x m_p v_p + m_p eps : B_p^T maps to sum_i x_i x m_i v_i,
// and back), for ANY weights with partition of unity and linear reproduction (sum_i w_ip x_i = x_p).
//
// Tensor-product weights w_ip = wx_a(x_p) wy_b(y_p) with those two properties per axis make D_p
// diagonal: D_xx = sum_a wx_a (x_a - x_p)^2 (the off-diagonal sum_a wx_a (x_a - x_p) sum_b wy_b (y_b - y_p)
// is zero), so w_ip D_p^-1 (x_i - x_p) = (ax_a wy_b, wx_a ay_b) with the per-axis affine weights
// ax_a = wx_a (x_a - x_p) / D_xx (affine_weights below):
//   - uGIMP (Bardenhagen & Kober 2004): D_xx >= lp h / 2 > 0 (its minimum, with the particle on a node),
//     so the division is safe; D_xx is NOT the constant h^2/4 of quadratic B-splines.
//   - bilinear: ax_a = dwx_a / dx exactly (1D, nodes at 0 and h, particle at x: D = x (h - x), and
//     w_0 (0 - x) / D = -1/h = dw_0/dx), the identity APIC 2015 notes for multilinear weights;
//     the gradient form stays finite where D_p is singular (a particle on a grid line).
// Constrained nodes: g2p reads the constrained (and frictional) updated nodal velocity, so v_p and B_p
// both see the boundary velocity, and MUSL's remap (p2g of the updated particle field) maps the same
// affine field back before the constraints are applied again.
#include <cstddef>

#include "mpm/core/lanes.hpp"
#include "mpm/core/shape_functions.hpp"
#include "mpm/core/stencil_kernels.hpp"
#include "mpm/problem/deck.hpp"

namespace mpm::core {

/// The transfer of one run.
struct VelocityTransfer {
  Transfer kind = Transfer::FLIP;
  double pic = 0.0;  ///< FLIP blend: PIC weight b (1 for PIC, 0 for pure FLIP); unused by APIC

  /// From the analysis block: transfer, velocity_update (true = PIC) and pic_blend. Throws
  /// common::InputError when they contradict each other (a deck built in code; the deck reader
  /// already refuses such JSON) or when pic_blend is outside [0, 1].
  static VelocityTransfer from(const Analysis& analysis);

  bool affine() const { return kind == Transfer::APIC; }

  /// The velocity component g2p hands back, from the particle's old velocity, the interpolated updated
  /// grid velocity sum w v_i^new and the interpolated grid acceleration sum w a_i; T = double, or
  /// Double4 for the four particles of a stencil run (the same operations per lane).
  template <class T>
  T particle_velocity(T v_old, T v_grid, T a_grid, double dt) const {
    if (kind == Transfer::APIC) return v_grid;
    const T flip = v_old + dt * a_grid;
    return pic > 0.0 ? (1.0 - pic) * flip + pic * v_grid : flip;
  }
};

/// APIC's per-axis affine weights of one particle, `a` = ax[W] then ay[W], ax_k = wx_k d_k / D_xx with
/// d_k = ox + k hx the signed distance node minus particle (m) and D_xx = sum_k wx_k d_k^2 (the axis's
/// entry of D_p; y alike). uGIMP: from the weights, both axes at once in the lanes of one Double2 (each
/// lane the scalar sums, in the same order). `w` = the particle's weights,
/// (ox, oy) = first stencil node minus particle. p2g forms them once per particle per step and MUSL's
/// remap, at the same position, reads them back (Engine::affine_weights_).
inline void affine_weights(GimpShape, const StencilWeights<GimpShape::kWidth>& w, double ox, double oy, double hx,
                           double hy, double* a) {
  constexpr int W = GimpShape::kWidth;
  const Double2 o{ox, oy}, h{hx, hy};
  Double2 wd[W], d[W];
  Double2 D = splat2(0.0);
  for (int k = 0; k < W; ++k) {
    d[k] = o + static_cast<double>(k) * h;
    wd[k] = Double2{w.wx[k], w.wy[k]} * d[k];
    D += wd[k] * d[k];
  }
  const Double2 inv_D = splat2(1.0) / D;
  for (int k = 0; k < W; ++k) {
    const Double2 ak = wd[k] * inv_D;
    a[k] = ak[0];
    a[W + k] = ak[1];
  }
}

/// Bilinear: the gradients dw (per metre), equal to w d / D wherever D > 0 (see the file comment).
inline void affine_weights(LinearShape, const StencilWeights<LinearShape::kWidth>& w, double /*ox*/, double /*oy*/,
                           double /*hx*/, double /*hy*/, double* a) {
  constexpr int W = LinearShape::kWidth;
  for (int k = 0; k < W; ++k) {
    a[k] = w.dwx[k];
    a[W + k] = w.dwy[k];
  }
}

/// One axis's entry of APIC's D_p / h^2 = sum_a w_a (s_a - s)^2 for a particle at lattice coordinate s
/// (units of h; uGIMP half-size l in units of h; `max_cell` the last cell of the axis), evaluated afresh
/// (p2g computes it from the stored weights: affine_weights). Bilinear: t (1 - t), t the position
/// in the cell LinearShape::eval picks.
inline double apic_inertia(LinearShape, double s, double /*l*/, int max_cell) {
  int base = 0;
  double w[2], dw[2];
  LinearShape::eval(s, 0.0, max_cell, base, w, dw);
  return w[0] * w[1];
}
inline double apic_inertia(GimpShape, double s, double l, int max_cell) {
  int base = 0;
  double w[GimpShape::kWidth], dw[GimpShape::kWidth];
  GimpShape::eval(s, l, max_cell, base, w, dw);
  double D = 0.0;
  for (int a = 0; a < GimpShape::kWidth; ++a) D += w[a] * (base + a - s) * (base + a - s);
  return D;
}

/// g2p's new APIC matrix B_p of one particle, as read at lattice coordinates (sx, sy) (units of h from
/// the lattice origin; `max_cell_*` the last cell per axis) with D_p at that position, from the two
/// stencil sums at x^n: B = sum_i N v_i (x_i - x_p^n)^T and C = sum_i v_i grad w_ip^T (xx xy yx yy).
/// - uGIMP: B, the same wherever it is read (Jiang et al. 2015, the APIC transfer; Jiang, Schroeder &
///   Teran 2017): read with D_p(x^(n+1)) at the next p2g, the transfers conserve angular momentum
///   exactly, and D_p >= lp h / 2 keeps B D_p^-1 bounded.
inline void affine_matrix_at(GimpShape, const double* B, const double* /*C*/, double /*sx*/, double /*sy*/,
                             int /*max_cell_x*/, int /*max_cell_y*/, double /*hx*/, double /*hy*/, double* out) {
  for (int k = 0; k < 4; ++k) out[k] = B[k];
}

/// - Bilinear: C (= B D_p^-1 at x^n, the identity APIC 2015 notes for multilinear weights) times D_p at
///   the position where it is read, D_p = diag(t (1 - t) h^2) with t the position in its cell: p2g then
///   reads C itself. B(x^n) read with D_p(x^(n+1))^-1 would be unbounded where D_p vanishes on a grid
///   line (the nearly empty node ahead of a front runs away: the sliding block at step 70). The price:
///   the affine angular momentum m eps : (C D_p)^T follows D_p along the particle's path, so bilinear
///   APIC conserves angular momentum only to O(dt) per step (the spinning disk,
///   tests/verification/mpm/apic_transfer_test.cpp).
inline void affine_matrix_at(LinearShape, const double* /*B*/, const double* C, double sx, double sy, int max_cell_x,
                             int max_cell_y, double hx, double hy, double* out) {
  const double Dxx = apic_inertia(LinearShape{}, sx, 0.0, max_cell_x) * hx * hx;
  const double Dyy = apic_inertia(LinearShape{}, sy, 0.0, max_cell_y) * hy * hy;
  out[0] = C[0] * Dxx;
  out[1] = C[1] * Dyy;
  out[2] = C[2] * Dxx;
  out[3] = C[3] * Dyy;
}

/// What one particle adds to the momentum of node (a, b) of its stencil (weight N = wx_a wy_b):
/// m_p N v_p, and with APIC (Affine) also m_p B_p (ax_a wy_b, wx_a ay_b) = m_p N B_p D_p^-1 (x_i - x_p).
/// Built once per particle per p2g (and per MUSL remap) from its weights and affine weights at its
/// current position. The x and y components go together in one Double2 (lanes.hpp). FLIP / PIC: m v N.
/// APIC, factored by stencil column (the terms that share wy_b first), per lane
///   x: (m vx wx_a + m Bxx ax_a) wy_b + (m Bxy ay_b) wx_a,   y: (m vy wx_a + m Byx ax_a) wy_b + (m Byy ay_b) wx_a,
/// two multiplies and one add per node on the column and row terms formed once per particle (the
/// unfactored m v N + (m B ax_a) wy_b + (m B ay_b) wx_a takes three and two; the two forms differ by
/// round-off only: 1e-14 relative on the paper's column after 600 steps, docs/study/transfer_comparison.md).
template <class Shape, bool Affine>
struct MomentumContribution {
  static constexpr int W = Shape::kWidth;
  Double2 mv = splat2(0.0);
  /// APIC per stencil column a: m v_p wx_a + m B_p (ax_a, 0)^T, i.e. (m vx wx_a + m Bxx ax_a, m vy wx_a + m Byx ax_a)
  Double2 column[W] = {};
  /// APIC per stencil row b: m B_p (0, ay_b)^T = (m Bxy ay_b, m Byy ay_b)
  Double2 row[W] = {};
  /// The axis weights in both lanes, (wx_a, wx_a) and (wy_b, wy_b)
  Double2 wx[W] = {}, wy[W] = {};

  /// `b_x` = (Bxx, Byx) and `b_y` = (Bxy, Byy) the columns of the particle's matrix B_p, `a` its affine
  /// weights ax[W], ay[W] (affine_weights) and `w` its weights; all read only when Affine.
  MomentumContribution(double m, double vx, double vy, Double2 b_x, Double2 b_y, const double* a,
                       const StencilWeights<W>& w)
      : mv{m * vx, m * vy} {
    if constexpr (Affine) {
      const Double2 mb_x = m * b_x, mb_y = m * b_y;
      for (int k = 0; k < W; ++k) {
        wx[k] = splat2(w.wx[k]);
        wy[k] = splat2(w.wy[k]);
        column[k] = mv * wx[k] + mb_x * a[k];
        row[k] = mb_y * a[W + k];
      }
    }
  }
  /// Node (a, b) with weight N = wx_a wy_b.
  Double2 xy(int a, int b, double N) const {
    if constexpr (Affine) return column[a] * wy[b] + row[b] * wx[a];
    return mv * N;
  }
};

}  // namespace mpm::core
