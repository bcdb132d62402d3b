#pragma once
// The geometry of OpenSees' `block2D` mesh generator (OpenSees 3.8, SRC/modelbuilder/tcl/Block2D.cpp by
// Ed Love, and TclCommand_doBlock2D in SRC/modelbuilder/tcl/TclModelBuilder.cpp): a numX x numY grid of
// nodes mapped from the natural square [-1, 1]^2 onto the block by the 9-node Lagrange (biquadratic) map.
//
// Block points (1-based as in the command): 1-4 the corners counter-clockwise, 5 on edge 1-2, 6 on 2-3,
// 7 on 3-4, 8 on 4-1, 9 the centre. A missing mid-side point is the midpoint of its edge's corners; a
// missing centre is the mean of the FOUR CORNERS (not of the mid-side points), exactly as OpenSees.
// Shape functions (Block2D::shape2d): Nx = {x (x - 1) / 2, 1 - x^2, x (x + 1) / 2}, likewise Ny;
// N1 = Nx0 Ny0, N2 = Nx2 Ny0, N3 = Nx2 Ny2, N4 = Nx0 Ny2, N5 = Nx1 Ny0, N6 = Nx2 Ny1, N7 = Nx1 Ny2,
// N8 = Nx0 Ny1, N9 = Nx1 Ny1 (the standard Lagrange 9-node element, e.g. Zienkiewicz & Taylor, The FEM
// vol. 1, 6th ed., section 8.6.2).
//
// Numbering (OpenSees): node (i, j), i = 0..numX, j = 0..numY, at natural (-1 + 2 i / numX,
// -1 + 2 j / numY), gets offset i + j (numX + 1) from startNode (row by row from point 1 towards 2, rows
// from edge 1-2 towards 4-3); element (i, j) gets offset i + j numX from startEle and the nodes
// {i + j n, i + 1 + j n, i + 1 + (j + 1) n, i + (j + 1) n}, n = numX + 1 (Block2D::getElementNodes).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "fem_tcl/domain/node.hpp"

namespace fem::elements {

/// The up-to-9 block points of `block2D ... {1 x y 2 x y ...}`; index k holds point k + 1.
using Block2dPoints = std::array<std::optional<domain::Vector2>, 9>;

/// The 9 points with the missing ones filled in as OpenSees does (points 1-4 must be given).
std::array<domain::Vector2, 9> complete_block2d_points(const Block2dPoints& points);

/// The 9 Lagrange shape functions at natural (xi, eta) in Block2D's point order.
std::array<double, 9> block2d_shape(double xi, double eta);

/// Node coordinates, (numX + 1)(numY + 1) of them in OpenSees' order (offset i + j (numX + 1)).
std::vector<domain::Vector2> block2d_node_coords(int num_x, int num_y, const Block2dPoints& points);

/// Offsets (from startNode) of the 4 nodes of element (i, j), counter-clockwise from its lower-left node.
std::array<int, 4> block2d_element_nodes(int num_x, int i, int j);

/// What is wrong with the block's corners 1-2-3-4, if anything, as a one-line description: zero area,
/// clockwise, crossed (the edges 1-2 and 3-4, or 2-3 and 4-1, intersect) or concave (a corner angle over 180
/// degrees): the sign of the cross product of the two edges at each corner, relative to 1e-12 x the block's
/// squared size.
std::optional<std::string> block2d_invalid_corners(const Block2dPoints& points);

/// The first element of the block whose corners are crossed, clockwise or of zero area (a corner cross
/// product of its two edges <= 1e-12 x the block's squared size, i.e. det J <= 0 at a corner of the
/// bilinear element), as a one-line description; nothing when every element is valid.
std::optional<std::string> block2d_invalid_element(int num_x, int num_y, const std::vector<domain::Vector2>& coords);

}  // namespace fem::elements
