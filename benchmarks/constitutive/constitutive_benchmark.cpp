// Cost of one plane-strain Mohr-Coulomb stress update (constitutive::mohr_coulomb_update) per return region,
// and of the consistent tangent: what the MPM engine pays per particle per step; the *Precomputed variants
// pass a MohrCoulombSurface (sin / cos evaluated once, as the MPM material does). Figures printed by Google
// Benchmark (use --benchmark_repetitions=N --benchmark_report_aggregates_only=true for medians).
// The *3D variants: the general-stress return (mohr_coulomb_3d.hpp) through a MohrCoulombReturnMap, as a 3D
// MPM material would hold it, beside the plane-strain return through the same map (*Map): what the full 3x3
// eigenproblem costs (issue 37's 3D engine budget: ~330 ns per particle-step at 3 M particle-steps/s).
#include <benchmark/benchmark.h>

#include <cmath>

#include "constitutive/mohr_coulomb.hpp"
#include "constitutive/mohr_coulomb_3d.hpp"

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

const MohrCoulombReturnMap& return_map() {
  static const MohrCoulombReturnMap map(kElastic, kSurface);
  return map;
}

/// The plane-strain trial through the return map (what mpm's MohrCoulomb2D does per particle).
void run_map(benchmark::State& state, const PlaneStrainStress& trial, ReturnRegion expected) {
  if (return_map().apply(trial).region != expected) {
    state.SkipWithError("unexpected return region");
    return;
  }
  for (auto _ : state) {
    const MohrCoulombUpdate u = return_map().apply(trial);
    benchmark::DoNotOptimize(u);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations());
}

/// The same stress as a general 3D stress, rotated out of the x-y plane (every shear non-zero).
void run_3d(benchmark::State& state, const PlaneStrainStress& plane, ReturnRegion expected) {
  const double c = std::cos(0.4), s = std::sin(0.4);  // a rotation about x
  Eigen::Matrix3d r;
  r << 1, 0, 0, 0, c, -s, 0, s, c;
  Eigen::Matrix3d m;
  m << plane[0], plane[3], 0, plane[3], plane[1], 0, 0, 0, plane[2];
  m = r * m * r.transpose();
  Stress6 trial;
  trial << m(0, 0), m(1, 1), m(2, 2), m(0, 1), m(1, 2), m(0, 2);
  if (mohr_coulomb_return_3d(trial, return_map()).region != expected) {
    state.SkipWithError("unexpected return region");
    return;
  }
  for (auto _ : state) {
    const MohrCoulombUpdate3D u = mohr_coulomb_return_3d(trial, return_map());
    benchmark::DoNotOptimize(u);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_ElasticMap(benchmark::State& st) { run_map(st, rotated(-100e3, -120e3, -90e3, 0.3), ReturnRegion::Elastic); }
void BM_FaceMap(benchmark::State& st) { run_map(st, rotated(-20e3, -400e3, -200e3, 0.3), ReturnRegion::Face); }
void BM_EdgeTCMap(benchmark::State& st) {
  run_map(st, rotated(-20e3, -400e3, -25e3, 0.3), ReturnRegion::EdgeTriaxialCompression);
}
void BM_Elastic3D(benchmark::State& st) { run_3d(st, rotated(-100e3, -120e3, -90e3, 0.3), ReturnRegion::Elastic); }
void BM_Face3D(benchmark::State& st) { run_3d(st, rotated(-20e3, -400e3, -200e3, 0.3), ReturnRegion::Face); }
void BM_EdgeTC3D(benchmark::State& st) {
  run_3d(st, rotated(-20e3, -400e3, -25e3, 0.3), ReturnRegion::EdgeTriaxialCompression);
}

BENCHMARK(BM_Elastic);
BENCHMARK(BM_ElasticPrecomputed);
BENCHMARK(BM_Face);
BENCHMARK(BM_FacePrecomputed);
BENCHMARK(BM_EdgeTC);
BENCHMARK(BM_Apex);
BENCHMARK(BM_Tangent);
BENCHMARK(BM_ElasticMap);
BENCHMARK(BM_FaceMap);
BENCHMARK(BM_EdgeTCMap);
BENCHMARK(BM_Elastic3D);
BENCHMARK(BM_Face3D);
BENCHMARK(BM_EdgeTC3D);

}  // namespace

BENCHMARK_MAIN();
