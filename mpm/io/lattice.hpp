#pragma once
// Recognising a CB-Geo mesh file as a uniform grid of `dim` axes: the nodes must be the points of a
// uniform lattice (each exactly once) and the cells a full rectangle (2D) or box (3D) of lattice cells,
// each listing its nodes in CB-Geo's order (cell_nodes.hpp: ED2Q4, ED2Q16G, ED3H8, ED3H64G).
#include <array>
#include <map>
#include <string>
#include <vector>

#include "mpm/io/ascii_files.hpp"
#include "mpm/problem/deck.hpp"

namespace mpm::io {

/// The lattice position of a cell: the lattice node at its lowest corner (natural coordinates -1, ..., -1).
using LatticeCell = std::array<int, kMaxDim>;

struct Lattice {
  Grid grid;
  std::vector<int> node_index;       ///< lattice index (Grid's node numbering) of each file node id
  std::vector<LatticeCell> cell_ij;  ///< lattice cell of each file cell id (entries d >= grid.dim are 0)
};

/// Throws common::InputError naming `shown` (the mesh file) and what is wrong. The grid's dim is the
/// mesh's. Linear cells (ED2Q4, ED3H8) may list their corners from any corner in any rotation of CB-Geo's
/// order (the cell's map is then the same up to a rotation of its natural axes); GIMP cells (ED2Q16G,
/// ED3H64G) must list theirs exactly in CB-Geo's order, which their halo nodes follow.
Lattice recognise_lattice(const MeshFile& mesh, CellType type, const std::string& shown);

/// Extension (no mesh file): `cells[d]` cells of size `h[d]` along each of the `dim` axes from `origin`
/// (the lowest corner of the cells). Node ids are lattice indices; cell ids count the cells from the
/// lowest one, x fastest, then y, then z. GIMP grids get CB-Geo's halo of nodes outside the cells.
Lattice generate_lattice(int dim, const std::array<double, kMaxDim>& origin, const std::array<double, kMaxDim>& h,
                         const std::array<int, kMaxDim>& cells, CellType type);

/// The named node sets of a generated grid: the nodes on or beyond one side of the cells (so a GIMP
/// halo is included, as in CB-Geo's GIMP decks) and "all". 2D: "left", "right", "bottom", "top"; 3D:
/// "x_min", "x_max", "y_min", "y_max", "z_min", "z_max".
std::map<std::string, std::vector<int>> boundary_node_sets(const Grid& grid);

/// The names boundary_node_sets gives a grid of `dim` axes, for messages ("left, right, bottom, top or all").
std::string boundary_set_names(int dim);

/// The lattice cell holding the point `x` of the grid's region (points on the upper faces belong to the
/// last cell), as a cell number: i + cells_x * (j + cells_y * k).
long cell_of(const Grid& grid, const std::array<double, kMaxDim>& x);

}  // namespace mpm::io
