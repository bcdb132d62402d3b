// The engine's construction from a problem (mpm/problem/deck.hpp): the grid and its constraints, the
// materials, the particles and their first order; the checks only the core can make (a particle outside
// the mesh's cells, a damping factor out of range). engine.hpp says what each member holds.
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/cpu_variants.hpp"
#include "common/input_error.hpp"
#include "common/number_text.hpp"
#include "mpm/core/engine.hpp"
#include "mpm/core/shape_functions.hpp"

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
  for (auto* v : {&mass, &volume, &exx, &eyy, &gxy, &epsv}) v->resize(n);
  for (int d = 0; d < kDim; ++d)
    for (auto* v : {&position[d], &displacement[d], &velocity[d], &half_size[d]}) v->resize(n);
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
  if (grid_.dim != kDim)
    throw common::InputError("mesh", "a " + std::to_string(grid_.dim) + "D grid: this engine runs " +
                                         std::to_string(kDim) + "D problems only");
  const auto& nodes = grid_.nodes_per_axis;
  const auto& h = grid_.spacing;
  for (int d = 0; d < kDim; ++d)
    if (nodes[d] < 2 || !(h[d] > 0))
      throw common::InputError("mesh", "the node lattice needs at least 2 x 2 nodes and a positive cell size");
  nodes_ = 1;
  std::size_t cells = 1;
  for (int d = 0; d < kDim; ++d) {
    nodes_per_axis_[d] = nodes[d];
    cells_per_axis_[d] = nodes[d] - 1;
    inv_h_[d] = 1.0 / h[d];
    nodes_ *= static_cast<std::size_t>(nodes[d]);
    cells *= static_cast<std::size_t>(cells_per_axis_[d]);
  }
  const bool gimp = grid_.cell_type == CellType::Gimp16;
  gimp_margin_ = gimp ? 1.0 : 0.0;
  // cell_keys computes in 32 bits: the largest key is below kKeysPerCell x cells.
  keys_fit_int32_ = kKeysPerCell * static_cast<double>(cells) <= std::numeric_limits<std::int32_t>::max();
  if (gimp) {
    // uGIMP reaches one node beyond the cell: the lattice must hold CB-Geo's halo ring around the region.
    const double tol = 1e-9;
    for (int d = 0; d < kDim; ++d)
      if (grid_.region_min[d] - grid_.origin[d] < h[d] * (1 - tol) ||
          grid_.origin[d] + (nodes[d] - 1) * h[d] - grid_.region_max[d] < h[d] * (1 - tol))
        throw common::InputError("mesh",
                                 "ED2Q16G cells need a ring of halo nodes around the cells that hold particles");
  }

  scheme_ = an.scheme;
  transfer_ = VelocityTransfer::from(an);
  stencil_runs_ = options.stencil_runs && common::wide_vector_kernels();
  locate_ = an.locate_particles;
  damping_ = an.cundall_damping;
  if (!(damping_ >= 0.0 && damping_ < 1.0))
    throw common::InputError("analysis.damping.damping_factor", "expected a number in [0, 1), got " + num(damping_));
  body_force_ = BodyForce{an.gravity, deck.base_acceleration};
  loads_ = ExternalLoads(deck, nodes_);
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
    const double auto_dt = an.cfl * smallest_cell_side() / max_wave_speed;
    dt_ = (an.dt > 0) ? std::min(an.dt, auto_dt) : auto_dt;
  }
  if (!(dt_ > 0) || !std::isfinite(dt_)) throw common::InputError("analysis.dt", "expected a time step > 0");
  courant_number_ = dt_ * max_wave_speed / smallest_cell_side();

  // Small-mass cutoff (on bilinear cells, where particles read unweighted gradients of the updated grid
  // velocity: USL's strain increment, APIC's C_p): a fraction of a full node of the lightest material.
  double lightest = std::numeric_limits<double>::infinity();
  for (const auto& spec : deck.materials) lightest = std::min(lightest, spec.density);
  const bool reads_updated_gradients = !gimp && (scheme_ == Scheme::USL || transfer_.affine());
  // rho h^d, multiplied left to right (rho hx hy in 2D, as before the axes).
  const auto times_cell_volume = [&](double v) {
    for (int d = 0; d < kDim; ++d) v *= h[d];
    return v;
  };
  small_mass_ = reads_updated_gradients ? times_cell_volume(kSmallMassFraction * lightest) : 0.0;
  // CB-Geo's absolute 1e-15, but never more than 1e-15 of a full node of the lightest material: a deck whose
  // densities are tiny numbers (other mass units) must not find every node empty and its body frozen.
  mass_tolerance_ = std::min(kMassTolerance, times_cell_volume(kMassTolerance * lightest));

  // Boundary conditions on nodes (CB-Geo: a later constraint on the same node and direction wins).
  constraint_of_.assign(nodes_, -1);
  const auto constraint_at = [&](int n) -> NodeConstraint<kDim>& {
    if (constraint_of_[n] < 0) {
      constraint_of_[n] = static_cast<std::int32_t>(constraints_.size());
      constraints_.emplace_back();
    }
    return constraints_[static_cast<std::size_t>(constraint_of_[n])];
  };
  const std::string axes = kDim == 2 ? "0 or 1" : "0, 1 or 2";  // the axes a constraint's dir may name
  for (std::size_t i = 0; i < deck.velocity_constraints.size(); ++i) {
    const auto& c = deck.velocity_constraints[i];
    const std::string where = "velocity_constraints[" + std::to_string(i) + "]";
    if (c.dir < 0 || c.dir >= kDim) throw common::InputError(where, "dir must be " + axes + ", got " + std::to_string(c.dir));
    for (int n : c.nodes) {
      if (n < 0 || static_cast<std::size_t>(n) >= nodes_)
        throw common::InputError(where, "node " + std::to_string(n) + " is not in the mesh");
      NodeConstraint<kDim>& nc = constraint_at(n);
      nc.fixed |= static_cast<std::uint8_t>(1u << c.dir);
      nc.fixed_velocity[c.dir] = c.velocity;
    }
  }
  for (std::size_t i = 0; i < deck.friction_constraints.size(); ++i) {
    const auto& c = deck.friction_constraints[i];
    const std::string where = "friction_constraints[" + std::to_string(i) + "]";
    if (c.dir < 0 || c.dir >= kDim) throw common::InputError(where, "dir must be " + axes + ", got " + std::to_string(c.dir));
    for (int n : c.nodes) {
      if (n < 0 || static_cast<std::size_t>(n) >= nodes_)
        throw common::InputError(where, "node " + std::to_string(n) + " is not in the mesh");
      NodeConstraint<kDim>& nc = constraint_at(n);
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
  std::vector<std::uint32_t> per_cell(cells, 0);
  for (std::size_t p = 0; p < n; ++p) {
    const ParticleRecord& r = deck.particles[p];
    const std::string who = "particle " + std::to_string(r.id);
    const std::array<double, kDim> coord = {r.coord_x, r.coord_y};
    bool inside = true;
    for (int d = 0; d < kDim; ++d)
      inside = inside && std::isfinite(coord[d]) && coord[d] >= grid_.region_min[d] && coord[d] <= grid_.region_max[d];
    if (!inside)
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
    for (int d = 0; d < kDim; ++d) cur_.position[d][p] = coord[d];
    cur_.key[p] = cell_key(coord);
    ++per_cell[static_cast<std::size_t>(cell_of(cur_.key[p]))];
  }
  for (std::size_t p = 0; p < n; ++p) {
    const ParticleRecord& r = deck.particles[p];
    const Material& mat = materials_[cur_.material[p]];
    // CB-Geo defaults: volume = cell area / particles in the cell, mass = density * volume,
    // nsize = 2 / sqrt(particles in the cell) (2 / particles per direction). Each applies on its own
    // (a deck may give volumes, e.g. mesh.particles_volumes, but no sizes).
    const double count = per_cell[static_cast<std::size_t>(cell_of(cur_.key[p]))];
    cur_.volume[p] = r.volume > 0 ? r.volume : times_cell_volume(1.0) / count;
    cur_.mass[p] = r.volume > 0 && r.mass > 0 ? r.mass : mat.density * cur_.volume[p];
    const bool sized = r.nsize_x > 0 && r.nsize_y > 0;
    const double nsize_x = sized ? r.nsize_x : 2.0 / std::sqrt(count);
    const double nsize_y = sized ? r.nsize_y : 2.0 / std::sqrt(count);
    if (gimp && !(nsize_x > 0 && nsize_x <= 2 && nsize_y > 0 && nsize_y <= 2))
      throw common::InputError("particle " + std::to_string(r.id), "nsize must be in (0, 2] for ED2Q16G cells");
    cur_.half_size[0][p] = nsize_x / 4.0;
    cur_.half_size[1][p] = nsize_y / 4.0;
    cur_.displacement[0][p] = r.displacement_x;
    cur_.displacement[1][p] = r.displacement_y;
    cur_.velocity[0][p] = r.velocity_x;
    cur_.velocity[1][p] = r.velocity_y;
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
  bucket_.resize(kKeysPerCell * cells + 1);
  const std::size_t max_chunks = n / kChunkParticles + 2;
  chunk_.resize(max_chunks + 1);
  bands_.resize(max_chunks);
  row_sums_.resize(static_cast<std::size_t>(threads_) * kBandValues * node_row_stride());
  row_first_chunk_.resize(static_cast<std::size_t>(nodes_per_axis_[kDim - 1]));
  local_.resize(n);
  mass_.assign(nodes_, 0.0);
  momentum_.assign(kVectorStride * nodes_, 0.0);
  force_.assign(kVectorStride * nodes_, 0.0);
  velocity_.assign(kVectorStride * nodes_, 0.0);
  updated_.assign(kUpdatedStride * nodes_, 0.0);
  if (nodal_projection(smoothing_).values > 0) nodal_remedy_.assign(3 * nodes_, 0.0);
  problems_.resize(max_chunks);

  order_.resize(n);
  for (std::size_t p = 0; p < n; ++p) order_[p] = static_cast<std::uint32_t>(p);
  sort_particles();
}

}  // namespace mpm::core
