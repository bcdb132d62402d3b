// The sliding block of issue 10 under every scheme, velocity transfer and cell type (not a test; prints
// a table). A 2 m x 1 m elastic block on a Coulomb base (mu 0.3) under gravity rotated 30 degrees:
// analytic a = g (sin 30 - mu cos 30) = 2.357 m/s2, d(t) = a t^2 / 2, v(t) = a t (rigid block, Coulomb
// friction). Prints the block's mean displacement and velocity at t_end, their errors, and the step
// of a numerical failure (runaway velocity) if one happens.
//
//   mpm_sliding_block_benchmark [t_end [E [h [ppd [cfl [mu [angle_deg [only [nu [base [start [L [V*]]]]]]]]]]]]]
//   defaults:                    2      1e6 0.25 2   0.4  0.3  30             0.3 friction k0    0  0
// base "contact": the friction constraint alone (a one-sided frictional contact, fem2mpm's default base).
// start "slope": the block starts with the self-weight shear of a layer on the slope as well ("k0":
// the normal stresses only). L, V*: the base's normal_lag (slip distance m, reference speed m/s;
// mpm/core/lagged_friction.hpp); L = 0: instantaneous Coulomb friction (CB-Geo's).
// `only` keeps the rows whose label ("ED2Q4/MUSL/FLIP") contains it ("" for all).
//
//   mpm_sliding_block_benchmark --flutter [E [L V*]]
// The friction limit of each transfer: uGIMP, MUSL, gravity rotated 45 degrees, 2 s; for nu = 0, 0.1,
// 0.2, 0.3 and mu = 0.1 ... 0.8 whether d and v are within 3 % of Coulomb's rigid block, and the
// largest mu up to which every mu is (the flutter threshold; mpm/README.md "Friction and flutter").
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "common/input_error.hpp"
#include "support/mpm_test_decks.hpp"

namespace {

using namespace mpm_test;

const char* scheme_name(mpm::Scheme s) {
  return s == mpm::Scheme::USF ? "USF" : (s == mpm::Scheme::USL ? "USL" : "MUSL");
}

}  // namespace

struct Transfer {
  const char* name;
  mpm::Transfer kind;
  double blend;
};
constexpr Transfer kTransfers[] = {{"FLIP", mpm::Transfer::FLIP, 0.0},
                                   {"PIC", mpm::Transfer::PIC, 0.0},
                                   {"blend0.2", mpm::Transfer::FLIP, 0.2},
                                   {"APIC", mpm::Transfer::APIC, 0.0}};

/// Runs the block to t_end; the mean motion, or a failure message.
MeanMotion run(SlidingBlockSpec spec, mpm::Scheme scheme, const Transfer& tr, double cfl, double t_end,
               std::string& failure) {
  Deck deck = sliding_block(spec);
  deck.analysis.scheme = scheme;
  deck.analysis.transfer = tr.kind;
  deck.analysis.velocity_update = tr.kind == mpm::Transfer::PIC;
  deck.analysis.pic_blend = tr.blend;
  deck.analysis.cfl = cfl;
  deck.analysis.dt = 1.0;
  mpm::core::Simulation sim(deck, 1);
  try {
    while (sim.time() < t_end - 1e-12) sim.step();
  } catch (const common::NumericalError& e) {
    failure = e.what();
  }
  MeanMotion m = mean_motion(sim.snapshot());
  m.t = sim.time();
  return m;
}

double coulomb(const SlidingBlockSpec& s) {
  const double a = s.angle_deg * std::acos(-1.0) / 180.0;
  return std::max(0.0, 9.81 * (std::sin(a) - s.mu * std::cos(a)));
}

int flutter_table(double E, double lag_slip, double lag_speed) {
  std::printf("friction limit: uGIMP 0.25 m, MUSL, CFL 0.4, E %g Pa, gravity at 45 deg, 2 s, normal lag L %g m V* %g m/s; "
              "'+' = d and v within 3 %%\n", E, lag_slip, lag_speed);
  std::printf("%-9s %-4s  mu: 0.1 0.2 0.3 0.4 0.5 0.6 0.7 0.8   threshold\n", "transfer", "nu");
  for (const Transfer& tr : kTransfers) {
    if (tr.blend > 0.0) continue;
    for (double nu : {0.0, 0.1, 0.2, 0.3}) {
      std::printf("%-9s %-4g      ", tr.name, nu);
      double threshold = 0.0;
      bool all_so_far = true;
      for (int k = 1; k <= 8; ++k) {
        SlidingBlockSpec spec;
        spec.E = E;
        spec.nu = nu;
        spec.mu = 0.1 * k;
        spec.angle_deg = 45.0;
        spec.type = CellType::Gimp16;
        spec.lag_slip_distance = lag_slip;
        spec.lag_reference_velocity = lag_speed;
        const double a = coulomb(spec), t_end = 2.0;
        spec.cells_x = static_cast<int>(std::ceil((spec.x0 + spec.width + 0.5 * a * t_end * t_end + 2.0) / spec.h));
        std::string failure;
        const MeanMotion m = run(spec, mpm::Scheme::MUSL, tr, 0.4, t_end, failure);
        const double d = 0.5 * a * m.t * m.t, v = a * m.t;
        const bool ok = failure.empty() && std::abs(m.ux - d) <= 0.03 * d && std::abs(m.vx - v) <= 0.03 * v;
        std::printf(" %s  ", ok ? "+" : (failure.empty() ? "-" : "X"));
        std::fflush(stdout);
        if (ok && all_so_far) threshold = spec.mu;
        all_so_far = all_so_far && ok;
      }
      std::printf("  %.1f\n", threshold);
    }
  }
  return 0;
}

int main(int argc, char** argv) {
  if (argc > 1 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
    std::puts("usage: mpm_sliding_block_benchmark [t_end [E [h [ppd [cfl [mu [angle_deg [only [nu [base [start [L [V*]]]]]]]]]]]]]\n"
              "       base: friction (CB-Geo's bilateral base, default) or contact (one-sided frictional contact)\n"
              "       start: k0 (self-weight normal stresses, default) or slope (and the self-weight shear)\n"
              "       L, V*: the base's normal_lag (slip distance m, reference speed m/s; 0: none, the default)\n"
              "       mpm_sliding_block_benchmark --flutter [E [L V*]]");
    return 0;
  }
  const auto arg = [&](int i, double fallback) { return argc > i ? std::atof(argv[i]) : fallback; };
  if (argc > 1 && std::strcmp(argv[1], "--flutter") == 0) return flutter_table(arg(2, 1e7), arg(3, 0.0), arg(4, 0.0));
  const double t_end = arg(1, 2.0);
  SlidingBlockSpec spec;
  spec.E = arg(2, 1e6);
  spec.h = arg(3, 0.25);
  spec.ppd = static_cast<int>(arg(4, 2));
  const double cfl = arg(5, 0.4);
  spec.mu = arg(6, 0.3);
  spec.angle_deg = arg(7, 30.0);
  const std::string only = argc > 8 ? argv[8] : "";
  spec.nu = arg(9, 0.3);
  const std::string base = argc > 10 ? argv[10] : "friction";
  if (base != "friction" && base != "contact") {
    std::fprintf(stderr, "mpm_sliding_block_benchmark: error: base: expected friction or contact, got '%s'\n", base.c_str());
    return 2;
  }
  spec.one_sided = base == "contact";
  const std::string start = argc > 11 ? argv[11] : "k0";
  if (start != "k0" && start != "slope") {
    std::fprintf(stderr, "mpm_sliding_block_benchmark: error: start: expected k0 or slope, got '%s'\n", start.c_str());
    return 2;
  }
  spec.slope_start = start == "slope";
  spec.lag_slip_distance = arg(12, 0.0);
  spec.lag_reference_velocity = arg(13, 0.0);
  const double acc = coulomb(spec);
  const double d_exact = 0.5 * acc * t_end * t_end, v_exact = acc * t_end;
  spec.cells_x = static_cast<int>(std::ceil((spec.x0 + spec.width + d_exact + 2.0) / spec.h));
  std::printf("block %g x %g m, E %g Pa, nu %g, h %g m, %d x %d particles per cell, CFL %g, mu %g, angle %g deg, base %s, start %s, "
              "normal lag L %g m V* %g m/s\n",
              spec.width, spec.height, spec.E, spec.nu, spec.h, spec.ppd, spec.ppd, cfl, spec.mu, spec.angle_deg,
              base.c_str(), start.c_str(), spec.lag_slip_distance, spec.lag_reference_velocity);
  std::printf("analytic at t = %g s: d = %.4f m, v = %.4f m/s\n", t_end, d_exact, v_exact);
  std::printf("%-6s %-5s %-10s %10s %8s %10s %8s %8s\n", "cells", "scheme", "transfer", "d (m)", "d err%",
              "v (m/s)", "v err%", "wall s");
  for (auto type : {CellType::Linear4, CellType::Gimp16}) {
    for (auto scheme : {mpm::Scheme::USF, mpm::Scheme::USL, mpm::Scheme::MUSL}) {
      for (const Transfer& tr : kTransfers) {
        const std::string label = std::string(type == CellType::Linear4 ? "ED2Q4/" : "ED2Q16G/") +
                                  scheme_name(scheme) + "/" + tr.name;
        if (label.find(only) == std::string::npos) continue;
        spec.type = type;
        const auto t0 = std::chrono::steady_clock::now();
        std::string failure;
        const MeanMotion m = run(spec, scheme, tr, cfl, t_end, failure);
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::printf("%-6s %-5s %-10s %10.4f %8.2f %10.4f %8.2f %8.2f%s%s\n", type == CellType::Linear4 ? "ED2Q4" : "ED2Q16G",
                    scheme_name(scheme), tr.name, m.ux, 100 * (m.ux - d_exact) / std::max(d_exact, 1e-12), m.vx,
                    100 * (m.vx - v_exact) / std::max(v_exact, 1e-12), wall, failure.empty() ? "" : "  FAILED: ",
                    failure.c_str());
      }
    }
  }
  return 0;
}
