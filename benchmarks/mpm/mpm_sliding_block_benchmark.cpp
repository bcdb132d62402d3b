// The sliding block of issue 10 under every scheme, velocity transfer and cell type (not a test; prints
// a table). A 2 m x 1 m elastic block on a Coulomb base (mu 0.3) under gravity rotated 30 degrees:
// analytic a = g (sin 30 - mu cos 30) = 2.357 m/s2, d(t) = a t^2 / 2, v(t) = a t (rigid block, Coulomb
// friction). Prints the block's mean displacement and velocity at t_end, their errors, and the step
// of a numerical failure (runaway velocity) if one happens.
//
//   mpm_sliding_block_benchmark [t_end [E [h [ppd [cfl [mu [angle_deg [only]]]]]]]]
//   defaults:                    2      1e6 0.25 2   0.4  0.3  30
// `only` keeps the rows whose label ("ED2Q4/MUSL/FLIP") contains it.
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

const char* scheme_name(mpm::io::Scheme s) {
  return s == mpm::io::Scheme::USF ? "USF" : (s == mpm::io::Scheme::USL ? "USL" : "MUSL");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
    std::puts("usage: mpm_sliding_block_benchmark [t_end [E [h [ppd [cfl [mu [angle_deg [only]]]]]]]]");
    return 0;
  }
  const auto arg = [&](int i, double fallback) { return argc > i ? std::atof(argv[i]) : fallback; };
  const double t_end = arg(1, 2.0);
  SlidingBlockSpec spec;
  spec.E = arg(2, 1e6);
  spec.h = arg(3, 0.25);
  spec.ppd = static_cast<int>(arg(4, 2));
  const double cfl = arg(5, 0.4);
  spec.mu = arg(6, 0.3);
  spec.angle_deg = arg(7, 30.0);
  const std::string only = argc > 8 ? argv[8] : "";
  const double a = spec.angle_deg * std::acos(-1.0) / 180.0;
  const double acc = std::max(0.0, 9.81 * (std::sin(a) - spec.mu * std::cos(a)));
  const double d_exact = 0.5 * acc * t_end * t_end, v_exact = acc * t_end;
  spec.cells_x = static_cast<int>(std::ceil((spec.x0 + spec.width + d_exact + 2.0) / spec.h));
  std::printf("block %g x %g m, E %g Pa, h %g m, %d x %d particles per cell, CFL %g, mu %g, angle %g deg\n",
              spec.width, spec.height, spec.E, spec.h, spec.ppd, spec.ppd, cfl, spec.mu, spec.angle_deg);
  std::printf("analytic at t = %g s: d = %.4f m, v = %.4f m/s\n", t_end, d_exact, v_exact);
  std::printf("%-6s %-5s %-10s %10s %8s %10s %8s %8s\n", "cells", "scheme", "transfer", "d (m)", "d err%",
              "v (m/s)", "v err%", "wall s");
  struct Transfer {
    const char* name;
    bool pic;
    double blend;
  };
  for (auto type : {CellType::Linear4, CellType::Gimp16}) {
    for (auto scheme : {mpm::io::Scheme::USF, mpm::io::Scheme::USL, mpm::io::Scheme::MUSL}) {
      for (const Transfer tr : {Transfer{"FLIP", false, 0.0}, Transfer{"PIC", true, 0.0},
                                Transfer{"blend0.2", false, 0.2}}) {
        const std::string label = std::string(type == CellType::Linear4 ? "ED2Q4/" : "ED2Q16G/") +
                                  scheme_name(scheme) + "/" + tr.name;
        if (label.find(only) == std::string::npos) continue;
        spec.type = type;
        Deck deck = sliding_block(spec);
        deck.analysis.scheme = scheme;
        deck.analysis.velocity_update = tr.pic;
        deck.analysis.pic_blend = tr.blend;
        deck.analysis.cfl = cfl;
        deck.analysis.dt = 1.0;
        const auto t0 = std::chrono::steady_clock::now();
        mpm::core::Simulation sim(deck, 1);
        std::string failure;
        try {
          while (sim.time() < t_end - 1e-12) sim.step();
        } catch (const common::NumericalError& e) {
          failure = e.what();
        }
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const MeanMotion m = mean_motion(sim.snapshot());
        std::printf("%-6s %-5s %-10s %10.4f %8.2f %10.4f %8.2f %8.2f%s%s\n", type == CellType::Linear4 ? "ED2Q4" : "ED2Q16G",
                    scheme_name(scheme), tr.name, m.ux, 100 * (m.ux - d_exact) / std::max(d_exact, 1e-12), m.vx,
                    100 * (m.vx - v_exact) / std::max(v_exact, 1e-12), wall, failure.empty() ? "" : "  FAILED: ",
                    failure.c_str());
      }
    }
  }
  return 0;
}
