#include "bridge/nodal_loads.hpp"

#include <map>

#include "bridge/particle_mapping.hpp"
#include "bridge/quad_geometry.hpp"

namespace bridge {

std::vector<ParticleLoad> particle_loads(const TransferState& state, int particles_per_direction) {
  std::vector<ParticleLoad> out;
  if (state.load.empty()) return out;
  const int n = particles_per_direction;
  const GaussRule rule = gauss_legendre(n);
  const std::vector<std::size_t> slots = particle_slots(state);
  // Per node: the (element, corner) pairs that hold it.
  std::vector<std::vector<std::pair<std::size_t, int>>> corners_of(state.reference.size());
  for (std::size_t e = 0; e < state.elements.size(); ++e)
    for (int k = 0; k < 4; ++k) corners_of[static_cast<std::size_t>(state.elements[e].nodes[static_cast<std::size_t>(k)])].emplace_back(e, k);
  const auto weight = [&](int k, int i, int j) {
    return shape_functions(rule.points[static_cast<std::size_t>(i)], rule.points[static_cast<std::size_t>(j)])[static_cast<std::size_t>(k)];
  };
  std::map<std::int64_t, Vec2> force_of;
  for (std::size_t a = 0; a < state.load.size(); ++a) {
    const Vec2& F = state.load[a];
    if (F.isZero(0.0) || corners_of[a].empty()) continue;
    double total = 0.0;
    for (const auto& [e, k] : corners_of[a])
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) total += weight(k, i, j);
    for (const auto& [e, k] : corners_of[a])
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const auto id = static_cast<std::int64_t>(slots[e] * static_cast<std::size_t>(n * n) + static_cast<std::size_t>(j * n + i));
          auto [it, fresh] = force_of.try_emplace(id, Vec2::Zero());
          it->second += (weight(k, i, j) / total) * F;
        }
  }
  for (const auto& [id, f] : force_of) out.push_back({id, f});
  return out;
}

}  // namespace bridge
