#pragma once
// The FEM's applied nodal loads at the transfer time (a surcharge on the crest, a footing: `load` commands
// of a Plain pattern, recorded by `recorder Node ... -dof 1 2 unbalance`; fem2mpm --loads) carried to the
// particles, so the MPM run keeps carrying them.
//
// A nodal force F_a acts on the material around node a: it is spread over the particles of the elements
// that share node a with the weights of node a's shape function at each particle, f_p = F_a N_a(xi_p) /
// sum_q N_a(xi_q). The forces sum to F_a exactly, centred on the node, and the particles then carry them
// wherever they move (mpm's particle_surface_traction, written by mpm_deck.cpp as t = f sqrt(V0) / V so
// that mpm's force t V / sqrt(V0) is f; V0 = m / rho). The loads keep their transfer-time value.
#include <cstdint>
#include <vector>

#include "bridge/transfer_state.hpp"

namespace bridge {

struct ParticleLoad {
  std::int64_t id = 0;  ///< particle id (generate_particles' numbering)
  Vec2 force = Vec2::Zero();  ///< N per unit thickness
};

/// The particle forces of state.load (empty when state.load is empty or all zero), for particles made by
/// generate_particles with `particles_per_direction` points per direction, in id order.
std::vector<ParticleLoad> particle_loads(const TransferState& state, int particles_per_direction);

}  // namespace bridge
