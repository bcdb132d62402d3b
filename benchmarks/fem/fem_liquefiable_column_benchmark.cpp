// Benchmark (not a test): the effective-stress column of the golden OpenSees run up_liquefiable_column
// (tests/data/reference_runs/opensees/up_liquefiable_column/model.tcl: 20 SSPquadUP elements, PM4Sand loose
// over dense, 0.15 g sine, dt = 0.005 s) through fem_tcl's interpreter, its script unchanged but for the
// shaking's duration: 18 s + 2 s of free vibration = 20 s, 4000 steps (the benchmark).
// Prints the median over the repeats of the shaking's wall time per step and of the whole script, beside
// OpenSees 3.8's ~12 ms per step on the same script (README section 4 of the reference runs: 20.9 s for its
// 1,600 dynamic steps on the reference machine, this machine kind).
// Usage: fem_liquefiable_column_benchmark [repeats = 5] [seconds of shaking = 18]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "fem_tcl/tcl/interpreter.hpp"

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at == std::string::npos) {
    std::fprintf(stderr, "the reference script no longer contains '%s'\n", from.c_str());
    std::exit(1);
  }
  return text.replace(at, from.size(), to);
}

}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  const double shaking = argc > 2 ? std::atof(argv[2]) : 18.0;
  const std::filesystem::path script_path =
      GEOFLOW_SOURCE_DIR "/tests/data/reference_runs/opensees/up_liquefiable_column/model.tcl";
  std::ifstream in(script_path);
  std::stringstream ss;
  ss << in.rdbuf();
  std::string script = ss.str();
  script = replaced(script, "lassign {. 4 6 0.4 0.75 0.15 0.4 6}", "lassign {. 4 6 0.4 0.75 0.15 0.4 " + std::to_string(shaking) + "}");
  script = replaced(script, "set ok [analyze $n $dt]",
                    "set t0 [clock microseconds]; set ok [analyze $n $dt]; set shake_us [expr {[clock microseconds] - $t0}]");
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "geoflow_liquefiable_column_benchmark";
  std::filesystem::create_directories(dir);
  std::filesystem::current_path(dir);
  std::vector<double> per_step, total;
  long steps = 0;
  for (int r = 0; r < repeats; ++r) {
    fem::tcl::Interpreter interp;
    std::string message;
    const auto t0 = std::chrono::steady_clock::now();
    if (!interp.eval_script(script, "up_liquefiable_column", message)) {
      std::fprintf(stderr, "%s\n", message.c_str());
      return 1;
    }
    total.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    steps = std::atol(interp.eval("set n").c_str());
    per_step.push_back(std::atof(interp.eval("set shake_us").c_str()) * 1e-3 / static_cast<double>(steps));
    if (interp.eval("set ok") != "0") std::printf("repeat %d: analyze returned %s\n", r + 1, interp.eval("set ok").c_str());
  }
  std::filesystem::current_path(std::filesystem::temp_directory_path());
  std::filesystem::remove_all(dir);
  std::printf("fem_tcl, the golden liquefiable column shaken %.0f s + 2 s (%ld steps of 0.005 s), %d repeats:\n",
              shaking, steps, repeats);
  std::printf("  shaking: median %.3f ms per step (min %.3f, max %.3f); whole script median %.2f s\n", median(per_step),
              *std::min_element(per_step.begin(), per_step.end()), *std::max_element(per_step.begin(), per_step.end()),
              median(total));
  std::printf("  OpenSees 3.8 on the same script: ~12 ms per step (20.9 s for 1,600 steps + gravity); ratio %.1fx\n",
              12.0 / median(per_step));
  return 0;
}
