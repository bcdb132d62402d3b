#include "bridge/material_exclusion.hpp"

#include <algorithm>
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
  std::vector<TransferElement> elements;
  std::vector<Stress6> stress, reference_stress;
  std::vector<double> shear_strain;
  const bool has_reference = !state.reference_gauss_stress.empty(), has_strain = !state.gauss_shear_strain.empty();
  out.top = -std::numeric_limits<double>::infinity();
  for (std::size_t e = 0; e < state.elements.size(); ++e) {
    const TransferElement& el = state.elements[e];
    if (excluded[el.material]) {
      ++out.elements;
      out.mass += el.density * std::abs(quad_area(state.reference_nodes(el)));  // rho0 A0: the mass itself
      const QuadNodes x = state.current_nodes(el);
      for (int a = 0; a < el.node_count; ++a) out.top = std::max(out.top, x[a].y());
      continue;
    }
    elements.push_back(el);
    elements.back().material = new_index[el.material];
    for (std::size_t g = state.gauss_offset[e]; g < state.gauss_offset[e + 1]; ++g) {
      stress.push_back(state.gauss_stress[g]);
      if (has_reference) reference_stress.push_back(state.reference_gauss_stress[g]);
      if (has_strain) shear_strain.push_back(state.gauss_shear_strain[g]);
    }
  }
  if (elements.empty()) throw common::InputError(option, "every element of the model would be left out");
  state.elements = std::move(elements);
  state.materials = std::move(materials);
  state.gauss_stress = std::move(stress);
  state.reference_gauss_stress = std::move(reference_stress);
  state.gauss_shear_strain = std::move(shear_strain);
  state.index_gauss_points();
  return out;
}

}  // namespace bridge
