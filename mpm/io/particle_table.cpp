#include "mpm/io/particle_table.hpp"

#include <hdf5.h>
#include <hdf5_hl.h>

#include <cassert>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <system_error>
#include <stdexcept>

#include "common/atomic_file.hpp"
#include "common/finite_number.hpp"
#include "common/input_error.hpp"

namespace mpm::io {
namespace {

static_assert(sizeof(ParticleRecord) == 416, "CB-Geo record size");
static_assert(offsetof(ParticleRecord, cell_id) == 232, "CB-Geo cell_id offset");
static_assert(offsetof(ParticleRecord, status) == 240, "CB-Geo status offset");
static_assert(offsetof(ParticleRecord, svars) == 256, "CB-Geo svars offset");

enum class MemberType { Int64, Float64, UInt8, UInt32 };

struct Member {
  std::string name;
  std::size_t offset;
  MemberType type;
};

// The schema, in the FILE's member order (status before cell_id).
std::vector<Member> schema() {
  std::vector<Member> m;
  auto f64 = [&](const char* name, std::size_t off) { m.push_back({name, off, MemberType::Float64}); };
#define GEOFLOW_F64(member) f64(#member, offsetof(ParticleRecord, member))
  m.push_back({"id", offsetof(ParticleRecord, id), MemberType::Int64});
  GEOFLOW_F64(mass); GEOFLOW_F64(volume); GEOFLOW_F64(pressure);
  GEOFLOW_F64(coord_x); GEOFLOW_F64(coord_y); GEOFLOW_F64(coord_z);
  GEOFLOW_F64(displacement_x); GEOFLOW_F64(displacement_y); GEOFLOW_F64(displacement_z);
  GEOFLOW_F64(nsize_x); GEOFLOW_F64(nsize_y); GEOFLOW_F64(nsize_z);
  GEOFLOW_F64(velocity_x); GEOFLOW_F64(velocity_y); GEOFLOW_F64(velocity_z);
  GEOFLOW_F64(stress_xx); GEOFLOW_F64(stress_yy); GEOFLOW_F64(stress_zz);
  GEOFLOW_F64(tau_xy); GEOFLOW_F64(tau_yz); GEOFLOW_F64(tau_xz);
  GEOFLOW_F64(strain_xx); GEOFLOW_F64(strain_yy); GEOFLOW_F64(strain_zz);
  GEOFLOW_F64(gamma_xy); GEOFLOW_F64(gamma_yz); GEOFLOW_F64(gamma_xz);
  GEOFLOW_F64(epsilon_v);
#undef GEOFLOW_F64
  m.push_back({"status", offsetof(ParticleRecord, status), MemberType::UInt8});
  m.push_back({"cell_id", offsetof(ParticleRecord, cell_id), MemberType::Int64});
  m.push_back({"material_id", offsetof(ParticleRecord, material_id), MemberType::UInt32});
  m.push_back({"nstate_vars", offsetof(ParticleRecord, nstate_vars), MemberType::UInt32});
  for (std::size_t k = 0; k < kMaxStateVariables; ++k)
    f64(("svars_" + std::to_string(k)).c_str(), offsetof(ParticleRecord, svars) + k * sizeof(double));
  assert(m.size() == kParticleTableMembers);  // FORMATS.md section 4: 53 members
  return m;
}

hid_t native_type(MemberType t) {
  switch (t) {
    case MemberType::Int64: return H5T_NATIVE_INT64;
    case MemberType::Float64: return H5T_NATIVE_DOUBLE;
    case MemberType::UInt8: return H5T_NATIVE_UINT8;
    case MemberType::UInt32: return H5T_NATIVE_UINT32;
  }
  return H5T_NATIVE_DOUBLE;
}

/// Closes an HDF5 handle on scope exit.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() { if (id_ >= 0) close_(id_); }
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  /// Gives up ownership (the caller closes the handle).
  hid_t release() {
    const hid_t id = id_;
    id_ = -1;
    return id;
  }
 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

/// Silences HDF5's automatic error stack printing while alive (we report our own errors).
class QuietHdf5 {
 public:
  QuietHdf5() { H5Eget_auto2(H5E_DEFAULT, &func_, &data_); H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }
  ~QuietHdf5() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }
 private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

}  // namespace

void write_particle_table(const std::filesystem::path& file, std::span<const ParticleRecord> records) {
  write_particle_table(file, records, nullptr);
}

void write_particle_table(const std::filesystem::path& file, std::span<const ParticleRecord> records,
                          const std::function<void(std::int64_t file_id)>& add_datasets) {
  QuietHdf5 quiet;
  const auto members = schema();
  std::vector<const char*> names;
  std::vector<std::size_t> offsets;
  std::vector<hid_t> types;
  for (const auto& m : members) {
    names.push_back(m.name.c_str());
    offsets.push_back(m.offset);
    types.push_back(native_type(m.type));
  }
  const auto temporary = common::temporary_path_for(file);
  {
    Handle h5(H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
    if (!h5.valid()) {
      common::discard_temporary(temporary);
      throw common::OutputError(file.string() + ": cannot create HDF5 file");
    }
    const hsize_t chunk = records.empty() ? 1 : std::min<hsize_t>(records.size(), 10000);
    const herr_t status = H5TBmake_table("Table Title", h5.get(), "table", members.size(), records.size(),
                                         sizeof(ParticleRecord), names.data(), offsets.data(), types.data(),
                                         chunk, nullptr, 0, records.data());
    if (status < 0) {
      common::discard_temporary(temporary);
      throw common::OutputError(file.string() + ": writing the particle table failed (disk full?)");
    }
    if (add_datasets) {
      try {
        add_datasets(static_cast<std::int64_t>(h5.get()));
      } catch (...) {
        common::discard_temporary(temporary);
        throw;
      }
    }
    // Closing flushes the metadata: a failure here (a full disk) leaves an unusable file.
    if (H5Fclose(h5.release()) < 0) {
      common::discard_temporary(temporary);
      throw common::OutputError(file.string() + ": closing the HDF5 file failed (disk full?)");
    }
  }
  common::commit_file(temporary, file);
}

namespace {
/// A dataset's declared row count, checked before allocating: against the bytes the file holds (rows
/// stored unfiltered, as H5TB, CB-Geo, h5py and this project write them, take at least `file_row_bytes`
/// each) and against what this machine can hold (`memory_row_bytes` each). Throws common::InputError
/// naming `file` and the dataset (`what`); `items` names the rows in the second message.
void check_declared_rows(const std::filesystem::path& file, hid_t dset, hsize_t rows, std::size_t file_row_bytes,
                         std::size_t memory_row_bytes, const std::string& what, const std::string& items) {
  std::error_code ec;
  const auto file_bytes = std::filesystem::file_size(file, ec);
  Handle plist(H5Dget_create_plist(dset), H5Pclose);
  const bool filtered = plist.valid() && H5Pget_nfilters(plist.get()) > 0;
  const double declared = static_cast<double>(rows) * static_cast<double>(file_row_bytes);
  if (!filtered && !ec && declared > static_cast<double>(file_bytes))
    throw common::InputError(file.string(), what + " declares " + std::to_string(rows) + " rows (" +
                                                std::to_string(file_row_bytes) + " bytes each) but the file has only " +
                                                std::to_string(file_bytes) + " bytes (truncated or corrupt file)");
  if (const auto problem = common::size_problem(static_cast<double>(rows), memory_row_bytes, items); !problem.empty())
    throw common::InputError(file.string(), what + ": " + problem);
}
}  // namespace

std::vector<ParticleRecord> read_particle_table(const std::filesystem::path& file) {
  QuietHdf5 quiet;
  if (!std::filesystem::exists(file)) throw common::InputError(file.string(), "particle file not found");
  Handle h5(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!h5.valid()) throw common::InputError(file.string(), "not a readable HDF5 file");
  Handle dset(H5Dopen2(h5.get(), "table", H5P_DEFAULT), H5Dclose);
  if (!dset.valid()) throw common::InputError(file.string(), "no dataset \"/table\" (expected CB-Geo's particle table)");
  Handle ftype(H5Dget_type(dset.get()), H5Tclose);
  if (H5Tget_class(ftype.get()) != H5T_COMPOUND)
    throw common::InputError(file.string(), "\"/table\" is not a compound dataset");
  Handle space(H5Dget_space(dset.get()), H5Sclose);
  if (H5Sget_simple_extent_ndims(space.get()) != 1)
    throw common::InputError(file.string(), "\"/table\" must be one-dimensional");
  hsize_t n = 0;
  H5Sget_simple_extent_dims(space.get(), &n, nullptr);
  check_declared_rows(file, dset.get(), n, H5Tget_size(ftype.get()), sizeof(ParticleRecord), "\"/table\"",
                      "particle rows");

  // Memory type matched by member name; every schema member must be in the file.
  Handle mtype(H5Tcreate(H5T_COMPOUND, sizeof(ParticleRecord)), H5Tclose);
  for (const auto& m : schema()) {
    if (H5Tget_member_index(ftype.get(), m.name.c_str()) < 0)
      throw common::InputError(file.string(), "particle table has no member \"" + m.name + "\"");
    H5Tinsert(mtype.get(), m.name.c_str(), m.offset, native_type(m.type));
  }
  std::vector<ParticleRecord> records(n);
  if (n > 0 && H5Dread(dset.get(), mtype.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, records.data()) < 0)
    throw common::InputError(file.string(), "reading \"/table\" failed (truncated or corrupt file?)");
  const auto members = schema();
  for (const auto& r : records) {
    if (r.nstate_vars > kMaxStateVariables)
      throw common::InputError(file.string(), "particle " + std::to_string(r.id) + ": nstate_vars " +
                                                  std::to_string(r.nstate_vars) + " exceeds 20");
    // A NaN or infinity would be carried into every later output: the file is not a usable state.
    for (const auto& m : members) {
      if (m.type != MemberType::Float64) continue;
      double v = 0;
      std::memcpy(&v, reinterpret_cast<const char*>(&r) + m.offset, sizeof v);
      if (!std::isfinite(v))
        throw common::InputError(file.string(), "particle " + std::to_string(r.id) + ": " + m.name + " is " +
                                                    (std::isnan(v) ? "nan" : "infinite") +
                                                    " (a particle file must hold finite values)");
    }
  }
  return records;
}

namespace {
/// Writes `rows` x `columns` doubles as the 2-D float64 dataset `name` of the open file `file_id`.
void write_rows(std::int64_t file_id, const char* name, const double* data, std::size_t rows, std::size_t columns,
                const std::string& shown) {
  QuietHdf5 quiet;
  const hsize_t dims[2] = {static_cast<hsize_t>(rows), static_cast<hsize_t>(columns)};
  Handle space(H5Screate_simple(2, dims, nullptr), H5Sclose);
  Handle dset(H5Dcreate2(static_cast<hid_t>(file_id), name, H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT,
                         H5P_DEFAULT),
              H5Dclose);
  if (!dset.valid() || (rows > 0 && H5Dwrite(dset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0))
    throw std::runtime_error(shown + ": writing the /" + std::string(name) + " dataset failed");
}

/// Reads the 2-D float dataset `name` of `file` as rows of `Columns` doubles: std::nullopt when the file
/// has none; common::InputError naming the file when it has another shape (`rows`: the rows expected, or
/// nullopt for any number) or cannot be read. `shape`: the expected shape in words, for the message.
template <std::size_t Columns>
std::optional<std::vector<std::array<double, Columns>>> read_rows(const std::filesystem::path& file, const char* name,
                                                                  std::optional<std::size_t> rows, const std::string& shape) {
  QuietHdf5 quiet;
  Handle h5(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!h5.valid()) throw common::InputError(file.string(), "not a readable HDF5 file");
  if (H5Lexists(h5.get(), name, H5P_DEFAULT) <= 0) return std::nullopt;
  const std::string what = "dataset \"/" + std::string(name) + "\"";
  Handle dset(H5Dopen2(h5.get(), name, H5P_DEFAULT), H5Dclose);
  if (!dset.valid()) throw common::InputError(file.string(), what + " cannot be opened");
  Handle ftype(H5Dget_type(dset.get()), H5Tclose);
  Handle space(H5Dget_space(dset.get()), H5Sclose);
  hsize_t dims[2] = {0, 0};
  if (H5Tget_class(ftype.get()) != H5T_FLOAT || H5Sget_simple_extent_ndims(space.get()) != 2 ||
      H5Sget_simple_extent_dims(space.get(), dims, nullptr) < 0 || (rows && dims[0] != *rows) || dims[1] != Columns)
    throw common::InputError(file.string(), what + " must be " + shape);
  check_declared_rows(file, dset.get(), dims[0], Columns * H5Tget_size(ftype.get()), Columns * sizeof(double), what,
                      "rows");
  std::vector<std::array<double, Columns>> out(static_cast<std::size_t>(dims[0]));
  if (!out.empty() && H5Dread(dset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
    throw common::InputError(file.string(), "reading " + what + " failed (truncated or corrupt file?)");
  return out;
}
}  // namespace

template <int dim>
void write_affine_dataset(std::int64_t file_id, std::span<const AffineMatrix<dim>> affine, const std::string& shown) {
  constexpr std::size_t columns = dim * dim;
  write_rows(file_id, kAffineDataset, affine.empty() ? nullptr : affine.front().data(), affine.size(), columns, shown);
}

template <int dim>
std::optional<std::vector<AffineMatrix<dim>>> read_affine_dataset(const std::filesystem::path& file, std::size_t rows) {
  constexpr std::size_t columns = dim * dim;
  const std::string layout = dim == 3 ? "the 3 x 3 B_p row by row, a 3D deck" : "B_xx B_xy B_yx B_yy, a 2D deck";
  return read_rows<columns>(file, kAffineDataset, rows,
                            std::to_string(rows) + " x " + std::to_string(columns) +
                                " floats (one row per particle of /table: " + layout + ")");
}

template void write_affine_dataset<2>(std::int64_t, std::span<const AffineMatrix<2>>, const std::string&);
template void write_affine_dataset<3>(std::int64_t, std::span<const AffineMatrix<3>>, const std::string&);
template std::optional<std::vector<AffineMatrix<2>>> read_affine_dataset<2>(const std::filesystem::path&, std::size_t);
template std::optional<std::vector<AffineMatrix<3>>> read_affine_dataset<3>(const std::filesystem::path&, std::size_t);

void write_friction_memory_dataset(std::int64_t file_id, std::span<const FrictionMemoryRecord> memory,
                                   const std::string& shown) {
  std::vector<double> rows;
  rows.reserve(3 * memory.size());
  for (const FrictionMemoryRecord& r : memory) rows.insert(rows.end(), {static_cast<double>(r.node), r.force, r.mass});
  write_rows(file_id, kFrictionMemoryDataset, rows.data(), memory.size(), 3, shown);
}

std::optional<std::vector<FrictionMemoryRecord>> read_friction_memory_dataset(const std::filesystem::path& file) {
  const auto rows = read_rows<3>(file, kFrictionMemoryDataset, std::nullopt, "n x 3 floats (node, force N_s, node mass)");
  if (!rows) return std::nullopt;
  std::vector<FrictionMemoryRecord> memory;
  memory.reserve(rows->size());
  for (std::size_t k = 0; k < rows->size(); ++k) {
    const auto& [node, force, mass] = (*rows)[k];
    // A node index is stored as a float64: exact below 2^53, so an integral value in range is the node.
    if (!(node >= 0 && node < 9.0e15 && node == std::floor(node)) || !(force >= 0 && std::isfinite(force)) ||
        !(mass > 0 && std::isfinite(mass)))
      throw common::InputError(file.string(), "dataset \"/" + std::string(kFrictionMemoryDataset) + "\" row " +
                                                  std::to_string(k) + ": expected a node index >= 0, a force >= 0 "
                                                  "and a mass > 0 (finite)");
    memory.push_back({static_cast<std::int64_t>(node), force, mass});
  }
  return memory;
}

void write_pore_pressure_dataset(std::int64_t file_id, std::span<const PorePressureRecord> rows, const std::string& shown) {
  std::vector<double> values;
  values.reserve(3 * rows.size());
  for (const PorePressureRecord& r : rows) values.insert(values.end(), {r.pressure, r.sigma_v0, r.ru});
  write_rows(file_id, kPorePressureDataset, values.data(), rows.size(), 3, shown);
}

std::optional<std::vector<PorePressureRecord>> read_pore_pressure_dataset(const std::filesystem::path& file,
                                                                         std::size_t rows) {
  const auto values = read_rows<3>(file, kPorePressureDataset, rows,
                                   std::to_string(rows) + " x 3 floats (p, sigma'v0, r_u per particle of /table)");
  if (!values) return std::nullopt;
  std::vector<PorePressureRecord> out;
  out.reserve(values->size());
  for (std::size_t k = 0; k < values->size(); ++k) {
    const auto& [p, sigma_v0, ru] = (*values)[k];
    if (!std::isfinite(p) || !std::isfinite(sigma_v0) || !std::isfinite(ru))
      throw common::InputError(file.string(), "dataset \"/" + std::string(kPorePressureDataset) + "\" row " +
                                                  std::to_string(k) + ": expected finite p, sigma'v0 and r_u");
    out.push_back({p, sigma_v0, ru});
  }
  return out;
}

std::string particle_file_name(long long step, long long nsteps) {
  const int digits = nsteps > 0 ? static_cast<int>(std::log10(static_cast<double>(nsteps))) + 1 : 1;
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "particles%0*lld.h5", digits, step);
  return buffer;
}

void skip_hdf5_exit_cleanup() { H5dont_atexit(); }

}  // namespace mpm::io
