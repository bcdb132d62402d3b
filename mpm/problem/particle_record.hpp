#pragma once
// The particles of a problem as CB-Geo stores them (include/hdf5_particle.h) and the state this project keeps
// beside them for an exact resume: what mpm/io reads and writes (particle_table.hpp) and mpm/core runs.
// SI units, tension positive, engineering shear strains.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace mpm {

inline constexpr std::size_t kMaxStateVariables = 20;

/// One particle as CB-Geo stores it, in 2D and 3D alike (CB-Geo's HDF5Particle has the same 53 members in
/// both): a 3D particle uses every member (x y z; stresses xx yy zz xy yz xz; engineering strains in the same
/// order), a 2D one holds z = 0 in its coordinate, displacement, velocity and size, and tau_yz = tau_xz = 0.
/// The byte layout matches CB-Geo's struct (cell_id before status in memory; in the file's member list
/// status comes first). Value-initialise it
/// (`ParticleRecord r{};`) so padding bytes are zero and files are byte-reproducible.
struct ParticleRecord {
  std::int64_t id = 0;
  double mass = 0, volume = 0, pressure = 0;
  double coord_x = 0, coord_y = 0, coord_z = 0;
  double displacement_x = 0, displacement_y = 0, displacement_z = 0;
  double nsize_x = 0, nsize_y = 0, nsize_z = 0;  ///< GIMP size in natural cell coordinates (2/ppd)
  double velocity_x = 0, velocity_y = 0, velocity_z = 0;
  double stress_xx = 0, stress_yy = 0, stress_zz = 0;  ///< Pa; stress_zz is the out-of-plane stress
  double tau_xy = 0, tau_yz = 0, tau_xz = 0;
  double strain_xx = 0, strain_yy = 0, strain_zz = 0;
  double gamma_xy = 0, gamma_yz = 0, gamma_xz = 0;  ///< engineering shear strains
  double epsilon_v = 0;
  std::int64_t cell_id = -1;  ///< -1: the reader searches for the cell
  std::uint8_t status = 1;    ///< 1: active
  std::uint32_t material_id = 0;
  std::uint32_t nstate_vars = 0;
  double svars[kMaxStateVariables] = {};  ///< material state variables in the material's order
};

/// One lagged friction strength (mpm/core/lagged_friction.hpp): a row of io::kFrictionMemoryDataset.
struct FrictionMemoryRecord {
  std::int64_t node = 0;
  double force = 0;  ///< N_s
  double mass = 0;
  bool operator==(const FrictionMemoryRecord&) const = default;
};

/// The pore pressure state of a particle at a u-p transfer: a row of io::kPorePressureDataset.
struct PorePressureRecord {
  double pressure = 0;  ///< p, Pa, compression positive
  double sigma_v0 = 0;  ///< sigma'v0, Pa, compression positive
  double ru = 0;        ///< r_u, -
  bool operator==(const PorePressureRecord&) const = default;
};

/// An APIC affine matrix B_p of a `dim`-axis problem, row by row (m^2/s): 2D Bxx Bxy Byx Byy; 3D Bxx Bxy Bxz
/// Byx Byy Byz Bzx Bzy Bzz.
template <int dim>
using AffineMatrix = std::array<double, static_cast<std::size_t>(dim * dim)>;

/// What a particle file carries beside CB-Geo's "/table" for a bit-for-bit resume: the APIC matrices
/// (empty unless the transfer is APIC: none written; `affine` for a 2D problem, `affine_3d` for a 3D one,
/// at most one of them filled) and the lagged friction strengths (none without a normal_lag; with one,
/// written even when no node holds a memory).
struct ParticleFileExtras {
  std::vector<AffineMatrix<2>> affine;
  std::optional<std::vector<FrictionMemoryRecord>> friction_memory;
  std::vector<AffineMatrix<3>> affine_3d = {};
};

}  // namespace mpm
