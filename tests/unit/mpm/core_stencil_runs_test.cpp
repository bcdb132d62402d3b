// Unit tests of the four-particle run kernels (mpm/core/stencil_runs.hpp): each must give the
// one-particle kernels' values bit for bit (EXPECT_EQ on doubles, not a tolerance), since the engine
// takes either path for a particle depending on its neighbours and promises the same state for any
// thread count. The inputs are random particles in one stencil cell and random nodal fields.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "mpm/core/stencil_runs.hpp"
#include "mpm/core/velocity_transfer.hpp"

namespace {

using namespace mpm::core;

constexpr int kLanes = 4;
constexpr std::size_t kRowNodes = 7;  // nodes per lattice row of the test field

/// Four particles of one stencil: the lattice coordinates of each (units of h) inside the quadrant of
/// cell (2, 3) whose nearest node is (3, 3) (uGIMP) or anywhere in the cell (bilinear), and half-sizes.
struct Run {
  double sx[kLanes], sy[kLanes], lx[kLanes], ly[kLanes];
};

template <class Shape>
Run random_run(std::mt19937& rng) {
  const bool gimp = Shape::kWidth == 3;
  std::uniform_real_distribution<double> x(gimp ? 2.5 : 2.0, 3.0 - 1e-9), y(3.0, gimp ? 3.5 - 1e-9 : 4.0 - 1e-9);
  std::uniform_real_distribution<double> l(0.05, 0.5);
  Run r{};
  for (int p = 0; p < kLanes; ++p) {
    r.sx[p] = x(rng);
    r.sy[p] = y(rng);
    r.lx[p] = l(rng);
    r.ly[p] = l(rng);
  }
  return r;
}

/// The weights of the run: one block per particle (eval_axes<2>) and interleaved (eval_run_axis).
template <class Shape>
void weights_both_ways(const Run& r, double ihx, double ihy, double* blocks, double* interleaved, int& bi, int& bj) {
  constexpr int W = Shape::kWidth;
  int first[2] = {0, 0};
  for (int p = 0; p < kLanes; ++p)
    Shape::template eval_axes<2>({r.sx[p], r.sy[p]}, {r.lx[p], r.ly[p]}, {5, 5}, {ihx, ihy}, first, blocks + 4 * W * p);
  bi = first[0];
  bj = first[1];
  Double4 w[W], dw[W];
  eval_run_axis(Shape{}, Double4{r.sx[0], r.sx[1], r.sx[2], r.sx[3]}, Double4{r.lx[0], r.lx[1], r.lx[2], r.lx[3]}, bi,
                       ihx, w, dw);
  for (int a = 0; a < W; ++a) {
    store4(interleaved + 4 * a, w[a]);
    store4(interleaved + 4 * (2 * W + a), dw[a]);
  }
  eval_run_axis(Shape{}, Double4{r.sy[0], r.sy[1], r.sy[2], r.sy[3]}, Double4{r.ly[0], r.ly[1], r.ly[2], r.ly[3]}, bj,
                       ihy, w, dw);
  for (int a = 0; a < W; ++a) {
    store4(interleaved + 4 * (W + a), w[a]);
    store4(interleaved + 4 * (3 * W + a), dw[a]);
  }
}

template <class Shape>
void check_run_kernels(unsigned seed) {
  constexpr int W = Shape::kWidth;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-3.0, 3.0);
  std::vector<double> field(4 * kRowNodes * kRowNodes);
  for (double& v : field) v = value(rng);
  const double ihx = 1.0 / 0.7, ihy = 1.0 / 1.3;
  for (int trial = 0; trial < 200; ++trial) {
    const Run r = random_run<Shape>(rng);
    double blocks[4 * W * kLanes], interleaved[4 * W * kLanes];
    int bi = 0, bj = 0;
    weights_both_ways<Shape>(r, ihx, ihy, blocks, interleaved, bi, bj);
    for (int p = 0; p < kLanes; ++p)
      for (int e = 0; e < 4 * W; ++e) ASSERT_EQ(interleaved[4 * e + p], blocks[4 * W * p + e]) << "entry " << e;
    // The interleaved block read per particle (stride 4) is the particle's own block.
    for (int p = 0; p < kLanes; ++p) {
      const StencilWeights<W> one(blocks + 4 * W * p), strided(interleaved + p, kLanes);
      for (int a = 0; a < W; ++a) {
        EXPECT_EQ(strided.wx[a], one.wx[a]);
        EXPECT_EQ(strided.dwy[a], one.dwy[a]);
      }
    }
    const std::size_t first = static_cast<std::size_t>(bi) + static_cast<std::size_t>(bj) * kRowNodes;
    const StencilWeights4<W> w4(interleaved);

    // g2p: the velocity gradient (stride 2) and the FLIP sums with the gradient (stride 4).
    const VelocityGradient4 L4 = gather_velocity_gradient4(field.data(), 2, first, kRowNodes, w4);
    const GridSums4 run = gather_updated4(field.data(), first, kRowNodes, w4, true);
    for (int p = 0; p < kLanes; ++p) {
      const StencilWeights<W> w(blocks + 4 * W * p);
      const VelocityGradient L = gather_velocity_gradient(field.data(), 2, first, kRowNodes, w);
      for (int i = 0; i < 2; ++i) {
        EXPECT_EQ(L4.lane(p).d_dx[i], L.d_dx[i]);
        EXPECT_EQ(L4.lane(p).d_dy[i], L.d_dy[i]);
      }
      const GridSums s = gather_updated<W, false>(field.data(), first, kRowNodes, w, nullptr, nullptr, true);
      const GridSums lane = run.lane(p);
      for (int i = 0; i < 2; ++i) {
        EXPECT_EQ(lane.v[i], s.v[i]);
        EXPECT_EQ(lane.a[i], s.a[i]);
        EXPECT_EQ(lane.L.d_dx[i], s.L.d_dx[i]);
        EXPECT_EQ(lane.L.d_dy[i], s.L.d_dy[i]);
      }
    }

    // APIC: the affine weights (first node minus particle o, per axis), the sums B (and C), the
    // momentum with the particles' matrices B_p.
    const double hx = 0.7, hy = 1.3;
    double ox[kLanes], oy[kLanes], affine_one[2 * W * kLanes], affine_run[2 * W * kLanes];
    for (int p = 0; p < kLanes; ++p) {
      ox[p] = bi * hx - r.sx[p] * hx;
      oy[p] = bj * hy - r.sy[p] * hy;
      affine_weights(Shape{}, StencilWeights<W>(blocks + 4 * W * p), ox[p], oy[p], hx, hy, affine_one + 2 * W * p);
    }
    {
      const Double4 o4x{ox[0], ox[1], ox[2], ox[3]}, o4y{oy[0], oy[1], oy[2], oy[3]};
      Double4 a[W];
      affine_weights_run_axis(Shape{}, w4.wx, w4.dwx, o4x, hx, a);
      for (int e = 0; e < W; ++e) store4(affine_run + 4 * e, a[e]);
      affine_weights_run_axis(Shape{}, w4.wy, w4.dwy, o4y, hy, a);
      for (int e = 0; e < W; ++e) store4(affine_run + 4 * (W + e), a[e]);
      Double4 dxs[W], dys[W];
      for (int k = 0; k < W; ++k) {
        dxs[k] = o4x + k * hx;
        dys[k] = o4y + k * hy;
      }
      const GridSums4 affine4 = gather_updated_affine4(field.data(), first, kRowNodes, w4, dxs, dys, true);
      for (int p = 0; p < kLanes; ++p) {
        for (int e = 0; e < 2 * W; ++e) ASSERT_EQ(affine_run[4 * e + p], affine_one[2 * W * p + e]);
        double dx1[W], dy1[W];
        for (int k = 0; k < W; ++k) {
          dx1[k] = ox[p] + k * hx;
          dy1[k] = oy[p] + k * hy;
        }
        const GridSums s = gather_updated<W, true>(field.data(), first, kRowNodes, StencilWeights<W>(blocks + 4 * W * p),
                                                   dx1, dy1, true);
        for (int i = 0; i < 2; ++i) {
          EXPECT_EQ(affine4.lane(p).v[i], s.v[i]);
          EXPECT_EQ(affine4.lane(p).b_dx[i], s.b_dx[i]);
          EXPECT_EQ(affine4.lane(p).b_dy[i], s.b_dy[i]);
          EXPECT_EQ(affine4.lane(p).L.d_dx[i], s.L.d_dx[i]);
        }
      }
    }

    // p2g: mass, momentum and forces of the four, against the one-particle kernels in particle order,
    // into a band that already holds values (the sums continue those of earlier particles).
    const std::size_t row_stride = 5 * kRowNodes;
    std::vector<double> band_one(5 * kRowNodes * kRowNodes), band_run, remap_one, remap_run;
    for (double& v : band_one) v = value(rng);
    band_run = band_one;
    remap_one = remap_run = band_one;  // MUSL's remap goes to a band of its own
    double m[kLanes], vx[kLanes], vy[kLanes], V[kLanes], sxx[kLanes], syy[kLanes], sxy[kLanes];
    for (int p = 0; p < kLanes; ++p) {
      m[p] = 1.0 + value(rng) * value(rng);
      vx[p] = value(rng);
      vy[p] = value(rng);
      V[p] = 0.5 + 0.1 * value(rng);
      sxx[p] = 1e4 * value(rng);
      syy[p] = 1e4 * value(rng);
      sxy[p] = 1e3 * value(rng);
    }
    double B[kLanes][4];  // APIC matrices, xx xy yx yy
    for (auto& b : B)
      for (double& v : b) v = value(rng);
    std::vector<double> affine_band_one = band_one, affine_band_run = band_one;
    const double gx = 0.3, gy = -9.81;
    for (int p = 0; p < kLanes; ++p) {
      const StencilWeights<W> w(blocks + 4 * W * p);
      const MomentumContribution<Shape, false> momentum(m[p], vx[p], vy[p], splat2(0.0), splat2(0.0), nullptr, w);
      scatter_mass_momentum(band_one.data() + 5 * first, row_stride, w, m[p], momentum);
      scatter_forces(band_one.data() + 5 * first, row_stride, w, Double2{m[p] * gx, m[p] * gy}, V[p], sxx[p], syy[p],
                     sxy[p]);
      scatter_momentum(remap_one.data() + 5 * first, row_stride, w, momentum);
      const MomentumContribution<Shape, true> affine(m[p], vx[p], vy[p], Double2{B[p][0], B[p][2]},
                                                     Double2{B[p][1], B[p][3]}, affine_one + 2 * W * p, w);
      scatter_mass_momentum(affine_band_one.data() + 5 * first, row_stride, w, m[p], affine);
    }
    const Double4 m4{m[0], m[1], m[2], m[3]}, vx4{vx[0], vx[1], vx[2], vx[3]}, vy4{vy[0], vy[1], vy[2], vy[3]};
    double* run_row = band_run.data() + 5 * first;
    scatter_mass_momentum4(run_row, row_stride, w4, m4, m4 * vx4, m4 * vy4);
    scatter_forces4(run_row, row_stride, w4, m4 * gx, m4 * gy, Double4{V[0], V[1], V[2], V[3]},
                    Double4{sxx[0], sxx[1], sxx[2], sxx[3]}, Double4{syy[0], syy[1], syy[2], syy[3]},
                    Double4{sxy[0], sxy[1], sxy[2], sxy[3]});
    scatter_momentum4(remap_run.data() + 5 * first, row_stride, w4, m4 * vx4, m4 * vy4);
    Double4 mB[4];
    for (int e = 0; e < 4; ++e) mB[e] = m4 * Double4{B[0][e], B[1][e], B[2][e], B[3][e]};
    scatter_affine_momentum4(affine_band_run.data() + 5 * first, row_stride, w4,
                             AffineMomentum4<W>(m4 * vx4, m4 * vy4, mB, affine_run, w4), &m4);
    // Each node's sums in particle order: mass, momentum and force of particle 0, 1, ... in turn for
    // the one-particle kernels, all masses and momenta then all forces for the run's; every slot sums
    // its own contributions in particle order either way.
    for (std::size_t i = 0; i < band_one.size(); ++i) {
      ASSERT_EQ(band_run[i], band_one[i]) << "band value " << i;
      ASSERT_EQ(remap_run[i], remap_one[i]) << "remap band value " << i;
      ASSERT_EQ(affine_band_run[i], affine_band_one[i]) << "APIC band value " << i;
    }
  }
}

TEST(StencilRuns, GimpRunKernelsAreTheOneParticleKernelsBitForBit) { check_run_kernels<GimpShape>(11); }

TEST(StencilRuns, LinearRunKernelsAreTheOneParticleKernelsBitForBit) { check_run_kernels<LinearShape>(12); }

}  // namespace
