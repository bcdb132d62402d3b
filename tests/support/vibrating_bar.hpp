#pragma once
// The 1D vibrating bar in its first mode (Sulsky, Zhou & Schreyer 1995, CPC 87; Bardenhagen 2002,
// JCP 180), shared by the verification tests: a bar of length L fixed at x = 0 and free at x = L,
// E = 100, rho = 1, starting with v(x, 0) = v0 sin(beta x), beta = pi / (2L). The exact solution
// v(x, t) = v0 sin(beta x) cos(omega t), omega = beta sqrt(E / rho), gives the centre-of-mass velocity
// v_cm(t) = (2 v0 / pi) cos(omega t). Modelled as a strip one cell high with nu = 0 and y-velocities
// fixed (uniaxial strain = uniaxial stress at nu = 0).
#include <algorithm>
#include <cmath>

#include "support/mpm_test_decks.hpp"

namespace mpm_test {

struct VibratingBar {
  static constexpr double kL = 25.0, kE = 100.0, kRho = 1.0, kV0 = 0.01;  // end displacement 0.016 m < h / 4
  static double beta() { return std::acos(-1.0) / (2 * kL); }
  static double omega() { return beta() * std::sqrt(kE / kRho); }
  static double period() { return 2 * std::acos(-1.0) / omega(); }

  /// The bar on `cells` cells (2 x 2 particles per cell), CFL 0.2; the caller may change the analysis.
  static Deck deck(int cells, mpm::Scheme scheme, CellType type) {
    const double h = kL / cells;
    Deck d;
    d.grid = make_grid(0, 0, h, cells + 2, 1, type);
    d.materials.push_back(elastic(0, kRho, kE, 0.0));
    fill_block(d, 0, kL, 0, h, 2, 0);
    for (auto& p : d.particles) p.velocity_x = kV0 * std::sin(beta() * p.coord_x);
    d.velocity_constraints.push_back({nodes_where(d.grid, [](double x, double) { return x <= 1e-9; }), 0, 0.0});
    d.velocity_constraints.push_back({nodes_where(d.grid, [](double, double) { return true; }), 1, 0.0});
    d.analysis.scheme = scheme;
    d.analysis.cfl = 0.2;
    d.analysis.dt = 1.0;
    d.analysis.locate_particles = true;
    return d;
  }

  struct Errors {
    double period = 0;     ///< |T_measured - T| / T
    double amplitude = 0;  ///< |min v_cm over the first period + 2 v0 / pi| / (2 v0 / pi)
    double amplitude_end = 0;  ///< v_cm at the last maximum (about 1 period) / (2 v0 / pi): 1 without damping
  };

  /// Runs `deck` (initial amplitude v0) for 1.1 periods on one thread; the period from the zero crossings of v_cm at T/4 and
  /// 3T/4 (linear interpolation), the amplitude from its minimum and from its last maximum.
  static Errors run(const Deck& deck, double v0 = kV0) {
    mpm::core::Simulation sim(deck, 1);
    double prev = totals(sim.snapshot()).px;
    const double mass = totals(sim.snapshot()).mass;
    double t_zero1 = -1, t_zero2 = -1, vmin = 0, vmax_late = 0;
    while (sim.time() < 1.1 * period()) {
      sim.step();
      const double p = totals(sim.snapshot()).px;
      vmin = std::min(vmin, p / mass);
      if (sim.time() > 0.75 * period()) vmax_late = std::max(vmax_late, p / mass);
      const double t_cross = sim.time() - sim.dt() * p / (p - prev);
      if (prev > 0 && p <= 0 && t_zero1 < 0) t_zero1 = t_cross;
      if (prev < 0 && p >= 0 && t_zero2 < 0) t_zero2 = t_cross;
      prev = p;
    }
    Errors e;
    const double amplitude = 2 * v0 / std::acos(-1.0);
    e.period = std::abs(2 * (t_zero2 - t_zero1) - period()) / period();
    e.amplitude = std::abs(-vmin - amplitude) / amplitude;
    e.amplitude_end = vmax_late / amplitude;
    return e;
  }
};

}  // namespace mpm_test
