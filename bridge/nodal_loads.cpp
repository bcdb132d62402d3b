#include "bridge/nodal_loads.hpp"

#include <map>

#include "bridge/particle_mapping.hpp"

namespace bridge {

std::vector<ParticleLoad> particle_loads(const TransferState& state, int particles_per_direction) {
  std::vector<ParticleLoad> out;
  if (state.load.empty()) return out;
  const auto per_element = static_cast<std::size_t>(particles_per_direction * particles_per_direction);
  const std::vector<ParticlePoint> points = particle_points(particles_per_direction);
  const std::vector<std::size_t> slots = particle_slots(state);
  // Per node: the (element, corner) pairs that hold it.
  std::vector<std::vector<std::pair<std::size_t, int>>> corners_of(state.reference.size());
  for (std::size_t e = 0; e < state.elements.size(); ++e)
    for (int k = 0; k < 4; ++k) corners_of[static_cast<std::size_t>(state.elements[e].nodes[static_cast<std::size_t>(k)])].emplace_back(e, k);
  std::map<std::int64_t, Vec2> force_of;
  for (std::size_t a = 0; a < state.load.size(); ++a) {
    const Vec2& F = state.load[a];
    if (F.isZero(0.0) || corners_of[a].empty()) continue;
    double total = 0.0;
    for (const auto& [e, k] : corners_of[a])
      for (const ParticlePoint& pt : points) total += pt.shape[static_cast<std::size_t>(k)];
    for (const auto& [e, k] : corners_of[a])
      for (std::size_t q = 0; q < per_element; ++q) {
        auto [it, fresh] = force_of.try_emplace(static_cast<std::int64_t>(slots[e] * per_element + q), Vec2::Zero());
        it->second += (points[q].shape[static_cast<std::size_t>(k)] / total) * F;
      }
  }
  for (const auto& [id, f] : force_of) out.push_back({id, f});
  return out;
}

}  // namespace bridge
