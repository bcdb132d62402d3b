#include "mpm/io/vtk_files.hpp"

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
  std::vector<double> xs(static_cast<std::size_t>(g.nodes_per_axis[0]));
  std::vector<double> ys(static_cast<std::size_t>(g.nodes_per_axis[1])), zs{0.0};
  for (std::size_t i = 0; i < xs.size(); ++i) xs[i] = g.origin[0] + static_cast<double>(i) * h[0];
  for (std::size_t j = 0; j < ys.size(); ++j) ys[j] = g.origin[1] + static_cast<double>(j) * h[1];
  std::vector<std::int64_t> fixed_x(nodes, 0), fixed_y(nodes, 0), in_mesh(nodes, 0);
  std::vector<double> friction(nodes, 0.0);
  for (const auto& c : deck.velocity_constraints)
    for (int node : c.nodes) (c.dir == 0 ? fixed_x : fixed_y)[static_cast<std::size_t>(node)] = 1;
  for (const auto& c : deck.friction_constraints)
    for (int node : c.nodes) friction[static_cast<std::size_t>(node)] = c.friction;
  constexpr double kTol = 1e-9;
  for (std::size_t j = 0; j < ys.size(); ++j)
    for (std::size_t i = 0; i < xs.size(); ++i)
      in_mesh[i + j * xs.size()] = xs[i] >= g.region_min[0] - kTol * h[0] && xs[i] <= g.region_max[0] + kTol * h[0] &&
                                   ys[j] >= g.region_min[1] - kTol * h[1] && ys[j] <= g.region_max[1] + kTol * h[1];
  std::ostringstream xml;
  AppendedData data;
  const std::string extent =
      "0 " + std::to_string(g.nodes_per_axis[0] - 1) + " 0 " + std::to_string(g.nodes_per_axis[1] - 1) + " 0 0";
  xml << kHeader
      << "<VTKFile type=\"RectilinearGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      << " <RectilinearGrid WholeExtent=\"" << extent << "\">\n  <Piece Extent=\"" << extent << "\">\n   <PointData>\n";
  data.array<std::int64_t>(xml, "fixed_x", 1, fixed_x);
  data.array<std::int64_t>(xml, "fixed_y", 1, fixed_y);
  data.array<double>(xml, "friction", 1, friction);
  data.array<std::int64_t>(xml, "in_mesh", 1, in_mesh);
  xml << "   </PointData>\n   <Coordinates>\n";
  data.array<double>(xml, "x", 1, xs);
  data.array<double>(xml, "y", 1, ys);
  data.array<double>(xml, "z", 1, zs);
  xml << "   </Coordinates>\n  </Piece>\n </RectilinearGrid>\n";
  write_file(file, xml.str(), data, "</VTKFile>\n");
}

}  // namespace mpm::io
