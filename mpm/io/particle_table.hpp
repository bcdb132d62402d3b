#pragma once
// CB-Geo MPM's particle HDF5 table ("/table", 53 members, 416-byte records), defined once for the
// writer (fem2mpm, mpm) and the reader (mpm resume). Schema: ../shared/FORMATS.md section 4, read
// from CB-Geo's include/hdf5_particle.h. SI units, tension positive, engineering shear strains.
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "mpm/problem/particle_record.hpp"

namespace mpm::io {


/// Number of members in the file's compound type.
inline constexpr std::size_t kParticleTableMembers = 53;

/// Writes `records` as CB-Geo's table (H5TB attributes, extendible chunked dataset "/table").
/// The file is written to a temporary name and renamed, so a failed write leaves no file.
/// Throws std::runtime_error naming the file on failure.
void write_particle_table(const std::filesystem::path& file, std::span<const ParticleRecord> records);

/// As above; `add_datasets(file_id)` receives the open HDF5 file (an hid_t) after "/table" is written
/// and before the rename, to add datasets of its own (CB-Geo's reader opens "/table" only, so extra
/// datasets keep the file resumable by CB-Geo). It reports failure by throwing.
void write_particle_table(const std::filesystem::path& file, std::span<const ParticleRecord> records,
                          const std::function<void(std::int64_t file_id)>& add_datasets);

/// Reads a particle table written by CB-Geo, by this project, or by h5py with the same member
/// names (members are matched by name, so member order in the file does not matter).
/// Throws common::InputError naming the file and the missing member or the problem.
std::vector<ParticleRecord> read_particle_table(const std::filesystem::path& file);

/// The APIC affine matrices beside "/table" (this project's extension; CB-Geo's reader opens "/table" only):
/// a 2-D float64 dataset of rows x dim^2 columns, one row per particle (row k for particle k of "/table"):
/// B_p row by row (m^2/s), AffineMatrix<dim>: 4 columns B_xx B_xy B_yx B_yy for a 2D deck, 9 for a 3D one.
inline constexpr const char* kAffineDataset = "apic_affine";

/// Writes kAffineDataset (rows x dim^2) into the open HDF5 file `file_id` (an hid_t, e.g. from
/// write_particle_table's add_datasets). Throws std::runtime_error naming `shown` on failure. Defined for
/// dim 2 and 3 (dim is not deduced: `write_affine_dataset<3>(...)` for 3D).
template <int dim = 2>
void write_affine_dataset(std::int64_t file_id, std::span<const AffineMatrix<dim>> affine, const std::string& shown);

/// Reads kAffineDataset of a `dim`-axis deck from `file`: std::nullopt when the file has none;
/// common::InputError naming the file and the dataset when it is not `rows` x dim^2 float64 (a 2D file on
/// a 3D deck, or the reverse, among others) or cannot be read. Defined for dim 2 and 3.
template <int dim = 2>
std::optional<std::vector<AffineMatrix<dim>>> read_affine_dataset(const std::filesystem::path& file, std::size_t rows);

/// The lagged friction strengths of a run with friction_constraints[].normal_lag (mpm/core/lagged_friction.hpp),
/// so that a resumed run continues bit for bit (this project's extension, beside "/table"): a 2-D float64
/// dataset of n x 3 columns, node index, lagged normal force N_s (N per m) and the node's mass when N_s was
/// last updated (kg per m), one row per frictional node that holds a memory.
inline constexpr const char* kFrictionMemoryDataset = "friction_memory";


/// Writes kFrictionMemoryDataset into the open HDF5 file `file_id`. Throws std::runtime_error naming
/// `shown` on failure.
void write_friction_memory_dataset(std::int64_t file_id, std::span<const FrictionMemoryRecord> memory,
                                   const std::string& shown);

/// Reads kFrictionMemoryDataset from `file`: std::nullopt when the file has none; common::InputError
/// naming the file and row when it is not n x 3 floats, a node index is not a whole number >= 0, a force
/// is negative or a mass not positive (or either not finite).
std::optional<std::vector<FrictionMemoryRecord>> read_friction_memory_dataset(const std::filesystem::path& file);

/// The pore pressure state of each particle at the FEM -> MPM transfer of a u-p model (fem2mpm --pore-pressure;
/// this project's extension beside "/table", which CB-Geo's reader ignores): a 2-D float64 dataset of rows x 3
/// columns, row k for particle k of "/table": the pore pressure p and the reference vertical effective stress
/// sigma'v0 (Pa, both compression positive) and the excess pore pressure ratio r_u = (p - p0) / sigma'v0.
/// mpm reads it on resume and writes it into every output file, each particle keeping its transfer-time row.
inline constexpr const char* kPorePressureDataset = "pore_pressure";


/// Writes kPorePressureDataset (rows x 3; zero rows is a dataset too) into the open HDF5 file `file_id`.
/// Throws std::runtime_error naming `shown` on failure.
void write_pore_pressure_dataset(std::int64_t file_id, std::span<const PorePressureRecord> rows, const std::string& shown);

/// Reads kPorePressureDataset from `file`: std::nullopt when the file has none; common::InputError naming the
/// file (and the row) when it is not `rows` x 3 floats or a value is not finite.
std::optional<std::vector<PorePressureRecord>> read_pore_pressure_dataset(const std::filesystem::path& file,
                                                                         std::size_t rows);


/// CB-Geo's output name for `step` of a run of `nsteps` steps: "particles" + step zero-padded to
/// int(log10(nsteps)) + 1 digits + ".h5" (e.g. step 250 of 1001 -> "particles0250.h5").
std::string particle_file_name(long long step, long long nsteps);

/// For a program's main, before any HDF5 call: HDF5's own clean-up at exit is skipped. Every file this
/// project opens is closed by its owner; the library's atexit pass would only retry a corrupt file it
/// could not close and print "HDF5: infinite loop closing library" after the program's one-line error.
void skip_hdf5_exit_cleanup();

}  // namespace mpm::io
