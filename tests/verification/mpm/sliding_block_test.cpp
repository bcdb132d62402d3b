// A block sliding on a frictional base under inclined gravity (Coulomb friction; the MPM check of
// Bardenhagen, Brackbill & Sulsky 2000, CMAME 187, and of CB-Geo's friction constraint): with
// gravity g (sin a, -cos a) and friction coefficient mu < tan a the block accelerates uniformly,
// x(t) = 1/2 g (sin a - mu cos a) t^2; with mu >= tan a it stays at rest. The base nodes carry CB-Geo's
// friction constraint (dir 1, sign_n -1) and a zero normal velocity.
#include <gtest/gtest.h>

#include <cmath>

#include "support/tolerance.hpp"
#include "support/mpm_test_decks.hpp"

namespace {

using namespace mpm_test;

constexpr double kG = 9.81;

/// Returns the mean x displacement of the block after `t_end` seconds.
double slide(double angle_deg, double mu, CellType type, mpm::io::Scheme scheme, double t_end, double E = 1e6,
             double pic_blend = 0.0) {
  const double a = angle_deg * std::acos(-1.0) / 180.0;
  Deck deck;
  deck.grid = make_grid(0, 0, 0.25, 40, 8, type);
  deck.materials.push_back(elastic(0, 1000, E, 0.3));
  fill_block(deck, 0.5, 1.5, 0.0, 1.0, 2, 0);
  for (auto& p : deck.particles) {  // at rest under the normal gravity component (K0 = nu / (1 - nu))
    p.stress_yy = -1000 * kG * std::cos(a) * (1.0 - p.coord_y);
    p.stress_xx = p.stress_zz = 0.3 / 0.7 * p.stress_yy;
  }
  const auto& g = deck.grid;
  const auto base = nodes_where(g, [](double, double y) { return y <= 1e-9; });
  deck.velocity_constraints.push_back({base, 1, 0.0});
  deck.friction_constraints.push_back({base, 1, -1, mu});
  deck.analysis.scheme = scheme;
  deck.analysis.gravity = {kG * std::sin(a), -kG * std::cos(a)};
  deck.analysis.cfl = 0.4;
  deck.analysis.dt = 1.0;
  deck.analysis.pic_blend = pic_blend;
  mpm::core::Simulation sim(deck, 1);
  while (sim.time() < t_end - 1e-12) sim.step();
  double ux = 0;
  const auto ps = sim.snapshot();
  for (const auto& p : ps) ux += p.displacement_x;
  return ux / static_cast<double>(ps.size());
}

TEST(SlidingBlock, DisplacementFollowsCoulombFriction) {
  const double angle = 30.0, mu = 0.3, t = 1.0;
  const double a = angle * std::acos(-1.0) / 180.0;
  const double exact = 0.5 * kG * (std::sin(a) - mu * std::cos(a)) * t * t;  // 1.178 m
  for (auto type : {CellType::Linear4, CellType::Gimp16}) {
    for (auto scheme : {mpm::io::Scheme::USF, mpm::io::Scheme::MUSL}) {
      SCOPED_TRACE(testing::Message() << "cell type " << static_cast<int>(type) << " scheme " << static_cast<int>(scheme));
      // 3 %: the elastic block's stress waves and the time discretisation.
      EXPECT_CLOSE(slide(angle, mu, type, scheme, t), exact, 0.0, 0.03);
    }
  }
}

TEST(SlidingBlock, StiffBlockNeedsALittlePic) {
  // A stiff block (E = 50 MPa) rings as it crosses cells; pure FLIP keeps that noise, and friction,
  // acting on |normal force|, turns it into extra drag (documented limitation). A 5 % PIC blend damps
  // the noise and recovers the Coulomb solution.
  const double a = 30.0 * std::acos(-1.0) / 180.0;
  const double exact = 0.5 * kG * (std::sin(a) - 0.3 * std::cos(a));
  for (auto type : {CellType::Linear4, CellType::Gimp16})
    EXPECT_CLOSE(slide(30.0, 0.3, type, mpm::io::Scheme::MUSL, 1.0, 5e7, 0.05), exact, 0.0, 0.03);
}

TEST(SlidingBlock, StaysAtRestWhenFrictionHolds) {
  // tan(20 deg) = 0.364 < mu = 0.5: static friction holds (only elastic shear straining moves the
  // particles: rho g sin(a) H / G ~ 1 cm at E = 1 MPa).
  EXPECT_LT(std::abs(slide(20.0, 0.5, CellType::Gimp16, mpm::io::Scheme::MUSL, 0.5)), 0.02);
}

TEST(SlidingBlock, FrictionlessBaseGivesFreeSliding) {
  const double a = 30.0 * std::acos(-1.0) / 180.0;
  // 2 %: symplectic Euler adds (n + 1) / n, and the run ends at the first step past 0.5 s.
  EXPECT_CLOSE(slide(30.0, 0.0, CellType::Linear4, mpm::io::Scheme::MUSL, 0.5), 0.5 * kG * std::sin(a) * 0.25, 0.0, 0.02);
}

}  // namespace
