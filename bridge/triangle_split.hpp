#pragma once
// Triangles (Tri31) into quadrilaterals, so that the mapping works on quads alone: each triangle becomes
// the three quads that join its centroid to the midpoints of its sides (the standard split of a triangle
// into quadrilaterals; Zienkiewicz, Taylor & Zhu 2013, "The Finite Element Method", 7th ed., sec. 8.10).
// The new points are nodes whose reference position, displacement and velocity are the means of the
// vertices' (the triangle's fields are linear, so these are its values there, and the bilinear fields
// of the quads are the triangle's exactly); they carry no load. Each quad keeps the triangle's tag,
// material and density, and its one Gauss point holds the triangle's (constant) stress.
#include <cstddef>

#include "bridge/transfer_state.hpp"

namespace bridge {

/// Splits every three-node element of `state` as above, in place (quads stay as they are, in order;
/// two triangles that share a side share its midpoint). Returns the number of triangles split.
std::size_t split_triangles(TransferState& state);

}  // namespace bridge
