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

}  // namespace bridge
