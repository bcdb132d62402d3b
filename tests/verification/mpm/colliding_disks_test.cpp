// Two elastic disks colliding (Sulsky, Chen & Schreyer 1994, CMAME 118; also Sulsky, Zhou & Schreyer
// 1995, CPC 87): disks of
// radius 0.2 centred at (0.2, 0.2) and (0.8, 0.8) move towards each other at v = +-(0.1, 0.1);
// E = 1000, nu = 0.3, rho = 1000; no-slip contact comes from the single-valued grid velocity. Checks:
// total momentum stays zero; the motion is point-symmetric about (0.5, 0.5); kinetic energy drops
// while the disks are in contact and is largely recovered as strain energy and rebound; the total
// energy never grows (FLIP/MUSL, as in Sulsky et al.'s energy plots).
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "support/tolerance.hpp"
#include "support/mpm_test_decks.hpp"

namespace {

using namespace mpm_test;

Deck disks_deck(mpm::Scheme scheme) {
  Deck deck;
  const double h = 0.05;
  deck.grid = make_grid(0, 0, h, 20, 20, CellType::Linear4);
  deck.materials.push_back(elastic(0, 1000, 1000, 0.3));
  // 2 x 2 particles per cell inside each disk (point-symmetric sets: ids of disk 2 mirror disk 1).
  const int ppd = 2, n = 20 * ppd;
  std::int64_t id = 0;
  std::vector<mpm::ParticleRecord> second;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = (i + 0.5) * h / ppd, y = (j + 0.5) * h / ppd;
      if (std::hypot(x - 0.2, y - 0.2) >= 0.2) continue;
      mpm::ParticleRecord a{}, b{};
      a.id = id;
      b.id = id + 100000;
      ++id;
      a.coord_x = x;
      a.coord_y = y;
      b.coord_x = 1.0 - x;
      b.coord_y = 1.0 - y;
      a.velocity_x = a.velocity_y = 0.1;
      b.velocity_x = b.velocity_y = -0.1;
      deck.particles.push_back(a);
      second.push_back(b);
    }
  deck.particles.insert(deck.particles.end(), second.begin(), second.end());
  deck.analysis.scheme = scheme;
  deck.analysis.dt = 1e-3;
  return deck;
}

double strain_energy(const std::vector<mpm::ParticleRecord>& ps) {
  double e = 0;
  for (const auto& p : ps)
    e += 0.5 * p.volume * (p.stress_xx * p.strain_xx + p.stress_yy * p.strain_yy + p.tau_xy * p.gamma_xy);
  return e;
}

TEST(CollidingDisks, MomentumSymmetryAndEnergy) {
  mpm::core::Simulation sim(disks_deck(mpm::Scheme::MUSL), 1);
  const auto start = sim.snapshot();
  const double ke0 = totals(start).kinetic;
  double ke_min = ke0, e_max = ke0;
  while (sim.time() < 3.0) {
    sim.step();
    const auto ps = sim.snapshot();
    const Totals t = totals(ps);
    ke_min = std::min(ke_min, t.kinetic);
    e_max = std::max(e_max, t.kinetic + strain_energy(ps));
    ASSERT_CLOSE(t.px, 0.0, 1e-12, 0);
    ASSERT_CLOSE(t.py, 0.0, 1e-12, 0);
  }
  const auto end = sim.snapshot();
  // Point symmetry about (0.5, 0.5): particle id + 100000 mirrors particle id.
  std::map<std::int64_t, const mpm::ParticleRecord*> by_id;
  for (const auto& p : end) by_id[p.id] = &p;
  for (const auto& p : end) {
    if (p.id >= 100000) continue;
    const auto* q = by_id.at(p.id + 100000);
    EXPECT_CLOSE(p.coord_x, 1.0 - q->coord_x, 1e-9, 0);
    EXPECT_CLOSE(p.coord_y, 1.0 - q->coord_y, 1e-9, 0);
    EXPECT_CLOSE(p.velocity_x, -q->velocity_x, 1e-9, 0);
    EXPECT_CLOSE(p.stress_yy, q->stress_yy, 1e-6, 0);
  }
  const double ke_end = totals(end).kinetic;
  EXPECT_LT(ke_min, 0.5 * ke0);  // the collision stores most of the kinetic energy as strain energy
  EXPECT_GT(ke_end, 0.5 * ke0);  // ... and gives much of it back as the disks rebound
  EXPECT_LT(e_max, 1.02 * ke0);  // the total energy does not grow
  // The disks have rebounded: disk 1 moves away from the centre again.
  double vsum = 0;
  for (const auto& p : end)
    if (p.id < 100000) vsum += p.velocity_x + p.velocity_y;
  EXPECT_LT(vsum, 0.0);
}

}  // namespace
