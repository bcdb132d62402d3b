#pragma once
// CB-Geo's loads besides gravity (external_loading_conditions.concentrated_nodal_forces and
// .particle_surface_traction; include/solvers/mpm_base.tcc initialise_loads), read into deck.hpp's
// NodalForce and ParticleTraction with their node and particle sets resolved.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <vector>

#include "mpm/problem/deck.hpp"

namespace mpm::io {

class StrictObject;

/// What the deck reader resolves for the loads: the nodes of an entry's `nset_id` and the particles of its
/// `pset_id` (each fails naming the key), and the lattice index of a node id read from a file.
struct LoadSets {
  int dim = 2;  ///< the deck's dimension: the `dir` keys and columns take 0 .. dim - 1
  std::function<std::vector<int>(StrictObject&)> nodes;
  std::function<std::vector<std::int64_t>(StrictObject&)> particles;
  std::function<int(const std::string& shown, double node_id, int entry)> file_node;
};

/// `concentrated_nodal_forces`: entries {"nset_id", "dir", "force", <"math_function_id">} or {"file"} with
/// lines "node dir force" (CB-Geo's read_forces; not scaled by a function). Errors name the entry and key.
std::vector<NodalForce> read_nodal_forces(StrictObject& loads, const std::map<unsigned, MathFunction>& functions,
                                          const LoadSets& sets, const std::filesystem::path& dir);

/// `particle_surface_traction`: entries {"pset_id", "dir", "traction", <"math_function_id">}.
std::vector<ParticleTraction> read_particle_tractions(StrictObject& loads,
                                                      const std::map<unsigned, MathFunction>& functions,
                                                      const LoadSets& sets);

}  // namespace mpm::io
