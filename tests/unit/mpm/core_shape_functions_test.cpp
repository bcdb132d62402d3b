// Unit tests of mpm/core/shape_functions.hpp: linear hat functions (Sulsky et al. 1994) and uGIMP
// (Bardenhagen & Kober 2004, eq. 32-33; CB-Geo quadrilateral_gimp_element.tcc).
#include <gtest/gtest.h>

#include <cmath>

#include "mpm/core/shape_functions.hpp"
#include "support/tolerance.hpp"

namespace {

using mpm::core::GimpShape;
using mpm::core::LinearShape;

template <class Shape>
void check_partition_of_unity(double l) {
  for (double s = 1.0; s <= 4.0; s += 0.0137) {
    int base = 0;
    double w[Shape::kWidth], dw[Shape::kWidth];
    Shape::eval(s, l, 10, base, w, dw);
    double sum = 0, dsum = 0, first = 0;
    for (int a = 0; a < Shape::kWidth; ++a) {
      sum += w[a];
      dsum += dw[a];
      first += w[a] * (base + a);  // reproduces linear fields: sum N_i x_i = x
      EXPECT_GE(w[a], -1e-15);
    }
    EXPECT_CLOSE(sum, 1.0, 1e-14, 0);
    EXPECT_CLOSE(dsum, 0.0, 1e-14, 0);
    EXPECT_CLOSE(first, s, 1e-13, 0);
  }
}

TEST(ShapeFunctions, LinearPartitionOfUnityAndLinearCompleteness) { check_partition_of_unity<LinearShape>(0.0); }

TEST(ShapeFunctions, GimpPartitionOfUnityAndLinearCompleteness) {
  for (double l : {0.05, 0.125, 0.25, 0.5}) check_partition_of_unity<GimpShape>(l);
}

TEST(ShapeFunctions, GimpGradientMatchesFiniteDifference) {
  const double l = 0.125, eps = 1e-6;
  for (double r = -1.3; r <= 1.3; r += 0.0173) {
    double w0, d0, wp, dp, wm, dm;
    GimpShape::node(r, l, w0, d0);
    GimpShape::node(r + eps, l, wp, dp);
    GimpShape::node(r - eps, l, wm, dm);
    EXPECT_CLOSE(d0, (wp - wm) / (2 * eps), 1e-6, 0);
  }
}

TEST(ShapeFunctions, GimpTendsToLinearForPointParticles) {
  // Away from the nodes (|r| in (l, 1 - l)) uGIMP equals the hat function exactly; as l -> 0 it does
  // everywhere.
  for (double s = 2.05; s < 3.0; s += 0.1) {
    int bl = 0, bg = 0;
    double wl[2], dwl[2], wg[3], dwg[3];
    LinearShape::eval(s, 0, 10, bl, wl, dwl);
    GimpShape::eval(s, 1e-4, 10, bg, wg, dwg);
    for (int a = 0; a < 3; ++a) {
      const int node = bg + a;
      const double expected = node == bl ? wl[0] : (node == bl + 1 ? wl[1] : 0.0);
      EXPECT_CLOSE(wg[a], expected, 1e-12, 0);
    }
  }
}

// The engine evaluates both axes at once without branches (GimpShape::node2 / eval_axes<2>, two lanes):
// the weights and gradients must be eval()'s per axis bit for bit, in every piece of the function
// (outside, edge, hat, core), on the piece boundaries and at both signs of r.
template <class Shape>
void check_eval_axes_matches_eval(double lx, double ly) {
  constexpr int W = Shape::kWidth;
  const double ihx = 1.0 / 0.7, ihy = 1.0 / 1.3;
  for (double s = 1.0; s <= 4.0; s += 0.0037) {
    const double sx = s, sy = 5.0 - 0.61 * s;
    int first[2] = {0, 0}, ex = 0, ey = 0;
    double wk[4 * W], wx[W], dwx[W], wy[W], dwy[W];
    Shape::template eval_axes<2>({sx, sy}, {lx, ly}, {10, 10}, {ihx, ihy}, first, wk);
    const int bi = first[0], bj = first[1];
    Shape::eval(sx, lx, 10, ex, wx, dwx);
    Shape::eval(sy, ly, 10, ey, wy, dwy);
    ASSERT_EQ(bi, ex);
    ASSERT_EQ(bj, ey);
    for (int a = 0; a < W; ++a) {
      EXPECT_EQ(wk[a], wx[a]) << s;
      EXPECT_EQ(wk[W + a], wy[a]) << s;
      EXPECT_EQ(wk[2 * W + a], dwx[a] * ihx) << s;
      EXPECT_EQ(wk[3 * W + a], dwy[a] * ihy) << s;
    }
  }
}

TEST(ShapeFunctions, BothAxesAtOnceGiveTheSameWeightsBitForBit) {
  check_eval_axes_matches_eval<LinearShape>(0.0, 0.0);
  for (double l : {0.05, 0.125, 0.25, 0.5}) check_eval_axes_matches_eval<GimpShape>(l, 0.5 * l);
  // Each piece and its boundaries, both signs: the two-lane node functions against node, lane by lane
  // (the middle node for |r| <= 1/2, an outer node beyond, on either side).
  for (double l : {0.125, 0.5})
    for (double r : {-1.6, -1.0 - l, -1.2, -1.0 + l, -0.6, -l, -0.05, 0.0, -0.0, 0.05, l, 0.6, 1.0 - l, 1.2, 1.0 + l, 1.6}) {
      double w, dw, wm, dwm;
      GimpShape::node(r, l, w, dw);
      GimpShape::node(-r, l, wm, dwm);
      const mpm::core::Double2 l2 = mpm::core::splat2(l), il2 = mpm::core::splat2(1.0 / l);
      mpm::core::Double2 w2, dw2, wm2, dwm2;
      if (std::abs(r) <= 0.5) {
        GimpShape::middle_node(mpm::core::Double2{r, -r}, l2, il2, w2, dw2);
        wm2 = mpm::core::Double2{w2[1], w2[1]};
        dwm2 = mpm::core::Double2{dw2[1], dw2[1]};
      } else {  // the node before the particle has r > 0 (sign +1)
        const double sgn = r > 0 ? 1.0 : -1.0;
        GimpShape::outer_node(mpm::core::splat2(std::abs(r)), sgn, l2, il2, w2, dw2);
        GimpShape::outer_node(mpm::core::splat2(std::abs(r)), -sgn, l2, il2, wm2, dwm2);
      }
      EXPECT_EQ(w2[0], w) << r;
      EXPECT_EQ(dw2[0], dw) << r;
      EXPECT_EQ(wm2[0], wm) << r;
      EXPECT_EQ(dwm2[0], dwm) << r;
    }
}

TEST(ShapeFunctions, GimpValuesAtKnownPoints) {
  // Particle at a node (r = 0): N = 1 - l/2; at r = 1: N = l/4 (overlap of the particle with the next cell).
  const double l = 0.25;
  double w, dw;
  GimpShape::node(0.0, l, w, dw);
  EXPECT_CLOSE(w, 1 - l / 2, 1e-15, 0);
  EXPECT_CLOSE(dw, 0.0, 1e-15, 0);
  GimpShape::node(1.0, l, w, dw);
  EXPECT_CLOSE(w, l / 4, 1e-15, 0);
  GimpShape::node(1.0 + l, l, w, dw);
  EXPECT_CLOSE(w, 0.0, 1e-15, 0);
}

TEST(ShapeFunctions, LinearClampsToTheLastCell) {
  int base = 0;
  double w[2], dw[2];
  LinearShape::eval(10.0, 0, 9, base, w, dw);  // a particle on the last node line stays in cell 9
  EXPECT_EQ(base, 9);
  EXPECT_CLOSE(w[1], 1.0, 1e-15, 0);
}

// The dimension-generic evaluation (eval_axes<dim>, for the 3D engine of issue 37):
// in 2D and 3D eval()'s values per axis (bit for bit away from l = 1/2's mid-line ulp), and the 27- (uGIMP)
// or 8-node (linear) tensor-product stencil a partition of unity that reproduces linear fields and their
// gradients: sum N = 1, sum grad N = 0, sum N x_i = x_p, sum x_i (x) grad N_i = I.
template <class Shape>
void check_eval_axes(double l) {
  constexpr int W = Shape::kWidth;
  const double h[3] = {0.7, 1.3, 0.9};
  const double ih[3] = {1.0 / h[0], 1.0 / h[1], 1.0 / h[2]};
  const int max_cell[3] = {10, 10, 10};
  for (double t = 1.0; t <= 4.0; t += 0.0137) {
    // 2D: eval() per axis (BothAxesAtOnce checks it on the piece boundaries).
    {
      const double s2[2] = {t, 5.0 - 0.61 * t}, l2[2] = {l, 0.5 * l}, ih2[2] = {ih[0], ih[1]};
      const int max2[2] = {10, 10};
      int first[2] = {0, 0};
      double wk[4 * W];
      Shape::template eval_axes<2>(s2, l2, max2, ih2, first, wk);
      for (int d = 0; d < 2; ++d) {
        int base = 0;
        double w[W], dw[W];
        Shape::eval(s2[d], l2[d], 10, base, w, dw);
        ASSERT_EQ(first[d], base);
        for (int a = 0; a < W; ++a) {
          ASSERT_EQ(wk[d * W + a], w[a]) << "2D axis " << d << " t " << t;
          ASSERT_EQ(wk[(2 + d) * W + a], dw[a] * ih2[d]) << "2D axis " << d << " t " << t;
        }
      }
    }
    // 3D: eval per axis, and the tensor product.
    const double s3[3] = {t, 5.0 - 0.61 * t, 1.3 + 0.37 * t}, l3[3] = {l, 0.5 * l, 0.75 * l};
    int first[3] = {0, 0, 0};
    double wk[6 * W];
    Shape::template eval_axes<3>(s3, l3, max_cell, ih, first, wk);
    for (int d = 0; d < 3; ++d) {
      int base = 0;
      double w[W], dw[W];
      Shape::eval(s3[d], l3[d], 10, base, w, dw);
      ASSERT_EQ(first[d], base);
      for (int a = 0; a < W; ++a) {
        ASSERT_EQ(wk[d * W + a], w[a]) << "axis " << d << " t " << t;
        ASSERT_EQ(wk[(3 + d) * W + a], dw[a] * ih[d]) << "axis " << d << " t " << t;
      }
    }
    double sum = 0, grad[3] = {0, 0, 0}, x[3] = {0, 0, 0}, xgrad[3][3] = {};
    for (int a = 0; a < W; ++a)
      for (int b = 0; b < W; ++b)
        for (int c = 0; c < W; ++c) {
          const int idx[3] = {a, b, c};
          double n = 1.0, g[3] = {1.0, 1.0, 1.0};
          for (int d = 0; d < 3; ++d) {
            n *= wk[d * W + idx[d]];
            for (int e = 0; e < 3; ++e) g[e] *= e == d ? wk[(3 + d) * W + idx[d]] : wk[d * W + idx[d]];
          }
          sum += n;
          for (int d = 0; d < 3; ++d) {
            const double xi = (first[d] + idx[d]) * h[d];  // the node's coordinate
            grad[d] += g[d];
            x[d] += n * xi;
            for (int e = 0; e < 3; ++e) xgrad[d][e] += xi * g[e];
          }
        }
    EXPECT_CLOSE(sum, 1.0, 1e-14, 0);
    for (int d = 0; d < 3; ++d) {
      EXPECT_CLOSE(grad[d], 0.0, 1e-13, 0);
      EXPECT_CLOSE(x[d], s3[d] * h[d], 1e-13, 0);
      for (int e = 0; e < 3; ++e) EXPECT_CLOSE(xgrad[d][e], d == e ? 1.0 : 0.0, 1e-13, 0);
    }
  }
}

TEST(ShapeFunctions, EveryAxisAtOnceIn2DAnd3D) {
  check_eval_axes<LinearShape>(0.0);
  for (double l : {0.05, 0.125, 0.25, 0.45}) check_eval_axes<GimpShape>(l);
}

}  // namespace

