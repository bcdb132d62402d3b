// Throughput and accuracy of the MPM engine (not a test; prints figures).
//
//   mpm_core_benchmark [--quick | --throughput [steps [repeats]] | --scaling [repeats] | --checksum [steps] | --accuracy |
//                       --profile [scheme [transfer [steps [threads]]]] | --runout [threads [usl|musl|usf [pic_blend]]]]
//
// Figures are wall-clock medians; the CPU-time rate (particle-steps per CPU-second of all threads) is
// printed next to them because on a shared machine the wall clock also measures the other jobs.
// --runout runs the paper's column for the full 20 s at CFL 0.5 (stability and runout).
//
// 1. Particle-steps per second on the paper's column: 50 m x 40 m Mohr-Coulomb column (phi 22.2 deg,
//    c 1 Pa, psi 0, E 172 MPa, nu 0.23, rho 1925) in a 150 m x 45 m domain of 1 m uGIMP cells, 4 x 4
//    particles per cell (32,000), K0 initial stress, rough base (mu 0.4), USL and MUSL, FLIP and APIC, dt
//    at CFL 0.5. Median over repeats of a timed block of steps, at 1 and 2 threads; FLIP and APIC blocks
//    alternate, and their cost ratio is the median of the paired blocks' CPU-time ratios.
//    --scaling: the same column at 2, 1, 0.5, 0.25 and 0.125 m cells (8,000 to 2,048,000 particles), USF
//    FLIP, 1 and 2 threads: particle-steps per second and the growth of the cost per particle-step.
//    --profile scheme transfer steps threads: just `steps` steps of one configuration (for perf stat /
//    perf record: the difference of two step counts gives the instructions per particle-step).
//    --checksum: a hash of every particle's state after a few steps for each scheme, transfer and
//    thread count, and with the stencil runs off (what "bit-identical" is checked with before and after
//    a change of the kernels; every line of one scheme and transfer must agree).
// 2. Speed against error: the vibrating bar (period error vs the analytical mode) and the column's
//    runout at t = 2 s against the finest resolution run here, for a few resolutions.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstdint>
#include <cstring>
#include <ctime>
#include <fstream>
#include <string>
#include <vector>

#include "support/mpm_test_decks.hpp"

namespace {

using namespace mpm_test;
using Clock = std::chrono::steady_clock;

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

std::string load_average() {
  std::ifstream f("/proc/loadavg");
  std::string a;
  f >> a;
  return a;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

const char* scheme_name(mpm::Scheme s) {
  return s == mpm::Scheme::USL ? "USL" : (s == mpm::Scheme::MUSL ? "MUSL" : "USF");
}

/// The paper's column (see the file comment) at cell size h and ppd x ppd particles per cell.
Deck paper_column(double h, int ppd, mpm::Scheme scheme) {
  Deck deck;
  deck.grid = make_grid(0, 0, h, static_cast<int>(std::lround(150 / h)), static_cast<int>(std::lround(45 / h)),
                        CellType::Gimp16);
  deck.materials.push_back(mohr_coulomb(0, 1925, 172e6, 0.23, 22.2, 1.0, 0.0));
  fill_block(deck, 0, 50, 0, 40, ppd, 0);
  const double k0 = 1 - std::sin(22.2 * std::acos(-1.0) / 180);
  for (auto& p : deck.particles) {
    p.stress_yy = -1925 * 9.81 * (40 - p.coord_y);
    p.stress_xx = p.stress_zz = k0 * p.stress_yy;
  }
  const auto& g = deck.grid;
  deck.velocity_constraints.push_back({nodes_where(g, [](double x, double) { return x <= 1e-9; }), 0, 0.0});
  deck.velocity_constraints.push_back({nodes_where(g, [](double, double y) { return y <= 1e-9; }), 1, 0.0});
  deck.friction_constraints.push_back({nodes_where(g, [](double, double y) { return y <= 1e-9; }), 1, -1, 0.4});
  deck.analysis.scheme = scheme;
  deck.analysis.gravity = {0, -9.81};
  deck.analysis.cfl = 0.5;
  deck.analysis.dt = 1.0;  // upper bound; CFL decides
  return deck;
}

double runout_p98(const std::vector<mpm::ParticleRecord>& ps) {
  std::vector<double> x;
  for (const auto& p : ps) x.push_back(p.coord_x);
  std::sort(x.begin(), x.end());
  return x[static_cast<std::size_t>(0.98 * static_cast<double>(x.size() - 1))];
}

/// A timed block of `steps` steps: wall-clock and CPU-time rates in particle-steps per second.
std::pair<double, double> timed_block(mpm::core::Simulation& sim, int steps) {
  const auto t0 = Clock::now();
  const double c0 = cpu_seconds();
  for (int i = 0; i < steps; ++i) sim.step();
  const double s = std::chrono::duration<double>(Clock::now() - t0).count();
  const double c = cpu_seconds() - c0;
  const double work = static_cast<double>(sim.particle_count()) * steps;
  return {work / s, work / c};
}

void throughput(bool quick, int steps_arg = 0, int repeats_arg = 0) {
  std::printf("== Paper column throughput (32,000 uGIMP particles, Mohr-Coulomb, rough base, CFL 0.5): FLIP and "
              "APIC ==\n");
  const int steps = steps_arg > 0 ? steps_arg : (quick ? 50 : 200);
  const int repeats = repeats_arg > 0 ? repeats_arg : (quick ? 3 : 5);
  for (auto scheme : {mpm::Scheme::USF, mpm::Scheme::USL, mpm::Scheme::MUSL}) {
    for (int threads : {1, 2}) {
      // FLIP and APIC advance side by side, their timed blocks alternating, so both see the same load.
      Deck deck = paper_column(1.0, 4, scheme);
      mpm::core::Simulation flip(deck, threads);
      deck.analysis.transfer = mpm::Transfer::APIC;
      mpm::core::Simulation apic(deck, threads);
      for (int i = 0; i < 20; ++i) {  // warm-up (the column starts to move)
        flip.step();
        apic.step();
      }
      std::vector<double> rates[2], cpu_rates[2], ratios;
      for (int r = 0; r < repeats; ++r) {
        const auto f = timed_block(flip, steps), a = timed_block(apic, steps);
        rates[0].push_back(f.first);
        cpu_rates[0].push_back(f.second);
        rates[1].push_back(a.first);
        cpu_rates[1].push_back(a.second);
        ratios.push_back(f.second / a.second);  // cost per particle-step, APIC / FLIP (CPU time)
      }
      const char* name = scheme_name(scheme);
      for (int t = 0; t < 2; ++t)
        std::printf("%-4s %-4s threads %d: %6.2f M particle-steps/s wall (median of %d x %d steps; dt %.4g s); "
                    "%5.2f M per CPU-second; load average %s\n",
                    name, t == 0 ? "FLIP" : "APIC", threads, median(rates[t]) / 1e6, repeats, steps, flip.dt(),
                    median(cpu_rates[t]) / 1e6, load_average().c_str());
      std::printf("%-4s threads %d: APIC / FLIP cost per particle-step %.3f (median of %d paired blocks, CPU time)\n",
                  name, threads, median(ratios), repeats);
    }
  }
}

/// Growth of the cost per particle-step with the problem size: the column at finer cells (4 x 4
/// particles per cell), USF FLIP, 1 and 2 threads, median of `repeats` blocks of about 4 M particle-steps.
void scaling(int repeats) {
  std::printf("== Scaling: paper column, USF FLIP, 4 x 4 particles per cell, finer cells ==\n");
  std::printf("%8s %10s %7s %14s %14s %8s %10s\n", "h (m)", "particles", "steps", "1 thread M/s", "2 threads M/s",
              "2T / 1T", "ns/p-step");
  double ns_first = 0;
  for (double h : {2.0, 1.0, 0.5, 0.25, 0.125}) {
    const Deck deck = paper_column(h, 4, mpm::Scheme::USF);
    const int steps = std::max(2, static_cast<int>(4.0e6 / static_cast<double>(deck.particles.size())));
    double rate[2] = {0, 0};
    for (int threads : {1, 2}) {
      mpm::core::Simulation sim(deck, threads);
      for (int i = 0; i < 2; ++i) sim.step();
      std::vector<double> rates;
      for (int r = 0; r < repeats; ++r) rates.push_back(timed_block(sim, steps).first);
      rate[threads - 1] = median(rates);
    }
    const double ns = 1e9 / rate[0];
    if (ns_first == 0) ns_first = ns;
    std::printf("%8.3f %10zu %7d %14.2f %14.2f %8.2f %10.1f (x%.2f of the smallest); load average %s\n", h,
                deck.particles.size(), steps, rate[0] / 1e6, rate[1] / 1e6, rate[1] / rate[0], ns, ns / ns_first,
                load_average().c_str());
  }
}

/// `steps` steps of the column under one configuration, nothing else timed (for perf).
void profile(mpm::Scheme scheme, mpm::Transfer transfer, int steps, int threads) {
  Deck deck = paper_column(1.0, 4, scheme);
  deck.analysis.transfer = transfer;
  mpm::core::Simulation sim(deck, threads);
  const auto t0 = Clock::now();
  for (int i = 0; i < steps; ++i) sim.step();
  const double s = std::chrono::duration<double>(Clock::now() - t0).count();
  std::printf("%s %s, %d threads: %d steps of %zu particles, %.3f s, %.2f M particle-steps/s\n", scheme_name(scheme),
              transfer == mpm::Transfer::APIC ? "APIC" : "FLIP", threads, steps, sim.particle_count(), s,
              static_cast<double>(sim.particle_count()) * steps / s / 1e6);
}

/// FNV-1a over the bytes of every particle record (and APIC matrix) after `steps` steps.
std::uint64_t state_hash(const mpm::core::Simulation& sim) {
  std::uint64_t h = 1469598103934665603ull;
  const auto mix = [&](const void* data, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
  };
  for (const auto& r : sim.snapshot()) {
    const double v[] = {r.coord_x, r.coord_y, r.displacement_x, r.displacement_y, r.velocity_x, r.velocity_y,
                        r.stress_xx, r.stress_yy, r.stress_zz, r.tau_xy, r.strain_xx, r.strain_yy, r.gamma_xy,
                        r.epsilon_v, r.volume, r.mass};
    mix(&r.id, sizeof r.id);
    mix(v, sizeof v);
    mix(r.svars, r.nstate_vars * sizeof(double));
  }
  for (const auto& b : sim.affine_snapshot()) mix(b.data(), sizeof(double) * 4);
  return h;
}

/// The state hash of the paper column after `steps` steps for every scheme, transfer and thread count,
/// and on 1 thread with the stencil runs off (every particle through the one-particle kernels).
void checksum(int steps) {
  std::printf("== State hash of the paper column after %d steps (bit-identity check) ==\n", steps);
  struct Execution {
    int threads;
    bool stencil_runs;
  };
  for (auto scheme : {mpm::Scheme::USF, mpm::Scheme::USL, mpm::Scheme::MUSL})
    for (auto transfer : {mpm::Transfer::FLIP, mpm::Transfer::APIC})
      for (const Execution e : {Execution{1, true}, Execution{2, true}, Execution{1, false}}) {
        Deck deck = paper_column(1.0, 4, scheme);
        deck.analysis.transfer = transfer;
        mpm::core::Simulation sim(deck, e.threads, mpm::core::ExecutionOptions{e.stencil_runs});
        for (int i = 0; i < steps; ++i) sim.step();
        std::printf("%-4s %-4s threads %d%s: %016llx\n", scheme_name(scheme),
                    transfer == mpm::Transfer::APIC ? "APIC" : "FLIP", e.threads,
                    e.stencil_runs ? "" : ", no stencil runs", static_cast<unsigned long long>(state_hash(sim)));
      }
}

/// The vibrating bar's first mode (see tests/verification/mpm/vibrating_bar_test.cpp): returns the
/// relative period error of the centre-of-mass velocity.
double bar_period_error(int cells, int ppd, double& seconds) {
  const double L = 25.0, E = 100.0, rho = 1.0, v0 = 0.01;  // small: no particle crosses the free end's cell
  const double h = L / cells;
  Deck deck;
  deck.grid = make_grid(0, 0, h, cells + 1, 1, CellType::Linear4);
  deck.materials.push_back(elastic(0, rho, E, 0.0));
  fill_block(deck, 0, L, 0, h, ppd, 0);
  const double pi = std::acos(-1.0), beta = pi / (2 * L), omega = beta * std::sqrt(E / rho);
  for (auto& p : deck.particles) p.velocity_x = v0 * std::sin(beta * p.coord_x);
  deck.velocity_constraints.push_back({nodes_where(deck.grid, [](double x, double) { return x <= 1e-9; }), 0, 0.0});
  deck.velocity_constraints.push_back({nodes_where(deck.grid, [](double, double) { return true; }), 1, 0.0});
  deck.analysis.scheme = mpm::Scheme::MUSL;
  deck.analysis.cfl = 0.2;
  deck.analysis.dt = 1.0;
  mpm::core::Simulation sim(deck, 1);
  const double period = 2 * pi / omega;
  double prev = 1, t_zero1 = -1, t_zero2 = -1;
  const auto t0 = Clock::now();
  while (sim.time() < 1.1 * period) {
    sim.step();
    double p = 0;
    for (const auto& r : sim.snapshot()) p += r.mass * r.velocity_x;
    const double t_cross = sim.time() - sim.dt() * p / (p - prev);  // linear interpolation of the zero
    if (prev > 0 && p <= 0 && t_zero1 < 0) t_zero1 = t_cross;       // T / 4
    if (prev < 0 && p >= 0 && t_zero2 < 0) t_zero2 = t_cross;       // 3 T / 4
    prev = p;
  }
  seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return std::abs(2 * (t_zero2 - t_zero1) - period) / period;
}

void accuracy(bool quick) {
  std::printf("\n== Vibrating bar (MUSL, linear, 2 ppd, CFL 0.2): period error vs resolution ==\n");
  for (int cells : {12, 25, 50, 100}) {
    double s = 0;
    const double err = bar_period_error(cells, 2, s);
    std::printf("cells %4d: period error %.3e, %.3f s\n", cells, err, s);
  }
  std::printf("\n== Paper column runout at t = %s s (MUSL, 2 threads, 4 x 4 particles per cell) vs cell size ==\n", quick ? "0.5" : "2");
  const double t_end = quick ? 0.5 : 2.0;
  std::vector<std::pair<double, double>> results;
  for (double h : {2.0, 1.0, 0.5}) {
    if (quick && h < 1.0) continue;
    const Deck deck = paper_column(h, 4, mpm::Scheme::MUSL);
    mpm::core::Simulation sim(deck, 2);
    const auto t0 = Clock::now();
    while (sim.time() < t_end) sim.step();
    const double s = std::chrono::duration<double>(Clock::now() - t0).count();
    results.push_back({h, runout_p98(sim.snapshot())});
    std::printf("h %.2f m: %7zu particles, runout P98(x) %.4f m, %.2f s wall\n", h, sim.particle_count(),
                results.back().second, s);
  }
  const double ref = results.back().second;
  for (const auto& [h, r] : results)
    std::printf("h %.2f m: runout difference from the finest run %.4f m (%.2f %%)\n", h, r - ref,
                100 * (r - ref) / ref);
}

}  // namespace

/// The paper's full 20 s runout at CFL 0.5 on 2 threads: stability, runout and time.
void runout(int threads, mpm::Scheme scheme, double pic_blend) {
  std::printf("== Paper column, full 20 s runout (%s, FLIP with PIC blend %g, CFL 0.5, %d threads) ==\n",
              scheme_name(scheme), pic_blend,
              threads);
  Deck deck = paper_column(1.0, 4, scheme);
  deck.analysis.pic_blend = pic_blend;
  deck.analysis.locate_particles = false;  // the flow reaches the domain's end (x = 150 m): remove them
  mpm::core::Simulation sim(deck, threads);
  const auto t0 = Clock::now();
  double next = 0;
  while (sim.time() < 20.0) {
    sim.step();
    if (sim.time() >= next) {
      const auto ps = sim.snapshot();
      double vmax = 0, ymax = 0;
      for (const auto& p : ps) {
        vmax = std::max(vmax, std::hypot(p.velocity_x, p.velocity_y));
        ymax = std::max(ymax, p.coord_y);
      }
      std::printf("t %5.2f s: runout P98(x) %7.3f m, max y %6.3f m, max speed %6.3f m/s, %zu particles, %.1f s wall\n",
                  sim.time(), runout_p98(ps), ymax, vmax, ps.size(),
                  std::chrono::duration<double>(Clock::now() - t0).count());
      next += 2.0;
    }
  }
  std::printf("%lld steps of dt %.4g s in %.1f s wall\n", sim.step_index(), sim.dt(),
              std::chrono::duration<double>(Clock::now() - t0).count());
}

int main(int argc, char** argv) {
  const char* usage =
      "usage: mpm_core_benchmark [--quick | --throughput [steps [repeats]] | --scaling [repeats] | --checksum [steps] | "
      "--profile [usf|usl|musl [flip|apic [steps [threads]]]] | --accuracy | --runout [threads [usl|musl|usf [pic_blend]]]]\n";
  if (argc > 1 && std::strcmp(argv[1], "--quick") != 0 && std::strcmp(argv[1], "--throughput") != 0 &&
      std::strcmp(argv[1], "--accuracy") != 0 && std::strcmp(argv[1], "--runout") != 0 &&
      std::strcmp(argv[1], "--scaling") != 0 && std::strcmp(argv[1], "--checksum") != 0 &&
      std::strcmp(argv[1], "--profile") != 0) {
    const bool help = std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0;
    std::fputs(usage, help ? stdout : stderr);
    return help ? 0 : 2;
  }
  if (argc > 1 && std::strcmp(argv[1], "--runout") == 0) {
    const std::string scheme = argc > 3 ? argv[3] : "musl";
    runout(argc > 2 ? std::atoi(argv[2]) : 2,
           scheme == "usl" ? mpm::Scheme::USL : (scheme == "usf" ? mpm::Scheme::USF : mpm::Scheme::MUSL),
           argc > 4 ? std::atof(argv[4]) : 0.0);
    return 0;
  }
  if (argc > 1 && std::strcmp(argv[1], "--profile") == 0) {
    const std::string scheme = argc > 2 ? argv[2] : "usf", transfer = argc > 3 ? argv[3] : "flip";
    profile(scheme == "usl" ? mpm::Scheme::USL : (scheme == "musl" ? mpm::Scheme::MUSL : mpm::Scheme::USF),
            transfer == "apic" ? mpm::Transfer::APIC : mpm::Transfer::FLIP, argc > 4 ? std::atoi(argv[4]) : 200,
            argc > 5 ? std::atoi(argv[5]) : 1);
    return 0;
  }
  if (argc > 1 && std::strcmp(argv[1], "--scaling") == 0) {
    scaling(argc > 2 ? std::max(1, std::atoi(argv[2])) : 3);
    return 0;
  }
  if (argc > 1 && std::strcmp(argv[1], "--checksum") == 0) {
    checksum(argc > 2 ? std::max(1, std::atoi(argv[2])) : 40);
    return 0;
  }
  if (argc > 1 && std::strcmp(argv[1], "--accuracy") == 0) {
    accuracy(false);
    return 0;
  }
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const bool only_throughput = argc > 1 && std::strcmp(argv[1], "--throughput") == 0;
  throughput(quick, only_throughput && argc > 2 ? std::atoi(argv[2]) : 0,
             only_throughput && argc > 3 ? std::atoi(argv[3]) : 0);
  if (!(argc > 1 && std::strcmp(argv[1], "--throughput") == 0)) accuracy(quick);
  return 0;
}
