// Cost of one plane-strain Mohr-Coulomb stress update (constitutive::mohr_coulomb_update) per return region,
// and of the consistent tangent: what the MPM engine pays per particle per step; the *Precomputed variants
// pass a MohrCoulombSurface (sin / cos evaluated once, as the MPM material does). Figures printed by Google
// Benchmark (use --benchmark_repetitions=N --benchmark_report_aggregates_only=true for medians).
#include <benchmark/benchmark.h>

#include <cmath>

#include "constitutive/mohr_coulomb.hpp"

namespace {

using namespace constitutive;

const IsotropicElasticity kElastic = IsotropicElasticity::from_young_poisson(172e6, 0.23);
const MohrCoulombStrength kStrength{22.2 * M_PI / 180.0, 0.0, 10.0, 0.0};  // the paper's soil, cutoff at 0
const MohrCoulombSurface kSurface(kStrength);

PlaneStrainStress rotated(double a, double b, double szz, double alpha) {
  const double c = 0.5 * (a + b), r = 0.5 * (a - b);
  return {c + r * std::cos(2 * alpha), c - r * std::cos(2 * alpha), szz, r * std::sin(2 * alpha)};
}

/// `strength`: a MohrCoulombStrength (sin / cos on every call) or a MohrCoulombSurface (precomputed).
template <class Strength>
void run(benchmark::State& state, const PlaneStrainStress& s0, ReturnRegion expected, const Strength& strength) {
  const PlaneStrainStrain de(1e-9, -1e-9, 2e-9);
  if (mohr_coulomb_update(s0, de, kElastic, strength).region != expected) {
    state.SkipWithError("unexpected return region");
    return;
  }
  PlaneStrainStress s = s0;
  for (auto _ : state) {
    const MohrCoulombUpdate u = mohr_coulomb_update(s, de, kElastic, strength);
    benchmark::DoNotOptimize(u);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_Elastic(benchmark::State& st) { run(st, rotated(-100e3, -120e3, -90e3, 0.3), ReturnRegion::Elastic, kStrength); }
void BM_ElasticPrecomputed(benchmark::State& st) {
  run(st, rotated(-100e3, -120e3, -90e3, 0.3), ReturnRegion::Elastic, kSurface);
}
void BM_Face(benchmark::State& st) { run(st, rotated(-20e3, -400e3, -200e3, 0.3), ReturnRegion::Face, kStrength); }
void BM_FacePrecomputed(benchmark::State& st) {
  run(st, rotated(-20e3, -400e3, -200e3, 0.3), ReturnRegion::Face, kSurface);
}
void BM_EdgeTC(benchmark::State& st) {
  run(st, rotated(-20e3, -400e3, -25e3, 0.3), ReturnRegion::EdgeTriaxialCompression, kStrength);
}
void BM_Apex(benchmark::State& st) {
  const MohrCoulombStrength no_cutoff{kStrength.friction, 0.0, 10.0, INFINITY};
  PlaneStrainStress s = rotated(60e3, 40e3, 30e3, 0.3);
  for (auto _ : st) {
    const MohrCoulombUpdate u = mohr_coulomb_update(s, {1e-9, 0, 0}, kElastic, no_cutoff);
    benchmark::DoNotOptimize(u);
  }
  st.SetItemsProcessed(st.iterations());
}
void BM_Tangent(benchmark::State& st) {
  const PlaneStrainStress trial = rotated(-20e3, -400e3, -200e3, 0.3);
  for (auto _ : st) {
    const Eigen::Matrix3d t = mohr_coulomb_tangent(trial, kElastic, kStrength);
    benchmark::DoNotOptimize(t);
  }
  st.SetItemsProcessed(st.iterations());
}

BENCHMARK(BM_Elastic);
BENCHMARK(BM_ElasticPrecomputed);
BENCHMARK(BM_Face);
BENCHMARK(BM_FacePrecomputed);
BENCHMARK(BM_EdgeTC);
BENCHMARK(BM_Apex);
BENCHMARK(BM_Tangent);

}  // namespace

BENCHMARK_MAIN();
