#include "mpm/io/results.hpp"

#include <hdf5.h>
#include <hdf5_hl.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

#include "common/atomic_file.hpp"

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
                          const Grid& grid, const Eigen::Vector2d& gravity) {
  SeriesRow row;
  row.step = step;
  row.time = time;
  row.dt = dt;
  row.particle_count = particles.size();
  if (particles.empty()) {
    row.runout_x_p98 = row.height_y_p995 = row.checkerboard_index = std::numeric_limits<double>::quiet_NaN();
    return row;
  }
  std::vector<double> xs, ys;
  xs.reserve(particles.size());
  ys.reserve(particles.size());
  double mass = 0, volume = 0, ymin = std::numeric_limits<double>::infinity(), vmax2 = 0;
  for (const auto& p : particles) {
    xs.push_back(p.coord_x);
    ys.push_back(p.coord_y);
    ymin = std::min(ymin, p.coord_y);
    mass += p.mass;
    volume += p.volume;
    row.potential_energy -= p.mass * (gravity.x() * p.coord_x + gravity.y() * p.coord_y);
    row.kinetic_energy_x += 0.5 * p.mass * p.velocity_x * p.velocity_x;
    row.kinetic_energy_y += 0.5 * p.mass * p.velocity_y * p.velocity_y;
    vmax2 = std::max(vmax2, p.velocity_x * p.velocity_x + p.velocity_y * p.velocity_y);
  }
  row.max_speed = std::sqrt(vmax2);
  row.runout_x_p98 = percentile(std::move(xs), 98.0);
  row.height_y_p995 = percentile(std::move(ys), 99.5);

  // Checkerboard index: shear stress deviation from the cell mean, over rho g H.
  const int cells_x = std::max(grid.nodes_x - 1, 1), cells_y = std::max(grid.nodes_y - 1, 1);
  auto cell_of = [&](const ParticleRecord& p) {
    const int i = std::clamp(static_cast<int>(std::floor((p.coord_x - grid.x0) / grid.hx)), 0, cells_x - 1);
    const int j = std::clamp(static_cast<int>(std::floor((p.coord_y - grid.y0) / grid.hy)), 0, cells_y - 1);
    return static_cast<long long>(i) + static_cast<long long>(j) * cells_x;
  };
  std::map<long long, std::pair<double, int>> cell_sum;
  for (const auto& p : particles) {
    auto& s = cell_sum[cell_of(p)];
    s.first += p.tau_xy;
    s.second += 1;
  }
  double sq = 0;
  for (const auto& p : particles) {
    const auto& s = cell_sum[cell_of(p)];
    const double d = p.tau_xy - s.first / s.second;
    sq += d * d;
  }
  const double rms = std::sqrt(sq / static_cast<double>(particles.size()));
  const double rho = volume > 0 ? mass / volume : 0.0;
  const double scale = rho * gravity.norm() * (row.height_y_p995 - ymin);
  row.checkerboard_index = scale > 0 ? rms / scale : std::numeric_limits<double>::quiet_NaN();
  return row;
}

const std::string& series_header() {
  static const std::string header =
      "step,time,runout_x_p98,height_y_p995,potential_energy,kinetic_energy_x,kinetic_energy_y,max_speed,"
      "n_particles,dt,checkerboard_index";
  return header;
}

namespace {

std::string format_row(const SeriesRow& r) {
  std::ostringstream os;
  os.precision(12);
  os << r.step << ',' << r.time << ',' << r.runout_x_p98 << ',' << r.height_y_p995 << ',' << r.potential_energy << ','
     << r.kinetic_energy_x << ',' << r.kinetic_energy_y << ',' << r.max_speed << ',' << r.particle_count << ',' << r.dt
     << ',' << r.checkerboard_index;
  return os.str();
}

/// Writes the "/xdmf" datasets that particles.xdmf points at.
void write_xdmf_datasets(hid_t file, std::span<const ParticleRecord> ps, const std::string& name) {
  const hid_t group = H5Gcreate2(file, "xdmf", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (group < 0) throw std::runtime_error(name + ": cannot create group /xdmf");
  const hsize_t n = ps.size();
  bool ok = true;
  auto vector3 = [&](const char* dset, auto fx, auto fy, auto fz) {
    std::vector<double> v(3 * n);
    for (std::size_t k = 0; k < n; ++k) {
      v[3 * k] = fx(ps[k]);
      v[3 * k + 1] = fy(ps[k]);
      v[3 * k + 2] = fz(ps[k]);
    }
    const hsize_t dims[2] = {n, 3};
    ok = ok && H5LTmake_dataset_double(group, dset, 2, dims, v.data()) >= 0;
  };
  auto scalar = [&](const char* dset, auto f) {
    std::vector<double> v(n);
    for (std::size_t k = 0; k < n; ++k) v[k] = f(ps[k]);
    const hsize_t dims[1] = {n};
    ok = ok && H5LTmake_dataset_double(group, dset, 1, dims, v.data()) >= 0;
  };
  vector3("coordinates", [](auto& p) { return p.coord_x; }, [](auto& p) { return p.coord_y; }, [](auto&) { return 0.0; });
  vector3("velocity", [](auto& p) { return p.velocity_x; }, [](auto& p) { return p.velocity_y; }, [](auto&) { return 0.0; });
  vector3("displacement", [](auto& p) { return p.displacement_x; }, [](auto& p) { return p.displacement_y; },
          [](auto&) { return 0.0; });
  scalar("id", [](auto& p) { return static_cast<double>(p.id); });
  scalar("material_id", [](auto& p) { return static_cast<double>(p.material_id); });
  scalar("mass", [](auto& p) { return p.mass; });
  scalar("volume", [](auto& p) { return p.volume; });
  scalar("stress_xx", [](auto& p) { return p.stress_xx; });
  scalar("stress_yy", [](auto& p) { return p.stress_yy; });
  scalar("stress_zz", [](auto& p) { return p.stress_zz; });
  scalar("tau_xy", [](auto& p) { return p.tau_xy; });
  scalar("strain_xx", [](auto& p) { return p.strain_xx; });
  scalar("strain_yy", [](auto& p) { return p.strain_yy; });
  scalar("gamma_xy", [](auto& p) { return p.gamma_xy; });
  scalar("epsilon_v", [](auto& p) { return p.epsilon_v; });
  // Polyvertex connectivity 0..n-1 (explicit, so readers that do not default it still read the grid).
  {
    std::vector<std::int64_t> connectivity(n);
    for (std::size_t k = 0; k < n; ++k) connectivity[k] = static_cast<std::int64_t>(k);
    const hsize_t dims[1] = {n};
    ok = ok && H5LTmake_dataset(group, "connectivity", 1, dims, H5T_NATIVE_INT64, connectivity.data()) >= 0;
  }
  // CB-Geo's Mohr-Coulomb keeps pdstrain as its 7th state variable.
  scalar("pdstrain", [](auto& p) { return p.nstate_vars >= 7 ? p.svars[6] : 0.0; });
  H5Gclose(group);
  if (!ok) throw std::runtime_error(name + ": writing the /xdmf datasets failed");
}

const char* kScalars[] = {"id", "material_id", "mass", "volume", "stress_xx", "stress_yy", "stress_zz", "tau_xy",
                          "strain_xx", "strain_yy", "gamma_xy", "epsilon_v", "pdstrain"};
const char* kVectors[] = {"velocity", "displacement"};

}  // namespace

ResultsWriter::ResultsWriter(const Deck& deck)
    : deck_(deck), folder_(deck.working_dir / deck.output.path / deck.output.uuid) {}

fs::path ResultsWriter::particle_file(long long step) const {
  return folder_ / particle_file_name(step, deck_.analysis.nsteps);
}

void ResultsWriter::prepare() {
  if (prepared_) return;
  prepared_ = true;
  fs::create_directories(folder_);
  if (!deck_.resumed) return;
  // A resumed run keeps the rows of the run it continues, up to the resume step.
  std::ifstream in(folder_ / "series.csv");
  std::string line;
  if (!in || !std::getline(in, line) || line != series_header()) return;
  const long long last = deck_.first_step - 1;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string step_s, time_s, field;
    if (!std::getline(fields, step_s, ',') || !std::getline(fields, time_s, ',')) continue;
    std::vector<std::string> rest;
    while (std::getline(fields, field, ',')) rest.push_back(field);
    if (rest.size() != 9) continue;
    try {
      const long long step = std::stoll(step_s);
      if (step > last) continue;
      rows_.push_back(line);
      row_steps_.push_back(step);
      if (step % deck_.output.output_steps == 0 && fs::exists(particle_file(step)))
        xdmf_.push_back({step, std::stod(time_s), static_cast<std::size_t>(std::stoull(rest[6]))});
    } catch (const std::exception&) {
      continue;  // a malformed row of an earlier run is dropped
    }
  }
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

void ResultsWriter::write_particles(long long step, double time, std::span<const ParticleRecord> particles,
                                    std::span<const std::array<double, 4>> affine) {
  const fs::path file = particle_file(step);
  write_particle_table(file, particles, [&](std::int64_t id) {
    write_xdmf_datasets(static_cast<hid_t>(id), particles, file.string());
    if (!affine.empty()) write_affine_dataset(id, affine, file.string());
  });
  std::erase_if(xdmf_, [&](const XdmfEntry& e) { return e.step == step; });
  xdmf_.push_back({step, time, particles.size()});
}

void ResultsWriter::write_output(long long step, double time, double dt, std::span<const ParticleRecord> particles,
                                 std::span<const std::array<double, 4>> affine) {
  prepare();
  write_particles(step, time, particles, affine);
  write_xdmf();
  add_row(summarize_state(step, time, dt, particles, deck_.grid, deck_.analysis.gravity));
  write_series();
}

void ResultsWriter::write_series_row(long long step, double time, double dt, std::span<const ParticleRecord> particles) {
  prepare();
  add_row(summarize_state(step, time, dt, particles, deck_.grid, deck_.analysis.gravity));
  write_series();
}

fs::path ResultsWriter::write_state(long long step, double time, std::span<const ParticleRecord> particles,
                                   std::span<const std::array<double, 4>> affine) {
  prepare();
  write_particles(step, time, particles, affine);
  write_xdmf();
  return particle_file(step);
}

void ResultsWriter::write_series() const {
  common::AtomicTextFile out(folder_ / "series.csv");
  out.stream() << series_header() << '\n';
  for (const auto& r : rows_) out.stream() << r << '\n';
  out.commit();
}

void ResultsWriter::write_xdmf() const {
  common::AtomicTextFile out(folder_ / "particles.xdmf");
  auto& os = out.stream();
  os.precision(12);
  os << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
     << "  <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  auto entries = xdmf_;
  std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) { return a.step < b.step; });
  for (const auto& e : entries) {
    const std::string h5 = particle_file_name(e.step, deck_.analysis.nsteps);
    const std::string n = std::to_string(e.count);
    auto item = [&](const std::string& dims, const std::string& dset) {
      os << "     <DataItem Dimensions=\"" << dims << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << h5
         << ":/xdmf/" << dset << "</DataItem>\n";
    };
    os << "   <Grid Name=\"step " << e.step << "\" GridType=\"Uniform\">\n"
       << "    <Time Value=\"" << e.time << "\"/>\n"
       << "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n << "\" NodesPerElement=\"1\">\n"
       << "     <DataItem Dimensions=\"" << n << "\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">" << h5
       << ":/xdmf/connectivity</DataItem>\n"
       << "    </Topology>\n"
       << "    <Geometry GeometryType=\"XYZ\">\n";
    item(n + " 3", "coordinates");
    os << "    </Geometry>\n";
    for (const char* v : kVectors) {
      os << "    <Attribute Name=\"" << v << "\" AttributeType=\"Vector\" Center=\"Node\">\n";
      item(n + " 3", v);
      os << "    </Attribute>\n";
    }
    for (const char* s : kScalars) {
      os << "    <Attribute Name=\"" << s << "\" AttributeType=\"Scalar\" Center=\"Node\">\n";
      item(n, s);
      os << "    </Attribute>\n";
    }
    os << "   </Grid>\n";
  }
  os << "  </Grid>\n </Domain>\n</Xdmf>\n";
  out.commit();
}

}  // namespace mpm::io
