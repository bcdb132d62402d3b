#include "mpm/io/results.hpp"

#include <hdf5.h>
#include <hdf5_hl.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "common/atomic_file.hpp"
#include "common/input_error.hpp"
#include "mpm/io/particle_fields.hpp"
#include "mpm/io/resume_extras.hpp"
#include "mpm/io/vtk_files.hpp"

namespace mpm::io {
namespace fs = std::filesystem;

double percentile(std::vector<double> values, double q) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const double pos = q / 100.0 * static_cast<double>(values.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(pos));
  const std::size_t hi = std::min(lo + 1, values.size() - 1);
  const double frac = pos - static_cast<double>(lo);
  return values[lo] + frac * (values[hi] - values[lo]);
}

SeriesRow summarize_state(long long step, double time, double dt, std::span<const ParticleRecord> particles,
                          const Grid& grid, const Eigen::Vector2d& gravity, double gravity_z) {
  SeriesRow row;
  row.dim = grid.dim;
  row.step = step;
  row.time = time;
  row.dt = dt;
  row.particle_count = particles.size();
  const bool three = grid.dim == 3;
  if (particles.empty()) {
    row.runout_x_p98 = row.height_p995 = row.checkerboard_index = std::numeric_limits<double>::quiet_NaN();
    if (three) row.runout_y_p98 = row.runout_x_p98;
    return row;
  }
  // The vertical coordinate: the grid's last axis.
  auto up = [&](const ParticleRecord& p) { return three ? p.coord_z : p.coord_y; };
  std::vector<double> xs, ys, heights;
  xs.reserve(particles.size());
  heights.reserve(particles.size());
  if (three) ys.reserve(particles.size());
  double mass = 0, volume = 0, lowest = std::numeric_limits<double>::infinity(), vmax2 = 0;
  for (const auto& p : particles) {
    xs.push_back(p.coord_x);
    if (three) ys.push_back(p.coord_y);
    heights.push_back(up(p));
    lowest = std::min(lowest, up(p));
    mass += p.mass;
    volume += p.volume;
    double g_dot_x = gravity.x() * p.coord_x + gravity.y() * p.coord_y;
    if (three) g_dot_x += gravity_z * p.coord_z;
    row.potential_energy -= p.mass * g_dot_x;
    row.kinetic_energy_x += 0.5 * p.mass * p.velocity_x * p.velocity_x;
    row.kinetic_energy_y += 0.5 * p.mass * p.velocity_y * p.velocity_y;
    double v2 = p.velocity_x * p.velocity_x + p.velocity_y * p.velocity_y;
    if (three) {
      row.kinetic_energy_z += 0.5 * p.mass * p.velocity_z * p.velocity_z;
      v2 += p.velocity_z * p.velocity_z;
    }
    vmax2 = std::max(vmax2, v2);
  }
  row.max_speed = std::sqrt(vmax2);
  row.runout_x_p98 = percentile(std::move(xs), 98.0);
  if (three) row.runout_y_p98 = percentile(std::move(ys), 98.0);
  row.height_p995 = percentile(std::move(heights), 99.5);

  // Checkerboard index: shear stress deviation from the cell mean, over rho g H.
  std::array<int, kMaxDim> cells{1, 1, 1};
  for (int d = 0; d < grid.dim; ++d) cells[d] = std::max(grid.nodes_per_axis[d] - 1, 1);
  auto cell_of = [&](const ParticleRecord& p) {
    const double x[kMaxDim] = {p.coord_x, p.coord_y, p.coord_z};
    long long cell = 0;
    for (int d = grid.dim - 1; d >= 0; --d) {
      const int i = std::clamp(static_cast<int>(std::floor((x[d] - grid.origin[d]) / grid.spacing[d])), 0, cells[d] - 1);
      cell = cell * cells[d] + i;
    }
    return cell;
  };
  const int shears = three ? 3 : 1;
  auto shear = [](const ParticleRecord& p, int c) { return c == 0 ? p.tau_xy : c == 1 ? p.tau_yz : p.tau_xz; };
  std::map<long long, std::pair<std::array<double, 3>, int>> cell_sum;
  for (const auto& p : particles) {
    auto& s = cell_sum[cell_of(p)];
    for (int c = 0; c < shears; ++c) s.first[c] += shear(p, c);
    s.second += 1;
  }
  double sq = 0;
  for (const auto& p : particles) {
    const auto& s = cell_sum[cell_of(p)];
    double d2 = 0;
    for (int c = 0; c < shears; ++c) {
      const double d = shear(p, c) - s.first[c] / s.second;
      d2 += d * d;
    }
    sq += d2;
  }
  const double rms = std::sqrt(sq / static_cast<double>(particles.size()));
  const double rho = volume > 0 ? mass / volume : 0.0;
  const double g = three ? Eigen::Vector3d(gravity.x(), gravity.y(), gravity_z).norm() : gravity.norm();
  const double scale = rho * g * (row.height_p995 - lowest);
  row.checkerboard_index = scale > 0 ? rms / scale : std::numeric_limits<double>::quiet_NaN();
  return row;
}

namespace {
/// The columns of series.csv for a grid of `dim` axes.
std::vector<std::string> series_columns(int dim) {
  if (dim == 3)
    return {"step", "time", "runout_x_p98", "runout_y_p98", "height_z_p995", "potential_energy", "kinetic_energy_x",
            "kinetic_energy_y", "kinetic_energy_z", "max_speed", "n_particles", "dt", "checkerboard_index"};
  return {"step", "time", "runout_x_p98", "height_y_p995", "potential_energy", "kinetic_energy_x", "kinetic_energy_y",
          "max_speed", "n_particles", "dt", "checkerboard_index"};
}

std::string join_columns(int dim) {
  std::string header;
  for (const auto& c : series_columns(dim)) header += (header.empty() ? "" : ",") + c;
  return header;
}
}  // namespace

const std::string& series_header(int dim) {
  static const std::string header2 = join_columns(2), header3 = join_columns(3);
  return dim == 3 ? header3 : header2;
}

namespace {

std::string format_row(const SeriesRow& r) {
  std::ostringstream os;
  os.precision(12);
  const bool three = r.dim == 3;
  os << r.step << ',' << r.time << ',' << r.runout_x_p98 << ',';
  if (three) os << r.runout_y_p98 << ',';
  os << r.height_p995 << ',' << r.potential_energy << ',' << r.kinetic_energy_x << ',' << r.kinetic_energy_y;
  if (three) os << ',' << r.kinetic_energy_z;
  os << ',' << r.max_speed << ',' << r.particle_count << ',' << r.dt << ',' << r.checkerboard_index;
  return os.str();
}

/// Writes the "/xdmf" datasets that particles.xdmf points at: coordinates, connectivity and every
/// particle_fields() array. `start` (the first frame) also records its step and time as attributes.
void write_xdmf_datasets(hid_t file, std::span<const ParticleRecord> ps, const Grid& grid, const std::string& name,
                         const XdmfFrame* start = nullptr) {
  const hid_t group = H5Gcreate2(file, "xdmf", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (group < 0) throw std::runtime_error(name + ": cannot create group /xdmf");
  const hsize_t n = ps.size();
  bool ok = true;
  const std::vector<double> xyz = particle_coordinates(ps, grid);
  const hsize_t dims3[2] = {n, 3};
  ok = ok && H5LTmake_dataset_double(group, "coordinates", 2, dims3, xyz.data()) >= 0;
  // Polyvertex connectivity 0..n-1 (explicit, so readers that do not default it still read the grid).
  std::vector<std::int64_t> connectivity(n);
  for (std::size_t k = 0; k < n; ++k) connectivity[k] = static_cast<std::int64_t>(k);
  const hsize_t dims1[1] = {n};
  ok = ok && H5LTmake_dataset(group, "connectivity", 1, dims1, H5T_NATIVE_INT64, connectivity.data()) >= 0;
  for (const auto& f : particle_fields(ps, grid)) {
    const hsize_t dims[2] = {n, static_cast<hsize_t>(components(f.kind))};
    const int rank = f.kind == FieldKind::Scalar ? 1 : 2;
    ok = ok && (f.integer ? H5LTmake_dataset(group, f.name.c_str(), 1, dims, H5T_NATIVE_INT64, f.whole.data())
                          : H5LTmake_dataset_double(group, f.name.c_str(), rank, dims, f.real.data())) >= 0;
  }
  if (start) {
    ok = ok && H5LTset_attribute_double(group, ".", "time", &start->time, 1) >= 0;
    ok = ok && H5LTset_attribute_long_long(group, ".", "step", &start->step, 1) >= 0;
  }
  H5Gclose(group);
  if (!ok) throw std::runtime_error(name + ": writing the /xdmf datasets failed");
}

const char* xdmf_attribute_type(FieldKind kind) {
  return kind == FieldKind::Scalar ? "Scalar" : kind == FieldKind::Vector ? "Vector" : "Tensor6";
}

/// The fields of the VTK files: the deck's choice plus what identifies and sizes a particle.
std::vector<ParticleField> vtk_fields(std::span<const ParticleRecord> ps, const Deck& deck) {
  std::vector<std::string> wanted = deck.output.vtk_fields;
  for (const char* always : {"id", "material_id", "status", "size", "radius"})
    if (std::find(wanted.begin(), wanted.end(), always) == wanted.end()) wanted.emplace_back(always);
  std::vector<ParticleField> chosen;
  for (auto& f : particle_fields(ps, deck.grid))
    if (std::find(wanted.begin(), wanted.end(), f.name) != wanted.end()) chosen.push_back(std::move(f));
  for (const auto& sv : deck.output.vtk_statevars) chosen.push_back(state_variable_field(ps, sv));
  return chosen;
}

}  // namespace

ResultsWriter::ResultsWriter(const Deck& deck)
    : deck_(deck), folder_(deck.working_dir / deck.output.path / deck.output.uuid) {}

fs::path ResultsWriter::particle_file(long long step) const {
  return folder_ / particle_file_name(step, deck_.analysis.nsteps);
}

bool ResultsWriter::writes_vtk() const { return !deck_.output.vtk_fields.empty() || !deck_.output.vtk_statevars.empty(); }

void ResultsWriter::check_output_targets() const {
  if (fs::exists(folder_) && !fs::is_directory(folder_))
    throw common::InputError(folder_.string() + ": the results folder (post_processing.path / uuid) exists and is "
                             "not a directory");
  std::vector<std::string> names{"grid.vtr", kStartFile, "series.csv", "particles.xdmf"};
  const long long every = deck_.output.output_steps;
  for (long long step = (deck_.first_step + every - 1) / every * every; step < deck_.analysis.nsteps; step += every)
    if (deck_.output.writes_particles(step)) names.push_back(particle_file_name(step, deck_.analysis.nsteps));
  if (writes_vtk()) {
    const std::size_t h5_files = names.size();
    for (std::size_t i = 1; i < h5_files; ++i)
      if (names[i].ends_with(".h5")) names.push_back(vtp_name(names[i]));
    names.push_back("particles.pvd");
  }
  for (const auto& name : names) common::check_output_target(folder_ / name);
}

void ResultsWriter::prepare() {
  if (prepared_) return;
  prepared_ = true;
  check_output_targets();
  fs::create_directories(folder_);
  write_grid_vtr(folder_ / "grid.vtr", deck_);
  if (!deck_.resumed) return;
  // A resumed run keeps the rows of the run it continues, up to the resume step.
  const long long last = deck_.first_step - 1;
  if (auto start = read_start_frame(); start && start->step <= last) frames_.push_back(*start);
  std::ifstream in(folder_ / "series.csv");
  std::string line;
  if (!in || !std::getline(in, line) || line != series_header(deck_.grid.dim)) return;
  // The columns after step and time, and where n_particles is among them (series_header).
  const std::vector<std::string> names = series_columns(deck_.grid.dim);
  const std::size_t columns = names.size() - 2;
  const auto count_column = static_cast<std::size_t>(std::find(names.begin(), names.end(), "n_particles") - names.begin()) - 2;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string step_s, time_s, field;
    if (!std::getline(fields, step_s, ',') || !std::getline(fields, time_s, ',')) continue;
    std::vector<std::string> rest;
    while (std::getline(fields, field, ',')) rest.push_back(field);
    if (rest.size() != columns) continue;
    try {
      const long long step = std::stoll(step_s);
      if (step > last) continue;
      rows_.push_back(line);
      row_steps_.push_back(step);
      if (step % deck_.output.output_steps == 0 && fs::exists(particle_file(step)))
        frames_.push_back({step, std::stod(time_s), static_cast<std::size_t>(std::stoull(rest[count_column])),
                           particle_file_name(step, deck_.analysis.nsteps)});
    } catch (const std::exception&) {
      continue;  // a malformed row of an earlier run is dropped
    }
  }
}

std::optional<XdmfFrame> ResultsWriter::read_start_frame() const {
  const fs::path file = folder_ / kStartFile;
  if (!fs::exists(file)) return std::nullopt;
  const hid_t id = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (id < 0) return std::nullopt;
  XdmfFrame frame{0, 0, 0, kStartFile};
  hsize_t dims[2] = {0, 0};
  const bool ok = H5LTget_attribute_double(id, "/xdmf", "time", &frame.time) >= 0 &&
                  H5LTget_attribute_long_long(id, "/xdmf", "step", &frame.step) >= 0 &&
                  H5LTget_dataset_info(id, "/xdmf/id", dims, nullptr, nullptr) >= 0;
  H5Fclose(id);
  frame.count = static_cast<std::size_t>(dims[0]);
  return ok ? std::optional<XdmfFrame>(frame) : std::nullopt;
}

void ResultsWriter::add_row(const SeriesRow& row) {
  // A step written twice (an output step that is also the last step) keeps one row.
  if (!row_steps_.empty() && row_steps_.back() == row.step) {
    rows_.back() = format_row(row);
    return;
  }
  rows_.push_back(format_row(row));
  row_steps_.push_back(row.step);
}

void ResultsWriter::add_frame(const XdmfFrame& frame, std::span<const ParticleRecord> particles) {
  std::erase_if(frames_, [&](const XdmfFrame& f) { return f.step == frame.step; });
  frames_.push_back(frame);
  std::sort(frames_.begin(), frames_.end(), [](const auto& a, const auto& b) { return a.step < b.step; });
  if (writes_vtk()) {
    const std::vector<ParticleField> fields = vtk_fields(particles, deck_);
    write_particles_vtp(folder_ / vtp_name(frame.file), particle_coordinates(particles, deck_.grid), fields);
    std::vector<PvdEntry> entries;
    for (const auto& f : frames_)
      if (fs::exists(folder_ / vtp_name(f.file))) entries.push_back({f.time, vtp_name(f.file)});
    write_pvd(folder_ / "particles.pvd", entries);
  }
  write_xdmf();
}

std::string ResultsWriter::vtp_name(const std::string& h5_name) {
  return fs::path(h5_name).replace_extension(".vtp").string();
}

void ResultsWriter::write_start(double time, std::span<const ParticleRecord> particles) {
  prepare();
  if (!frames_.empty()) return;  // a resumed run that already has frames keeps its first one
  const XdmfFrame frame{deck_.first_step - 1, time, particles.size(), kStartFile};
  const fs::path file = folder_ / kStartFile;
  // The start state is a view, not a restart point: only the /xdmf datasets (no CB-Geo /table).
  const fs::path temporary = common::temporary_path_for(file);
  const hid_t id = H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (id < 0) throw std::runtime_error(file.string() + ": cannot create the file");
  bool closed = false;
  try {
    write_xdmf_datasets(id, particles, deck_.grid, file.string(), &frame);
    closed = true;
    if (H5Fclose(id) < 0) throw std::runtime_error(file.string() + ": closing the file failed");
  } catch (...) {
    if (!closed) H5Fclose(id);
    fs::remove(temporary);
    throw;
  }
  common::commit_file(temporary, file);
  add_frame(frame, particles);
}

void ResultsWriter::write_particles(long long step, double time, std::span<const ParticleRecord> particles,
                                    const ParticleFileExtras& extras) {
  const fs::path file = particle_file(step);
  write_particle_table(file, particles, [&](std::int64_t id) {
    write_xdmf_datasets(static_cast<hid_t>(id), particles, deck_.grid, file.string());
    if (!extras.affine.empty()) write_affine_dataset<2>(id, extras.affine, file.string());
    if (!extras.affine_3d.empty()) write_affine_dataset<3>(id, extras.affine_3d, file.string());
    if (extras.friction_memory) write_friction_memory_dataset(id, *extras.friction_memory, file.string());
    if (deck_.particle_pore_pressure)
      write_pore_pressure_dataset(id, carried_pore_pressure(deck_, particles), file.string());
  });
  add_frame({step, time, particles.size(), file.filename().string()}, particles);
}

void ResultsWriter::write_output(long long step, double time, double dt, std::span<const ParticleRecord> particles,
                                 const ParticleFileExtras& extras) {
  prepare();
  if (deck_.output.writes_particles(step)) write_particles(step, time, particles, extras);
  add_row(summarize_state(step, time, dt, particles, deck_.grid, deck_.analysis.gravity, deck_.analysis.gravity_z));
  write_series();
}

void ResultsWriter::write_series_row(long long step, double time, double dt, std::span<const ParticleRecord> particles) {
  prepare();
  add_row(summarize_state(step, time, dt, particles, deck_.grid, deck_.analysis.gravity, deck_.analysis.gravity_z));
  write_series();
}

fs::path ResultsWriter::write_state(long long step, double time, std::span<const ParticleRecord> particles,
                                   const ParticleFileExtras& extras) {
  prepare();
  write_particles(step, time, particles, extras);
  return particle_file(step);
}

void ResultsWriter::write_series() const {
  common::AtomicTextFile out(folder_ / "series.csv");
  out.stream() << series_header(deck_.grid.dim) << '\n';
  for (const auto& r : rows_) out.stream() << r << '\n';
  out.commit();
}

void ResultsWriter::write_xdmf() const {
  common::AtomicTextFile out(folder_ / "particles.xdmf");
  auto& os = out.stream();
  os.precision(12);
  os << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
     << "  <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  const std::vector<ParticleField> layout = particle_fields({}, deck_.grid);  // names and kinds only
  for (const auto& e : frames_) {
    const std::string n = std::to_string(e.count);
    auto item = [&](const std::string& dims, const std::string& dset, bool integer) {
      os << "     <DataItem Dimensions=\"" << dims << "\" NumberType=\"" << (integer ? "Int" : "Float")
         << "\" Precision=\"8\" Format=\"HDF\">" << e.file << ":/xdmf/" << dset << "</DataItem>\n";
    };
    os << "   <Grid Name=\"step " << e.step << "\" GridType=\"Uniform\">\n"
       << "    <Time Value=\"" << e.time << "\"/>\n"
       << "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n << "\" NodesPerElement=\"1\">\n";
    item(n, "connectivity", true);
    os << "    </Topology>\n    <Geometry GeometryType=\"XYZ\">\n";
    item(n + " 3", "coordinates", false);
    os << "    </Geometry>\n";
    for (const auto& f : layout) {
      os << "    <Attribute Name=\"" << f.name << "\" AttributeType=\"" << xdmf_attribute_type(f.kind)
         << "\" Center=\"Node\">\n";
      item(f.kind == FieldKind::Scalar ? n : n + " " + std::to_string(components(f.kind)), f.name, f.integer);
      os << "    </Attribute>\n";
    }
    os << "   </Grid>\n";
  }
  os << "  </Grid>\n </Domain>\n</Xdmf>\n";
  out.commit();
}

}  // namespace mpm::io
