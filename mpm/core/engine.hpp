#pragma once
// The explicit MPM engine behind mpm::core::Simulation (see simulation.hpp for the algorithm).
//
// Data layout (STYLE.md "Performance habits"): particles as structure-of-arrays, double-buffered: a step
// reads the current arrays through `order_` (the live particles sorted by cell and stencil quadrant, then id) and writes the
// next arrays in that order; the buffers are swapped only when the whole step succeeded, so after a
// NumericalError the engine still holds the last good state. Shape-function weights are computed once
// per particle per step and stored. The sorted particles are cut into chunks of ~2048 at cell
// boundaries (a function of the state only); threads take chunks dynamically (a preempted thread on a
// shared machine does not hold the others back), each chunk scatters lock-free into its own band of
// the grid (the rows and columns its stencils reach), and the bands are summed in chunk order: results
// are bit-identical for ANY thread count.
// Per-cell work (the cell remedies of stress_remedy.hpp) stays inside one chunk.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "mpm/core/body_force.hpp"
#include "mpm/core/external_loads.hpp"
#include "mpm/core/materials.hpp"
#include "mpm/core/nodal_constraints.hpp"
#include "mpm/core/order_merge.hpp"
#include "mpm/core/simulation.hpp"
#include "mpm/core/stencil_runs.hpp"
#include "mpm/core/stress_remedy.hpp"
#include "mpm/core/velocity_transfer.hpp"
#include "mpm/problem/deck.hpp"
#include "mpm/problem/particle_record.hpp"

namespace mpm::core {

/// The grid fields a p2g pass maps into the chunks' bands and a node phase sums from them.
struct GridFields {
  bool mass, momentum, forces;
};
inline constexpr GridFields kMassMomentum{true, true, false};
inline constexpr GridFields kForces{false, false, true};
inline constexpr GridFields kAllFields{true, true, true};
inline constexpr GridFields kMomentum{false, true, false};

/// What g2p does besides updating the particle velocity and position.
enum class G2pAlso {
  Nothing,
  StrainIncrements,  ///< USL: the strain increment from the updated grid velocity, from the same nodes
  RemapMomentum,     ///< MUSL: the updated particle momentum m N v back into the chunk's band
};

/// Where update_stress takes the strain increment from.
enum class StrainFrom {
  NodalVelocity,  ///< the gradient of velocity_ (momentum / mass, constraints applied) at the particle
  G2p,            ///< the increment g2p stored (G2pAlso::StrainIncrements)
};

/// What update_stress does next with each chunk, while its particles are in cache.
enum class AfterStress {
  Nothing,
  MapForces,  ///< USF: p2g of the forces from the updated stress (the same sums as a separate p2g pass)
};

/// The engine's dimension: the `dim` of the template it is becoming (issue 37, mpm/core/README.md).
inline constexpr int kDim = 2;

struct ParticleArrays {
  std::vector<std::int64_t> id;
  std::vector<std::uint32_t> material;  ///< index into Engine::materials_
  std::vector<double> mass, volume;
  /// Per axis d: position[d][p] (m), displacement (m), velocity (m/s).
  std::array<std::vector<double>, kDim> position, displacement, velocity;
  /// GIMP half-size in cell units, CB-Geo's nsize / 4 (exactly: nsize = 4 half_size).
  std::array<std::vector<double>, kDim> half_size;
  std::vector<double> stress;         ///< 4 per particle: sxx, syy, szz, sxy (one block: the material reads it whole)
  std::vector<double> exx, eyy, gxy, epsv;
  std::vector<double> svars;          ///< kStateVariables per particle
  std::vector<double> affine;         ///< 4 per particle: the APIC matrix B_p (Bxx, Bxy, Byx, Byy), m^2/s
  std::vector<std::int64_t> key;      ///< sort key (Engine::cell_key): cell and stencil quadrant, or kRemoved
  /// Per particle: its slot in Engine::loads_ (external_loads.hpp), -1 no traction; empty without tractions.
  std::vector<std::int32_t> traction_slot;
  void resize(std::size_t n);
};

class Engine {
 public:
  Engine(const Deck& deck, int threads, ExecutionOptions options = {});
  void step();
  long long step_index() const { return step_index_; }
  double dt() const { return dt_; }
  /// dt c_p / h of the stiffest material on the smaller cell side (the elastic Courant number).
  double courant_number() const { return courant_number_; }
  double time() const { return static_cast<double>(step_index_) * dt_; }
  std::size_t particle_count() const { return order_.size(); }
  std::vector<ParticleRecord> snapshot() const;
  /// The APIC matrices in snapshot() order (by id); empty unless the transfer is APIC.
  std::vector<std::array<double, 4>> affine_snapshot() const;
  /// The nodes' lagged friction strengths (nodes holding one, by node); nullopt without a normal_lag.
  std::optional<std::vector<FrictionMemoryRecord>> friction_memory_snapshot() const;

  static constexpr std::int64_t kRemoved = -1;

 private:
  // --- the phases of a step (inside one parallel region; each waits for the one before) ---
  template <class Shape>
  void run_step();
  void run_gimp_step();    ///< run_step<GimpShape>, compiled for the baseline and for AVX2 (engine.cpp)
  void run_linear_step();  ///< run_step<LinearShape>, alike
  template <class Shape>
  void p2g(GridFields fields);  ///< particles to the chunks' bands
  void nodal_velocity(GridFields summed);  ///< sum the bands, nodal velocity = momentum / mass
  void update_grid(GridFields summed);  ///< sum the bands, (nodal velocity,) integrate the grid equation
  template <class Shape>
  void g2p(G2pAlso also);  ///< grid to particles: velocity and position
  template <class Shape>
  void update_stress(StrainFrom from, AfterStress then);  ///< strain increment, remedy, material update

  // --- their parts (particle parts per chunk, node parts per row) ---
  template <class F>
  void for_each_chunk(F&& f);  ///< dynamic schedule over the chunks (no barrier at the end)
  template <class F>
  void for_each_row(F&& f);  ///< static schedule over the rows of the active node box (no barrier)
  template <class Shape, bool Affine>
  void p2g_chunk(std::size_t c, GridFields fields);  ///< Affine: the APIC momentum (velocity_transfer.hpp)
  template <class Shape, bool Affine>
  bool evaluate_shape_functions(std::size_t c, std::size_t k);
  template <class Shape, bool Affine>
  bool evaluate_run(std::size_t c, std::size_t k);
  void set_stencil(std::size_t c, std::size_t k, int bi, int bj, std::int32_t lane);
  template <int W, bool Affine>
  void scatter_run(std::size_t k, double* g, std::size_t row_stride, bool mass_momentum, bool forces,
                   bool forces_from_next);
  template <class Shape, bool Affine>
  void scatter_particle(std::size_t k, double* g, std::size_t row_stride, bool mass_momentum, bool forces,
                        bool forces_from_next);
  void reduce_row(int j, GridFields summed);
  void sum_bands_of_row(int j, int values, double* sums) const;
  double* thread_row_sums();
  void nodal_velocity_row(int j);
  void integrate_row(int j);
  template <class Shape, bool Affine>
  void g2p_chunk(std::size_t c, G2pAlso also);  ///< Affine: APIC (v_p, B_p from the grid)
  template <class Shape, bool Affine>
  void g2p_particle(std::size_t c, std::size_t k, G2pAlso also, double* band);
  template <class Shape, bool Affine>
  void g2p_run(std::size_t c, std::size_t k, G2pAlso also, double* band);
  template <class Shape>
  void new_affine_matrix(std::size_t k, std::uint32_t p, const GridSums& sums, double vgx, double vgy,
                         double* at_old);
  void place_particle(std::size_t c, std::size_t k, std::uint32_t p, double vgx, double vgy, double vx, double vy);
  void place_run(std::size_t c, std::size_t k, const std::uint32_t* p, Double4 vgx, Double4 vgy, Double4 vx,
                 Double4 vy);
  template <class Shape>
  void compute_strain_increments(std::size_t c);
  void apply_cell_remedy(std::size_t c);  ///< a cell remedy on each cell of chunk c
  template <class Shape>
  void scatter_remedy_values(std::size_t c);  ///< a nodal remedy, 1/3: weighted values to the band
  void nodal_remedy_row(int j);               ///< 2/3: nodal values = sum w N value / sum w N
  template <class Shape>
  void gather_remedy_values(std::size_t c);   ///< 3/3: interpolated back, applied to the increment
  void update_material_state(std::size_t c);
  template <class Dispatch>
  void update_material_state(std::size_t k0, std::size_t k1, std::size_t c, const Dispatch& dispatch);
  double* cleared_band(std::size_t c);  ///< chunk c's band of the grid pool, zeroed

  // --- serial parts ---
  void sort_particles();  ///< order_ from cur_.key: by key, then id; drops removed particles; chunks
  void resort_particles();  ///< the same after a step, by a merge
  void cut_chunks();      ///< the active node box and the chunks of order_
  void throw_first_error() const;
  void set_up_wall_contacts();  ///< contact_nodes_ from the constraints (wall_contact.cpp)
  /// normal_memory_ from a resumed deck's friction_memory; InputError for a node without a lagged friction.
  void restore_friction_memory(const std::vector<FrictionMemoryRecord>& memory);
  void find_wall_contacts();  ///< touching_ from the particles at the start of the step (wall_contact.cpp)
  NodeConstraint<kDim> constraint_now(std::int32_t c) const;  ///< constraints_[c], without its contact if not touching
  std::array<int, kDim> node_axes(std::size_t node) const;  ///< the node's lattice index per axis (wall_contact.cpp)
  std::size_t node_at(const std::array<int, kDim>& at) const;  ///< the node at lattice index `at` (axis 0 fastest)
  std::vector<std::uint32_t> live_by_id() const;  ///< the live particles' storage indices, by id
  /// Sort keys per cell: one per stencil quadrant (an octant in 3D).
  static constexpr int kKeysPerCell = 1 << kDim;
  /// The particle's sort key at position x: kKeysPerCell x its lattice cell (axis 0 fastest) + the
  /// quadrant of the cell whose node is its nearest (uGIMP: bit d set in the cell's upper half on axis d;
  /// else 0), so that the particles of a cell come in runs that share one stencil (uGIMP: the 3 x 3 nodes
  /// around the nearest node; bilinear: the cell's 2 x 2). cell_of(key) is the cell.
  std::int64_t cell_key(std::array<double, kDim> x) const;  // by value: in registers in 2D
  /// cell_key in lanes, for positions inside the region.
  Long4 cell_keys(const std::array<Double4, kDim>& x) const;
  static std::int64_t cell_of(std::int64_t key) { return key >> kDim; }

  // grid
  Grid grid_;
  std::array<int, kDim> nodes_per_axis_{};  ///< the node lattice's nodes along each axis
  std::array<int, kDim> cells_per_axis_{};  ///< its cells: nodes_per_axis_ - 1
  std::array<double, kDim> inv_h_{};        ///< 1 / cell size, per axis
  /// Nodes from one node row to the next: node (i, j) is i + j * node_row_stride().
  std::size_t node_row_stride() const { return static_cast<std::size_t>(nodes_per_axis_[0]); }
  /// The shortest cell side, m (the CFL length; the farthest a particle may move in a step).
  double smallest_cell_side() const {
    double h = grid_.spacing[0];
    for (int d = 1; d < kDim; ++d) h = std::min(h, grid_.spacing[d]);
    return h;
  }
  double gimp_margin_ = 0;  ///< 1 for uGIMP (a particle may leave the region by its half-size lp), 0 for linear
  bool keys_fit_int32_ = false;  ///< every cell_key fits 32 bits (cell_keys computes in them)
  std::size_t nodes_ = 0;
  /// The active node box: nodes [box_lo_[d], box_hi_[d]) on each axis d (the union of the chunks' bands).
  std::array<int, kDim> box_lo_{}, box_hi_{};
  /// A node row: the nodes along axis 0 at one index on each outer axis d = 1 .. kDim - 1, numbered as its
  /// first node's index / node_row_stride() (j in 2D, j + ny k in 3D). Its index on each outer axis:
  std::array<int, kDim> row_axes(int row) const {
    std::array<int, kDim> at{};
    for (int d = 1; d < kDim - 1; ++d) {
      at[d] = row % nodes_per_axis_[d];
      row /= nodes_per_axis_[d];
    }
    at[kDim - 1] = row;
    return at;
  }
  std::vector<double> mass_;      ///< nodal mass
  /// Values per node: one per axis in the nodal vectors momentum_, force_ and velocity_; the updated
  /// velocity, then the acceleration, in updated_.
  static constexpr std::size_t kVectorStride = kDim, kUpdatedStride = 2 * kDim;
  std::vector<double> momentum_;  ///< kVectorStride per node
  std::vector<double> force_;     ///< kVectorStride per node (external + internal)
  /// kVectorStride per node: momentum / mass, constraints as the strain rate reads them.
  std::vector<double> velocity_;
  std::vector<double> updated_;   ///< kUpdatedStride per node: updated velocity, then acceleration, per axis
  std::vector<double> nodal_remedy_;  ///< 3 per node: the values a nodal remedy smooths (stress_remedy.hpp)
  /// Values per node of a band: the mass, then the momentum and the force per axis (m, px, py, fx, fy in
  /// 2D: the layout of stencil_kernels.hpp).
  static constexpr std::size_t kBandValues = 1 + 2 * kDim;
  static_assert(kDim != 2 || kBandValues == 5, "stencil_kernels.hpp reads 5 values per node in 2D");
  /// A chunk's band of the grid: the nodes [lo[d], hi[d]) on each axis d that its particles' stencils
  /// reach, kBandValues per node, row by row (axis 0 fastest, then the outer axes as node rows are
  /// numbered) from `offset` in pool_; summed in chunk order by reduce_row. Bounded on every axis, so a
  /// band holds about as many nodes as the chunk's cells touch, however wide the active box (a long,
  /// thin runout).
  struct Band {
    std::array<int, kDim> lo{}, hi{};
    std::size_t offset = 0;
    std::size_t row_stride() const { return kBandValues * static_cast<std::size_t>(hi[0] - lo[0]); }
    std::size_t size() const {
      std::size_t s = row_stride();
      for (int d = 1; d < kDim; ++d) s *= static_cast<std::size_t>(hi[d] - lo[d]);
      return s;
    }
    /// The band's row at outer indices `at` (d >= 1, inside the band), counted from its first row.
    std::size_t row_of(const std::array<int, kDim>& at) const {
      std::size_t r = static_cast<std::size_t>(at[kDim - 1] - lo[kDim - 1]);
      for (int d = kDim - 2; d >= 1; --d)
        r = r * static_cast<std::size_t>(hi[d] - lo[d]) + static_cast<std::size_t>(at[d] - lo[d]);
      return r;
    }
  };
  std::vector<Band> bands_;
  std::vector<double> pool_;
  /// Per index on the outermost axis (a node row in 2D, a plane of rows in 3D): the first chunk whose band
  /// reaches it (chunks follow the sort key, whose cell index has the outermost axis slowest).
  std::vector<std::size_t> row_first_chunk_;
  std::vector<double> row_sums_;              ///< per thread: kBandValues per node of one row (reduce_row)
  /// Small-mass cutoff of USL and of APIC on bilinear cells (kg per unit thickness; otherwise 0): a node with less mass than 2 % of a full node of the
  /// lightest material (0.02 rho_min hx hy) is accelerated by gravity alone: its internal force
  /// -sum V grad N . sigma is dropped (the body force per unit mass is g at every node). Why: at a node of mass fraction xi = m / (rho h^2) that only a particle's edge touches,
  /// a = f / m grows like 1 / xi (f ~ V sigma grad N stays finite), and USL's strain increment from
  /// v_new = v + a dt is amplified by about CFL^2 / xi: a particle entering an empty cell at speed sees
  /// its stress explode (the USL instability of Sulsky, Zhou & Schreyer 1995, section 4). The cutoff
  /// keeps that amplification below ~12 at CFL 0.5. APIC on bilinear cells reads the same unweighted
  /// gradient, C_p = sum v_i grad w_ip^T (velocity_transfer.hpp), so it takes the cutoff in every scheme
  /// (without it the sliding block's front runs away at step 70). USF and MUSL take the strain increment from the
  /// velocity of the mapped (or remapped) momentum, a mass-weighted mean of particle velocities that
  /// stays bounded, so with FLIP, PIC or uGIMP APIC they need no cutoff and keep every nodal force. Cf. Uintah's min_mass_for_acceleration
  /// (MPMFlags; there the whole acceleration is zeroed below an absolute mass). uGIMP cells take no
  /// cutoff in any scheme: their weights and gradients both fade in as a particle's domain reaches a node,
  /// and without it USL ran every measured case (the block entering empty cells at 9.8 m/s, the quick and
  /// the paper's columns with FLIP and APIC to 20 s and 8 s), while the forces it dropped made USL's
  /// sliding block on a one-sided contact miss Coulomb by 5 % (FLIP) and 9 % (APIC) in v (now 0.6 %).
  double small_mass_ = 0.0;
  double mass_tolerance_ = 1.0e-15;  ///< nodes with no more mass are empty (kMassTolerance, scaled for tiny densities)
  std::vector<std::int32_t> constraint_of_;       ///< per node: index into constraints_, -1: unconstrained
  std::vector<NodeConstraint<kDim>> constraints_;      ///< the constrained nodes' velocity and friction constraints
  std::vector<NormalMemory> normal_memory_;       ///< per constraint: its lagged normal force (lagged_friction.hpp)
  bool lagged_friction_ = false;                  ///< some friction constraint has a normal_lag
  /// A one-sided contact node (NodeConstraint::one_sided): its constraint index, the lattice index, along
  /// the wall's normal, of the wall face it belongs to (the innermost node of its run of contact nodes:
  /// nodes behind the face lie inside the rigid wall), and the cells whose particles may touch the face
  /// there: contact_cells_[cells_begin, cells_end) (wall_contact.cpp).
  struct WallContactNode {
    std::size_t constraint;
    int face;
    std::size_t cells_begin, cells_end;
  };
  /// The one-sided contacts, and per constraint whether the material touches the wall there this step
  /// (1 for every other constraint).
  std::vector<WallContactNode> contact_nodes_;
  std::vector<std::int64_t> contact_cells_;  ///< the contact nodes' cells (lattice cell indices, as cell_of)
  std::vector<std::uint8_t> touching_;

  // particles
  ParticleArrays cur_, nxt_;
  std::vector<std::uint32_t> order_;      ///< live particles (storage index in cur_), by key (cell_key) then id
  std::vector<std::int32_t> base_;        ///< per iteration index: stencil's first node
  std::vector<std::int32_t> local_;       ///< per iteration index: stencil's first node in the chunk's band
  /// The particles' weight blocks wx, wy, dwx/h, dwy/h (4 * width values per iteration index k, from
  /// 4 * width * k on), interleaved within a stencil run (kRunLanes consecutive particles on one
  /// stencil, from index k0): entry e of particle k0 + l at 4 * width * k0 + 4 e + l, so that the run
  /// kernels load an entry of all four at once (stencil_runs.hpp).
  std::vector<double> weights_;
  std::vector<std::int32_t> run_lane_;  ///< per iteration index: its lane in its stencil run, -1 outside one
  /// Whether p2g forms stencil runs: with 4-double vector registers (common::wide_vector_kernels) unless
  /// ExecutionOptions turn them off; the results are the same either way, bit for bit.
  bool stencil_runs_ = true;
  static constexpr int kRunLanes = 4;
  /// The weights of the particle at iteration index k, in a run or not.
  template <int W>
  StencilWeights<W> stencil_weights(std::size_t k) const {
    const std::int32_t lane = run_lane_[k];
    return lane < 0 ? StencilWeights<W>(&weights_[4 * W * k])
                    : StencilWeights<W>(&weights_[4 * W * (k - static_cast<std::size_t>(lane)) + lane], kRunLanes);
  }
  std::vector<double> dstrain_;           ///< per iteration index: 3 (scratch for the stress update)
  std::vector<double> stencil_offset_;    ///< APIC, per iteration index: first stencil node - particle (x, y), m
  std::vector<double> affine_weights_;    ///< APIC, per iteration index: ax, ay (2 * width; p2g's, reread by the remap)
  std::vector<std::size_t> chunk_;        ///< chunks_ + 1 boundaries (iteration indices), at cell boundaries
  std::size_t chunks_ = 0;
  static constexpr std::size_t kChunkParticles = 2048;  ///< target chunk size
  std::vector<std::uint32_t> bucket_;     ///< counting-sort scratch (keys + 1: kKeysPerCell x cells + 1)
  std::vector<std::uint32_t> sorted_;     ///< counting-sort scratch
  OrderMerge merge_;                      ///< resort_particles: the particles that changed key, merged in

  // materials and analysis
  std::vector<Material> materials_;
  bool uniform_material_ = true;
  Scheme scheme_ = Scheme::USF;
  VelocityTransfer transfer_;  ///< FLIP, PIC, blend or APIC (velocity_transfer.hpp)
  bool locate_ = true;
  double courant_number_ = 0;
  double damping_ = 0.0;
  BodyForce body_force_;   ///< gravity and the shaken base's inertial force (body_force.hpp)
  ExternalLoads loads_;    ///< concentrated nodal forces and particle tractions (external_loads.hpp)
  std::array<double, kDim> body_force_now_{};  ///< body_force_ at the start of the current step, per axis
  StressSmoothing smoothing_ = StressSmoothing::None;
  double dt_ = 0;
  long long step_index_ = 0;
  int threads_ = 1;

  /// The first problem a chunk met in a step (by iteration index), reported after the step.
  enum class ProblemKind { None, VelocityNotFinite, RunawayVelocity, LeftTheGrid, StressNotFinite };
  struct Problem {
    std::size_t k = static_cast<std::size_t>(-1);
    ProblemKind kind = ProblemKind::None;
    std::int64_t id = 0;
    double a = 0, b = 0;
  };
  std::vector<Problem> problems_;
  void report(std::size_t c, std::size_t k, ProblemKind kind, std::int64_t id, double a, double b);
};

}  // namespace mpm::core
