#include "bridge/material_exclusion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/input_error.hpp"

namespace bridge {

ExcludedMaterials exclude_materials(TransferState& state, const std::vector<std::string>& names,
                                    const std::string& option) {
  ExcludedMaterials out;
  out.names = names;
  std::vector<char> excluded(state.materials.size(), 0);
  for (const std::string& name : names) {
    const auto it = std::find_if(state.materials.begin(), state.materials.end(),
                                 [&](const MpmMaterial& m) { return m.fem_name == name; });
    if (it == state.materials.end()) {
      std::string known;
      for (const auto& m : state.materials) known += (known.empty() ? "" : ", ") + m.fem_name;
      throw common::InputError(option, "the model's elements use no material '" + name + "' (they use: " + known + ")");
    }
    excluded[static_cast<std::size_t>(it - state.materials.begin())] = 1;
  }
  // The kept materials, renumbered in their order.
  std::vector<unsigned> new_index(state.materials.size(), 0);
  std::vector<MpmMaterial> materials;
  for (std::size_t m = 0; m < state.materials.size(); ++m) {
    if (excluded[m]) continue;
    new_index[m] = static_cast<unsigned>(materials.size());
    materials.push_back(state.materials[m]);
    materials.back().id = new_index[m];
  }
  // The kept elements with every per-Gauss-point field (as split_triangles renumbers them).
  RenumberedElements kept(state);
  out.top = -std::numeric_limits<double>::infinity();
  for (std::size_t e = 0; e < state.elements.size(); ++e) {
    TransferElement el = state.elements[e];
    if (excluded[el.material]) {
      ++out.elements;
      out.mass += el.density * std::abs(quad_area(state.reference_nodes(el)));  // rho0 A0: the mass itself
      const QuadNodes x = state.current_nodes(el);
      for (int a = 0; a < el.node_count; ++a) out.top = std::max(out.top, x[a].y());
      continue;
    }
    el.material = new_index[el.material];
    kept.add(el, state.gauss_offset[e], state.gauss_offset[e + 1]);
  }
  if (kept.empty()) throw common::InputError(option, "every element of the model would be left out");
  kept.install(state);
  state.materials = std::move(materials);
  return out;
}

}  // namespace bridge
