#include "mpm/io/output_keys.hpp"

#include <algorithm>
#include <map>

#include "mpm/io/particle_fields.hpp"

namespace mpm::io {
namespace {
using nlohmann::json;

/// CB-Geo's VTK attribute names (include/solvers/mpm_base.tcc write_vtk) and the field each shows.
const std::map<std::string, std::string>& cbgeo_attributes() {
  static const std::map<std::string, std::string> names = {
      {"displacements", "displacement"}, {"velocities", "velocity"}, {"stresses", "stress"}, {"strains", "strain"}};
  return names;
}

std::string list(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

void add_unique(std::vector<std::string>& v, const std::string& name) {
  if (std::find(v.begin(), v.end(), name) == v.end()) v.push_back(name);
}

void read_statevar(StrictObject& pp, const json& name, Output& out) {
  const auto known = mohr_coulomb_state_variable_names();
  if (!name.is_string() || std::find(known.begin(), known.end(), name.get<std::string>()) == known.end()) {
    const std::vector<std::string> names(known.begin(), known.end());
    pp.fail("vtk_statevars", "expected state variable names among " + list(names) + ", got " + name.dump());
  }
  add_unique(out.vtk_statevars, name.get<std::string>());
}

}  // namespace

void read_vtk_keys(StrictObject& pp, Output& out) {
  if (const json* vtk = pp.optional("vtk")) {
    std::vector<std::string> fields;
    for (const auto& f : particle_fields({}, Grid{})) fields.push_back(f.name);
    if (!vtk->is_array()) pp.fail("vtk", "expected an array of attribute names, got " + json_kind(*vtk));
    for (const auto& a : *vtk) {
      const std::string name = a.is_string() ? a.get<std::string>() : a.dump();
      const auto cbgeo = cbgeo_attributes().find(name);
      if (cbgeo != cbgeo_attributes().end()) add_unique(out.vtk_fields, cbgeo->second);
      else if (a.is_string() && std::find(fields.begin(), fields.end(), name) != fields.end()) add_unique(out.vtk_fields, name);
      else pp.fail("vtk", "unknown attribute " + name + " (expected displacements, velocities, stresses, strains or one of " +
                            list(fields) + ")");
    }
  }
  if (const json* sv = pp.optional("vtk_statevars")) {
    if (!sv->is_array()) pp.fail("vtk_statevars", "expected an array, got " + json_kind(*sv));
    for (const auto& entry : *sv) {
      if (!entry.is_object()) {
        read_statevar(pp, entry, out);
        continue;
      }
      // CB-Geo's newer form: {"phase_id": 0, "statevars": [...]}; this engine has one phase.
      StrictObject phase(entry, pp.file(), pp.path_of("vtk_statevars[]"));
      if (phase.integer_or("phase_id", 0) != 0) phase.fail("phase_id", "expected 0 (single-phase MPM)");
      const json& names = phase.required("statevars");
      if (!names.is_array()) phase.fail("statevars", "expected an array of state variable names");
      for (const auto& n : names) read_statevar(pp, n, out);
      phase.finish();
    }
  }
}

void read_particle_output_steps(StrictObject& pp, long long nsteps, Output& out) {
  const json* steps = pp.optional("particle_output_steps");
  if (steps == nullptr) return;
  const std::string expected = "expected an array of output steps (multiples of output_steps = " +
                               std::to_string(out.output_steps) + " below nsteps = " + std::to_string(nsteps) + ")";
  if (!steps->is_array() || steps->empty()) pp.fail("particle_output_steps", expected + ", got " + steps->dump());
  for (const auto& s : *steps) {
    if (!s.is_number_integer()) pp.fail("particle_output_steps", expected + ", got " + s.dump());
    const long long step = s.get<long long>();
    if (step < 0 || step >= nsteps || step % out.output_steps != 0)
      pp.fail("particle_output_steps", expected + ", got " + std::to_string(step));
    out.particle_output_steps.push_back(step);
  }
  std::sort(out.particle_output_steps.begin(), out.particle_output_steps.end());
  if (std::adjacent_find(out.particle_output_steps.begin(), out.particle_output_steps.end()) !=
      out.particle_output_steps.end())
    pp.fail("particle_output_steps", expected + ", got a step twice");
}

}  // namespace mpm::io
