#pragma once
// Recognising a CB-Geo mesh file as a uniform rectangular grid: the nodes must be the points of a
// uniform lattice (each exactly once) and the cells a full rectangle of lattice cells, each listing
// its nodes in CB-Geo's order (FORMATS.md section 5: ED2Q4 corners counter-clockwise from (-1,-1);
// ED2Q16G the 4 corners, then the 12-node ring from (-3,-3) counter-clockwise).
#include <array>
#include <map>
#include <string>
#include <vector>

#include "mpm/io/ascii_files.hpp"
#include "mpm/problem/deck.hpp"

namespace mpm::io {

struct Lattice {
  Grid grid;
  std::vector<int> node_index;                ///< lattice index (i + j * grid.nodes_per_axis[0]) of each file node id
  std::vector<std::array<int, 2>> cell_ij;    ///< lattice cell (i, j) of each file cell id (its node (i, j) is corner (-1,-1))
};

/// Natural coordinates of the nodes of an ED2Q16G cell, in CB-Geo's order.
const std::array<std::array<int, 2>, 16>& gimp_node_natural_coordinates();

/// Throws common::InputError naming `shown` (the mesh file) and what is wrong.
Lattice recognise_lattice(const MeshFile& mesh, CellType type, const std::string& shown);

/// Extension (no mesh file): `cells_x` x `cells_y` cells of size `h` from `origin` (the lower-left
/// corner of the cells). Node ids are lattice indices; cell id i + j*cells_x is cell (i, j) from the
/// lower left. GIMP grids get CB-Geo's halo ring of nodes outside the cells.
Lattice generate_lattice(const Eigen::Vector2d& origin, const Eigen::Vector2d& h, int cells_x, int cells_y, CellType type);

/// The named node sets of a generated grid: "left", "right", "bottom", "top" (the nodes on or beyond
/// that side of the cells, so a GIMP halo is included, as in CB-Geo's GIMP decks) and "all".
std::map<std::string, std::vector<int>> boundary_node_sets(const Grid& grid);

}  // namespace mpm::io
