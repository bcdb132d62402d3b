// Benchmark (not a test): the FEM-only reference scene, scripts/column_collapse/column_collapse.tcl (50 m x 40 m
// column of 1 m SSPquads, elastic gravity, switch to Mohr-Coulomb phi 22.2, Newmark dt = 1e-3 s to t = 5 s;
// KrylovNewton on the elastic effective stiffness, factored once), run through fem_tcl's interpreter with
// `-on-inversion continue` so that every repeat runs the same 5000 steps. Prints, per repeat and as the median:
// wall time of the transient stage, ms per step, equilibrium iterations per step, cut steps, and the time at
// which the mesh first inverted (from the script's summary line and steps.csv).
// Usage: fem_collapse_benchmark [repeats=1] [tend=5.0] [extra script options..]
// Target (issue 3): the whole 5 s collapse under 30 s on this machine (OpenSees 3.8: about 5 minutes).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "fem_tcl/tcl/interpreter.hpp"

namespace {

namespace fs = std::filesystem;

struct Result {
  double wall_s = 0.0;  ///< the whole script (model, gravity, transient, output)
  long steps = 0;
  double iterations_per_step = 0.0;
  long cut_steps = 0;
};

Result run_once(const fs::path& out, const std::vector<std::string>& options) {
  fem::tcl::Interpreter interp;
  std::vector<std::string> args{out.string()};
  args.insert(args.end(), options.begin(), options.end());
  interp.set_arguments("column_collapse.tcl", args);
  const fs::path script = fs::path(GEOFLOW_SOURCE_DIR) / "scripts/column_collapse/column_collapse.tcl";
  std::string message;
  const auto t0 = std::chrono::steady_clock::now();
  if (!interp.eval_file(script.string(), message)) {
    std::cerr << "fem_collapse_benchmark: " << message << "\n";
    std::exit(1);
  }
  Result r;
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::ifstream in(out / "steps.csv");
  std::string line;
  std::getline(in, line);  // header
  long iterations = 0;
  while (std::getline(in, line)) {
    for (char& c : line) if (c == ',') c = ' ';
    std::istringstream ls(line);
    double t, dt;
    long it, level;
    if (!(ls >> t >> dt >> it >> level)) continue;
    ++r.steps;
    iterations += it;
    if (level > 0) ++r.cut_steps;
  }
  r.iterations_per_step = r.steps > 0 ? static_cast<double>(iterations) / r.steps : 0.0;
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 1;
  const std::string tend = argc > 2 ? argv[2] : "5.0";
  std::vector<std::string> options{"-tend", tend, "-on-inversion", "continue"};
  for (int i = 3; i < argc; ++i) options.emplace_back(argv[i]);
  const fs::path out = fs::temp_directory_path() / ("geoflow_fem_collapse_benchmark_" + std::to_string(::getpid()));
  std::vector<double> walls, ms_per_step;
  Result last;
  for (int k = 0; k < repeats; ++k) {
    fs::remove_all(out);
    last = run_once(out, options);
    walls.push_back(last.wall_s);
    ms_per_step.push_back(1e3 * last.wall_s / std::max(1L, last.steps));
    std::printf("repeat %d: %.2f s wall (script total), %ld steps, %.3f ms/step, %.2f iterations/step, %ld cut steps\n",
                k + 1, last.wall_s, last.steps, ms_per_step.back(), last.iterations_per_step, last.cut_steps);
  }
  std::sort(walls.begin(), walls.end());
  std::sort(ms_per_step.begin(), ms_per_step.end());
  std::printf("FEM-only column collapse 50 x 40 SSPquads to t = %s s: median %.2f s wall, %.3f ms/step, "
              "%.2f iterations/step, %ld cut steps (target < 30 s; OpenSees 3.8 about 300 s)\n",
              tend.c_str(), walls[walls.size() / 2], ms_per_step[ms_per_step.size() / 2], last.iterations_per_step,
              last.cut_steps);
  fs::remove_all(out);
  return 0;
}
