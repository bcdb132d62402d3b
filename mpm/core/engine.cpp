#include "mpm/core/engine.hpp"

#include <omp.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <type_traits>
#include <limits>

#include "common/cpu_variants.hpp"
#include "common/input_error.hpp"
#include "common/number_text.hpp"
#include "constitutive/mohr_coulomb.hpp"
#include "mpm/core/boundary_rules.hpp"
#include "mpm/core/nodal_constraints.hpp"
#include "mpm/core/shape_functions.hpp"
#include "mpm/core/stencil_kernels.hpp"

namespace mpm::core {

// The particle's sort key (engine_order.cpp), here for g2p to inline it.
std::int64_t Engine::cell_key(std::array<double, kDim> x) const {
  // Per axis the lattice coordinate s and the cell i: truncation, then the clamp, the same as floor + clamp
  // without the floor calls.
  double s[kDim];
  int i[kDim];
  for (int d = 0; d < kDim; ++d) {
    s[d] = (x[d] - grid_.origin[d]) * inv_h_[d];
    i[d] = std::clamp(static_cast<int>(s[d]), 0, cells_per_axis_[d] - 1);
  }
  std::int64_t cell = i[kDim - 1];  // axis 0 fastest: i + j cells_x in 2D
  for (int d = kDim - 2; d >= 0; --d) cell = cell * cells_per_axis_[d] + i[d];
  std::int64_t key = kKeysPerCell * cell;
  if (grid_.cell_type != CellType::Gimp16) return key;
  // uGIMP: the upper half of the cell on an axis has the next node as its nearest (GimpShape::nearest_node).
  for (int d = 0; d < kDim; ++d) key += (GimpShape::nearest_node(s[d]) > i[d] ? 1 : 0) << d;
  return key;
}

// ---------------------------------------------------------------------------------------------------
// The step
// ---------------------------------------------------------------------------------------------------
void Engine::step() {
  for (std::size_t c = 0; c < chunks_; ++c) problems_[c] = Problem{};
  const Vec2 b = body_force_.at(time());
  for (int d = 0; d < kDim; ++d) body_force_now_[d] = b[d];
  loads_.set_time(time());
  find_wall_contacts();
  merge_.start(chunks_, threads_);  // g2p_chunk records each chunk's kept particles and movers
  const bool gimp = grid_.cell_type == CellType::Gimp16;
#pragma omp parallel num_threads(threads_)
  {
    if (gimp)
      run_gimp_step();
    else
      run_linear_step();
  }
  throw_first_error();
  std::swap(cur_, nxt_);
  // The next buffer was written in iteration order: storage index k is the particle of iteration k.
  resort_particles();
  ++step_index_;
}

/// One explicit step; USF, USL and MUSL differ only in the order of the calls (CB-Geo
/// include/solvers/mpm_scheme/mpm_scheme_{usf,usl,musl}.tcc; Bardenhagen 2002 for USF/USL, Sulsky,
/// Zhou & Schreyer 1995 for MUSL). Runs inside one parallel region: particle phases run over chunks,
/// node phases over the rows of the active box; each phase first waits (barrier) for the one before,
/// except p2g of the mass, which starts every step.
template <class Shape>
void Engine::run_step() {
  switch (scheme_) {
    case Scheme::USF:  // update stress first: strain rate from the velocity of the mapped momentum
      p2g<Shape>(kMassMomentum);
      nodal_velocity(kMassMomentum);
      update_stress<Shape>(StrainFrom::NodalVelocity, AfterStress::MapForces);  // and p2g of the forces from it
      update_grid(kForces);
      g2p<Shape>(G2pAlso::Nothing);
      break;
    case Scheme::USL:  // update stress last: strain rate from the updated grid velocity
      p2g<Shape>(kAllFields);
      update_grid(kAllFields);
      g2p<Shape>(G2pAlso::StrainIncrements);
      update_stress<Shape>(StrainFrom::G2p, AfterStress::Nothing);
      break;
    case Scheme::MUSL:  // modified USL: strain rate from the remapped particle momentum
      p2g<Shape>(kAllFields);
      update_grid(kAllFields);
      g2p<Shape>(G2pAlso::RemapMomentum);
      nodal_velocity(kMomentum);
      update_stress<Shape>(StrainFrom::NodalVelocity, AfterStress::Nothing);
      break;
  }
}

// The step for each cell type, in a baseline and an AVX2 build (common/cpu_variants.hpp).
CPU_VARIANTS void Engine::run_gimp_step() { run_step<GimpShape>(); }
CPU_VARIANTS void Engine::run_linear_step() { run_step<LinearShape>(); }

template <class F>
void Engine::for_each_chunk(F&& f) {
#pragma omp for schedule(dynamic, 1) nowait
  for (std::size_t c = 0; c < chunks_; ++c) f(c);
}

template <class F>
void Engine::for_each_row(F&& f) {
  // The node rows of the active box (row_axes), the outermost axis slowest.
  if constexpr (kDim == 2) {
    // The rows j, written out for 2D: the loop over the outer axes below cost 1.1 M instructions more in
    // 20 steps of the profile (mpm_core_benchmark --profile usf flip 20 1; the flattened step's register
    // allocation: spills in the stress update and the stencil runs).
#pragma omp for schedule(static) nowait
    for (int j = box_lo_[1]; j < box_hi_[1]; ++j) f(j);
  } else {
    int rows = 1;
    for (int d = 1; d < kDim; ++d) rows *= box_hi_[d] - box_lo_[d];
#pragma omp for schedule(static) nowait
    for (int q = 0; q < rows; ++q) {
      int row = 0, stride = 1, rest = q;
      for (int d = 1; d < kDim - 1; ++d) {
        const int extent = box_hi_[d] - box_lo_[d];
        row += (box_lo_[d] + rest % extent) * stride;
        rest /= extent;
        stride *= nodes_per_axis_[d];
      }
      f(row + (box_lo_[kDim - 1] + rest) * stride);
    }
  }
}

/// Waits for every thread of the step's parallel region (called from inside it).
static inline void wait_for_previous_phase() {
#pragma omp barrier
}

template <class Shape>
void Engine::p2g(GridFields fields) {
  assert(fields.mass == fields.momentum);
  if (!fields.mass) wait_for_previous_phase();  // the mass is mapped first in every scheme
  const bool affine = transfer_.affine() && fields.momentum;
  for_each_chunk([&](std::size_t c) {
    if (affine)
      p2g_chunk<Shape, true>(c, fields);
    else
      p2g_chunk<Shape, false>(c, fields);
  });
}

void Engine::nodal_velocity(GridFields summed) {
  wait_for_previous_phase();
  for_each_row([&](int j) {
    reduce_row(j, summed);
    nodal_velocity_row(j);
  });
}

void Engine::update_grid(GridFields summed) {
  wait_for_previous_phase();
  for_each_row([&](int j) {
    reduce_row(j, summed);
    if (summed.momentum) nodal_velocity_row(j);
    integrate_row(j);
  });
}

template <class Shape>
void Engine::g2p(G2pAlso also) {
  wait_for_previous_phase();
  for_each_chunk([&](std::size_t c) {
    if (transfer_.affine())
      g2p_chunk<Shape, true>(c, also);
    else
      g2p_chunk<Shape, false>(c, also);
  });
}

double* Engine::cleared_band(std::size_t c) {
  double* g = pool_.data() + bands_[c].offset;
  std::fill_n(g, bands_[c].size(), 0.0);
  return g;
}

/// Particle-to-grid transfer (Sulsky et al. 1994, eqs. 14-17): nodal mass sum m N, momentum sum m N v,
/// force sum m N g - V grad(N) . sigma; with APIC (Affine) the momentum adds m N B_p D_p^-1 (x_i - x_p)
/// (MomentumContribution, velocity_transfer.hpp). The pass that maps the mass (the first of a step)
/// computes the particle's weights (once per step) and stores them for the later phases. Reads the
/// current particle state through order_, except the forces of USF, which use the stress and volume just
/// updated (next buffer).
template <class Shape, bool Affine>
void Engine::p2g_chunk(std::size_t c, GridFields fields) {
  constexpr int W = Shape::kWidth;
  double* g = cleared_band(c);
  const std::size_t row_stride = bands_[c].row_stride();
  const bool shape_functions = fields.mass, mass_momentum = fields.mass, forces = fields.forces;
  const bool forces_from_next = forces && !mass_momentum;
  const std::size_t k1 = chunk_[c + 1];
  for (std::size_t k = chunk_[c]; k < k1;) {
    const bool run = shape_functions ? evaluate_shape_functions<Shape, Affine>(c, k) : run_lane_[k] == 0;
    if (run) {
      scatter_run<W, Affine>(k, g, row_stride, mass_momentum, forces, forces_from_next);
      k += kRunLanes;
    } else {
      scatter_particle<Shape, Affine>(k, g, row_stride, mass_momentum, forces, forces_from_next);
      ++k;
    }
  }
}

// scatter_particle, evaluate_shape_functions, evaluate_run and scatter_run: engine_p2g.inl (end of file).

/// Sums the chunks' bands over node row j of the active box (row_axes) into `sums` (`values` per node,
/// kBandValues apart, from node box_lo_[0]), each node in chunk order: the same sums for any thread count.
/// A band that does not reach a node adds nothing to it, so skipping it changes no bit (a sum that starts
/// at +0 never becomes -0).
void Engine::sum_bands_of_row(int j, int values, double* sums) const {
  constexpr int outer = kDim - 1;  // the outermost axis, along which the chunks' bands ascend
  const std::array<int, kDim> at = row_axes(j);
  std::fill_n(sums, kBandValues * static_cast<std::size_t>(box_hi_[0] - box_lo_[0]), 0.0);
  for (std::size_t c = row_first_chunk_[static_cast<std::size_t>(at[outer])]; c < chunks_; ++c) {
    const Band& band = bands_[c];
    if (band.size() == 0 || at[outer] >= band.hi[outer]) continue;
    if (band.lo[outer] > at[outer]) break;  // bands are ordered along the outermost axis
    bool reaches = true;  // the axes between (3D: the row's j)
    for (int d = 1; d < outer; ++d) reaches = reaches && band.lo[d] <= at[d] && at[d] < band.hi[d];
    if (!reaches) continue;
    const double* row = pool_.data() + band.offset + band.row_of(at) * band.row_stride();
    double* s = sums + kBandValues * static_cast<std::size_t>(band.lo[0] - box_lo_[0]);
    for (int i = band.lo[0]; i < band.hi[0]; ++i, row += kBandValues, s += kBandValues)
      for (int f = 0; f < values; ++f) s[f] += row[f];
  }
}

/// The calling thread's scratch row for sum_bands_of_row.
double* Engine::thread_row_sums() {
  return &row_sums_[kBandValues * node_row_stride() * static_cast<std::size_t>(omp_get_thread_num())];
}

/// The grid fields of row j from the chunks' bands (sum_bands_of_row).
void Engine::reduce_row(int j, GridFields summed) {
  double* s = thread_row_sums();
  sum_bands_of_row(j, kBandValues, s);
  for (int i = box_lo_[0]; i < box_hi_[0]; ++i, s += kBandValues) {
    const std::size_t n = static_cast<std::size_t>(i) + static_cast<std::size_t>(j) * node_row_stride();
    if (summed.mass) mass_[n] = s[0];
    // Written out for 2D: a loop over the axes here took 0.15 M instructions more in 20 steps of the
    // profile (mpm_core_benchmark --profile usf flip 20 1).
    if constexpr (kDim == 2) {
      if (summed.momentum) {
        momentum_[kVectorStride * n] = s[1];
        momentum_[kVectorStride * n + 1] = s[2];
      }
      if (summed.forces) {
        force_[kVectorStride * n] = s[3];
        force_[kVectorStride * n + 1] = s[4];
      }
    } else {
      for (int d = 0; d < kDim; ++d) {
        if (summed.momentum) momentum_[kVectorStride * n + d] = s[1 + d];
        if (summed.forces) force_[kVectorStride * n + d] = s[1 + kDim + d];
      }
    }
  }
}

/// Nodal velocity = momentum / mass, then the velocity constraints (CB-Geo Node::compute_velocity) and no
/// approach into a wall (strain_rate_velocity, nodal_constraints.hpp).
void Engine::nodal_velocity_row(int j) {
  for (int i = box_lo_[0]; i < box_hi_[0]; ++i) {
    const std::size_t n = static_cast<std::size_t>(i) + static_cast<std::size_t>(j) * node_row_stride();
    Vector<kDim> v = Vector<kDim>::Zero();
    if (mass_[n] > mass_tolerance_)
      for (int d = 0; d < kDim; ++d) v[d] = momentum_[kVectorStride * n + d] / mass_[n];
    if (const std::int32_t c = constraint_of_[n]; c >= 0) v = strain_rate_velocity(v, constraint_now(c));
    for (int d = 0; d < kDim; ++d) velocity_[kVectorStride * n + d] = v[d];
  }
}

/// Explicit grid update (Sulsky et al. 1994, eq. 18), per axis d: a_d = f_d / m, f with the concentrated
/// nodal forces (external_loads.hpp), with Cundall's local damping f - alpha |f| sign(v) (Cundall 1987;
/// CB-Geo compute_acceleration_velocity_cundall; boundary_rules.hpp), v_new = v + a dt (a = b, the body
/// force per unit mass, below the small-mass cutoff); at a constrained node the friction and velocity
/// constraints in momentum form (nodal_constraints.hpp), and the rate (v_new - v_old) / dt handed to FLIP
/// in place of a. updated_ holds v_new, then a, kDim values each.
void Engine::integrate_row(int j) {
  for (int i = box_lo_[0]; i < box_hi_[0]; ++i) {
    const std::size_t n = static_cast<std::size_t>(i) + static_cast<std::size_t>(j) * node_row_stride();
    double* u = &updated_[kUpdatedStride * n];
    const double m = mass_[n];
    if (!(m > mass_tolerance_)) {
      std::fill_n(u, kUpdatedStride, 0.0);
      if (lagged_friction_ && constraint_of_[n] >= 0) normal_memory_[static_cast<std::size_t>(constraint_of_[n])].forget();
      continue;
    }
    Vector<kDim> v, f, a;
    for (int d = 0; d < kDim; ++d) {
      v[d] = velocity_[kVectorStride * n + d];
      f[d] = force_[kVectorStride * n + d];
    }
    if (loads_.has_nodal_forces()) {
      const Vec2 load = loads_.nodal_force(n);
      for (int d = 0; d < kDim; ++d) f[d] += load[d];
    }
    if (damping_ > 0.0) apply_cundall_damping(damping_, f, v);
    // Below the small-mass cutoff only the body force accelerates the node (see small_mass_).
    const bool small = m < small_mass_;
    for (int d = 0; d < kDim; ++d) a[d] = small ? body_force_now_[d] : f[d] / m;
    if (const std::int32_t c = constraint_of_[n]; c >= 0) {
      Vector<kDim> v_old;
      for (int d = 0; d < kDim; ++d) v_old[d] = momentum_[kVectorStride * n + d] / m;
      const NodeConstraint<kDim> now = constraint_now(c);
      NormalMemory& memory = normal_memory_[static_cast<std::size_t>(c)];
      if (now.friction_dir < 0) memory.forget();  // a contact the material does not touch
      const ConstrainedVelocity<kDim> r = constrained_velocity(v_old, a, dt_, now, &memory, m);
      for (int d = 0; d < kDim; ++d) {
        u[d] = r.velocity[d];
        u[kDim + d] = r.rate[d];
      }
    } else {
      for (int d = 0; d < kDim; ++d) {
        u[d] = v[d] + a[d] * dt_;
        u[kDim + d] = a[d];
      }
    }
  }
}

void Engine::report(std::size_t c, std::size_t k, ProblemKind kind, std::int64_t id, double a, double b) {
  Problem& pr = problems_[c];
  if (k < pr.k) pr = Problem{k, kind, id, a, b};
}

}  // namespace mpm::core

// p2g and g2p per particle and per stencil run (in this translation unit for the CPU variants to inline).
#include "mpm/core/engine_g2p.inl"
#include "mpm/core/engine_stress.inl"
#include "mpm/core/engine_p2g.inl"
