#include "mpm/io/external_loads.hpp"

#include <string>

#include "mpm/io/ascii_files.hpp"
#include "mpm/io/deck_rules.hpp"
#include "mpm/io/json_keys.hpp"
#include "mpm/io/math_functions.hpp"

namespace mpm::io {

using nlohmann::json;

namespace {

/// f(t) of an entry: its math_function_id's function, or 1 without one (CB-Geo's scalar).
MathFunction function_of(StrictObject& entry, const std::map<unsigned, MathFunction>& functions) {
  return entry.has("math_function_id") ? math_function_of(entry, functions) : MathFunction();
}

/// The entries of list `key` of `loads`, each read by `read` (which consumes its keys).
template <class Read>
void for_each_entry(StrictObject& loads, const std::string& key, Read&& read) {
  const json* list = loads.optional(key);
  if (list == nullptr) return;
  if (!list->is_array()) loads.fail(key, "expected an array");
  for (std::size_t k = 0; k < list->size(); ++k) {
    StrictObject entry((*list)[k], loads.file(), loads.path_of(key) + "[" + std::to_string(k) + "]");
    read(entry);
    entry.finish();
  }
}

}  // namespace

std::vector<NodalForce> read_nodal_forces(StrictObject& loads, const std::map<unsigned, MathFunction>& functions,
                                          const LoadSets& sets, const std::filesystem::path& dir) {
  std::vector<NodalForce> out;
  for_each_entry(loads, "concentrated_nodal_forces", [&](StrictObject& entry) {
    if (entry.has("file")) {
      const std::string f = entry.string("file");
      const auto rows = read_columns(dir / f, f, 3);
      for (std::size_t r = 0; r < rows.size(); ++r) {
        NodalForce nf;
        nf.nodes = {sets.file_node(f, rows[r][0], static_cast<int>(r))};
        nf.dir = axis_column(f, rows[r][1], r, sets.dim);
        nf.force = rows[r][2];
        out.push_back(std::move(nf));
      }
      return;
    }
    NodalForce nf;
    nf.nodes = sets.nodes(entry);
    nf.dir = read_axis(entry, sets.dim);
    nf.force = entry.number_in("force", kFiniteRange);
    nf.function = function_of(entry, functions);
    out.push_back(std::move(nf));
  });
  return out;
}

std::vector<ParticleTraction> read_particle_tractions(StrictObject& loads,
                                                      const std::map<unsigned, MathFunction>& functions,
                                                      const LoadSets& sets) {
  std::vector<ParticleTraction> out;
  for_each_entry(loads, "particle_surface_traction", [&](StrictObject& entry) {
    ParticleTraction pt;
    pt.particles = sets.particles(entry);
    pt.dir = read_axis(entry, sets.dim);
    pt.traction = entry.number_in("traction", kFiniteRange);
    pt.function = function_of(entry, functions);
    out.push_back(std::move(pt));
  });
  return out;
}

}  // namespace mpm::io
