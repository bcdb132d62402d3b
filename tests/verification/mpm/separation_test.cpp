// Stress-free separation of torn-off Mohr-Coulomb particles (mpm/core/materials.hpp MohrCoulomb::separated;
// Dunatunga & Kamrin 2015, J. Fluid Mech. 779, section 2.2: a granular material below its critical density
// is disconnected and carries no stress). A block of the paper's soil is pulled apart uniformly by
// prescribed nodal velocities v = r (x - xc, y - yc) on every node, so each particle's volume grows as
// V / V0 = exp(2 r t) exactly (tr(grad v) = 2 r). Under isotropic extension the Mohr-Coulomb stress sits at
// the apex of its surface, an isotropic tension min(tension_cutoff, c cot phi) (here the 245 Pa of
// c cot phi, the cutoff of the paper's decks); once V / V0 exceeds the separation ratio the stress must be
// exactly zero, and its volume grows no further (the field keeps pulling to V / V0 = 4: a separated
// particle's volume once grew without bound, to inf and a NaN force on the tailings dam), and without
// separation (ratio 0, CB-Geo's behaviour) it stays at the apex and reaches V / V0 = 4. This is what
// let the paper's column on bilinear cells run away under USL + FLIP and USF + APIC (a torn particle's
// nodal force V sigma grad N grew with its volume, 100-2000x; docs/study/transfer_comparison.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "support/mpm_test_decks.hpp"

namespace {

using namespace mpm_test;

struct Extension {
  double ratio_first = 0;    ///< V / V0 of every particle at the check before the separation ratio
  double tension_first = 0;  ///< its largest |stress| component, Pa
  double ratio_last = 0;     ///< V / V0 at the end
  double stress_last = 0;    ///< the largest |stress| component of any particle at the end, Pa
};

Extension pull_apart(double separation_ratio) {
  constexpr double rho = 1925, phi = 22.2, c = 100, rate = 0.5, h = 1.0;
  mpm::MaterialSpec soil = mohr_coulomb(0, rho, 1e6, 0.23, phi, c, 0.0);
  soil.tension_cutoff = c / std::tan(phi * std::acos(-1.0) / 180.0);
  soil.separation_volume_ratio = separation_ratio;
  Deck deck;
  deck.grid = make_grid(-4, -4, h, 8, 8, CellType::Linear4);
  deck.materials.push_back(soil);
  fill_block(deck, -1, 1, -1, 1, 2, 0);
  for (int i = 0; i < deck.grid.nodes_per_axis[0]; ++i) {
    const double x = deck.grid.origin[0] + i * h;
    deck.velocity_constraints.push_back(
        {nodes_where(deck.grid, [&](double xn, double) { return std::abs(xn - x) < 1e-9; }), 0, rate * x});
    deck.velocity_constraints.push_back(
        {nodes_where(deck.grid, [&](double, double yn) { return std::abs(yn - x) < 1e-9; }), 1, rate * x});
  }
  deck.analysis.transfer = mpm::Transfer::PIC;
  deck.analysis.velocity_update = true;
  deck.analysis.dt = 1e-3;
  mpm::core::Simulation sim(deck, 1);
  Extension e;
  const auto largest_stress = [](const mpm::ParticleRecord& p) {
    return std::max({std::abs(p.stress_xx), std::abs(p.stress_yy), std::abs(p.stress_zz), std::abs(p.tau_xy)});
  };
  const double t_check = 0.9 * std::log(mpm::kDefaultSeparationVolumeRatio) / (2 * rate);
  const double t_end = std::log(4.0) / (2 * rate);  // V / V0 = 4
  bool checked = false;
  while (sim.time() < t_end - 1e-12) {
    sim.step();
    if (!checked && sim.time() >= t_check) {
      checked = true;
      for (const auto& p : sim.snapshot()) {
        e.ratio_first = std::max(e.ratio_first, p.volume * rho / p.mass);
        e.tension_first = std::max(e.tension_first, largest_stress(p));
      }
    }
  }
  for (const auto& p : sim.snapshot()) {
    e.ratio_last = p.volume * rho / p.mass;
    e.stress_last = std::max(e.stress_last, largest_stress(p));
  }
  std::printf("separation ratio %.1f: V/V0 %.3f with stress %.2f Pa, then V/V0 %.3f with stress %.3g Pa\n",
              separation_ratio, e.ratio_first, e.tension_first, e.ratio_last, e.stress_last);
  return e;
}

TEST(Separation, APulledApartParticleCarriesNoStressBeyondTheRatio) {
  const Extension e = pull_apart(mpm::kDefaultSeparationVolumeRatio);
  // held at the first step beyond the ratio (one step multiplies V by 1 + 2 r dt = 1.001), not the 4 V0 the
  // field pulls it to
  EXPECT_GT(e.ratio_last, mpm::kDefaultSeparationVolumeRatio);
  EXPECT_LT(e.ratio_last, mpm::kDefaultSeparationVolumeRatio * 1.0011);
  EXPECT_LT(e.ratio_first, mpm::kDefaultSeparationVolumeRatio);
  EXPECT_NEAR(e.tension_first, 100 / std::tan(22.2 * std::acos(-1.0) / 180.0), 1.0);  // at the apex
  EXPECT_EQ(e.stress_last, 0.0);
}

TEST(Separation, WithoutItThePulledApartParticleStaysAtTheApex) {
  const Extension e = pull_apart(0.0);
  // V / V0 = exp(2 r t) (the stepwise product of 1 + 2 r dt, to 1e-3 over these steps)
  EXPECT_NEAR(e.ratio_last, 4.0, 4e-3);
  EXPECT_NEAR(e.stress_last, 100 / std::tan(22.2 * std::acos(-1.0) / 180.0), 1.0);
}

}  // namespace
