#include "fem_tcl/elements/block2d.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <sstream>

namespace fem::elements {

std::array<domain::Vector2, 9> complete_block2d_points(const Block2dPoints& points) {
  std::array<domain::Vector2, 9> p;
  for (int k = 0; k < 4; ++k) {
    assert(points[k].has_value());
    p[k] = *points[k];
  }
  // mid-side point k + 4 lies on the edge from corner k to corner k + 1 (Block2D::setUpXl)
  for (int k = 0; k < 4; ++k) p[k + 4] = points[k + 4] ? *points[k + 4] : domain::Vector2(0.5 * (p[k] + p[(k + 1) % 4]));
  p[8] = points[8] ? *points[8] : domain::Vector2(0.25 * (p[0] + p[1] + p[2] + p[3]));
  return p;
}

std::array<double, 9> block2d_shape(double xi, double eta) {
  const std::array<double, 3> nx{0.5 * xi * (xi - 1.0), 1.0 - xi * xi, 0.5 * xi * (xi + 1.0)};
  const std::array<double, 3> ny{0.5 * eta * (eta - 1.0), 1.0 - eta * eta, 0.5 * eta * (eta + 1.0)};
  return {nx[0] * ny[0], nx[2] * ny[0], nx[2] * ny[2], nx[0] * ny[2],
          nx[1] * ny[0], nx[2] * ny[1], nx[1] * ny[2], nx[0] * ny[1], nx[1] * ny[1]};
}

std::vector<domain::Vector2> block2d_node_coords(int num_x, int num_y, const Block2dPoints& points) {
  assert(num_x > 0 && num_y > 0);
  const auto p = complete_block2d_points(points);
  std::vector<domain::Vector2> coords;
  coords.reserve(static_cast<std::size_t>((num_x + 1) * (num_y + 1)));
  for (int j = 0; j <= num_y; ++j) {
    for (int i = 0; i <= num_x; ++i) {
      const auto n = block2d_shape(-1.0 + 2.0 * i / num_x, -1.0 + 2.0 * j / num_y);
      domain::Vector2 x = domain::Vector2::Zero();
      for (int k = 0; k < 9; ++k) x += n[k] * p[k];
      coords.push_back(x);
    }
  }
  return coords;
}

std::array<int, 4> block2d_element_nodes(int num_x, int i, int j) {
  const int n = num_x + 1;
  const int first = i + j * n;
  return {first, first + 1, first + 1 + n, first + n};
}

namespace {
/// x-component of a x b (twice the signed area of the triangle a, b).
double cross(const domain::Vector2& a, const domain::Vector2& b) { return a.x() * b.y() - a.y() * b.x(); }
}  // namespace

std::optional<std::string> block2d_invalid_corners(const Block2dPoints& points) {
  const auto p = complete_block2d_points(points);
  double size2 = 0.0;
  int positive = 0, negative = 0;
  for (int k = 0; k < 4; ++k) size2 = std::max(size2, (p[k] - p[0]).squaredNorm());
  const double tiny = 1e-12 * size2;
  for (int k = 0; k < 4; ++k) {
    const double c = cross(p[(k + 1) % 4] - p[k], p[(k + 3) % 4] - p[k]);
    positive += c > tiny;
    negative += c < -tiny;
  }
  if (positive == 4) return std::nullopt;
  if (positive + negative < 4) return "the corners 1-2-3-4 enclose zero area (a corner on a line through its neighbours)";
  if (negative == 4) return "the corners 1-2-3-4 are clockwise (give them counter-clockwise)";
  if (positive == 2) return "the corners 1-2-3-4 are crossed (two opposite edges intersect)";
  return "the corners 1-2-3-4 make a concave quadrilateral (a corner angle over 180 degrees; crossed if clockwise)";
}

std::optional<std::string> block2d_invalid_element(int num_x, int num_y, const std::vector<domain::Vector2>& coords) {
  double size2 = 0.0;
  for (const auto& a : coords) size2 = std::max(size2, (a - coords.front()).squaredNorm());
  const double tiny = 1e-12 * size2;
  for (int j = 0; j < num_y; ++j) {
    for (int i = 0; i < num_x; ++i) {
      const auto nodes = block2d_element_nodes(num_x, i, j);
      for (int c = 0; c < 4; ++c) {
        const domain::Vector2& x = coords[nodes[c]];
        const domain::Vector2 ahead = coords[nodes[(c + 1) % 4]] - x;
        const domain::Vector2 behind = coords[nodes[(c + 3) % 4]] - x;
        const double det = cross(ahead, behind);  // 4 det J of the bilinear element at this corner
        if (!(det > tiny)) {
          std::ostringstream os;
          os << "element (" << i << ", " << j << ") of the block (offset " << i + j * num_x << ") has "
             << (std::abs(det) <= tiny ? "zero area" : "a negative corner det J (folded by the mid-side points)")
             << " at its corner " << c + 1 << " (" << x.x() << ", " << x.y() << ")";
          return os.str();
        }
      }
    }
  }
  return std::nullopt;
}

}  // namespace fem::elements
