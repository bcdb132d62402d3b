#include "mpm/io/lattice.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>
#include <sstream>

#include "common/input_error.hpp"
#include "mpm/io/cell_nodes.hpp"

namespace mpm::io {
namespace {

const char* const kAxisNames[kMaxDim] = {"x", "y", "z"};

/// "(x, y)" or "(x, y, z)" of the first `dim` entries.
template <typename T>
std::string tuple_text(const std::array<T, kMaxDim>& p, int dim) {
  std::ostringstream os;
  os << "(";
  for (int d = 0; d < dim; ++d) os << (d ? ", " : "") << p[d];
  os << ")";
  return os.str();
}

/// "a x b" or "a x b x c".
template <typename T>
std::string extent_text(const std::array<T, kMaxDim>& n, int dim) {
  std::ostringstream os;
  for (int d = 0; d < dim; ++d) os << (d ? " x " : "") << n[d];
  return os.str();
}

/// Lattice spacing and line count along one axis: the smallest gap between distinct coordinates
/// (coordinates closer than `noise` are the same line).
struct Axis {
  double origin = 0, spacing = 0;
  int count = 1;
};

Axis find_axis(std::vector<double> values, const std::string& shown, int axis, int dim) {
  std::sort(values.begin(), values.end());
  const double lo = values.front(), hi = values.back();
  const double noise = 1e-9 * std::max({1.0, std::abs(lo), std::abs(hi)}) + 1e-6 * (hi - lo) / std::max<std::size_t>(values.size(), 1);
  double gap = 0;
  for (std::size_t k = 1; k < values.size(); ++k) {
    const double d = values[k] - values[k - 1];
    if (d > noise && (gap == 0 || d < gap)) gap = d;
  }
  Axis out;
  out.origin = lo;
  if (gap == 0)
    throw common::InputError(shown, std::string("all nodes have the same ") + kAxisNames[axis] +
                                        (dim == 3 ? " (a 3D grid needs at least 2 nodes along each axis)"
                                                  : " (a 2D grid needs at least 2 node columns and rows)"));
  out.count = static_cast<int>(std::lround((hi - lo) / gap)) + 1;
  out.spacing = (hi - lo) / (out.count - 1);
  return out;
}

/// A rotation of a cell's natural axes onto the lattice's: lattice axis `axis[c]` runs along natural axis
/// c with sign `sign[c]`.
struct Rotation {
  std::array<int, kMaxDim> axis{0, 1, 2};
  std::array<int, kMaxDim> sign{1, 1, 1};
};

/// The proper rotations (signed axis permutations of determinant +1) of `dim` axes, the identity first:
/// 4 in 2D, 24 in 3D.
std::vector<Rotation> proper_rotations(int dim) {
  std::vector<Rotation> out;
  std::array<int, kMaxDim> perm{0, 1, 2};
  do {
    int parity = 1;
    for (int a = 0; a < dim; ++a)
      for (int b = a + 1; b < dim; ++b)
        if (perm[a] > perm[b]) parity = -parity;
    for (int mask = 0; mask < (1 << dim); ++mask) {
      Rotation r;
      int det = parity;
      for (int c = 0; c < dim; ++c) {
        r.axis[c] = perm[c];
        r.sign[c] = (mask >> c) & 1 ? -1 : 1;
        det *= r.sign[c];
      }
      if (det == 1) out.push_back(r);
    }
  } while (std::next_permutation(perm.begin(), perm.begin() + dim));
  return out;
}

/// How a cell's listed nodes were laid over the lattice in CB-Geo's order: every node matched, or the first
/// one that did not (and whether its place lies outside the node lattice).
struct CellFit {
  int matched = 0;
  std::size_t first_bad = 0;
  bool bad_outside = false;
  LatticeCell lowest{};  ///< the lattice node of the cell's lowest corner
};

/// A cell's order in words, for messages.
std::string order_words(CellType type, int dim) {
  const bool gimp = type == CellType::Gimp16;
  if (dim == 3)
    return gimp ? "CB-Geo's ED3H64G order: corners from (-1, 1, -1), then the halo by y, z, x"
                : "each z face counter-clockwise from (-1, -1, -1), in any rotation";
  return gimp ? "corners counter-clockwise from (-1,-1), then the ring from (-3,-3)" : "corners counter-clockwise";
}

}  // namespace

Lattice recognise_lattice(const MeshFile& mesh, CellType type, const std::string& shown) {
  const int dim = mesh.dim;
  Lattice out;
  Grid& g = out.grid;
  g.dim = dim;
  g.cell_type = type;
  long long lattice_points = 1;
  for (int d = 0; d < dim; ++d) {
    std::vector<double> values;
    values.reserve(mesh.nodes.size());
    for (const auto& p : mesh.nodes) values.push_back(p[d]);
    const Axis axis = find_axis(std::move(values), shown, d, dim);
    g.origin[d] = axis.origin;
    g.spacing[d] = axis.spacing;
    g.nodes_per_axis[d] = axis.count;
    lattice_points *= axis.count;
  }
  if (lattice_points != static_cast<long long>(mesh.nodes.size()))
    throw common::InputError(shown, "nodes do not form a uniform " + std::string(dim == 3 ? "box-shaped" : "rectangular") +
                                        " lattice: the coordinates span " + extent_text(g.nodes_per_axis, dim) +
                                        " lattice points but the file has " + std::to_string(mesh.nodes.size()) + " nodes");
  const auto& origin = g.origin;
  const auto& h = g.spacing;
  const auto& n = g.nodes_per_axis;
  const auto index_of = [&](const LatticeCell& at) {
    long long k = 0;
    for (int d = dim - 1; d >= 0; --d) k = k * n[d] + at[d];
    return static_cast<int>(k);
  };
  // Each node on a lattice point, each lattice point used once.
  std::vector<int> owner(static_cast<std::size_t>(lattice_points), -1);
  std::vector<LatticeCell> node_at(mesh.nodes.size());
  out.node_index.resize(mesh.nodes.size());
  const double tol = 1e-4;  // fraction of a cell: the files print 6 decimals
  for (std::size_t k = 0; k < mesh.nodes.size(); ++k) {
    LatticeCell at{};
    for (int d = 0; d < dim; ++d) {
      const double f = (mesh.nodes[k][d] - origin[d]) / h[d];
      at[d] = static_cast<int>(std::lround(f));
      if (std::abs(f - at[d]) > tol)
        throw common::InputError(shown, "nodes do not form a uniform " + std::string(dim == 3 ? "box-shaped" : "rectangular") +
                                            " lattice: node " + std::to_string(k) + " at " + tuple_text(mesh.nodes[k], dim) +
                                            " is off the lattice of spacing " + extent_text(std::array<std::string, kMaxDim>{
                                                std::to_string(h[0]), std::to_string(h[1]), std::to_string(h[2])}, dim));
    }
    const int index = index_of(at);
    if (owner[index] >= 0)
      throw common::InputError(shown, "nodes " + std::to_string(owner[index]) + " and " + std::to_string(k) +
                                          " are at the same point " + tuple_text(mesh.nodes[k], dim));
    owner[index] = static_cast<int>(k);
    out.node_index[k] = index;
    node_at[k] = at;
  }

  // Each cell a lattice cell with its nodes in CB-Geo's order (linear cells: in any rotation of it).
  const bool gimp = type == CellType::Gimp16;
  const auto natural = cell_node_natural_coordinates(type, dim);
  const std::size_t anchor = gimp ? lowest_corner_position(type, dim) : 0;
  static const std::vector<Rotation> identity = {Rotation{}};
  const std::vector<Rotation> rotations = gimp ? identity : proper_rotations(dim);
  const std::string name = cell_type_name(type, dim);
  std::set<LatticeCell> used;
  LatticeCell first_cell{}, last_cell{};
  for (int d = 0; d < dim; ++d) {
    first_cell[d] = n[d];
    last_cell[d] = -1;
  }
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    const auto& ids = mesh.cells[c];
    const LatticeCell& base = node_at[ids[anchor]];
    CellFit best;
    best.matched = -1;
    for (const Rotation& r : rotations) {
      CellFit fit;
      bool bad_found = false;
      for (int d = 0; d < dim; ++d) fit.lowest[d] = n[d];
      for (std::size_t m = 0; m < natural.size(); ++m) {
        LatticeCell at = base;
        bool inside = true;
        for (int a = 0; a < dim; ++a) {
          at[r.axis[a]] += r.sign[a] * (natural[m][a] - natural[anchor][a]) / 2;
        }
        for (int d = 0; d < dim; ++d) inside = inside && at[d] >= 0 && at[d] < n[d];
        if (inside && out.node_index[ids[m]] == index_of(at)) {
          ++fit.matched;
          bool corner = true;
          for (int a = 0; a < dim; ++a) corner = corner && std::abs(natural[m][a]) == 1;
          if (corner)
            for (int d = 0; d < dim; ++d) fit.lowest[d] = std::min(fit.lowest[d], at[d]);
        } else if (!bad_found) {
          bad_found = true;
          fit.first_bad = m;
          fit.bad_outside = !inside;
        }
      }
      if (fit.matched > best.matched) best = fit;
      if (fit.matched == static_cast<int>(natural.size())) break;
    }
    if (best.matched != static_cast<int>(natural.size())) {
      const std::size_t m = best.first_bad;
      bool halo = false;
      for (int a = 0; a < dim; ++a) halo = halo || std::abs(natural[m][a]) == 3;
      if (halo && best.bad_outside)
        throw common::InputError(shown, "cell " + std::to_string(c) + ": node " + std::to_string(m) + " (id " +
                                            std::to_string(ids[m]) + ") is the GIMP halo node at natural coordinates " +
                                            tuple_text(natural[m], dim) + ", which lies outside the mesh's nodes (an " + name +
                                            " mesh needs a halo of nodes one cell beyond its cells)");
      throw common::InputError(shown, "cell " + std::to_string(c) + ": node " + std::to_string(m) + " (id " +
                                          std::to_string(ids[m]) + ") is not where a " +
                                          (dim == 3 ? "box-shaped " : "rectangular ") + name +
                                          " cell has it (natural coordinates " + tuple_text(natural[m], dim) +
                                          " from corner node " + std::to_string(ids[anchor]) + "; " + order_words(type, dim) + ")");
    }
    for (int d = 0; d < dim; ++d)
      if (best.lowest[d] + 1 >= n[d]) throw common::InputError(shown, "cell " + std::to_string(c) + " lies outside the node lattice");
    if (!used.insert(best.lowest).second)
      throw common::InputError(shown, "cell " + std::to_string(c) + " duplicates another cell at the same place");
    out.cell_ij.push_back(best.lowest);
    for (int d = 0; d < dim; ++d) {
      first_cell[d] = std::min(first_cell[d], best.lowest[d]);
      last_cell[d] = std::max(last_cell[d], best.lowest[d]);
    }
  }
  long long full = 1;
  LatticeCell span{};
  for (int d = 0; d < dim; ++d) {
    span[d] = last_cell[d] - first_cell[d] + 1;
    full *= span[d];
  }
  if (full != static_cast<long long>(mesh.cells.size()))
    throw common::InputError(shown, std::string("cells do not form a ") + (dim == 3 ? "box" : "rectangle") + ": they span " +
                                        extent_text(span, dim) + " cells but the file has " + std::to_string(mesh.cells.size()));
  for (int d = 0; d < dim; ++d) {
    g.region_min[d] = origin[d] + first_cell[d] * h[d];
    g.region_max[d] = origin[d] + (last_cell[d] + 1) * h[d];
  }
  return out;
}

Lattice generate_lattice(int dim, const std::array<double, kMaxDim>& origin, const std::array<double, kMaxDim>& h,
                         const std::array<int, kMaxDim>& cells, CellType type) {
  const int halo = type == CellType::Gimp16 ? 1 : 0;
  Lattice out;
  Grid& g = out.grid;
  g.dim = dim;
  g.cell_type = type;
  for (int d = 0; d < dim; ++d) {
    g.spacing[d] = h[d];
    g.origin[d] = origin[d] - halo * h[d];
    g.nodes_per_axis[d] = cells[d] + 1 + 2 * halo;
    g.region_min[d] = origin[d];
    g.region_max[d] = origin[d] + cells[d] * h[d];
  }
  out.node_index.resize(g.node_count());
  for (std::size_t k = 0; k < out.node_index.size(); ++k) out.node_index[k] = static_cast<int>(k);
  const int cells_z = dim == 3 ? cells[2] : 1;
  for (int k = 0; k < cells_z; ++k)
    for (int j = 0; j < cells[1]; ++j)
      for (int i = 0; i < cells[0]; ++i) out.cell_ij.push_back({i + halo, j + halo, dim == 3 ? k + halo : 0});
  return out;
}

std::map<std::string, std::vector<int>> boundary_node_sets(const Grid& g) {
  static const char* const names_2d[2][2] = {{"left", "right"}, {"bottom", "top"}};
  static const char* const names_3d[3][2] = {{"x_min", "x_max"}, {"y_min", "y_max"}, {"z_min", "z_max"}};
  std::map<std::string, std::vector<int>> sets;
  const auto count = static_cast<int>(g.node_count());
  for (int k = 0; k < count; ++k) {
    sets["all"].push_back(k);
    int rest = k;
    for (int d = 0; d < g.dim; ++d) {
      const int i = rest % g.nodes_per_axis[d];
      rest /= g.nodes_per_axis[d];
      const double x = g.origin[d] + i * g.spacing[d], eps = 1e-9 * g.spacing[d];
      const char* const* names = g.dim == 3 ? names_3d[d] : names_2d[d];
      if (x <= g.region_min[d] + eps) sets[names[0]].push_back(k);
      if (x >= g.region_max[d] - eps) sets[names[1]].push_back(k);
    }
  }
  return sets;
}

std::string boundary_set_names(int dim) {
  return dim == 3 ? "x_min, x_max, y_min, y_max, z_min, z_max or all" : "left, right, bottom, top or all";
}

long cell_of(const Grid& g, const std::array<double, kMaxDim>& x) {
  long cell = 0;
  for (int d = g.dim - 1; d >= 0; --d) {
    const int cells = g.nodes_per_axis[d] - 1;
    const int i = std::clamp(static_cast<int>(std::floor((x[d] - g.origin[d]) / g.spacing[d])), 0, cells - 1);
    cell = cell * cells + i;
  }
  return cell;
}

}  // namespace mpm::io
