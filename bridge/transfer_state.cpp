#include "bridge/transfer_state.hpp"

namespace bridge {

QuadNodes TransferState::current_nodes(const TransferElement& e) const {
  return {current(e.nodes[0]), current(e.nodes[1]), current(e.nodes[2]), current(e.nodes[3])};
}

QuadNodes TransferState::reference_nodes(const TransferElement& e) const {
  auto at = [&](int a) { return reference[static_cast<std::size_t>(e.nodes[a])]; };
  return {at(0), at(1), at(2), at(3)};
}

void TransferState::index_gauss_points() {
  gauss_offset.assign(elements.size() + 1, 0);
  for (std::size_t e = 0; e < elements.size(); ++e)
    gauss_offset[e + 1] = gauss_offset[e] + static_cast<std::size_t>(elements[e].gauss_points);
}

void RenumberedElements::add(const TransferElement& el, std::size_t g0, std::size_t g1) {
  elements_.push_back(el);
  for (std::size_t g = g0; g < g1; ++g) {
    stress_.push_back(state_.gauss_stress[g]);
    if (!state_.reference_gauss_stress.empty()) reference_stress_.push_back(state_.reference_gauss_stress[g]);
    if (!state_.gauss_shear_strain.empty()) shear_strain_.push_back(state_.gauss_shear_strain[g]);
  }
}

void RenumberedElements::install(TransferState& state) {
  state.elements = std::move(elements_);
  state.gauss_stress = std::move(stress_);
  state.reference_gauss_stress = std::move(reference_stress_);
  state.gauss_shear_strain = std::move(shear_strain_);
  state.index_gauss_points();
}

}  // namespace bridge
