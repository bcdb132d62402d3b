#include "mpm/io/external_loads.hpp"

#include <string>

#include "common/input_error.hpp"
#include "mpm/io/ascii_files.hpp"
#include "mpm/io/deck_rules.hpp"
#include "mpm/io/json_keys.hpp"

namespace mpm::io {

using nlohmann::json;

namespace {

int direction(StrictObject& entry) {
  const long long dir = entry.integer("dir");
  if (dir != 0 && dir != 1) entry.fail("dir", "expected 0 (x) or 1 (y), got " + std::to_string(dir));
  return static_cast<int>(dir);
}

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
        const int line = static_cast<int>(r);
        if (rows[r][1] != 0 && rows[r][1] != 1)
          throw common::InputError(f, "entry " + std::to_string(r) + ": dir must be 0 or 1");
        NodalForce nf;
        nf.nodes = {sets.file_node(f, rows[r][0], line)};
        nf.dir = static_cast<int>(rows[r][1]);
        nf.force = rows[r][2];
        out.push_back(std::move(nf));
      }
      return;
    }
    NodalForce nf;
    nf.nodes = sets.nodes(entry);
    nf.dir = direction(entry);
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
    pt.dir = direction(entry);
    pt.traction = entry.number_in("traction", kFiniteRange);
    pt.function = function_of(entry, functions);
    out.push_back(std::move(pt));
  });
  return out;
}

}  // namespace mpm::io
