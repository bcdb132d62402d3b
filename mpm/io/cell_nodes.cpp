#include "mpm/io/cell_nodes.hpp"

#include <cassert>
#include <cstdlib>
#include <vector>

namespace mpm::io {
namespace {

/// The corners of a square face counter-clockwise from (-1,-1), as (x, y) pairs.
constexpr std::array<std::array<int, 2>, 4> kFace = {{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}};

std::vector<NaturalPoint> linear_2d() {
  std::vector<NaturalPoint> out;
  for (const auto& [x, y] : kFace) out.push_back({x, y, 0});
  return out;
}

std::vector<NaturalPoint> gimp_2d() {
  std::vector<NaturalPoint> out = linear_2d();
  // The ring of 12 halo nodes, counter-clockwise from (-3,-3): along each side of the 3 x 3 square.
  const std::array<std::array<int, 2>, 4> start = {{{-3, -3}, {3, -3}, {3, 3}, {-3, 3}}};
  const std::array<std::array<int, 2>, 4> step = {{{2, 0}, {0, 2}, {-2, 0}, {0, -2}}};
  for (int side = 0; side < 4; ++side)
    for (int k = 0; k < 3; ++k) out.push_back({start[side][0] + k * step[side][0], start[side][1] + k * step[side][1], 0});
  return out;
}

std::vector<NaturalPoint> linear_3d() {
  std::vector<NaturalPoint> out;
  for (const int z : {-1, 1})
    for (const auto& [x, y] : kFace) out.push_back({x, y, z});
  return out;
}

std::vector<NaturalPoint> gimp_3d() {
  std::vector<NaturalPoint> out;
  // CB-Geo's GIMP hexahedron walks its corners with y = +1 first, each face counter-clockwise in (x, z).
  for (const int y : {1, -1})
    for (const auto& [x, z] : kFace) out.push_back({x, y, z});
  for (const int y : {3, 1, -1, -3})
    for (const int z : {-3, -1, 1, 3})
      for (const int x : {-3, -1, 1, 3})
        if (!(std::abs(x) == 1 && std::abs(y) == 1 && std::abs(z) == 1)) out.push_back({x, y, z});
  return out;
}

}  // namespace

std::span<const NaturalPoint> cell_node_natural_coordinates(CellType type, int dim) {
  static const std::vector<NaturalPoint> q4 = linear_2d(), q16 = gimp_2d(), h8 = linear_3d(), h64 = gimp_3d();
  assert(q4.size() == 4 && q16.size() == 16 && h8.size() == 8 && h64.size() == 64);
  const bool gimp = type == CellType::Gimp16;
  if (dim == 3) return gimp ? std::span<const NaturalPoint>(h64) : std::span<const NaturalPoint>(h8);
  return gimp ? std::span<const NaturalPoint>(q16) : std::span<const NaturalPoint>(q4);
}

std::string cell_type_name(CellType type, int dim) {
  const bool gimp = type == CellType::Gimp16;
  if (dim == 3) return gimp ? "ED3H64G" : "ED3H8";
  return gimp ? "ED2Q16G" : "ED2Q4";
}

std::size_t lowest_corner_position(CellType type, int dim) {
  const auto nodes = cell_node_natural_coordinates(type, dim);
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    bool lowest = true;
    for (int d = 0; d < dim; ++d) lowest = lowest && nodes[k][d] == -1;
    if (lowest) return k;
  }
  assert(false && "every cell has a lowest corner");
  return 0;
}

}  // namespace mpm::io
