#include "mpm/core/external_loads.hpp"

#include <cmath>
#include <map>
#include <string>

#include "common/input_error.hpp"

namespace mpm::core {

ExternalLoads::ExternalLoads(const Deck& deck, std::size_t nodes) {
  for (const auto& f : deck.nodal_forces) nodal_.push_back({f.force, f.function});
  for (const auto& t : deck.particle_tractions) tractions_.push_back({t.traction, t.function});
  if (!nodal_.empty()) {
    node_slot_.assign(nodes, -1);
    for (std::size_t e = 0; e < deck.nodal_forces.size(); ++e) {
      for (int n : deck.nodal_forces[e].nodes) {
        if (n < 0 || static_cast<std::size_t>(n) >= nodes)
          throw common::InputError("concentrated_nodal_forces[" + std::to_string(e) + "]",
                                   "node " + std::to_string(n) + " is not in the mesh");
        std::int32_t& s = node_slot_[static_cast<std::size_t>(n)];
        if (s < 0) {
          s = static_cast<std::int32_t>(node_entries_.size());
          node_entries_.push_back({-1, -1});
        }
        node_entries_[static_cast<std::size_t>(s)][static_cast<std::size_t>(deck.nodal_forces[e].dir)] = static_cast<std::int32_t>(e);
      }
    }
  }
  // Each particle's pair of entries, then one slot per distinct pair.
  std::unordered_map<std::int64_t, Entries> entries_of_id;
  for (std::size_t e = 0; e < deck.particle_tractions.size(); ++e)
    for (std::int64_t id : deck.particle_tractions[e].particles) {
      auto [it, fresh] = entries_of_id.try_emplace(id, Entries{-1, -1});
      it->second[static_cast<std::size_t>(deck.particle_tractions[e].dir)] = static_cast<std::int32_t>(e);
    }
  std::map<Entries, std::int32_t> slot_of_pair;
  for (const auto& [id, pair] : entries_of_id) {
    auto [it, fresh] = slot_of_pair.try_emplace(pair, static_cast<std::int32_t>(traction_entries_.size()));
    if (fresh) traction_entries_.push_back(pair);
    traction_slot_of_id_.emplace(id, it->second);
  }
  nodal_values_.assign(nodal_.size(), 0.0);
  traction_values_.assign(tractions_.size(), 0.0);
}

void ExternalLoads::set_time(double t) {
  for (std::size_t e = 0; e < nodal_.size(); ++e) nodal_values_[e] = nodal_[e].scale * nodal_[e].function.value(t);
  for (std::size_t e = 0; e < tractions_.size(); ++e) traction_values_[e] = tractions_[e].scale * tractions_[e].function.value(t);
}

Vec2 ExternalLoads::traction_force(std::int32_t s, double volume, double initial_volume) const {
  return value_of(traction_entries_[static_cast<std::size_t>(s)], traction_values_) * (volume / std::sqrt(initial_volume));
}

}  // namespace mpm::core
