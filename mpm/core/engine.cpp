#include "mpm/core/engine.hpp"

#include <omp.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <type_traits>
#include <limits>
#include <sstream>

#include "common/cpu_variants.hpp"
#include "common/input_error.hpp"
#include "common/number_text.hpp"
#include "constitutive/mohr_coulomb.hpp"
#include "mpm/core/boundary_rules.hpp"
#include "mpm/core/nodal_constraints.hpp"
#include "mpm/core/shape_functions.hpp"
#include "mpm/core/stencil_kernels.hpp"

namespace mpm::core {

namespace {
/// Nodes with less mass take no part in the grid update (CB-Geo's tolerance, include/node.tcc, in kg; see
/// Engine::mass_tolerance_ for decks in other mass units).
constexpr double kMassTolerance = 1.0e-15;
/// The small-mass cutoff as a fraction of a full node's mass rho hx hy (see Engine::small_mass_).
constexpr double kSmallMassFraction = 0.02;

/// A number quoted in an input error (10 significant digits, as the deck reader's).
std::string num(double v) { return common::number_text(v, 10); }
}  // namespace

void ParticleArrays::resize(std::size_t n) {
  id.resize(n);
  material.resize(n);
  for (auto* v : {&mass, &volume, &lx, &ly, &x, &y, &ux, &uy, &vx, &vy, &exx, &eyy, &gxy, &epsv})
    v->resize(n);
  stress.resize(4 * n);
  affine.resize(4 * n);
  svars.resize(n * kStateVariables);
  key.resize(n);
}

// ---------------------------------------------------------------------------------------------------
// Construction
// ---------------------------------------------------------------------------------------------------

Engine::Engine(const Deck& deck, int threads, ExecutionOptions options) : grid_(deck.grid) {
  const Analysis& an = deck.analysis;
  nx_ = grid_.nodes_x;
  ny_ = grid_.nodes_y;
  if (nx_ < 2 || ny_ < 2 || !(grid_.hx > 0) || !(grid_.hy > 0))
    throw common::InputError("mesh", "the node lattice needs at least 2 x 2 nodes and a positive cell size");
  cells_x_ = nx_ - 1;
  cells_y_ = ny_ - 1;
  inv_hx_ = 1.0 / grid_.hx;
  inv_hy_ = 1.0 / grid_.hy;
  nodes_ = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
  const bool gimp = grid_.cell_type == CellType::Gimp16;
  gimp_margin_ = gimp ? 1.0 : 0.0;
  // cell_keys computes in 32 bits: the largest key is below 4 x cells.
  keys_fit_int32_ = 4.0 * cells_x_ * cells_y_ <= std::numeric_limits<std::int32_t>::max();
  if (gimp) {
    // uGIMP reaches one node beyond the cell: the lattice must hold CB-Geo's halo ring around the region.
    const double tol = 1e-9;
    if (grid_.xmin - grid_.x0 < grid_.hx * (1 - tol) || grid_.ymin - grid_.y0 < grid_.hy * (1 - tol) ||
        grid_.x0 + (nx_ - 1) * grid_.hx - grid_.xmax < grid_.hx * (1 - tol) ||
        grid_.y0 + (ny_ - 1) * grid_.hy - grid_.ymax < grid_.hy * (1 - tol))
      throw common::InputError("mesh", "ED2Q16G cells need a ring of halo nodes around the cells that hold particles");
  }

  scheme_ = an.scheme;
  transfer_ = VelocityTransfer::from(an);
  stencil_runs_ = options.stencil_runs && common::wide_vector_kernels();
  locate_ = an.locate_particles;
  damping_ = an.cundall_damping;
  if (!(damping_ >= 0.0 && damping_ < 1.0))
    throw common::InputError("analysis.damping.damping_factor", "expected a number in [0, 1), got " + num(damping_));
  body_force_ = BodyForce{an.gravity, deck.base_acceleration};
  loads_ = ExternalLoads(deck, static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_));
  smoothing_ = parse_stress_smoothing(an.stress_smoothing);
  step_index_ = deck.first_step;
  threads_ = threads > 0 ? threads : omp_get_max_threads();
  // A thread beyond the number of particle chunks has no particle work and only joins the barriers of
  // every phase; on a loaded machine each barrier can then wait a scheduler time slice (the 256-particle
  // deposit of tests/verification/mpm/deposit_rest_test.cpp ran 0.34 s on 1 thread and 25 s on 2 while
  // the other core was busy). Results are the same for any thread count, so the count is capped.
  const std::size_t chunks_at_start = (deck.particles.size() + kChunkParticles - 1) / kChunkParticles;
  threads_ = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(std::max(threads_, 1)),
                                                    std::max<std::size_t>(chunks_at_start, 1)));

  // Materials, and the time step: dt from the deck, or cfl * h / c_p (c_p = sqrt((K + 4G/3) / rho)).
  if (deck.materials.empty()) throw common::InputError("materials", "no material defined");
  double max_wave_speed = 0.0;
  for (const auto& spec : deck.materials) {
    if (!(spec.density > 0)) throw common::InputError("materials", "material " + std::to_string(spec.id) + ": density must be > 0");
    materials_.push_back(Material::from(spec));
    max_wave_speed = std::max(max_wave_speed, std::sqrt(materials_.back().p_wave_modulus / spec.density));
  }
  dt_ = an.dt;
  if (an.cfl > 0) {
    const double auto_dt = an.cfl * std::min(grid_.hx, grid_.hy) / max_wave_speed;
    dt_ = (an.dt > 0) ? std::min(an.dt, auto_dt) : auto_dt;
  }
  if (!(dt_ > 0) || !std::isfinite(dt_)) throw common::InputError("analysis.dt", "expected a time step > 0");
  courant_number_ = dt_ * max_wave_speed / std::min(grid_.hx, grid_.hy);

  // Small-mass cutoff (on bilinear cells, where particles read unweighted gradients of the updated grid
  // velocity: USL's strain increment, APIC's C_p): a fraction of a full node of the lightest material.
  double lightest = std::numeric_limits<double>::infinity();
  for (const auto& spec : deck.materials) lightest = std::min(lightest, spec.density);
  const bool reads_updated_gradients = !gimp && (scheme_ == Scheme::USL || transfer_.affine());
  small_mass_ = reads_updated_gradients ? kSmallMassFraction * lightest * grid_.hx * grid_.hy : 0.0;
  // CB-Geo's absolute 1e-15, but never more than 1e-15 of a full node of the lightest material: a deck whose
  // densities are tiny numbers (other mass units) must not find every node empty and its body frozen.
  mass_tolerance_ = std::min(kMassTolerance, kMassTolerance * lightest * grid_.hx * grid_.hy);

  // Boundary conditions on nodes (CB-Geo: a later constraint on the same node and direction wins).
  constraint_of_.assign(nodes_, -1);
  const auto constraint_at = [&](int n) -> NodeConstraint& {
    if (constraint_of_[n] < 0) {
      constraint_of_[n] = static_cast<std::int32_t>(constraints_.size());
      constraints_.emplace_back();
    }
    return constraints_[static_cast<std::size_t>(constraint_of_[n])];
  };
  for (std::size_t i = 0; i < deck.velocity_constraints.size(); ++i) {
    const auto& c = deck.velocity_constraints[i];
    const std::string where = "velocity_constraints[" + std::to_string(i) + "]";
    if (c.dir < 0 || c.dir > 1) throw common::InputError(where, "dir must be 0 or 1, got " + std::to_string(c.dir));
    for (int n : c.nodes) {
      if (n < 0 || static_cast<std::size_t>(n) >= nodes_)
        throw common::InputError(where, "node " + std::to_string(n) + " is not in the mesh");
      NodeConstraint& nc = constraint_at(n);
      nc.fixed |= static_cast<std::uint8_t>(1u << c.dir);
      nc.fixed_velocity[c.dir] = c.velocity;
    }
  }
  for (std::size_t i = 0; i < deck.friction_constraints.size(); ++i) {
    const auto& c = deck.friction_constraints[i];
    const std::string where = "friction_constraints[" + std::to_string(i) + "]";
    if (c.dir < 0 || c.dir > 1) throw common::InputError(where, "dir must be 0 or 1, got " + std::to_string(c.dir));
    for (int n : c.nodes) {
      if (n < 0 || static_cast<std::size_t>(n) >= nodes_)
        throw common::InputError(where, "node " + std::to_string(n) + " is not in the mesh");
      NodeConstraint& nc = constraint_at(n);
      nc.friction_dir = c.dir;
      nc.sign_n = c.sign_n > 0 ? 1.0 : -1.0;
      nc.mu = c.friction;
      nc.lag = NormalLag{c.lag_slip_distance, c.lag_reference_velocity};
    }
    if (c.lag_slip_distance != 0.0 || c.lag_reference_velocity != 0.0) {
      if (!(c.lag_slip_distance > 0.0) || !std::isfinite(c.lag_slip_distance))
        throw common::InputError(where + ".normal_lag.slip_distance", "expected a finite slip distance > 0 (m)");
      if (!(c.lag_reference_velocity >= 0.0) || !std::isfinite(c.lag_reference_velocity))
        throw common::InputError(where + ".normal_lag.reference_velocity", "expected a finite speed >= 0 (m/s)");
      lagged_friction_ = true;
    }
  }
  normal_memory_.assign(constraints_.size(), NormalMemory{});
  restore_friction_memory(deck.friction_memory);
  set_up_wall_contacts();

  // Particles.
  const std::size_t n = deck.particles.size();
  cur_.resize(n);
  nxt_.resize(n);
  if (!deck.particle_affine.empty()) {
    if (deck.particle_affine.size() != n)
      throw common::InputError("particles", "the APIC matrices (" + std::to_string(deck.particle_affine.size()) +
                                                ") do not match the particles (" + std::to_string(n) + ")");
    if (transfer_.affine())
      for (std::size_t p = 0; p < n; ++p) std::copy_n(deck.particle_affine[p].data(), 4, &cur_.affine[4 * p]);
  }
  std::vector<std::uint32_t> per_cell(static_cast<std::size_t>(cells_x_) * cells_y_, 0);
  for (std::size_t p = 0; p < n; ++p) {
    const ParticleRecord& r = deck.particles[p];
    const std::string who = "particle " + std::to_string(r.id);
    if (!std::isfinite(r.coord_x) || !std::isfinite(r.coord_y) || r.coord_x < grid_.xmin || r.coord_x > grid_.xmax ||
        r.coord_y < grid_.ymin || r.coord_y > grid_.ymax)
      throw common::InputError(who, "at (" + num(r.coord_x) + ", " + num(r.coord_y) +
                                        ") is outside the mesh");
    std::size_t m = materials_.size();
    for (std::size_t i = 0; i < materials_.size(); ++i)
      if (materials_[i].id == r.material_id) m = i;
    if (m == materials_.size())
      throw common::InputError(who, "material_id " + std::to_string(r.material_id) + " is not defined");
    if (m != 0) uniform_material_ = false;
    cur_.id[p] = r.id;
    cur_.material[p] = static_cast<std::uint32_t>(m);
    cur_.x[p] = r.coord_x;
    cur_.y[p] = r.coord_y;
    cur_.key[p] = cell_key(r.coord_x, r.coord_y);
    ++per_cell[static_cast<std::size_t>(cell_of(cur_.key[p]))];
  }
  for (std::size_t p = 0; p < n; ++p) {
    const ParticleRecord& r = deck.particles[p];
    const Material& mat = materials_[cur_.material[p]];
    // CB-Geo defaults: volume = cell area / particles in the cell, mass = density * volume,
    // nsize = 2 / sqrt(particles in the cell) (2 / particles per direction). Each applies on its own
    // (a deck may give volumes, e.g. mesh.particles_volumes, but no sizes).
    const double count = per_cell[static_cast<std::size_t>(cell_of(cur_.key[p]))];
    cur_.volume[p] = r.volume > 0 ? r.volume : grid_.hx * grid_.hy / count;
    cur_.mass[p] = r.volume > 0 && r.mass > 0 ? r.mass : mat.density * cur_.volume[p];
    const bool sized = r.nsize_x > 0 && r.nsize_y > 0;
    const double nsize_x = sized ? r.nsize_x : 2.0 / std::sqrt(count);
    const double nsize_y = sized ? r.nsize_y : 2.0 / std::sqrt(count);
    if (gimp && !(nsize_x > 0 && nsize_x <= 2 && nsize_y > 0 && nsize_y <= 2))
      throw common::InputError("particle " + std::to_string(r.id), "nsize must be in (0, 2] for ED2Q16G cells");
    cur_.lx[p] = nsize_x / 4.0;
    cur_.ly[p] = nsize_y / 4.0;
    cur_.ux[p] = r.displacement_x;
    cur_.uy[p] = r.displacement_y;
    cur_.vx[p] = r.velocity_x;
    cur_.vy[p] = r.velocity_y;
    cur_.stress[4 * p] = r.stress_xx;
    cur_.stress[4 * p + 1] = r.stress_yy;
    cur_.stress[4 * p + 2] = r.stress_zz;
    cur_.stress[4 * p + 3] = r.tau_xy;
    cur_.exx[p] = r.strain_xx;
    cur_.eyy[p] = r.strain_yy;
    cur_.gxy[p] = r.gamma_xy;
    cur_.epsv[p] = r.epsilon_v;
    double* sv = &cur_.svars[p * kStateVariables];
    if (mat.state_count > 0 && r.nstate_vars == mat.state_count) {
      for (std::size_t i = 0; i < mat.state_count; ++i) sv[i] = r.svars[i];
    } else if (mat.type == MaterialType::MohrCoulomb2D) {
      mat.mohr_coulomb.initial_state(sv);
    }
  }
  if (loads_.has_tractions()) {
    cur_.traction_slot.resize(n);
    nxt_.traction_slot.resize(n);
    for (std::size_t p = 0; p < n; ++p) cur_.traction_slot[p] = loads_.traction_slot(cur_.id[p]);
  }

  // Scratch, sized once (no allocation per step).
  const int width = gimp ? GimpShape::kWidth : LinearShape::kWidth;
  base_.resize(n);
  weights_.resize(n * 4 * static_cast<std::size_t>(width));
  run_lane_.resize(n);
  dstrain_.resize(3 * n);
  if (transfer_.affine()) {
    stencil_offset_.resize(2 * n);
    affine_weights_.resize(n * 2 * static_cast<std::size_t>(width));
  }
  order_.reserve(n);
  sorted_.resize(n);
  bucket_.resize(4 * static_cast<std::size_t>(cells_x_) * cells_y_ + 1);
  const std::size_t max_chunks = n / kChunkParticles + 2;
  chunk_.resize(max_chunks + 1);
  bands_.resize(max_chunks);
  row_sums_.resize(static_cast<std::size_t>(threads_) * 5 * static_cast<std::size_t>(nx_));
  row_first_chunk_.resize(static_cast<std::size_t>(ny_));
  local_.resize(n);
  mass_.assign(nodes_, 0.0);
  momentum_.assign(2 * nodes_, 0.0);
  force_.assign(2 * nodes_, 0.0);
  velocity_.assign(2 * nodes_, 0.0);
  updated_.assign(4 * nodes_, 0.0);
  if (nodal_projection(smoothing_).values > 0) nodal_remedy_.assign(3 * nodes_, 0.0);
  problems_.resize(max_chunks);

  order_.resize(n);
  for (std::size_t p = 0; p < n; ++p) order_[p] = static_cast<std::uint32_t>(p);
  sort_particles();
}

std::int64_t Engine::cell_key(double x, double y) const {
  // Truncation, then the clamp below: the same as floor + clamp, without the floor calls.
  const double sx = (x - grid_.x0) * inv_hx_, sy = (y - grid_.y0) * inv_hy_;
  int i = static_cast<int>(sx);
  int j = static_cast<int>(sy);
  i = std::clamp(i, 0, cells_x_ - 1);
  j = std::clamp(j, 0, cells_y_ - 1);
  const std::int64_t cell = static_cast<std::int64_t>(i) + static_cast<std::int64_t>(j) * cells_x_;
  if (grid_.cell_type != CellType::Gimp16) return 4 * cell;
  // uGIMP: the upper half of the cell on an axis has the next node as its nearest (GimpShape::nearest_node).
  const int qx = GimpShape::nearest_node(sx) > i ? 1 : 0, qy = GimpShape::nearest_node(sy) > j ? 1 : 0;
  return 4 * cell + qx + 2 * qy;
}

// ---------------------------------------------------------------------------------------------------
// Sorting: order_ = live particles by (key, id), the key the cell and its stencil quadrant (cell_key).
// A counting sort by key of the previous order, then an insertion sort by id inside each key's run
// (nearly sorted already); after a step in which few particles changed key, a merge of those few into
// the rest (resort_particles, shared by the threads: order_merge.hpp). The result depends only on the
// particle state, so a resumed run iterates in the same order as the uninterrupted one.
// ---------------------------------------------------------------------------------------------------
void Engine::sort_particles() {
  std::fill(bucket_.begin(), bucket_.end(), 0u);
  // order_ holds the storage indices to sort, in their previous order (nearly sorted already).
  const std::size_t n_old = order_.size();
  for (std::size_t k = 0; k < n_old; ++k) {
    const std::int64_t key = cur_.key[order_[k]];
    if (key != kRemoved) ++bucket_[static_cast<std::size_t>(key) + 1];
  }
  for (std::size_t c = 0; c + 1 < bucket_.size(); ++c) bucket_[c + 1] += bucket_[c];
  const std::size_t n = bucket_.back();
  for (std::size_t k = 0; k < n_old; ++k) {
    const std::uint32_t p = order_[k];
    const std::int64_t key = cur_.key[p];
    if (key != kRemoved) sorted_[bucket_[static_cast<std::size_t>(key)]++] = p;
  }
  // bucket_[c] now holds the end of cell c; sort each cell's run by id.
  std::size_t start = 0;
  for (std::size_t c = 0; c + 1 < bucket_.size(); ++c) {
    const std::size_t end = bucket_[c];
    for (std::size_t a = start + 1; a < end; ++a) {
      const std::uint32_t p = sorted_[a];
      const std::int64_t id = cur_.id[p];
      std::size_t b = a;
      while (b > start && cur_.id[sorted_[b - 1]] > id) {
        sorted_[b] = sorted_[b - 1];
        --b;
      }
      sorted_[b] = p;
    }
    start = end;
  }
  order_.assign(sorted_.begin(), sorted_.begin() + static_cast<std::ptrdiff_t>(n));
  cut_chunks();
}

/// After a step, when few particles changed key: the particles that kept theirs are still in (key,
/// id) order along the previous order, so the new order is their sequence merged with the few others
/// sorted, in one pass instead of the counting sort. (key, id) is unique, so the order is the one
/// sort_particles() gives. g2p_chunk recorded which particles kept, changed or lost their key, per
/// chunk (merge_).
void Engine::resort_particles() {
  const std::size_t n_old = order_.size();  // the step's particles
  const std::size_t movers = merge_.collect_movers();  // recorded by g2p_chunk, chunk by chunk
  order_.resize(n_old);
  if (movers > n_old / 16) {  // many: the counting sort is cheaper than sorting them
    for (std::size_t k = 0; k < n_old; ++k) order_[k] = static_cast<std::uint32_t>(k);
    sort_particles();
    return;
  }
  const auto before = [&](std::uint32_t a, std::uint32_t b) {
    return cur_.key[a] != cur_.key[b] ? cur_.key[a] < cur_.key[b] : cur_.id[a] < cur_.id[b];
  };
  order_.resize(merge_.merge(order_.data(), [&](std::size_t k) { return cur_.key[k] == kRemoved; }, before));
  cut_chunks();
}

/// The chunks of the sorted particles (order_), each chunk's band and the active node box (their union).
void Engine::cut_chunks() {
  const std::size_t n = order_.size();
  // Chunks of about kChunkParticles particles, cut at cell boundaries. Their number and extent depend
  // only on the particle state (not on the thread count): threads take chunks dynamically, each chunk
  // scatters into its own band, and bands are summed in chunk order.
  chunks_ = n == 0 ? 0 : (n + kChunkParticles - 1) / kChunkParticles;
  chunk_[0] = 0;
  for (std::size_t c = 1; c < chunks_; ++c) {
    std::size_t k = std::max(chunk_[c - 1], n * c / chunks_);
    while (k > 0 && k < n && cell_of(cur_.key[order_[k]]) == cell_of(cur_.key[order_[k - 1]])) ++k;
    chunk_[c] = k;
  }
  chunk_[chunks_] = n;
  // Each chunk's band: every node its particles' stencils can reach (cell - 1 .. cell + 2 per axis).
  const auto chunks = static_cast<std::ptrdiff_t>(chunks_);
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::ptrdiff_t c = 0; c < chunks; ++c) {
    int imin = cells_x_, imax = -1, jmin = cells_y_, jmax = -1;
    std::int64_t previous_cell = kRemoved;  // a cell's particles are consecutive: one division per cell
    for (std::size_t k = chunk_[c]; k < chunk_[c + 1]; ++k) {
      const std::int64_t cell = cell_of(cur_.key[order_[k]]);
      if (cell == previous_cell) continue;
      previous_cell = cell;
      const int i = static_cast<int>(cell % cells_x_), j = static_cast<int>(cell / cells_x_);
      imin = std::min(imin, i);
      imax = std::max(imax, i);
      jmin = std::min(jmin, j);
      jmax = std::max(jmax, j);
    }
    Band& b = bands_[static_cast<std::size_t>(c)];
    if (imax < 0) {  // an empty chunk (its cell's particles all went to the chunk before)
      b = Band{};
      continue;
    }
    b.i0 = std::max(imin - 1, 0);
    b.i1 = std::min(imax + 3, nx_);
    b.j0 = std::max(jmin - 1, 0);
    b.j1 = std::min(jmax + 3, ny_);
  }
  // The active node box: the union of the bands.
  bi0_ = bj0_ = 0;
  bi1_ = bj1_ = 0;
  if (chunks_ > 0) {
    bi0_ = nx_;
    bj0_ = ny_;
    for (std::size_t c = 0; c < chunks_; ++c) {
      if (bands_[c].size() == 0) continue;
      bi0_ = std::min(bi0_, bands_[c].i0);
      bi1_ = std::max(bi1_, bands_[c].i1);
      bj0_ = std::min(bj0_, bands_[c].j0);
      bj1_ = std::max(bj1_, bands_[c].j1);
    }
  }
  std::size_t offset = 0;
  for (std::size_t c = 0; c < chunks_; ++c) {
    bands_[c].offset = offset;
    offset += bands_[c].size();
  }
  if (pool_.size() < offset) pool_.resize(offset);  // grows rarely; no allocation in a steady state
  // Chunks follow the rows: their bands' last rows ascend (an empty band has none).
  std::size_t first = 0;
  for (int j = bj0_; j < bj1_; ++j) {
    while (first < chunks_ && bands_[first].j1 <= j) ++first;
    row_first_chunk_[static_cast<std::size_t>(j)] = first;
  }
}

// ---------------------------------------------------------------------------------------------------
// The step
// ---------------------------------------------------------------------------------------------------
void Engine::step() {
  for (std::size_t c = 0; c < chunks_; ++c) problems_[c] = Problem{};
  const Vec2 b = body_force_.at(time());
  gx_ = b.x();
  gy_ = b.y();
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
#pragma omp for schedule(static) nowait
  for (int j = bj0_; j < bj1_; ++j) f(j);
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

/// Sums the chunks' bands over row j of the active box into `sums` (`values` per node, 5 apart, from
/// node bi0_), each node in chunk order: the same sums for any thread count. A band that does not reach
/// a node adds nothing to it, so skipping it changes no bit (a sum that starts at +0 never becomes -0).
void Engine::sum_bands_of_row(int j, int values, double* sums) const {
  std::fill_n(sums, 5 * static_cast<std::size_t>(bi1_ - bi0_), 0.0);
  for (std::size_t c = row_first_chunk_[static_cast<std::size_t>(j)]; c < chunks_; ++c) {
    const Band& band = bands_[c];
    if (band.size() == 0 || j >= band.j1) continue;
    if (band.j0 > j) break;  // bands are ordered by row
    const double* row = pool_.data() + band.offset + static_cast<std::size_t>(j - band.j0) * band.row_stride();
    double* s = sums + 5 * static_cast<std::size_t>(band.i0 - bi0_);
    for (int i = band.i0; i < band.i1; ++i, row += 5, s += 5)
      for (int f = 0; f < values; ++f) s[f] += row[f];
  }
}

/// The calling thread's scratch row for sum_bands_of_row.
double* Engine::thread_row_sums() {
  return &row_sums_[5 * static_cast<std::size_t>(nx_) * static_cast<std::size_t>(omp_get_thread_num())];
}

/// The grid fields of row j from the chunks' bands (sum_bands_of_row).
void Engine::reduce_row(int j, GridFields summed) {
  double* s = thread_row_sums();
  sum_bands_of_row(j, 5, s);
  for (int i = bi0_; i < bi1_; ++i, s += 5) {
    const std::size_t n = static_cast<std::size_t>(i) + static_cast<std::size_t>(j) * nx_;
    if (summed.mass) mass_[n] = s[0];
    if (summed.momentum) {
      momentum_[2 * n] = s[1];
      momentum_[2 * n + 1] = s[2];
    }
    if (summed.forces) {
      force_[2 * n] = s[3];
      force_[2 * n + 1] = s[4];
    }
  }
}

/// Nodal velocity = momentum / mass, then the velocity constraints (CB-Geo Node::compute_velocity) and no
/// approach into a wall (strain_rate_velocity, nodal_constraints.hpp).
void Engine::nodal_velocity_row(int j) {
  for (int i = bi0_; i < bi1_; ++i) {
    const std::size_t n = static_cast<std::size_t>(i) + static_cast<std::size_t>(j) * nx_;
    double vx = 0.0, vy = 0.0;
    if (mass_[n] > mass_tolerance_) {
      vx = momentum_[2 * n] / mass_[n];
      vy = momentum_[2 * n + 1] / mass_[n];
    }
    if (const std::int32_t c = constraint_of_[n]; c >= 0) {
      const Vec2 v = strain_rate_velocity(Vec2(vx, vy), constraint_now(c));
      vx = v.x();
      vy = v.y();
    }
    velocity_[2 * n] = vx;
    velocity_[2 * n + 1] = vy;
  }
}

/// Explicit grid update (Sulsky et al. 1994, eq. 18): a = f / m, f with the concentrated nodal forces
/// (external_loads.hpp), with Cundall's local damping
/// f - alpha |f| sign(v) (Cundall 1987; CB-Geo compute_acceleration_velocity_cundall), v_new = v + a dt
/// (a = g below the small-mass cutoff); at a constrained node the friction and velocity constraints in
/// momentum form (nodal_constraints.hpp), and the rate (v_new - v_old) / dt handed to FLIP in place of a.
void Engine::integrate_row(int j) {
  for (int i = bi0_; i < bi1_; ++i) {
    const std::size_t n = static_cast<std::size_t>(i) + static_cast<std::size_t>(j) * nx_;
    double* u = &updated_[4 * n];
    const double m = mass_[n];
    if (!(m > mass_tolerance_)) {
      u[0] = u[1] = u[2] = u[3] = 0.0;
      if (lagged_friction_ && constraint_of_[n] >= 0) normal_memory_[static_cast<std::size_t>(constraint_of_[n])].forget();
      continue;
    }
    const double vx = velocity_[2 * n], vy = velocity_[2 * n + 1];
    double fx = force_[2 * n], fy = force_[2 * n + 1];
    if (loads_.has_nodal_forces()) {
      const Vec2 f = loads_.nodal_force(n);
      fx += f.x();
      fy += f.y();
    }
    if (damping_ > 0.0) apply_cundall_damping(damping_, fx, fy, vx, vy);
    // Below the small-mass cutoff only gravity accelerates the node (see small_mass_).
    const bool small = m < small_mass_;
    const double ax = small ? gx_ : fx / m, ay = small ? gy_ : fy / m;
    if (const std::int32_t c = constraint_of_[n]; c >= 0) {
      const Vec2 v_old(momentum_[2 * n] / m, momentum_[2 * n + 1] / m);
      const NodeConstraint now = constraint_now(c);
      NormalMemory& memory = normal_memory_[static_cast<std::size_t>(c)];
      if (now.friction_dir < 0) memory.forget();  // a contact the material does not touch
      const ConstrainedVelocity r = constrained_velocity(v_old, Vec2(ax, ay), dt_, now, &memory, m);
      u[0] = r.velocity[0];
      u[1] = r.velocity[1];
      u[2] = r.rate[0];
      u[3] = r.rate[1];
    } else {
      u[0] = vx + ax * dt_;
      u[1] = vy + ay * dt_;
      u[2] = ax;
      u[3] = ay;
    }
  }
}

void Engine::report(std::size_t c, std::size_t k, ProblemKind kind, std::int64_t id, double a, double b) {
  Problem& pr = problems_[c];
  if (k < pr.k) pr = Problem{k, kind, id, a, b};
}

namespace {
/// Dispatch for a run where every particle has the same material: one instantiation per model. update4:
/// four consecutive particles at once where the model has it (MohrCoulomb::update4).
template <class Model>
struct SameMaterial {
  const Model& model;
  void operator()(std::uint32_t /*material*/, double* s, const double* de, double* sv) const { model.update(s, de, sv); }
  void update4(const std::uint32_t* /*material*/, double* s, const double* de, double* sv) const {
    if constexpr (requires { model.update4(s, de, sv); })
      model.update4(s, de, sv);
    else
      for (int l = 0; l < 4; ++l) model.update(s + 4 * l, de + 3 * l, sv + kStateVariables * l);
  }
  bool separated(std::uint32_t /*material*/, double mass, double volume) const { return model.separated(mass, volume); }
};
/// Dispatch for mixed materials: a switch on the material type (no virtual call).
struct MixedMaterials {
  const std::vector<Material>& materials;
  void operator()(std::uint32_t material, double* s, const double* de, double* sv) const {
    const Material& m = materials[material];
    if (m.type == MaterialType::MohrCoulomb2D)
      m.mohr_coulomb.update(s, de, sv);
    else
      m.elastic.update(s, de, sv);
  }
  void update4(const std::uint32_t* material, double* s, const double* de, double* sv) const {
    for (int l = 0; l < 4; ++l) (*this)(material[l], s + 4 * l, de + 3 * l, sv + kStateVariables * l);
  }
  bool separated(std::uint32_t material, double mass, double volume) const {
    const Material& m = materials[material];
    return m.type == MaterialType::MohrCoulomb2D && m.mohr_coulomb.separated(mass, volume);
  }
};
}  // namespace


/// Stress update: strain increment from the nodal velocity at the particle (or the one g2p stored),
/// the selected checkerboard remedy (stress_remedy.hpp), then the material's stress update and the
/// carried state (next buffer). A nodal remedy needs every chunk's values at the nodes first, hence
/// its barriers. With AfterStress::MapForces (USF) each chunk then maps its forces from the updated
/// stress into its band (p2g_chunk, kForces): the same sums, in the same order, as a separate p2g pass
/// after a barrier, while the chunk's particles are still in cache.
template <class Shape>
void Engine::update_stress(StrainFrom from, AfterStress then) {
  wait_for_previous_phase();
  const bool strain_ready = from == StrainFrom::G2p;
  const bool map_forces = then == AfterStress::MapForces;
  if (nodal_projection(smoothing_).values > 0) {
    for_each_chunk([&](std::size_t c) {
      if (!strain_ready) compute_strain_increments<Shape>(c);
      scatter_remedy_values<Shape>(c);
    });
#pragma omp barrier
    for_each_row([&](int j) { nodal_remedy_row(j); });
#pragma omp barrier
    for_each_chunk([&](std::size_t c) {
      gather_remedy_values<Shape>(c);
      update_material_state(c);
      if (map_forces) p2g_chunk<Shape, false>(c, kForces);
    });
  } else {
    const bool cell_remedy = is_cell_remedy(smoothing_);
    for_each_chunk([&](std::size_t c) {
      if (!strain_ready) compute_strain_increments<Shape>(c);
      if (cell_remedy) apply_cell_remedy(c);
      update_material_state(c);
      if (map_forces) p2g_chunk<Shape, false>(c, kForces);
    });
  }
}

/// (dexx, deyy, dgxy) = dt (dvx/dx, dvy/dy, dvx/dy + dvy/dx), the gradient of the nodal velocity at the
/// particle (CB-Geo compute_strain_rate, without its 1e-15 flush to zero).
template <class Shape>
void Engine::compute_strain_increments(std::size_t c) {
  constexpr int W = Shape::kWidth;
  for (std::size_t k = chunk_[c]; k < chunk_[c + 1]; ++k) {
    const auto first = static_cast<std::size_t>(base_[k]);
    if (run_lane_[k] == 0) {
      const VelocityGradient4 L = gather_velocity_gradient4(velocity_.data(), 2, first, static_cast<std::size_t>(nx_),
                                                            StencilWeights4<W>(&weights_[4 * W * k]));
      for (int l = 0; l < kRunLanes; ++l) L.lane(l).strain_increment(dt_, &dstrain_[3 * (k + l)]);
      k += kRunLanes - 1;
      continue;
    }
    const StencilWeights<W> w(&weights_[4 * W * k]);  // not in a run: a block of its own
    gather_velocity_gradient(velocity_.data(), 2, first, static_cast<std::size_t>(nx_), w)
        .strain_increment(dt_, &dstrain_[3 * k]);
  }
}

/// A cell remedy on every cell of chunk c (chunks start at cell boundaries, so each cell lies in one
/// chunk; its particles are consecutive in iteration order).
void Engine::apply_cell_remedy(std::size_t c) {
  const std::size_t k1 = chunk_[c + 1];
  std::size_t a = chunk_[c];
  while (a < k1) {
    const std::int64_t this_cell = cell_of(cur_.key[order_[a]]);
    std::size_t b = a + 1;
    while (b < k1 && cell_of(cur_.key[order_[b]]) == this_cell) ++b;
    const std::uint32_t* cell = &order_[a];
    core::apply_cell_remedy(smoothing_, &dstrain_[3 * a], b - a, [&](std::size_t i) { return cur_.volume[cell[i]]; });
    a = b;
  }
}

/// Nodal remedy, 1/3: w N values into the chunk's band (slots 0-2), and w N into slot 3 when the
/// weight is the volume (a mass weight is normalised by the nodal mass).
template <class Shape>
void Engine::scatter_remedy_values(std::size_t c) {
  constexpr int W = Shape::kWidth;
  const NodalProjection proj = nodal_projection(smoothing_);
  double* g = cleared_band(c);
  const std::size_t row_stride = bands_[c].row_stride();
  for (std::size_t k = chunk_[c]; k < chunk_[c + 1]; ++k) {
    const StencilWeights<W> sw = stencil_weights<W>(k);
    const double *wx = sw.wx, *wy = sw.wy;
    const std::uint32_t p = order_[k];
    const double w = proj.volume_weighted ? cur_.volume[p] : cur_.mass[p];
    double values[3];
    nodal_values(smoothing_, &dstrain_[3 * k], values);
    double* band_row = g + local_[k];
    for (int b = 0; b < W; ++b, band_row += row_stride) {
      double* gn = band_row;
      for (int a = 0; a < W; ++a, gn += 5) {
        const double wN = w * wx[a] * wy[b];
        for (int f = 0; f < proj.values; ++f) gn[f] += wN * values[f];
        if (proj.volume_weighted) gn[3] += wN;
      }
    }
  }
}

/// Nodal remedy, 2/3: nodal value = sum w N value / sum w N (summed in chunk order).
void Engine::nodal_remedy_row(int j) {
  const NodalProjection proj = nodal_projection(smoothing_);
  double* s = thread_row_sums();
  sum_bands_of_row(j, 4, s);
  for (int i = bi0_; i < bi1_; ++i, s += 5) {
    const std::size_t n = static_cast<std::size_t>(i) + static_cast<std::size_t>(j) * nx_;
    const double weight = proj.volume_weighted ? s[3] : mass_[n];
    const double inv_w = weight > (proj.volume_weighted ? 0.0 : mass_tolerance_) ? 1.0 / weight : 0.0;
    for (int f = 0; f < proj.values; ++f) nodal_remedy_[3 * n + f] = s[f] * inv_w;
  }
}

/// Nodal remedy, 3/3: the nodal values interpolated back, sum N value_i, applied to the increment.
template <class Shape>
void Engine::gather_remedy_values(std::size_t c) {
  constexpr int W = Shape::kWidth;
  const int nv = nodal_projection(smoothing_).values;
  for (std::size_t k = chunk_[c]; k < chunk_[c + 1]; ++k) {
    const StencilWeights<W> sw = stencil_weights<W>(k);
    const double *wx = sw.wx, *wy = sw.wy;
    double e[3] = {0, 0, 0};
    std::size_t node_row = static_cast<std::size_t>(base_[k]);
    for (int b = 0; b < W; ++b, node_row += static_cast<std::size_t>(nx_)) {
      const double* en = &nodal_remedy_[3 * node_row];
      for (int a = 0; a < W; ++a, en += 3) {
        const double N = wx[a] * wy[b];
        for (int f = 0; f < nv; ++f) e[f] += N * en[f];
      }
    }
    apply_nodal_values(smoothing_, e, &dstrain_[3 * k]);
  }
}

/// Material dispatch for one chunk: one templated loop per material model when all particles share a
/// material, else a switch on the material type per particle (no virtual call either way).
void Engine::update_material_state(std::size_t c) {
  const std::size_t k0 = chunk_[c], k1 = chunk_[c + 1];
  if (uniform_material_) {
    const Material& m = materials_[0];
    if (m.type == MaterialType::MohrCoulomb2D)
      update_material_state(k0, k1, c, SameMaterial<MohrCoulomb>{m.mohr_coulomb});
    else
      update_material_state(k0, k1, c, SameMaterial<LinearElastic>{m.elastic});
  } else {
    update_material_state(k0, k1, c, MixedMaterials{materials_});
  }
}

/// The material's stress update with the (possibly smoothed) increment, volume *= 1 + de_v (CB-Geo
/// update_volume, here with the particle's own increment), no stress once separated (materials.hpp),
/// the strain sums, and the particle fields carried unchanged, all into the next buffer.
template <class Dispatch>
void Engine::update_material_state(std::size_t k0, std::size_t k1, std::size_t c, const Dispatch& dispatch) {
  // The stress and state variables are updated in place in the next buffer (whole-block copies first:
  // no partial-store stalls), four particles at a time (their blocks follow one another there).
  // copy_in(k) returns p = order_[k], the particle's index in the current buffer, for carry(k, p).
  const auto copy_in = [&](std::size_t k) {
    const std::uint32_t p = order_[k];
    copy_doubles<4>(&cur_.stress[4 * p], &nxt_.stress[4 * k]);
    copy_doubles<kStateVariables>(&cur_.svars[p * kStateVariables], &nxt_.svars[k * kStateVariables]);
    return p;
  };
  const auto carry = [&](std::size_t k, std::uint32_t p) {
    const double* de = &dstrain_[3 * k];
    double* s = &nxt_.stress[4 * k];
    const double dv = de[0] + de[1];
    nxt_.volume[k] = cur_.volume[p] * (1.0 + dv);
    if (dispatch.separated(cur_.material[p], cur_.mass[p], nxt_.volume[k])) std::fill_n(s, 4, 0.0);
    nxt_.epsv[k] = cur_.epsv[p] + dv;
    nxt_.exx[k] = cur_.exx[p] + de[0];
    nxt_.eyy[k] = cur_.eyy[p] + de[1];
    nxt_.gxy[k] = cur_.gxy[p] + de[2];
    nxt_.id[k] = cur_.id[p];
    nxt_.material[k] = cur_.material[p];
    nxt_.mass[k] = cur_.mass[p];
    nxt_.lx[k] = cur_.lx[p];
    nxt_.ly[k] = cur_.ly[p];
    if (!cur_.traction_slot.empty()) nxt_.traction_slot[k] = cur_.traction_slot[p];
    if (!std::isfinite(s[0] + s[1] + s[2] + s[3])) report(c, k, ProblemKind::StressNotFinite, cur_.id[p], s[0], s[1]);
  };
  std::size_t k = k0;
  for (; k + 4 <= k1; k += 4) {
    std::uint32_t p[4], material[4];
    for (std::size_t l = 0; l < 4; ++l) {
      p[l] = copy_in(k + l);
      material[l] = cur_.material[p[l]];
    }
    dispatch.update4(material, &nxt_.stress[4 * k], &dstrain_[3 * k], &nxt_.svars[k * kStateVariables]);
    for (std::size_t l = 0; l < 4; ++l) carry(k + l, p[l]);
  }
  for (; k < k1; ++k) {
    const std::uint32_t p = copy_in(k);
    dispatch(cur_.material[p], &nxt_.stress[4 * k], &dstrain_[3 * k], &nxt_.svars[k * kStateVariables]);
    carry(k, p);
  }
}

void Engine::throw_first_error() const {
  const Problem* first = nullptr;
  for (const auto& p : problems_)
    if (p.kind != ProblemKind::None && (first == nullptr || p.k < first->k)) first = &p;
  if (first == nullptr) return;
  std::ostringstream os;
  os.precision(10);
  os << "step " << step_index_ << ": particle " << first->id;
  switch (first->kind) {
    case ProblemKind::VelocityNotFinite: os << " velocity is not finite (" << first->a << ", " << first->b << ")"; break;
    case ProblemKind::RunawayVelocity: os << " velocity runaway: speed " << first->a << " m/s exceeds one cell per step (" << first->b << " m/s)"; break;
    case ProblemKind::LeftTheGrid: os << " left the grid at (" << first->a << ", " << first->b << ")"; break;
    case ProblemKind::StressNotFinite:
    case ProblemKind::None: os << " stress is not finite (sxx " << first->a << ", syy " << first->b << ")"; break;
  }
  throw common::NumericalError(os.str());
}

std::vector<std::uint32_t> Engine::live_by_id() const {
  std::vector<std::uint32_t> by_id(order_.begin(), order_.end());
  std::sort(by_id.begin(), by_id.end(), [&](std::uint32_t a, std::uint32_t b) { return cur_.id[a] < cur_.id[b]; });
  return by_id;
}

std::vector<std::array<double, 4>> Engine::affine_snapshot() const {
  if (!transfer_.affine()) return {};
  const std::vector<std::uint32_t> by_id = live_by_id();
  std::vector<std::array<double, 4>> out(by_id.size());
  for (std::size_t k = 0; k < by_id.size(); ++k) std::copy_n(&cur_.affine[4 * by_id[k]], 4, out[k].data());
  return out;
}

std::optional<std::vector<FrictionMemoryRecord>> Engine::friction_memory_snapshot() const {
  if (!lagged_friction_) return std::nullopt;
  std::vector<FrictionMemoryRecord> out;
  for (std::size_t n = 0; n < nodes_; ++n)
    if (const std::int32_t c = constraint_of_[n]; c >= 0)
      if (const NormalMemory& m = normal_memory_[static_cast<std::size_t>(c)]; m.force >= 0.0)
        out.push_back({static_cast<std::int64_t>(n), m.force, m.mass});
  return out;
}

void Engine::restore_friction_memory(const std::vector<FrictionMemoryRecord>& memory) {
  for (std::size_t k = 0; k < memory.size(); ++k) {
    const FrictionMemoryRecord& r = memory[k];
    const std::string where = "friction_memory[" + std::to_string(k) + "]";
    const std::int32_t c = r.node >= 0 && static_cast<std::size_t>(r.node) < nodes_ ? constraint_of_[static_cast<std::size_t>(r.node)] : -1;
    if (c < 0 || !constraints_[static_cast<std::size_t>(c)].lag.active())
      throw common::InputError(where, "node " + std::to_string(r.node) + " has no friction constraint with a normal_lag");
    if (!(r.force >= 0.0 && std::isfinite(r.force)) || !(r.mass > 0.0 && std::isfinite(r.mass)))
      throw common::InputError(where, "expected a finite force >= 0 and mass > 0");
    normal_memory_[static_cast<std::size_t>(c)] = NormalMemory{r.force, r.mass};
  }
}

std::vector<ParticleRecord> Engine::snapshot() const {
  std::vector<ParticleRecord> out;
  out.reserve(order_.size());
  for (std::uint32_t p : live_by_id()) {  // by id: the indices sorted, not the records
    ParticleRecord r{};
    const Material& mat = materials_[cur_.material[p]];
    r.id = cur_.id[p];
    r.mass = cur_.mass[p];
    r.volume = cur_.volume[p];
    r.coord_x = cur_.x[p];
    r.coord_y = cur_.y[p];
    r.displacement_x = cur_.ux[p];
    r.displacement_y = cur_.uy[p];
    r.nsize_x = 4.0 * cur_.lx[p];
    r.nsize_y = 4.0 * cur_.ly[p];
    r.velocity_x = cur_.vx[p];
    r.velocity_y = cur_.vy[p];
    r.stress_xx = cur_.stress[4 * p];
    r.stress_yy = cur_.stress[4 * p + 1];
    r.stress_zz = cur_.stress[4 * p + 2];
    r.tau_xy = cur_.stress[4 * p + 3];
    r.strain_xx = cur_.exx[p];
    r.strain_yy = cur_.eyy[p];
    r.gamma_xy = cur_.gxy[p];
    r.epsilon_v = cur_.epsv[p];
    r.cell_id = -1;
    r.status = 1;
    r.material_id = mat.id;
    r.nstate_vars = static_cast<std::uint32_t>(mat.state_count);
    for (std::size_t i = 0; i < mat.state_count; ++i) r.svars[i] = cur_.svars[p * kStateVariables + i];
    if (mat.type == MaterialType::MohrCoulomb2D) {
      const double s[4] = {r.stress_xx, r.stress_yy, r.stress_zz, r.tau_xy};
      MohrCoulomb::set_invariants(s, r.svars);
    }
    out.push_back(r);
  }
  return out;
}

}  // namespace mpm::core

// p2g and g2p per particle and per stencil run (in this translation unit for the CPU variants to inline).
#include "mpm/core/engine_g2p.inl"
#include "mpm/core/engine_p2g.inl"
