// Nanoseconds per particle stress update of the MPM materials (mpm/core/materials.hpp, materials_3d.hpp),
// plane strain beside 3D: linear elastic; Mohr-Coulomb with an elastic trial, a plastic return (face) at
// the peak strength (the peak return map), and a return in the softening range (a surface of the
// particle's own strength). Each iteration restores the particle's stress and state variables first (a
// copy of 13 doubles, in every variant). Google Benchmark: add --benchmark_repetitions=5
// --benchmark_report_aggregates_only=true for medians.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

#include "mpm/core/materials.hpp"
#include "mpm/core/materials_3d.hpp"
#include "support/mpm_softening_soil.hpp"

namespace {

using namespace mpm::core;

mpm::MaterialSpec spec() { return mpm_test::softening_soil(mpm::MaterialType::MohrCoulomb2D); }

enum class Case { Elastic, Plastic, Softened };

/// A plane stress (sxx, syy, szz, sxy) and an increment (dexx, deyy, dgxy) for `c`; 3D: the same rotated
/// out of the x-y plane about x by 0.4 rad (every shear component non-zero).
template <int dim>
void state_of(Case c, double* stress, double* dstrain) {
  const double s2[4] = {-2e4, -1.5e4, -1.8e4, 1e3};
  const double de2[3] = {-1e-6, 1e-6, c == Case::Elastic ? 2e-6 : 4e-3};
  if constexpr (dim == 2) {
    std::copy(s2, s2 + 4, stress);
    std::copy(de2, de2 + 3, dstrain);
  } else {
    const double co = std::cos(0.4), si = std::sin(0.4);
    // R = rotation about x: y' = c y - s z, z' = s y + c z; sigma' = R sigma R^T (sxz, syz of s2 zero).
    const double syy = s2[1], szz = s2[2], sxy = s2[3];
    stress[0] = s2[0];
    stress[1] = co * co * syy + si * si * szz;
    stress[2] = si * si * syy + co * co * szz;
    stress[3] = co * sxy;
    stress[4] = co * si * (syy - szz);
    stress[5] = si * sxy;
    const double eyy = de2[1], gxy = de2[2];  // ezz = 0; shears engineering
    dstrain[0] = de2[0];
    dstrain[1] = co * co * eyy;
    dstrain[2] = si * si * eyy;
    dstrain[3] = co * gxy;
    dstrain[4] = 2 * co * si * eyy;
    dstrain[5] = si * gxy;
  }
}

template <class Model, int dim>
void run(benchmark::State& state, Case c) {
  mpm::MaterialSpec s = spec();
  const Model m = Model::from(s);
  double stress0[6], dstrain[6], sv0[kStateVariables] = {};
  state_of<dim>(c, stress0, dstrain);
  m.initial_state(sv0);
  if (c == Case::Softened) sv0[6] = 0.03;
  double stress[6], sv[kStateVariables];
  for (auto _ : state) {
    std::copy(stress0, stress0 + 6, stress);
    std::copy(sv0, sv0 + kStateVariables, sv);
    benchmark::ClobberMemory();
    m.update(stress, dstrain, sv);
    benchmark::DoNotOptimize(stress);
    benchmark::DoNotOptimize(sv);
    benchmark::ClobberMemory();
  }
  if (Model::kStateCount > 0 && (c == Case::Elastic) != (sv[6] == sv0[6])) state.SkipWithError("unexpected path");
  state.SetItemsProcessed(state.iterations());
}

void BM_LinearElastic2D(benchmark::State& st) { run<LinearElastic, 2>(st, Case::Elastic); }
void BM_LinearElastic3D(benchmark::State& st) { run<LinearElastic3D, 3>(st, Case::Elastic); }
void BM_MohrCoulomb2D_Elastic(benchmark::State& st) { run<MohrCoulomb, 2>(st, Case::Elastic); }
void BM_MohrCoulomb3D_Elastic(benchmark::State& st) { run<MohrCoulomb3D, 3>(st, Case::Elastic); }
void BM_MohrCoulomb2D_Plastic(benchmark::State& st) { run<MohrCoulomb, 2>(st, Case::Plastic); }
void BM_MohrCoulomb3D_Plastic(benchmark::State& st) { run<MohrCoulomb3D, 3>(st, Case::Plastic); }
void BM_MohrCoulomb2D_Softened(benchmark::State& st) { run<MohrCoulomb, 2>(st, Case::Softened); }
void BM_MohrCoulomb3D_Softened(benchmark::State& st) { run<MohrCoulomb3D, 3>(st, Case::Softened); }

BENCHMARK(BM_LinearElastic2D);
BENCHMARK(BM_LinearElastic3D);
BENCHMARK(BM_MohrCoulomb2D_Elastic);
BENCHMARK(BM_MohrCoulomb3D_Elastic);
BENCHMARK(BM_MohrCoulomb2D_Plastic);
BENCHMARK(BM_MohrCoulomb3D_Plastic);
BENCHMARK(BM_MohrCoulomb2D_Softened);
BENCHMARK(BM_MohrCoulomb3D_Softened);

}  // namespace

BENCHMARK_MAIN();
