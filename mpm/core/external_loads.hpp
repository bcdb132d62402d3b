#pragma once
// The deck's loads besides the body force (CB-Geo external_loading_conditions.concentrated_nodal_forces
// and .particle_surface_traction; mpm/problem/deck.hpp NodalForce, ParticleTraction), on the engine's nodes and
// particles, evaluated once per step at t_n as CB-Geo does (MPMScheme::compute_forces at step * dt):
// - a concentrated force is added to its node's external force (before Cundall damping, which acts on
//   the whole unbalanced force);
// - a particle traction t becomes the particle force t V / l0 (V its volume, l0 = sqrt(V0) the side of the
//   square it was made as, V0 = m / rho), mapped to the nodes with the shape functions like m g.
// As in CB-Geo, a later entry on the same node (particle) and direction replaces an earlier one. Unlike
// CB-Geo, each entry keeps its own math function (CB-Geo's node keeps one function, the last assigned,
// for both directions), and l0 comes from the mass, so a resumed run applies the same force (CB-Geo takes
// l0 from the volume read back).
#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "mpm/core/nodal_constraints.hpp"
#include "mpm/problem/deck.hpp"

namespace mpm::core {

class ExternalLoads {
 public:
  ExternalLoads() = default;
  /// Throws common::InputError naming the entry for a node outside the mesh.
  ExternalLoads(const Deck& deck, std::size_t nodes);

  bool has_nodal_forces() const { return !node_slot_.empty(); }
  bool has_tractions() const { return !traction_slot_of_id_.empty(); }

  /// Evaluates every entry at time t (the start of the step).
  void set_time(double t);

  /// The concentrated force on node n at the time set (zero where none), N per unit thickness.
  Vec2 nodal_force(std::size_t n) const {
    const std::int32_t s = node_slot_[n];
    return s < 0 ? Vec2::Zero() : value_of(node_entries_[static_cast<std::size_t>(s)], nodal_values_);
  }

  /// The traction slot of the particle with this id (-1: no traction), for the engine's particle arrays.
  std::int32_t traction_slot(std::int64_t id) const {
    const auto it = traction_slot_of_id_.find(id);
    return it == traction_slot_of_id_.end() ? -1 : it->second;
  }
  /// The force t V / sqrt(V0) of a particle in traction slot s (>= 0) with volume V and initial volume V0.
  Vec2 traction_force(std::int32_t s, double volume, double initial_volume) const;

 private:
  using Entries = std::array<std::int32_t, 2>;  ///< per direction: the entry that loads it, -1 none
  static Vec2 value_of(const Entries& e, const std::vector<double>& values) {
    return Vec2(e[0] < 0 ? 0.0 : values[static_cast<std::size_t>(e[0])], e[1] < 0 ? 0.0 : values[static_cast<std::size_t>(e[1])]);
  }
  /// Per entry: its magnitude (force or traction) and math function, the value at the time set.
  struct Scaled {
    double scale;
    MathFunction function;
  };
  std::vector<Scaled> nodal_, tractions_;
  std::vector<double> nodal_values_, traction_values_;  ///< per entry: scale * f(t)
  std::vector<std::int32_t> node_slot_;                 ///< per node: index into node_entries_, -1 none
  std::vector<Entries> node_entries_;
  std::unordered_map<std::int64_t, std::int32_t> traction_slot_of_id_;
  std::vector<Entries> traction_entries_;               ///< per slot (one per distinct pair of entries)
};

}  // namespace mpm::core
