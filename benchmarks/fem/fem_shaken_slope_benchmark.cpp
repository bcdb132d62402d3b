// Benchmark (not a test): a 2D slope on a foundation (125 x 40 = 5000 SSPquads, MohrCoulomb) shaken through a
// compliant base (Lysmer-Kuhlemeyer dashpot + Joyner-Chen force from a synthetic velocity record) at
// dt = 0.005 s, the model of benchmarks/fem/shaken_slope.tcl, run through fem_tcl's interpreter.
// Prints the wall time of the gravity stage and of the shaking, ms per step, iterations per step and the
// extrapolation to 20 s of shaking (4000 steps) when a shorter duration is run.
// Usage: fem_shaken_slope_benchmark [seconds of shaking = 20] [nx = 125] [ny = 40]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fem_tcl/tcl/interpreter.hpp"

int main(int argc, char** argv) {
  const double tend = argc > 1 ? std::atof(argv[1]) : 20.0;
  const int nx = argc > 2 ? std::atoi(argv[2]) : 125;
  const int ny = argc > 3 ? std::atoi(argv[3]) : 40;
  const double dt = 0.005;
  const int steps = static_cast<int>(tend / dt + 0.5);
  fem::tcl::Interpreter interp;
  std::string message;
  char head[160];
  std::snprintf(head, sizeof head, "set nx %d; set ny %d; set dt %g; set tend %g\n", nx, ny, dt, tend);
  const auto t0 = std::chrono::steady_clock::now();
  if (!interp.eval_script(std::string(head) + "source " GEOFLOW_SOURCE_DIR "/benchmarks/fem/shaken_slope.tcl",
                          "benchmark", message)) {
    std::fprintf(stderr, "%s\n", message.c_str());
    return 1;
  }
  const auto t1 = std::chrono::steady_clock::now();
  if (!interp.eval_script("set ok [analyze " + std::to_string(steps) + " " + std::to_string(dt) + "]", "benchmark",
                          message)) {
    std::fprintf(stderr, "%s\n", message.c_str());
    return 1;
  }
  const int failed = interp.eval("set ok") != "0";
  const auto t2 = std::chrono::steady_clock::now();
  const double build_s = std::chrono::duration<double>(t1 - t0).count();
  const double shake_s = std::chrono::duration<double>(t2 - t1).count();
  const auto& stats = interp.context().analysis->stats();
  const double ms_per_step = 1e3 * shake_s / steps;
  std::printf("fem_tcl shaken slope: %d x %d SSPquads (%zu elements incl. the dashpot), dt = %g s, %d steps (%g s)\n",
              nx, ny, interp.context().domain.elements().size(), dt, steps, tend);
  std::printf("model + gravity: %.2f s; shaking: %.2f s wall = %.2f ms per step (target ~10 ms), %.2f iterations per "
              "step, %ld factorizations\n",
              build_s, shake_s, ms_per_step, static_cast<double>(stats.iterations) / stats.steps, stats.factorizations);
  std::printf("20 s of shaking (4000 steps) at this rate: %.1f s; crest displacement at the end: %s m\n",
              4000 * ms_per_step / 1e3, interp.eval("nodeDisp [expr {" + std::to_string(ny) + "*(" +
                                                    std::to_string(nx) + " + 1) + 1}] 1").c_str());
  if (failed) std::printf("analyze returned %s before the end\n", interp.eval("set ok").c_str());
  return failed;
}
