// Free fall of an elastic block (no boundary contact): every particle follows the symplectic-Euler
// discretisation of x'' = g exactly, v_n = g n dt and y_n = y_0 + g dt^2 n (n + 1) / 2, which tends to
// y_0 + g t^2 / 2 (Newton); the stress stays zero because the grid velocity field is uniform.
#include <gtest/gtest.h>

#include "support/tolerance.hpp"
#include "support/mpm_test_decks.hpp"

namespace {

using namespace mpm_test;

class FreeFall : public ::testing::TestWithParam<std::tuple<CellType, mpm::Scheme>> {};

TEST_P(FreeFall, FollowsNewtonAndStaysStressFree) {
  Deck deck;
  deck.grid = make_grid(0, 0, 0.5, 8, 16, std::get<0>(GetParam()));
  deck.materials.push_back(elastic(0, 1500, 4e6, 0.25));
  fill_block(deck, 1.5, 2.5, 6.0, 7.0, 2, 0);
  deck.analysis.scheme = std::get<1>(GetParam());
  deck.analysis.gravity = {0, -9.81};
  deck.analysis.dt = 1e-3;
  mpm::core::Simulation sim(deck, 1);
  const auto start = sim.snapshot();
  const int n = 400;
  for (int i = 0; i < n; ++i) sim.step();
  const auto end = sim.snapshot();
  ASSERT_EQ(end.size(), start.size());
  const double dt = 1e-3, g = -9.81;
  for (std::size_t p = 0; p < end.size(); ++p) {
    EXPECT_CLOSE(end[p].velocity_y, g * n * dt, 1e-9, 1e-9);
    EXPECT_CLOSE(end[p].coord_y, start[p].coord_y + g * dt * dt * n * (n + 1) / 2.0, 1e-9, 1e-9);
    EXPECT_CLOSE(end[p].coord_x, start[p].coord_x, 1e-12, 0);
    EXPECT_CLOSE(end[p].stress_yy, 0.0, 1e-6, 0);
  }
  // Newton's free fall, to the time-discretisation error g t dt / 2.
  EXPECT_CLOSE(end[0].coord_y - start[0].coord_y, 0.5 * g * (n * dt) * (n * dt), 0.5 * 9.81 * n * dt * dt * 1.01, 0);
  EXPECT_CLOSE(sim.time(), n * dt, 1e-12, 0);
}

// The same block with its density and modulus in other units (x 1e-19: 1.5e-16 "kg/m3", the wave speed
// and the time step unchanged) falls the same way: the empty-node tolerance (CB-Geo's absolute 1e-15 kg)
// scales with the lightest material, so its nodes are not all empty and the body not frozen.
TEST(FreeFall, TinyDensityUnitsFallTheSame) {
  Deck deck;
  deck.grid = make_grid(0, 0, 0.5, 8, 16, CellType::Gimp16);
  deck.materials.push_back(elastic(0, 1500e-19, 4e6 * 1e-19, 0.25));
  fill_block(deck, 1.5, 2.5, 6.0, 7.0, 2, 0);
  deck.analysis.gravity = {0, -9.81};
  deck.analysis.dt = 1e-3;
  mpm::core::Simulation sim(deck, 1);
  const auto start = sim.snapshot();
  const int n = 100;
  for (int i = 0; i < n; ++i) sim.step();
  const auto end = sim.snapshot();
  for (std::size_t p = 0; p < end.size(); ++p)
    EXPECT_CLOSE(end[p].coord_y, start[p].coord_y - 9.81 * 1e-6 * n * (n + 1) / 2.0, 1e-9, 1e-9) << "particle " << p;
}

INSTANTIATE_TEST_SUITE_P(Schemes, FreeFall,
                         ::testing::Combine(::testing::Values(CellType::Linear4, CellType::Gimp16),
                                            ::testing::Values(mpm::Scheme::USF, mpm::Scheme::USL,
                                                              mpm::Scheme::MUSL)));

}  // namespace
