#pragma once
// The node orders of CB-Geo's cells as its mesh files list them: each node's natural coordinates in the
// cell (-1 and 1 the cell's corners, -3 and 3 the GIMP halo one lattice cell beyond). Read from CB-Geo's
// elements (include/elements/2d/quadrilateral_element.tcc, quadrilateral_gimp_element.tcc,
// 3d/hexahedron_element.tcc unit_cell_coordinates, 3d/hexahedron_gimp_element.tcc natural_nodal_coordinates):
//   ED2Q4    corners counter-clockwise from (-1,-1)
//   ED2Q16G  the 4 corners as ED2Q4, then the 12-node ring counter-clockwise from (-3,-3)
//   ED3H8    the z = -1 face counter-clockwise from (-1,-1,-1), then the z = +1 face the same way
//   ED3H64G  the 8 corners with y = +1 first: (-1,1,-1) (1,1,-1) (1,1,1) (-1,1,1), then the same four at
//            y = -1; then the other 56 nodes in layers of y = 3, 1, -1, -3, each by z (-3 .. 3) then x
//            (-3 .. 3), the 8 corners left out
#include <array>
#include <span>
#include <string>

#include "mpm/problem/deck.hpp"

namespace mpm::io {

/// Natural coordinates of one node (entries d >= dim are 0).
using NaturalPoint = std::array<int, kMaxDim>;

/// The nodes of a `dim`-D cell of `type` in CB-Geo's order (4, 16, 8 or 64 of them).
std::span<const NaturalPoint> cell_node_natural_coordinates(CellType type, int dim);

/// CB-Geo's name of the cell type: "ED2Q4", "ED2Q16G", "ED3H8", "ED3H64G".
std::string cell_type_name(CellType type, int dim);

/// The position in the list of the node at natural coordinates (-1, ..., -1): the cell's lowest corner.
std::size_t lowest_corner_position(CellType type, int dim);

}  // namespace mpm::io
