// Stability at the physical time-step limit: the collapsing Mohr-Coulomb column of the reference deck
// mc_column_gimp_short (10 m x 8 m, phi 30, c 500 Pa, rough base; see checkerboard_test.cpp), run with
// the automatic time step at CFL 0.5 (dt = 0.5 h / c_p = 1.3e-3 s, 13x CB-Geo's 1e-4) for 1.5 s of
// collapse. Explicit MPM is conditionally stable for dt < h / c_p (e.g. Bardenhagen 2002; Sulsky et al.
// 1995); the run must finish without NaN, runaway velocity or particles leaving the grid, keep every
// particle, and give the runout of a run at CFL 0.1 to within a cell. FLIP keeps velocity modes the
// grid cannot see (its null space), which USL turns into instability near nearly empty nodes (the
// paper's column blows up at t = 4 s with USL + FLIP at CFL 0.5); a 2 % PIC blend
// (analysis.pic_blend) removes them. The blend acts per step (its damping per second grows as dt
// shrinks), so FLIP runs are compared with a CFL 0.1 FLIP run and the blended USL run with the
// blended MUSL run at the same dt.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "mpm/io/results.hpp"
#include "support/tolerance.hpp"
#include "support/mpm_test_decks.hpp"

namespace {

using namespace mpm_test;

mpm::io::SeriesRow collapse(mpm::Scheme scheme, double cfl, double dt, double pic_blend, double t_end) {
  auto material = mohr_coulomb(0, 1800, 5e7, 0.3, 30, 500, 0);
  material.tension_cutoff = 300;
  Deck deck = collapsing_column(make_grid(0, 0, 0.5, 60, 20, CellType::Gimp16), material, 10, 8, 2, 0.5, 30);
  deck.analysis.scheme = scheme;
  deck.analysis.cfl = cfl;
  deck.analysis.dt = dt;
  deck.analysis.pic_blend = pic_blend;
  mpm::core::Simulation sim(deck, 1);
  while (sim.time() < t_end) sim.step();
  const auto ps = sim.snapshot();
  EXPECT_EQ(ps.size(), 1280u);
  return mpm::io::summarize_state(sim.step_index(), sim.time(), sim.dt(), ps, deck.grid, deck.analysis.gravity);
}

TEST(CflStability, CollapsingColumnAtCflHalf) {
  const double t_end = 1.5;
  const auto reference = collapse(mpm::Scheme::MUSL, 0.1, 1.0, 0.0, t_end);
  std::printf("CFL 0.1 MUSL FLIP: runout %.3f m\n", reference.runout_x_p98);
  for (auto scheme : {mpm::Scheme::MUSL, mpm::Scheme::USF}) {
    SCOPED_TRACE(testing::Message() << "scheme " << static_cast<int>(scheme));
    const auto r = collapse(scheme, 0.5, 1.0, 0.0, t_end);
    std::printf("CFL 0.5 (dt %.2e) scheme %d FLIP: runout %.3f m, max speed %.3f m/s\n", r.dt,
                static_cast<int>(scheme), r.runout_x_p98, r.max_speed);
    EXPECT_GT(r.dt, 1.2e-3);
    EXPECT_CLOSE(r.runout_x_p98, reference.runout_x_p98, 0.5, 0);  // within a cell
    EXPECT_GT(r.runout_x_p98, 11.0);                                // it did collapse (starts at 9.9 m)
    EXPECT_LT(r.max_speed, 15.0);                                   // no runaway (free fall from 8 m: 12.5 m/s)
  }
  const auto musl = collapse(mpm::Scheme::MUSL, 0.5, 1.0, 0.02, t_end);
  const auto usl = collapse(mpm::Scheme::USL, 0.5, 1.0, 0.02, t_end);
  std::printf("CFL 0.5, 2 %% PIC: runout %.3f m (MUSL), %.3f m (USL); max speed %.3f, %.3f m/s\n",
              musl.runout_x_p98, usl.runout_x_p98, musl.max_speed, usl.max_speed);
  EXPECT_CLOSE(usl.runout_x_p98, musl.runout_x_p98, 0.5, 0);
  EXPECT_GT(usl.runout_x_p98, 11.0);
  EXPECT_LT(usl.max_speed, 15.0);
}

}  // namespace
