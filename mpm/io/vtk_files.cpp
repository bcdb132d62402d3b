#include "mpm/io/vtk_files.hpp"

#include <array>
#include <bit>
#include <cstdint>
#include <ostream>
#include <sstream>
#include <type_traits>

#include "common/atomic_file.hpp"

namespace mpm::io {
namespace fs = std::filesystem;
namespace {

static_assert(std::endian::native == std::endian::little, "the VTK files declare LittleEndian");

/// Raw appended data of one file: arrays are appended in the order they are declared.
class AppendedData {
 public:
  /// Declares a DataArray of `values` (Float64 or Int64) and appends its bytes.
  template <class T>
  void array(std::ostream& xml, const std::string& name, int components, std::span<const T> values) {
    static_assert(std::is_same_v<T, double> || std::is_same_v<T, std::int64_t>);
    const char* type = std::is_same_v<T, double> ? "Float64" : "Int64";
    xml << "      <DataArray type=\"" << type << "\" Name=\"" << name << "\" NumberOfComponents=\"" << components
        << "\" format=\"appended\" offset=\"" << bytes_.size() << "\"/>\n";
    const std::uint64_t count = values.size_bytes();
    append(&count, sizeof count);
    append(values.data(), count);
  }
  void write(std::ostream& os) const {
    os << "  <AppendedData encoding=\"raw\">\n   _";
    os.write(bytes_.data(), static_cast<std::streamsize>(bytes_.size()));
    os << "\n  </AppendedData>\n";
  }

 private:
  void append(const void* p, std::size_t n) {
    const auto* c = static_cast<const char*>(p);
    bytes_.insert(bytes_.end(), c, c + n);
  }
  std::vector<char> bytes_;
};

const char* kHeader = "<?xml version=\"1.0\"?>\n";

void write_file(const fs::path& file, const std::string& xml_head, const AppendedData& data, const char* tail) {
  common::AtomicTextFile out(file);
  out.stream() << xml_head;
  data.write(out.stream());
  out.stream() << tail;
  out.commit();
}

}  // namespace

void write_particles_vtp(const fs::path& file, std::span<const double> xyz, std::span<const ParticleField> fields) {
  const std::size_t n = xyz.size() / 3;
  std::ostringstream xml;
  AppendedData data;
  xml << kHeader << "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      << " <PolyData>\n  <Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\"" << n
      << "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n   <PointData>\n";
  for (const auto& f : fields) {
    if (f.integer) data.array<std::int64_t>(xml, f.name, 1, f.whole);
    else data.array<double>(xml, f.name, components(f.kind), f.real);
  }
  xml << "   </PointData>\n   <Points>\n";
  data.array<double>(xml, "Points", 3, xyz);
  xml << "   </Points>\n   <Verts>\n";
  std::vector<std::int64_t> connectivity(n), offsets(n);
  for (std::size_t k = 0; k < n; ++k) {
    connectivity[k] = static_cast<std::int64_t>(k);
    offsets[k] = static_cast<std::int64_t>(k + 1);
  }
  data.array<std::int64_t>(xml, "connectivity", 1, connectivity);
  data.array<std::int64_t>(xml, "offsets", 1, offsets);
  xml << "   </Verts>\n  </Piece>\n </PolyData>\n";
  write_file(file, xml.str(), data, "</VTKFile>\n");
}

void write_pvd(const fs::path& file, std::span<const PvdEntry> entries) {
  common::AtomicTextFile out(file);
  auto& os = out.stream();
  os.precision(12);
  os << kHeader << "<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n <Collection>\n";
  for (const auto& e : entries)
    os << "  <DataSet timestep=\"" << e.time << "\" group=\"\" part=\"0\" file=\"" << e.file << "\"/>\n";
  os << " </Collection>\n</VTKFile>\n";
  out.commit();
}

void write_grid_vtr(const fs::path& file, const Deck& deck) {
  const Grid& g = deck.grid;
  const auto& h = g.spacing;
  const std::size_t nodes = g.node_count();
  // The node coordinates per axis; a 2D grid is one layer at z = 0.
  std::array<std::vector<double>, kMaxDim> axes{std::vector<double>{0.0}, std::vector<double>{0.0},
                                                std::vector<double>{0.0}};
  for (int d = 0; d < g.dim; ++d) {
    auto& c = axes[static_cast<std::size_t>(d)];
    c.resize(static_cast<std::size_t>(g.nodes_per_axis[d]));
    for (std::size_t i = 0; i < c.size(); ++i) c[i] = g.origin[d] + static_cast<double>(i) * h[d];
  }
  std::array<std::vector<std::int64_t>, kMaxDim> fixed;
  for (int d = 0; d < g.dim; ++d) fixed[static_cast<std::size_t>(d)].assign(nodes, 0);
  std::vector<std::int64_t> in_mesh(nodes, 0);
  std::vector<double> friction(nodes, 0.0);
  for (const auto& c : deck.velocity_constraints)
    for (int node : c.nodes) fixed[static_cast<std::size_t>(c.dir)][static_cast<std::size_t>(node)] = 1;
  for (const auto& c : deck.friction_constraints)
    for (int node : c.nodes) friction[static_cast<std::size_t>(node)] = c.friction;
  constexpr double kTol = 1e-9;
  auto inside = [&](int d, std::size_t i) {
    const double x = axes[static_cast<std::size_t>(d)][i];
    return x >= g.region_min[d] - kTol * h[d] && x <= g.region_max[d] + kTol * h[d];
  };
  // Node index i + nx (j + ny k) (deck.hpp Grid), k = 0 in 2D.
  const std::size_t nx = axes[0].size(), ny = axes[1].size();
  for (std::size_t k = 0; k < axes[2].size(); ++k)
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i)
        in_mesh[i + nx * (j + ny * k)] = inside(0, i) && inside(1, j) && (g.dim < 3 || inside(2, k));
  std::ostringstream xml;
  AppendedData data;
  std::string extent;
  for (std::size_t d = 0; d < kMaxDim; ++d) extent += (d ? " 0 " : "0 ") + std::to_string(static_cast<long long>(axes[d].size()) - 1);
  xml << kHeader
      << "<VTKFile type=\"RectilinearGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      << " <RectilinearGrid WholeExtent=\"" << extent << "\">\n  <Piece Extent=\"" << extent << "\">\n   <PointData>\n";
  constexpr const char* kAxisNames[kMaxDim] = {"x", "y", "z"};
  for (int d = 0; d < g.dim; ++d)
    data.array<std::int64_t>(xml, std::string("fixed_") + kAxisNames[d], 1, fixed[static_cast<std::size_t>(d)]);
  data.array<double>(xml, "friction", 1, friction);
  data.array<std::int64_t>(xml, "in_mesh", 1, in_mesh);
  xml << "   </PointData>\n   <Coordinates>\n";
  for (std::size_t d = 0; d < kMaxDim; ++d) data.array<double>(xml, kAxisNames[d], 1, axes[d]);
  xml << "   </Coordinates>\n  </Piece>\n </RectilinearGrid>\n";
  write_file(file, xml.str(), data, "</VTKFile>\n");
}

}  // namespace mpm::io
