// CB-Geo's concentrated_nodal_forces and particle_surface_traction (mpm/core/external_loads.hpp).
// - Impulse: without gravity or constraints the grid's internal forces cancel, so the particles' total
//   momentum after n steps is exactly the sum of the external forces over the steps, sum_k F(t_k) dt with
//   t_k = k dt (CB-Geo evaluates loads at step * dt). That holds to round-off for every scheme and
//   transfer (the nodal momentum is the particle momentum, p2g and g2p are partitions of unity; APIC's
//   affine term sums to zero over a stencil), and it checks the function's time convention exactly.
// - A particle traction t on a set of particles is the force t V / sqrt(V0) on each: on the top row of a
//   block of particles of side l0 it sums to t times the block's width.
// - A laterally confined elastic column (rollers on both sides, fixed base) under a traction q on its top
//   particles comes to rest in uniaxial strain: syy = -q at every depth and a top settlement q H / M with
//   the constrained modulus M = E (1 - nu) / ((1 + nu)(1 - 2 nu)) (e.g. Timoshenko & Goodier 1970, or any
//   oedometer test), within the particle discretisation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>

#include "support/mpm_test_decks.hpp"
#include "support/tolerance.hpp"

namespace {

using namespace mpm_test;
using mpm::Scheme;
using mpm::Transfer;

/// A free 2 m x 1 m elastic block (no gravity, no constraints) on uGIMP cells of 0.25 m in the middle of
/// its grid.
Deck free_block(Scheme scheme, Transfer transfer) {
  Deck deck;
  deck.grid = make_grid(0, 0, 0.25, 24, 16, CellType::Gimp16);
  deck.materials.push_back(elastic(0, 1000, 1e9, 0.3));  // stiff: the tractions' V / sqrt(V0) stays sqrt(V0)
  fill_block(deck, 2.0, 4.0, 1.5, 2.5, 2, 0);
  deck.analysis.scheme = scheme;
  deck.analysis.transfer = transfer;
  deck.analysis.velocity_update = transfer == Transfer::PIC;
  deck.analysis.dt = 2e-5;  // CFL ~0.08 on the stiff block
  return deck;
}

class ExternalLoads : public testing::TestWithParam<std::tuple<Scheme, Transfer>> {};

TEST_P(ExternalLoads, NodalForcesGiveTheirImpulseExactly) {
  const auto [scheme, transfer] = GetParam();
  Deck deck = free_block(scheme, transfer);
  // Two nodes inside the block, F(t) = F0 sin(a t) along y, and a constant force along x on one of them.
  const auto inside = nodes_where(deck.grid, [](double x, double y) {
    return std::abs(y - 2.0) < 1e-9 && (std::abs(x - 2.5) < 1e-9 || std::abs(x - 3.5) < 1e-9);
  });
  ASSERT_EQ(inside.size(), 2u);
  const double F0 = 300.0, a = 1000.0, Fx = -50.0;
  deck.nodal_forces.push_back({inside, 1, F0, mpm::SinFunction{a, 0.0}});
  deck.nodal_forces.push_back({{inside[0]}, 0, Fx, {}});
  mpm::core::Simulation sim(deck, 1);
  const int steps = 200;
  double impulse_y = 0.0;
  for (int k = 0; k < steps; ++k) {
    // SinFunction's default range starts above 0, so the step from t = 0 has no force (CB-Geo).
    if (k > 0) impulse_y += 2.0 * F0 * std::sin(a * k * deck.analysis.dt) * deck.analysis.dt;
    sim.step();
  }
  const Totals t = totals(sim.snapshot());
  EXPECT_CLOSE(t.py, impulse_y, 1e-12, 1e-9);  // measured 1e-11
  EXPECT_CLOSE(t.px, Fx * steps * deck.analysis.dt, 1e-12, 1e-9);
}

TEST_P(ExternalLoads, ParticleTractionIsTheTractionTimesTheFace) {
  const auto [scheme, transfer] = GetParam();
  Deck deck = free_block(scheme, transfer);
  mpm::ParticleTraction top;
  for (const auto& p : deck.particles)
    if (p.coord_y > 2.4) top.particles.push_back(p.id);  // the top row (16 particles of side 0.125 m)
  ASSERT_EQ(top.particles.size(), 16u);
  top.dir = 1;
  top.traction = -2000.0;  // Pa: 2 kN/m over the 2 m width, downwards
  deck.particle_tractions.push_back(top);
  mpm::core::Simulation sim(deck, 1);
  const int steps = 20;
  for (int k = 0; k < steps; ++k) sim.step();
  // The force t V / sqrt(V0) changes with the volume only (strains ~1e-5 here).
  EXPECT_CLOSE(totals(sim.snapshot()).py, -2000.0 * 2.0 * steps * deck.analysis.dt, 0.0, 1e-4);
}

INSTANTIATE_TEST_SUITE_P(SchemesAndTransfers, ExternalLoads,
                         testing::Combine(testing::Values(Scheme::USF, Scheme::USL, Scheme::MUSL),
                                          testing::Values(Transfer::FLIP, Transfer::PIC, Transfer::APIC)),
                         [](const testing::TestParamInfo<ExternalLoads::ParamType>& info) {
                           const Scheme s = std::get<0>(info.param);
                           const Transfer t = std::get<1>(info.param);
                           return std::string(s == Scheme::USF ? "USF" : (s == Scheme::USL ? "USL" : "MUSL")) + "_" +
                                  (t == Transfer::FLIP ? "FLIP" : (t == Transfer::PIC ? "PIC" : "APIC"));
                         });

TEST(ExternalLoadsColumn, TractionOnTheTopCompressesAConfinedColumnUniaxially) {
  const double H = 4.0, width = 1.0, h = 0.25, E = 1e7, nu = 0.25, q = 50e3;
  for (auto type : {CellType::Linear4, CellType::Gimp16}) {
    SCOPED_TRACE(type == CellType::Gimp16 ? "uGIMP" : "bilinear");
    Deck deck;
    deck.grid = make_grid(0, 0, h, 4, 20, type);
    deck.materials.push_back(elastic(0, 2000, E, nu));
    fill_block(deck, 0, width, 0, H, 2, 0);
    const auto& g = deck.grid;
    deck.velocity_constraints.push_back({nodes_where(g, [&](double x, double) { return x <= 1e-9 || x >= width - 1e-9; }), 0, 0.0});
    deck.velocity_constraints.push_back({nodes_where(g, [](double, double y) { return y <= 1e-9; }), 1, 0.0});
    mpm::ParticleTraction top;
    for (const auto& p : deck.particles)
      if (p.coord_y > H - h / 2) top.particles.push_back(p.id);
    top.dir = 1;
    top.traction = -q;
    top.function = mpm::LinearFunction{{0.0, 0.2}, {0.0, 1.0}};  // ramped over 0.2 s, then held
    deck.particle_tractions.push_back(top);
    deck.analysis.scheme = Scheme::MUSL;
    deck.analysis.cfl = 0.5;
    deck.analysis.dt = 1.0;
    deck.analysis.cundall_damping = 0.1;
    mpm::core::Simulation sim(deck, 1);
    while (sim.time() < 2.0) sim.step();
    const auto ps = sim.snapshot();
    const double M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
    double sum2 = 0, top_settlement = 0;
    int below_top = 0, top_count = 0;
    for (const auto& p : ps) {
      const double y0 = p.coord_y - p.displacement_y;
      if (y0 > H - h / 2) {
        top_settlement += p.displacement_y;
        ++top_count;
      }
      // The top cell carries ~3/4 of q (measured 0.71 q below the loaded row): the traction acts at the
      // loaded particles' centres, a quarter cell below the surface, and reaches the nodes below them
      // through the shape functions. Every cell below carries q (within 0.2 %, measured).
      if (y0 > H - h) continue;
      const double e = (p.stress_yy + q) / q;
      sum2 += e * e;
      ++below_top;
    }
    top_settlement /= top_count;
    const double rms = std::sqrt(sum2 / below_top);
    std::printf("syy RMS error %.4f of q; top settlement %.5f m (q H / M = %.5f; particles at H - h/4)\n", rms,
                top_settlement, -q * (H - h / 4) / M);
    EXPECT_LT(rms, 0.02);
    EXPECT_CLOSE(top_settlement, -q * (H - h / 4) / M, 0.0, 0.03);
    EXPECT_LT(totals(ps).kinetic, 1e-3 * q * q / M * H * width);  // at rest: kinetic energy << strain energy
  }
}

}  // namespace
