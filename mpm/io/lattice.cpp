#include "mpm/io/lattice.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "common/input_error.hpp"

namespace mpm::io {
namespace {

std::string point(const Eigen::Vector2d& p) {
  std::ostringstream os;
  os << "(" << p.x() << ", " << p.y() << ")";
  return os.str();
}

/// Lattice spacing and line count along one axis: the smallest gap between distinct coordinates
/// (coordinates closer than `noise` are the same line).
struct Axis {
  double origin = 0, spacing = 0;
  int count = 1;
};

Axis find_axis(std::vector<double> values, const std::string& shown, const char* name) {
  std::sort(values.begin(), values.end());
  const double lo = values.front(), hi = values.back();
  const double noise = 1e-9 * std::max({1.0, std::abs(lo), std::abs(hi)}) + 1e-6 * (hi - lo) / std::max<std::size_t>(values.size(), 1);
  double gap = 0;
  for (std::size_t k = 1; k < values.size(); ++k) {
    const double d = values[k] - values[k - 1];
    if (d > noise && (gap == 0 || d < gap)) gap = d;
  }
  Axis axis;
  axis.origin = lo;
  if (gap == 0) throw common::InputError(shown, std::string("all nodes have the same ") + name + " (a 2D grid needs at least 2 node columns and rows)");
  axis.count = static_cast<int>(std::lround((hi - lo) / gap)) + 1;
  axis.spacing = (hi - lo) / (axis.count - 1);
  return axis;
}

}  // namespace

const std::array<std::array<int, 2>, 16>& gimp_node_natural_coordinates() {
  static const std::array<std::array<int, 2>, 16> xi = {{{-1, -1}, {1, -1}, {1, 1}, {-1, 1},
                                                          {-3, -3}, {-1, -3}, {1, -3}, {3, -3},
                                                          {3, -1}, {3, 1}, {3, 3}, {1, 3},
                                                          {-1, 3}, {-3, 3}, {-3, 1}, {-3, -1}}};
  return xi;
}

Lattice recognise_lattice(const MeshFile& mesh, CellType type, const std::string& shown) {
  std::vector<double> xs, ys;
  for (const auto& p : mesh.nodes) {
    xs.push_back(p.x());
    ys.push_back(p.y());
  }
  const Axis ax = find_axis(xs, shown, "x"), ay = find_axis(ys, shown, "y");
  if (static_cast<long long>(ax.count) * ay.count != static_cast<long long>(mesh.nodes.size()))
    throw common::InputError(shown, "nodes do not form a uniform rectangular lattice: the coordinates span " +
                                        std::to_string(ax.count) + " x " + std::to_string(ay.count) +
                                        " lattice points but the file has " + std::to_string(mesh.nodes.size()) + " nodes");
  Lattice out;
  Grid& g = out.grid;
  g.dim = 2;
  const Axis axes[2] = {ax, ay};
  for (const int d : {0, 1}) {
    g.origin[d] = axes[d].origin;
    g.spacing[d] = axes[d].spacing;
    g.nodes_per_axis[d] = axes[d].count;
  }
  g.cell_type = type;
  const auto& origin = g.origin;
  const auto& h = g.spacing;
  const int nodes_x = g.nodes_per_axis[0], nodes_y = g.nodes_per_axis[1];

  // Each node on a lattice point, each lattice point used once.
  std::vector<int> owner(static_cast<std::size_t>(ax.count) * ay.count, -1);
  out.node_index.resize(mesh.nodes.size());
  const double tol = 1e-4;  // fraction of a cell: the files print 6 decimals
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n) {
    const double fi = (mesh.nodes[n].x() - origin[0]) / h[0], fj = (mesh.nodes[n].y() - origin[1]) / h[1];
    const long i = std::lround(fi), j = std::lround(fj);
    if (std::abs(fi - i) > tol || std::abs(fj - j) > tol)
      throw common::InputError(shown, "nodes do not form a uniform rectangular lattice: node " + std::to_string(n) + " at " +
                                          point(mesh.nodes[n]) + " is off the lattice of spacing " +
                                          std::to_string(h[0]) + " x " + std::to_string(h[1]));
    const std::size_t k = static_cast<std::size_t>(i + j * nodes_x);
    if (owner[k] >= 0)
      throw common::InputError(shown, "nodes " + std::to_string(owner[k]) + " and " + std::to_string(n) +
                                          " are at the same point " + point(mesh.nodes[n]));
    owner[k] = static_cast<int>(n);
    out.node_index[n] = static_cast<int>(k);
  }

  // Each cell a lattice cell with its nodes in CB-Geo's order.
  static const std::array<std::array<int, 2>, 4> corners = {{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}};
  const int per_cell = type == CellType::Gimp16 ? 16 : 4;
  std::set<std::pair<int, int>> used;
  int imin = nodes_x, imax = -1, jmin = nodes_y, jmax = -1;
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    const auto& ids = mesh.cells[c];
    // ED2Q4 corners may start at any corner (counter-clockwise): the isoparametric map of a rectangle
    // is the same. ED2Q16G must start at (-1,-1), since the ring order depends on it.
    int start = 0;
    if (per_cell == 4)
      for (int m = 1; m < 4; ++m) {
        const int km = out.node_index[ids[m]], ks = out.node_index[ids[start]];
        if (km % nodes_x + km / nodes_x < ks % nodes_x + ks / nodes_x) start = m;
      }
    const int k0 = out.node_index[ids[start]];
    const int i0 = k0 % nodes_x, j0 = k0 / nodes_x;
    for (int m = 0; m < per_cell; ++m) {
      const auto xi = per_cell == 16 ? gimp_node_natural_coordinates()[m] : corners[m];
      const int i = i0 + (xi[0] + 1) / 2, j = j0 + (xi[1] + 1) / 2;
      const bool inside = i >= 0 && j >= 0 && i < nodes_x && j < nodes_y;
      const int listed = (start + m) % per_cell;
      if (!inside || out.node_index[ids[listed]] != i + j * nodes_x)
        throw common::InputError(shown, "cell " + std::to_string(c) + ": node " + std::to_string(listed) + " (id " +
                                            std::to_string(ids[listed]) + ") is not where a rectangular " +
                                            (per_cell == 16 ? "ED2Q16G" : "ED2Q4") +
                                            " cell has it (natural coordinates (" + std::to_string(xi[0]) + ", " +
                                            std::to_string(xi[1]) + ") from corner node " + std::to_string(ids[start]) +
                                            "; corners counter-clockwise" +
                                            (per_cell == 16 ? " from (-1,-1), then the ring from (-3,-3)" : "") + ")");
    }
    if (i0 + 1 >= nodes_x || j0 + 1 >= nodes_y)
      throw common::InputError(shown, "cell " + std::to_string(c) + " lies outside the node lattice");
    if (!used.insert({i0, j0}).second)
      throw common::InputError(shown, "cell " + std::to_string(c) + " duplicates another cell at the same place");
    out.cell_ij.push_back({i0, j0});
    imin = std::min(imin, i0); imax = std::max(imax, i0);
    jmin = std::min(jmin, j0); jmax = std::max(jmax, j0);
  }
  const long long full = static_cast<long long>(imax - imin + 1) * (jmax - jmin + 1);
  if (full != static_cast<long long>(mesh.cells.size()))
    throw common::InputError(shown, "cells do not form a rectangle: they span " + std::to_string(imax - imin + 1) + " x " +
                                        std::to_string(jmax - jmin + 1) + " cells but the file has " +
                                        std::to_string(mesh.cells.size()));
  const int first_cell[2] = {imin, jmin}, last_cell[2] = {imax, jmax};
  for (const int d : {0, 1}) {
    g.region_min[d] = origin[d] + first_cell[d] * h[d];
    g.region_max[d] = origin[d] + (last_cell[d] + 1) * h[d];
  }
  return out;
}

Lattice generate_lattice(const Eigen::Vector2d& origin, const Eigen::Vector2d& h, int cells_x, int cells_y, CellType type) {
  const int halo = type == CellType::Gimp16 ? 1 : 0;
  Lattice out;
  Grid& g = out.grid;
  g.dim = 2;
  g.cell_type = type;
  const int cells[2] = {cells_x, cells_y};
  for (const int d : {0, 1}) {
    g.spacing[d] = h[d];
    g.origin[d] = origin[d] - halo * h[d];
    g.nodes_per_axis[d] = cells[d] + 1 + 2 * halo;
    g.region_min[d] = origin[d];
    g.region_max[d] = origin[d] + cells[d] * h[d];
  }
  out.node_index.resize(g.node_count());
  for (std::size_t k = 0; k < out.node_index.size(); ++k) out.node_index[k] = static_cast<int>(k);
  for (int j = 0; j < cells_y; ++j)
    for (int i = 0; i < cells_x; ++i) out.cell_ij.push_back({i + halo, j + halo});
  return out;
}

std::map<std::string, std::vector<int>> boundary_node_sets(const Grid& g) {
  std::map<std::string, std::vector<int>> sets;
  const auto& h = g.spacing;
  const auto& lo = g.region_min;
  const auto& hi = g.region_max;
  const double ex = 1e-9 * h[0], ey = 1e-9 * h[1];
  for (int j = 0; j < g.nodes_per_axis[1]; ++j)
    for (int i = 0; i < g.nodes_per_axis[0]; ++i) {
      const int k = i + j * g.nodes_per_axis[0];
      const double x = g.origin[0] + i * h[0], y = g.origin[1] + j * h[1];
      sets["all"].push_back(k);
      if (x <= lo[0] + ex) sets["left"].push_back(k);
      if (x >= hi[0] - ex) sets["right"].push_back(k);
      if (y <= lo[1] + ey) sets["bottom"].push_back(k);
      if (y >= hi[1] - ey) sets["top"].push_back(k);
    }
  return sets;
}

}  // namespace mpm::io
