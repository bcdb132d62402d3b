#include "bridge/triangle_split.hpp"

#include <algorithm>
#include <map>
#include <utility>

namespace bridge {

std::size_t split_triangles(TransferState& state) {
  const bool any = std::any_of(state.elements.begin(), state.elements.end(),
                               [](const TransferElement& e) { return e.node_count == 3; });
  if (!any) return 0;
  const bool loaded = !state.load.empty();
  const bool up = !state.pore_pressure.empty();
  // A new node at the mean of `vertices`.
  const auto add_node = [&](std::initializer_list<int> vertices) {
    Vec2 x = Vec2::Zero(), u = Vec2::Zero(), v = Vec2::Zero();
    for (int a : vertices) {
      const auto i = static_cast<std::size_t>(a);
      x += state.reference[i];
      u += state.displacement[i];
      v += state.velocity[i];
    }
    const double n = static_cast<double>(vertices.size());
    state.reference.push_back(x / n);
    state.displacement.push_back(u / n);
    state.velocity.push_back(v / n);
    if (loaded) state.load.push_back(Vec2::Zero());
    if (up) {  // the mean of the vertices' too (0 at a dry triangle's nodes, which have no pore pressure)
      double p = 0, p0 = 0;
      for (int a : vertices) {
        p += state.pore_pressure[static_cast<std::size_t>(a)];
        p0 += state.reference_pore_pressure[static_cast<std::size_t>(a)];
      }
      state.pore_pressure.push_back(p / n);
      state.reference_pore_pressure.push_back(p0 / n);
    }
    return static_cast<int>(state.reference.size() - 1);
  };
  std::map<std::pair<int, int>, int> midpoint_of;  // side (low, high node) -> its midpoint node
  const auto midpoint = [&](int a, int b) {
    const std::pair<int, int> key = std::minmax(a, b);  // a copy: minmax returns references to a and b
    if (const auto it = midpoint_of.find(key); it != midpoint_of.end()) return it->second;
    const int m = add_node({a, b});
    midpoint_of.emplace(key, m);
    return m;
  };

  RenumberedElements renumbered(state);  // every per-Gauss-point field with its element
  std::size_t split = 0;
  for (std::size_t e = 0; e < state.elements.size(); ++e) {
    const TransferElement& el = state.elements[e];
    const std::size_t g0 = state.gauss_offset[e], g1 = state.gauss_offset[e + 1];
    if (el.node_count != 3) {
      renumbered.add(el, g0, g1);
      continue;
    }
    ++split;
    const std::array<int, 3> v{el.nodes[0], el.nodes[1], el.nodes[2]};
    const int centroid = add_node({v[0], v[1], v[2]});
    const std::array<int, 3> side{midpoint(v[0], v[1]), midpoint(v[1], v[2]), midpoint(v[2], v[0])};
    for (int k = 0; k < 3; ++k) {
      TransferElement quad = el;
      // vertex k, the midpoint of the side after it, the centroid, the midpoint of the side before it
      quad.nodes = {v[static_cast<std::size_t>(k)], side[static_cast<std::size_t>(k)], centroid,
                    side[static_cast<std::size_t>((k + 2) % 3)]};
      quad.node_count = 4;
      quad.gauss_points = 1;
      renumbered.add(quad, g0, g0 + 1);
    }
  }
  renumbered.install(state);
  return split;
}

}  // namespace bridge
