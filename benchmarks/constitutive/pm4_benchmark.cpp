// Cost of one PM4Sand or PM4Silt update (fem_tcl/materials/pm4sand.hpp, pm4silt.hpp): set_trial_strain +
// commit_state at one point, as an analysis step pays it per integration point. Built twice (CMakeLists.txt):
// pm4sand_benchmark with the golden DSS run's sand (Dr 0.35, G0 = 167 sqrt(46 Dr^2 + 2.5), hpo 0.45, phicv 30,
// nu 1/3; tests/data/reference_runs/opensees/up_dss_pm4sand), pm4silt_benchmark (GEOFLOW_PM4SILT defined) with
// the golden DSS run's silt (S_u = 0.25 sigma'vc, G_o 500, h_po 4, OpenSees' defaults otherwise; up_dss_pm4silt).
// Cases: the elastic stage (stage 0); the plastic stage in undrained cyclic simple shear from K0 consolidation at
// 100 kPa, in strain steps of 5e-6 (the golden runs': one modified-Euler step per update) and of 5e-5 (five 1e-5
// sub-increments per update, OpenSees' default scheme 5). Each benchmark iteration replays one cycle of +-0.1 %
// shear strain from the same consolidated state (a copy of it), so the state does not drift towards liquefaction
// over the run; figures are per update.
// Run: build/bin/pm4sand_benchmark (or pm4silt_benchmark) --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "fem_tcl/materials/pm4sand.hpp"
#include "fem_tcl/materials/pm4silt.hpp"

namespace {

using fem::materials::Vector3;

#ifdef GEOFLOW_PM4SILT
using Model = fem::materials::PM4Silt;

/// The golden DSS run's silt: `nDMaterial PM4Silt 1 0.0 0.25 500.0 4.0 1.7`, OpenSees' defaults otherwise.
Model golden() {
  fem::materials::PM4SiltParameters p;
  p.Su = 0.0;
  p.Su_Rat = 0.25;
  p.G0 = 500.0;
  p.hpo = 4.0;
  p.density = 1.7;
  return Model(1, p);
}
#else
using Model = fem::materials::PM4Sand;

/// The golden DSS run's sand: Dr 0.35, G0 = 167 sqrt(46 Dr^2 + 2.5), hpo 0.45, phicv 30, nu 1/3.
Model golden() {
  fem::materials::PM4SandParameters p;
  p.Dr = 0.35;
  p.G0 = 167.0 * std::sqrt(46.0 * 0.35 * 0.35 + 2.5);
  p.hpo = 0.45;
  p.density = 1.7;
  p.phi_cv = 30.0;
  p.nu = 1.0 / 3.0;
  return Model(1, p);
}
#endif

/// K0 consolidation under 100 kPa in stage 0 (exx = 0), then `stage` (1: FirstCall as scripts do).
Model consolidated(int stage, Vector3& strain) {
  Model m = golden();
  const double G = m.parameters().G0 * m.parameters().P_atm;
  const double K = 2.0 / 3.0 * (1.0 + m.parameters().nu) / (1.0 - 2.0 * m.parameters().nu) * G;
  strain = Vector3(0.0, -100.0 / (K + 4.0 / 3.0 * G), 0.0);
  m.set_trial_strain(strain);
  m.commit_state();
  if (stage == 1) {
    m.update_stage(1);
    m.set_parameter("FirstCall", 0.0);
  }
  return m;
}

/// One cycle 0 -> +amplitude -> -amplitude -> 0 of shear strain at constant exx, eyy, in steps of `step`.
std::vector<Vector3> cycle(const Vector3& start, double amplitude, double step) {
  std::vector<Vector3> path;
  double g = 0.0;
  for (double target : {amplitude, -amplitude, 0.0}) {
    const int n = static_cast<int>(std::round(std::abs(target - g) / step));
    const double from = g;
    for (int i = 1; i <= n; ++i) path.push_back(start + Vector3(0.0, 0.0, from + (target - from) * i / n));
    g = target;
  }
  return path;
}

void run(benchmark::State& state, int stage, double step) {
  Vector3 start;
  const Model initial = consolidated(stage, start);
  const std::vector<Vector3> path = cycle(start, 1e-3, step);
  double tau = 0.0;
  for (auto _ : state) {
    Model m = initial;
    for (const Vector3& e : path) {
      m.set_trial_strain(e);
      m.commit_state();
    }
    tau = m.stress()[2];
    benchmark::DoNotOptimize(tau);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(path.size()));
  state.counters["ns_per_update"] = benchmark::Counter(static_cast<double>(state.iterations() * path.size()),
                                                       benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

}  // namespace

int main(int argc, char** argv) {
  // BM_PM4SandElasticStage, BM_PM4SandPlasticCyclicShear5e6, ... (BM_PM4Silt... in pm4silt_benchmark).
  const std::string prefix = "BM_" + golden().type_name();
  benchmark::RegisterBenchmark((prefix + "ElasticStage").c_str(), run, 0, 5e-6)->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark((prefix + "PlasticCyclicShear5e6").c_str(), run, 1, 5e-6)->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark((prefix + "PlasticCyclicShear5e5").c_str(), run, 1, 5e-5)->Unit(benchmark::kMicrosecond);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
