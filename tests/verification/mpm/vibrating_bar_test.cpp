// 1D vibrating bar in its first mode (Sulsky, Zhou & Schreyer 1995, CPC 87; Bardenhagen 2002,
// JCP 180): a bar of length L fixed at x = 0 and free at x = L, E = 100, rho = 1, starting with
// v(x, 0) = v0 sin(beta x), beta = pi / (2L). The exact solution v(x, t) = v0 sin(beta x) cos(omega t),
// omega = beta sqrt(E / rho), gives the centre-of-mass velocity v_cm(t) = (2 v0 / pi) cos(omega t).
// Modelled as a strip one cell high with nu = 0 and y-velocities fixed (uniaxial strain = uniaxial
// stress at nu = 0). Checks the period and amplitude of v_cm, and that the error shrinks with refinement.
#include <gtest/gtest.h>

#include <cmath>

#include "support/tolerance.hpp"
#include "support/mpm_test_decks.hpp"

namespace {

using namespace mpm_test;

constexpr double kL = 25.0, kE = 100.0, kRho = 1.0, kV0 = 0.01;  // end displacement 0.016 m < h / 4: no cell crossing
const double kPi = std::acos(-1.0);
const double kBeta = kPi / (2 * kL), kOmega = kBeta * std::sqrt(kE / kRho), kPeriod = 2 * kPi / kOmega;

struct BarResult {
  double period_error = 0;     ///< |T_measured - T| / T
  double amplitude_error = 0;  ///< |min v_cm over the first period + 2 v0 / pi| / (2 v0 / pi)
};

BarResult run_bar(int cells, mpm::io::Scheme scheme, CellType type, double v0 = kV0) {
  const double h = kL / cells;
  Deck deck;
  deck.grid = make_grid(0, 0, h, cells + 2, 1, type);
  deck.materials.push_back(elastic(0, kRho, kE, 0.0));
  fill_block(deck, 0, kL, 0, h, 2, 0);
  for (auto& p : deck.particles) p.velocity_x = v0 * std::sin(kBeta * p.coord_x);
  deck.velocity_constraints.push_back({nodes_where(deck.grid, [](double x, double) { return x <= 1e-9; }), 0, 0.0});
  deck.velocity_constraints.push_back({nodes_where(deck.grid, [](double, double) { return true; }), 1, 0.0});
  deck.analysis.scheme = scheme;
  deck.analysis.cfl = 0.2;
  deck.analysis.dt = 1.0;
  deck.analysis.locate_particles = true;
  mpm::core::Simulation sim(deck, 1);
  double prev = totals(sim.snapshot()).px, mass = totals(sim.snapshot()).mass;
  double t_zero1 = -1, t_zero2 = -1, vmin = 0;
  while (sim.time() < 1.1 * kPeriod) {
    sim.step();
    const double p = totals(sim.snapshot()).px;
    vmin = std::min(vmin, p / mass);
    const double t_cross = sim.time() - sim.dt() * p / (p - prev);  // linear interpolation of the zero
    if (prev > 0 && p <= 0 && t_zero1 < 0) t_zero1 = t_cross;
    if (prev < 0 && p >= 0 && t_zero2 < 0) t_zero2 = t_cross;
    prev = p;
  }
  BarResult r;
  // v_cm crosses zero at T/4 and 3T/4.
  r.period_error = std::abs(2 * (t_zero2 - t_zero1) - kPeriod) / kPeriod;
  const double amplitude = 2 * v0 / kPi;
  r.amplitude_error = std::abs(-vmin - amplitude) / amplitude;
  return r;
}

TEST(VibratingBar, PeriodAndAmplitudeMatchTheFirstMode) {
  for (auto scheme : {mpm::io::Scheme::USF, mpm::io::Scheme::USL, mpm::io::Scheme::MUSL}) {
    for (auto type : {CellType::Linear4, CellType::Gimp16}) {
      const BarResult r = run_bar(50, scheme, type);
      SCOPED_TRACE(testing::Message() << "scheme " << static_cast<int>(scheme) << " cell type " << static_cast<int>(type));
      EXPECT_LT(r.period_error, 0.01);
      EXPECT_LT(r.amplitude_error, 0.02);
    }
  }
}

TEST(VibratingBar, FreeEndCrossesIntoTheEmptyCell) {
  // v0 = 0.3 m/s: the free end swings v0 / omega = 0.48 m, about a cell, so its particles enter the
  // empty cell beyond x = L and leave it again (mpm/core/README.md: USL with linear cells used to be
  // unstable there). Every scheme and cell type runs through it and keeps the first mode. uGIMP: period
  // and amplitude within 1 % (measured 0.2 %, 0.02 %). Linear cells: period within 3 %, amplitude within
  // 20 % (measured 1-2 % and 13-16 % for USF, USL and MUSL alike): the grid-crossing error of linear
  // shape functions (Bardenhagen & Kober 2004, CMES 5, section 1), not an instability.
  for (auto scheme : {mpm::io::Scheme::USF, mpm::io::Scheme::USL, mpm::io::Scheme::MUSL}) {
    for (auto type : {CellType::Linear4, CellType::Gimp16}) {
      SCOPED_TRACE(testing::Message() << "scheme " << static_cast<int>(scheme) << " cell type " << static_cast<int>(type));
      BarResult r;
      ASSERT_NO_THROW(r = run_bar(50, scheme, type, 0.3));
      const bool linear = type == CellType::Linear4;
      EXPECT_LT(r.period_error, linear ? 0.03 : 0.01);
      EXPECT_LT(r.amplitude_error, linear ? 0.20 : 0.01);
    }
  }
}

TEST(VibratingBar, ErrorShrinksWithRefinement) {
  const BarResult coarse = run_bar(10, mpm::io::Scheme::MUSL, CellType::Linear4);
  const BarResult medium = run_bar(20, mpm::io::Scheme::MUSL, CellType::Linear4);
  const BarResult fine = run_bar(40, mpm::io::Scheme::MUSL, CellType::Linear4);
  std::printf("period error: %.3e (10 cells) %.3e (20) %.3e (40); amplitude error %.3e %.3e %.3e\n",
              coarse.period_error, medium.period_error, fine.period_error, coarse.amplitude_error,
              medium.amplitude_error, fine.amplitude_error);
  EXPECT_LT(medium.period_error, coarse.period_error);
  EXPECT_LT(fine.period_error, medium.period_error);
  EXPECT_LT(fine.amplitude_error, coarse.amplitude_error);
}

}  // namespace
