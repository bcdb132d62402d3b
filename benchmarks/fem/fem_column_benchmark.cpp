// Benchmark (not a test): the reference scene's elastic column (50 m x 40 m, SSPquad, E = 172 MPa, nu = 0.23,
// rho = 1925 kg/m3), static gravity, then Newmark (0.5, 0.25) steps of dt = 1e-3 s, run through fem_tcl's
// interpreter. Prints the median over repeats of the first transient step (it holds the one numeric
// factorization), milliseconds per following step and per equilibrium iteration, and how the time per step
// grows from 10 x 8 to 200 x 160 elements. `factors` counts numeric factorizations of the transient analysis.
// Usage: fem_column_benchmark [repeats=3]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "fem_tcl/tcl/interpreter.hpp"

namespace {

struct Result {
  double first_step_ms;  ///< includes the transient system's one numeric factorization
  double ms_per_step;    ///< the following steps
  double ms_per_iteration;
  double iterations_per_step;
  long factorizations;
};

std::string model_script(int nx, int ny, const std::string& algorithm, const std::string& system) {
  char head[256];
  std::snprintf(head, sizeof head, "set nx %d; set ny %d; set alg %s; set sys %s\n", nx, ny, algorithm.c_str(),
                system.c_str());
  return std::string(head) + R"tcl(
model basic -ndm 2 -ndf 2
set dx [expr {50.0/$nx}]; set dy [expr {40.0/$ny}]
for {set j 0} {$j <= $ny} {incr j} {
  for {set i 0} {$i <= $nx} {incr i} { node [expr {$j*($nx+1)+$i+1}] [expr {$i*$dx}] [expr {$j*$dy}] }
}
fixY 0.0 1 1
fixX 0.0 1 0
nDMaterial ElasticIsotropic 1 172000.0 0.23 1.925
set e 0
for {set j 0} {$j < $ny} {incr j} {
  for {set i 0} {$i < $nx} {incr i} {
    incr e; set n1 [expr {$j*($nx+1)+$i+1}]
    element SSPquad $e $n1 [expr {$n1+1}] [expr {$n1+$nx+2}] [expr {$n1+$nx+1}] 1 PlaneStrain 1.0 0.0 [expr {-1.925*9.81}]
  }
}
constraints Transformation; numberer RCM; system $sys; test NormDispIncr 1e-10 20; algorithm Newton
integrator LoadControl 1.0; analysis Static
analyze 1
loadConst -time 0.0
wipeAnalysis
constraints Transformation; numberer RCM; system $sys; test NormDispIncr 1e-10 20; algorithm $alg
integrator Newmark 0.5 0.25; analysis Transient
)tcl";
}

Result run_once(int nx, int ny, const std::string& algorithm, const std::string& system, int steps) {
  fem::tcl::Interpreter interp;
  std::string message;
  if (!interp.eval_script(model_script(nx, ny, algorithm, system), "benchmark", message)) {
    std::fprintf(stderr, "%s\n", message.c_str());
    std::exit(1);
  }
  const auto analyze = [&](int n) {
    const auto t0 = std::chrono::steady_clock::now();
    if (!interp.eval_script("analyze " + std::to_string(n) + " 0.001", "benchmark", message)) {
      std::fprintf(stderr, "%s\n", message.c_str());
      std::exit(1);
    }
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  };
  const double first = analyze(1);
  const long iterations_first = interp.context().analysis->stats().iterations;
  const double ms = analyze(steps - 1);
  const auto& stats = interp.context().analysis->stats();
  const double iters = static_cast<double>(stats.iterations - iterations_first);
  return {first, ms / (steps - 1), ms / std::max(iters, 1.0), iters / (steps - 1), stats.factorizations};
}

Result median_of(int repeats, int nx, int ny, const std::string& algorithm, const std::string& system, int steps) {
  std::vector<Result> results;
  for (int r = 0; r < repeats; ++r) results.push_back(run_once(nx, ny, algorithm, system, steps));
  std::sort(results.begin(), results.end(), [](const Result& a, const Result& b) { return a.ms_per_step < b.ms_per_step; });
  return results[results.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
  std::printf("fem_tcl elastic column benchmark: gravity, then Newmark dt = 1e-3 s (median of %d repeats)\n", repeats);
  std::printf("%-10s %-14s %-12s %8s %12s %10s %12s %10s %8s\n", "mesh", "algorithm", "system", "steps",
              "1st step ms", "ms/step", "ms/iteration", "iter/step", "factors");
  struct Case { int nx, ny; const char* alg; const char* sys; int steps; };
  const Case cases[] = {
      {50, 40, "KrylovNewton", "BandGeneral", 1000}, {50, 40, "Newton", "BandGeneral", 1000},
      {50, 40, "Newton", "SparseSYM", 1000},         {50, 40, "Linear", "BandSPD", 1000},
      {10, 8, "KrylovNewton", "BandGeneral", 1000},  {25, 20, "KrylovNewton", "BandGeneral", 1000},
      {100, 80, "KrylovNewton", "BandGeneral", 200}, {200, 160, "KrylovNewton", "BandGeneral", 50},
      {200, 160, "Newton", "SparseSYM", 50},
  };
  for (const Case& c : cases) {
    const Result r = median_of(repeats, c.nx, c.ny, c.alg, c.sys, c.steps);
    char mesh[32];
    std::snprintf(mesh, sizeof mesh, "%dx%d", c.nx, c.ny);
    std::printf("%-10s %-14s %-12s %8d %12.3f %10.3f %12.3f %10.2f %8ld\n", mesh, c.alg, c.sys, c.steps,
                r.first_step_ms, r.ms_per_step, r.ms_per_iteration, r.iterations_per_step, r.factorizations);
    std::fflush(stdout);
  }
  return 0;
}
