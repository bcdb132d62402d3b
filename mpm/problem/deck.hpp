#pragma once
// The description of a problem: what mpm/io fills from a CB-Geo-style mpm.json (+ mesh, particles, entity
// sets, stresses, or the resume HDF5 file) and what mpm/core builds a simulation from; neither library
// includes the other's headers for it. Plain data, SI units, angles in radians, everything already validated
// by the reader (the core only asserts).
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "mpm/problem/math_function.hpp"
#include "mpm/problem/particle_record.hpp"

namespace mpm {

/// The shape functions on the lattice's cells: linear (CB-Geo's ED2Q4, ED3H8) or GIMP over the cell and its
/// halo of neighbouring nodes (ED2Q16G, ED3H64G). The 3D names are the same families as the 2D ones (equal
/// values): the dimension is Grid::dim, so `cell_type == CellType::Gimp16` means GIMP in 2D and 3D alike.
enum class CellType { Linear4 /* ED2Q4 */, Gimp16 /* ED2Q16G */, Linear8 = Linear4 /* ED3H8 */, Gimp64 = Gimp16 /* ED3H64G */ };
enum class Scheme { USF, USL, MUSL };
/// The particle-grid velocity transfer (analysis.transfer; mpm/core/velocity_transfer.hpp).
enum class Transfer { FLIP, PIC, APIC };

/// The most axes a problem has (CB-Geo's 3D decks: MPMExplicit3D, Ascii3D).
inline constexpr int kMaxDim = 3;

/// A uniform rectangular node lattice of `dim` axes. Along axis d node i_d sits at origin[d] + i_d *
/// spacing[d]; node (i, j) has index i + j * nodes_per_axis[0] (3D: i + nodes_per_axis[0] * (j +
/// nodes_per_axis[1] * k)). Entries d >= dim are unused. For GIMP decks the lattice includes CB-Geo's
/// halo ring of nodes.
struct Grid {
  /// The problem's dimension: 2 for MPMExplicit2D decks (Ascii2D), 3 for MPMExplicit3D decks (Ascii3D).
  int dim = 2;
  std::array<double, kMaxDim> origin{};          ///< coordinates of node 0, m
  std::array<double, kMaxDim> spacing{1, 1, 1};  ///< cell size, m
  std::array<int, kMaxDim> nodes_per_axis{};
  CellType cell_type = CellType::Linear4;
  /// The region covered by the mesh file's cells (where particles may be), [region_min[d], region_max[d]]
  /// on axis d; outside it a particle has left the grid.
  std::array<double, kMaxDim> region_min{}, region_max{};
  /// The lattice's nodes: the product of nodes_per_axis over the dim axes.
  std::size_t node_count() const {
    std::size_t count = 1;
    for (int d = 0; d < dim; ++d) count *= static_cast<std::size_t>(nodes_per_axis[d]);
    return count;
  }
};

/// CB-Geo velocity constraint: velocity component `dir` (0 = x, 1 = y, 2 = z in 3D) fixed to `velocity` on `nodes`.
struct VelocityConstraint {
  std::vector<int> nodes;  ///< lattice node indices
  int dir = 0;
  double velocity = 0;
};

/// CB-Geo friction constraint (FORMATS.md section 5): boundary normal along `dir`, outward sign
/// `sign_n`, Coulomb coefficient `friction`.
struct FrictionConstraint {
  std::vector<int> nodes;
  int dir = 1;
  int sign_n = -1;
  double friction = 0;
  /// normal_lag (this code's key, not CB-Geo's): the friction strength follows the normal force over a
  /// slip distance (m) plus a reference speed (m/s) (mpm/core/lagged_friction.hpp); 0: none
  double lag_slip_distance = 0;
  double lag_reference_velocity = 0;
};

/// The constitutive model. CB-Geo names each model per dimension (LinearElastic2D / LinearElastic3D); the 3D
/// names are the same models as the 2D ones (equal values), the dimension being Grid::dim.
enum class MaterialType {
  LinearElastic2D,
  MohrCoulomb2D,
  LinearElastic3D = LinearElastic2D,
  MohrCoulomb3D = MohrCoulomb2D
};

/// A Mohr-Coulomb particle whose volume has grown past 3 times its initial one (porosity 0.4 -> 0.8) is
/// taken as disconnected grains: no soil skeleton carries stress that loose (mpm/core/materials.hpp).
inline constexpr double kDefaultSeparationVolumeRatio = 3.0;

/// CB-Geo material parameters (angles converted to radians by the reader).
struct MaterialSpec {
  unsigned id = 0;
  MaterialType type = MaterialType::LinearElastic2D;
  double density = 0, youngs_modulus = 0, poisson_ratio = 0;
  // MohrCoulomb2D only:
  double friction = 0, dilation = 0, cohesion = 0;
  double residual_friction = 0, residual_dilation = 0, residual_cohesion = 0;
  double peak_pdstrain = 0, residual_pdstrain = 0;
  double tension_cutoff = 0;
  bool softening = false;
  /// Extension: stress-free separation beyond this volume ratio V / V0 (V0 = mass / density); 0 = never.
  double separation_volume_ratio = kDefaultSeparationVolumeRatio;
};

struct Analysis {
  Scheme scheme = Scheme::USF;
  bool velocity_update = false;  ///< true: PIC (CB-Geo), false: FLIP (kept consistent with `transfer`)
  Transfer transfer = Transfer::FLIP;  ///< extension analysis.transfer ("flip", "pic", "apic")
  double pic_blend = 0.0;        ///< extension: FLIP only; 0 = pure FLIP, 1 = pure PIC
  bool locate_particles = true;  ///< true: a particle leaving the grid is an error; false: it is removed
  double dt = 0;                 ///< s; with cfl > 0 the engine chooses dt and this is the upper bound
  double cfl = 0;                ///< extension: automatic dt = cfl * h / c_p when > 0
  long long nsteps = 0;
  double cundall_damping = 0;    ///< Cundall local damping factor (0 = none)
  Eigen::Vector2d gravity = Eigen::Vector2d::Zero();  ///< m/s2, x and y
  double gravity_z = 0;  ///< m/s2, the z component of a 3D deck's gravity (0 in 2D)
  std::string stress_smoothing = "none";  ///< extension: checkerboard remedy ("none" or a named method)
};

struct Output {
  std::filesystem::path path;  ///< results folder (CB-Geo post_processing.path, relative to the working dir)
  std::string uuid;            ///< run name: outputs go to path/uuid/
  long long output_steps = 100;
  /// CB-Geo post_processing.vtk / vtk_statevars: the particle arrays of the VTK files
  /// (particles<step>.vtp + particles.pvd), as names of particle_fields() / CB-Geo state variables.
  /// Both empty: no VTK files (ParaView opens particles.xdmf).
  std::vector<std::string> vtk_fields;
  std::vector<std::string> vtk_statevars;
  /// Extension post_processing.particle_output_steps: the output steps (multiples of output_steps, below
  /// nsteps, ascending) after which the particle files are written; series.csv keeps a row at every
  /// output step. Empty (the key absent): particle files at every output step, as CB-Geo.
  std::vector<long long> particle_output_steps;
  /// Whether the output after loop step `step` (an output step) writes particle files.
  bool writes_particles(long long step) const {
    return particle_output_steps.empty() ||
           std::binary_search(particle_output_steps.begin(), particle_output_steps.end(), step);
  }
};

/// Extension (external_loading_conditions.base_acceleration): the grid's base, walls and whole frame
/// move with a ground acceleration a_g(t) = acceleration * f(t) along axis `dir` (f a math function), and
/// the run is made in that moving frame: every particle feels the inertial body force -m a_g(t) besides
/// gravity (d'Alembert; OpenSees' UniformExcitation, whose responses are relative to the ground).
struct BaseAcceleration {
  int dir = 0;
  double acceleration = 0;  ///< m/s2, the scale of f
  MathFunction history;
  double at(double t) const { return acceleration * history.value(t); }
};

/// CB-Geo concentrated_nodal_forces: a force `force` * f(t) (N per unit thickness) along `dir` at each
/// node of `nodes`, added to the nodal external force every step (CB-Geo Node::apply_concentrated_force).
struct NodalForce {
  std::vector<int> nodes;  ///< lattice node indices
  int dir = 0;
  double force = 0;
  MathFunction function;  ///< f = 1 without a math_function_id
};

/// CB-Geo particle_surface_traction: a traction `traction` * f(t) (Pa) along `dir` on each particle of a
/// particle set, applied as the force traction * V / l0 (V the particle's volume, l0 = sqrt(V0) its side
/// when it was made; CB-Geo Particle::assign_traction) mapped to the nodes with the shape functions.
struct ParticleTraction {
  std::vector<std::int64_t> particles;  ///< particle ids
  int dir = 0;
  double traction = 0;
  MathFunction function;
};

struct Deck {
  std::filesystem::path working_dir;  ///< the -f folder
  Grid grid;
  std::vector<VelocityConstraint> velocity_constraints;
  std::vector<FrictionConstraint> friction_constraints;
  std::vector<MaterialSpec> materials;
  /// Initial particles. Records with volume <= 0 get CB-Geo's defaults from the engine: volume = cell
  /// area / particles in that cell, mass = density * volume, nsize = 2 / sqrt(particles in the cell).
  std::vector<ParticleRecord> particles;
  /// APIC affine matrices B_p (Bxx, Bxy, Byx, Byy, m^2/s), one per particle in `particles` order; empty:
  /// all zero (a fresh start, a resume file without the dataset, or a 3D deck).
  std::vector<AffineMatrix<2>> particle_affine;
  /// As particle_affine for a 3D deck (Grid::dim = 3): the 3 x 3 B_p row by row (AffineMatrix<3>); empty on
  /// a 2D deck.
  std::vector<AffineMatrix<3>> particle_affine_3d;
  /// The lagged friction strengths of a resumed run (its file's kFrictionMemoryDataset): the nodes listed
  /// start from them, every other node from its instantaneous normal force; empty: all of them.
  std::vector<FrictionMemoryRecord> friction_memory;
  /// The pore pressure rows of a resumed run's particles (its file's kPorePressureDataset), in `particles`
  /// order; nullopt when the file has none. Carried unchanged into every output file (resume_extras.hpp).
  std::optional<std::vector<PorePressureRecord>> particle_pore_pressure;
  Analysis analysis;
  std::optional<BaseAcceleration> base_acceleration;
  std::vector<NodalForce> nodal_forces;
  std::vector<ParticleTraction> particle_tractions;
  Output output;
  bool resumed = false;         ///< particles came from a resume file
  long long first_step = 0;     ///< the first loop step to run (resume step + 1 when resumed)
  std::vector<std::string> warnings;  ///< things the reader accepted but the user should know (printed by main)
};

}  // namespace mpm
