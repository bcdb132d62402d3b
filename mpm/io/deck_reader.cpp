#include "mpm/io/deck_reader.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <numbers>
#include <optional>
#include <set>

#include "common/finite_number.hpp"
#include "common/input_error.hpp"
#include "common/json_file.hpp"
#include "common/number_text.hpp"
#include "mpm/io/ascii_files.hpp"
#include "mpm/io/cell_nodes.hpp"
#include "mpm/io/deck_rules.hpp"
#include "mpm/io/dimension_keys.hpp"
#include "mpm/io/external_loads.hpp"
#include "mpm/io/json_keys.hpp"
#include "mpm/io/lattice.hpp"
#include "mpm/io/math_functions.hpp"
#include "mpm/io/output_keys.hpp"
#include "mpm/io/particle_generators.hpp"
#include "mpm/io/particle_table.hpp"
#include "mpm/io/resume_extras.hpp"
#include "mpm/io/transfer_keys.hpp"

namespace mpm::io {
namespace fs = std::filesystem;
using nlohmann::json;

const std::vector<std::string>& stress_smoothing_methods() {
  static const std::vector<std::string> methods = {"none", "cell_volumetric", "cell_strain", "nodal_strain",
                                                   "nodal_volumetric"};
  return methods;
}

namespace {

/// A number quoted in an input error (10 significant digits).
std::string num(double v) { return common::number_text(v, 10); }

json parse_json_file(const fs::path& file, const std::string& shown) { return common::parse_json_file(file, shown); }

/// Entity sets file: {"node_sets": [{"id", "set"}], "particle_sets": [...], "cell_sets": [...]}.
struct EntitySets {
  std::map<long long, std::vector<long long>> nodes, particles, cells;
};

std::map<long long, std::vector<long long>> read_set_list(StrictObject& root, const std::string& key, long long limit,
                                                          const char* entity) {
  std::map<long long, std::vector<long long>> out;
  const json* list = root.optional(key);
  if (!list) return out;
  if (!list->is_array()) root.fail(key, "expected an array of {\"id\", \"set\"} objects, got " + json_kind(*list));
  for (std::size_t k = 0; k < list->size(); ++k) {
    StrictObject s((*list)[k], root.file(), key + "[" + std::to_string(k) + "]");
    const long long id = s.integer("id");
    const json& ids = s.required("set");
    if (!ids.is_array()) s.fail("set", "expected an array of " + std::string(entity) + " ids");
    std::vector<long long> members;
    for (const auto& v : ids) {
      if (!v.is_number_integer()) s.fail("set", "expected integer " + std::string(entity) + " ids, got " + json_kind(v));
      const long long m = v.get<long long>();
      if (m < 0 || (limit >= 0 && m >= limit))
        s.fail("set", std::string(entity) + " id " + std::to_string(m) + " is not in 0.." + std::to_string(limit - 1));
      members.push_back(m);
    }
    s.finish();
    if (!out.emplace(id, std::move(members)).second) s.fail("id", "duplicate set id " + std::to_string(id));
  }
  return out;
}

EntitySets read_entity_sets(const fs::path& file, const std::string& shown, long long nnodes, long long ncells) {
  const json j = parse_json_file(file, shown);
  StrictObject root(j, shown, "");
  EntitySets sets;
  sets.nodes = read_set_list(root, "node_sets", nnodes, "node");
  sets.particles = read_set_list(root, "particle_sets", -1, "particle");
  sets.cells = read_set_list(root, "cell_sets", ncells, "cell");
  root.finish();
  return sets;
}

/// Resolved material table.
MaterialSpec read_material(StrictObject& m, int dim) {
  MaterialSpec spec;
  const long long id = m.integer("id");
  if (id < 0) m.fail("id", "expected an integer >= 0, got " + std::to_string(id));
  spec.id = static_cast<unsigned>(id);
  spec.type = read_material_type(m, dim);
  spec.density = m.number_in("density", kDensityRange);
  spec.youngs_modulus = m.number_in("youngs_modulus", kYoungsModulusRange);
  spec.poisson_ratio = m.number_in("poisson_ratio", kPoissonRatioRange);
  if (spec.type == MaterialType::MohrCoulomb2D) {
    const double deg = std::numbers::pi / 180.0;
    auto angle = [&](const char* key) { return m.number_in(key, kFrictionAngleRange) * deg; };
    spec.friction = angle("friction");
    spec.dilation = angle("dilation");
    spec.cohesion = m.number_in("cohesion", kCohesionRange);
    spec.residual_friction = angle("residual_friction");
    spec.residual_dilation = angle("residual_dilation");
    spec.residual_cohesion = m.number_in("residual_cohesion", kCohesionRange);
    spec.peak_pdstrain = m.number_in("peak_pdstrain", kPdstrainRange);
    spec.residual_pdstrain = m.number_in("residual_pdstrain", kPdstrainRange);
    spec.tension_cutoff = m.number_in("tension_cutoff", kTensionCutoffRange);
    spec.softening = m.boolean("softening");
    spec.separation_volume_ratio = m.number_or("separation_volume_ratio", kDefaultSeparationVolumeRatio);
    if (const auto p = separation_volume_ratio_problem(spec.separation_volume_ratio); !p.empty())
      m.fail("separation_volume_ratio", p);
    if (const auto p = dilation_problem(spec.dilation / deg, spec.friction / deg); !p.empty()) m.fail("dilation", p);
    if (spec.softening && !(spec.residual_pdstrain > spec.peak_pdstrain))
      m.fail("residual_pdstrain", "must be > peak_pdstrain when softening is true");
    if (spec.friction == 0 && spec.cohesion == 0) m.fail("cohesion", "friction 0 and cohesion 0 give no strength");
  }
  m.finish();
  return spec;
}

std::vector<MaterialSpec> read_materials(StrictObject& root, int dim) {
  const json& list = root.required("materials");
  if (!list.is_array() || list.empty()) root.fail("materials", "expected a non-empty array of materials");
  std::vector<MaterialSpec> out;
  for (std::size_t k = 0; k < list.size(); ++k) {
    StrictObject m(list[k], root.file(), "materials[" + std::to_string(k) + "]");
    MaterialSpec spec = read_material(m, dim);
    for (const auto& other : out)
      if (other.id == spec.id) m.fail("id", "duplicate material id " + std::to_string(spec.id));
    out.push_back(spec);
  }
  return out;
}

const MaterialSpec* find_material(const std::vector<MaterialSpec>& ms, long long id) {
  for (const auto& m : ms)
    if (static_cast<long long>(m.id) == id) return &m;
  return nullptr;
}

struct ResumeSpec {
  bool resume = false;
  std::string uuid;
  long long step = 0;
};

/// analysis (its type sets deck.grid.dim).
void read_analysis(StrictObject& a, Deck& deck, ResumeSpec& resume, std::string& uuid) {
  deck.grid.dim = read_analysis_dimension(a);
  Analysis& an = deck.analysis;
  // CB-Geo's current key is mpm_scheme; older decks call it stress_update. Never a silent default.
  std::string scheme_key = a.has("mpm_scheme") ? "mpm_scheme" : "stress_update";
  if (a.has("mpm_scheme") && a.has("stress_update")) a.fail("stress_update", "give mpm_scheme or stress_update, not both");
  if (!a.has(scheme_key)) a.fail("mpm_scheme", "missing (required: usf, usl or musl; older decks call it stress_update)");
  const std::string scheme = a.string(scheme_key);
  if (scheme == "usf") an.scheme = Scheme::USF;
  else if (scheme == "usl") an.scheme = Scheme::USL;
  else if (scheme == "musl") an.scheme = Scheme::MUSL;
  else a.fail(scheme_key, "unknown scheme \"" + scheme + "\" (expected usf, usl or musl)");
  read_velocity_transfer(a, an);
  an.locate_particles = a.boolean_or("locate_particles", true);
  // Extension: with cfl > 0 the engine picks dt = cfl h / c_p, and dt (optional then) is its upper bound.
  an.cfl = a.number_or("cfl", 0.0);
  if (!(an.cfl >= 0 && an.cfl <= 1)) a.fail("cfl", "expected a number in (0, 1] (0 or absent: fixed dt), got " + num(an.cfl));
  an.dt = an.cfl > 0 ? a.number_or("dt", 0.0) : a.number("dt");
  if (!(an.dt > 0) && !(an.cfl > 0 && an.dt == 0)) a.fail("dt", "expected a number > 0, got " + num(an.dt));
  an.nsteps = a.integer("nsteps");
  if (an.nsteps <= 0) a.fail("nsteps", "expected an integer > 0, got " + std::to_string(an.nsteps));
  uuid = a.string_or("uuid", "");
  if (const json* d = a.optional("damping")) {
    StrictObject damping(*d, a.file(), a.path_of("damping"));
    const std::string dtype = damping.string("type");
    if (dtype != "Cundall") damping.fail("type", "unsupported damping \"" + dtype + "\" (expected Cundall)");
    an.cundall_damping = damping.number_in("damping_factor", kDampingFactorRange);
    damping.finish();
  }
  if (const json* r = a.optional("resume")) {
    StrictObject rs(*r, a.file(), a.path_of("resume"));
    resume.resume = rs.boolean("resume");
    resume.uuid = rs.string_or("uuid", "");
    resume.step = rs.integer_or("step", 0);
    if (resume.resume) {
      if (resume.uuid.empty()) rs.fail("uuid", "missing (required when resume is true)");
      if (resume.step < 0 || resume.step >= an.nsteps)
        rs.fail("step", "expected an integer in 0.." + std::to_string(an.nsteps - 1) + " (analysis.nsteps - 1), got " +
                            std::to_string(resume.step));
    }
    rs.finish();
  }
  // CB-Geo's pressure smoothing maps the "pressure" state variable of its fluid materials (Newtonian,
  // Bingham) to the nodes and back (mpm_explicit.tcc pressure_smoothing, particle.tcc
  // map_pressure_to_nodes: only where that state variable exists); its solids have none, so there it
  // changes nothing, as here.
  if (a.has("pressure_smoothing") && a.boolean("pressure_smoothing"))
    deck.warnings.push_back(a.path_of("pressure_smoothing") +
                              ": true changes nothing for LinearElastic2D and MohrCoulomb2D (as in CB-Geo, where it "
                              "smooths the pressure of fluid materials only); the checkerboard remedies for solids are "
                              "analysis.stress_smoothing");
  // Keys of CB-Geo that change nothing here, accepted only with the value this program honours.
  a.accept_only("interface", {false}, "multi-material contact is not implemented");
  if (const json* nlb = a.optional("nload_balance_steps"))
    if (!nlb->is_number_integer() || nlb->get<long long>() <= 0)
      a.fail("nload_balance_steps", "expected an integer > 0 (MPI load balancing; no effect here)");
  // Extensions (mpm/README.md).
  an.stress_smoothing = a.string_or("stress_smoothing", "none");
  const auto& methods = stress_smoothing_methods();
  if (std::find(methods.begin(), methods.end(), an.stress_smoothing) == methods.end()) {
    std::string list;
    for (const auto& m : methods) list += (list.empty() ? "" : ", ") + m;
    a.fail("stress_smoothing", "unknown method \"" + an.stress_smoothing + "\" (expected one of " + list + ")");
  }
  a.finish();
}

/// The lattice nodes of an entry's nset_id: an entity set, -1 for every node (CB-Geo), or (extension) a
/// generated grid's named set.
std::vector<int> nodes_of_set(StrictObject& c, const Lattice& lattice, const EntitySets& sets,
                              const std::map<std::string, std::vector<int>>& named) {
  std::vector<int> nodes;
  if (c.has("nset_id") && c.required("nset_id").is_string()) {  // extension: a generated grid's named set
    const std::string name = c.string("nset_id");
    const auto it = named.find(name);
    if (it == named.end())
      c.fail("nset_id", "no node set named \"" + name + "\"" +
                            (named.empty() ? " (named sets exist only on a generated grid)"
                                           : " (expected " + boundary_set_names(lattice.grid.dim) + ")"));
    return it->second;
  }
  const long long nset = c.integer("nset_id");
  if (nset == -1) {  // CB-Geo: set -1 is every node
    const auto count = static_cast<int>(lattice.grid.node_count());
    for (int k = 0; k < count; ++k) nodes.push_back(k);
    return nodes;
  }
  const auto it = sets.nodes.find(nset);
  if (it == sets.nodes.end()) c.fail("nset_id", "node set " + std::to_string(nset) + " is not defined in the entity sets");
  for (long long id : it->second) nodes.push_back(lattice.node_index[id]);
  return nodes;
}

/// The lattice index of a node id read from a file (`shown`, entry `line`).
int file_node(const Lattice& lattice, const std::string& shown, double value, int line) {
  const double r = std::round(value);
  if (r != value || r < 0 || r >= static_cast<double>(lattice.node_index.size()))
    throw common::InputError(shown, "entry " + std::to_string(line) + ": node id " + num(value) + " is not a node of the mesh");
  return lattice.node_index[static_cast<std::size_t>(r)];
}

/// Constraint lists of mesh.boundary_conditions.
void read_boundary_conditions(StrictObject& bc, const Lattice& lattice, const EntitySets& sets,
                              const std::map<std::string, std::vector<int>>& named, Deck& deck, const fs::path& dir) {
  auto node_set = [&](StrictObject& c) { return nodes_of_set(c, lattice, sets, named); };
  if (const json* list = bc.optional("velocity_constraints")) {
    if (!list->is_array()) bc.fail("velocity_constraints", "expected an array");
    for (std::size_t k = 0; k < list->size(); ++k) {
      StrictObject c((*list)[k], bc.file(), bc.path_of("velocity_constraints") + "[" + std::to_string(k) + "]");
      if (c.has("file")) {  // lines "node dir velocity"
        const std::string f = c.string("file");
        const auto rows = read_columns(dir / f, f, 3);
        for (std::size_t r = 0; r < rows.size(); ++r) {
          VelocityConstraint vc;
          vc.nodes = {file_node(lattice, f, rows[r][0], static_cast<int>(r))};
          vc.dir = axis_column(f, rows[r][1], r, lattice.grid.dim);
          vc.velocity = rows[r][2];
          deck.velocity_constraints.push_back(vc);
        }
      } else {
        VelocityConstraint vc;
        vc.nodes = node_set(c);
        vc.dir = read_axis(c, lattice.grid.dim);
        vc.velocity = c.number("velocity");
        deck.velocity_constraints.push_back(std::move(vc));
      }
      c.finish();
    }
  }
  if (const json* list = bc.optional("friction_constraints")) {
    if (!list->is_array()) bc.fail("friction_constraints", "expected an array");
    for (std::size_t k = 0; k < list->size(); ++k) {
      StrictObject c((*list)[k], bc.file(), bc.path_of("friction_constraints") + "[" + std::to_string(k) + "]");
      auto check = [&](double sign, double mu, const std::function<void(const std::string&)>& bad) {
        if (sign != 1 && sign != -1) bad("sign_n must be -1 or 1");
        if (!(mu >= 0)) bad("friction must be >= 0");
      };
      // normal_lag (this code's, optional): the strength lags the normal force (mpm/core/lagged_friction.hpp)
      double lag_slip = 0, lag_speed = 0;
      if (c.has("normal_lag")) {
        StrictObject lag = c.object("normal_lag");
        lag_slip = lag.number_in("slip_distance", common::NumberRange::positive());
        lag_speed = lag.number_in("reference_velocity", common::NumberRange::non_negative());
        lag.finish();
      }
      if (c.has("file")) {  // lines "node dir sign_n friction"
        const std::string f = c.string("file");
        const auto rows = read_columns(dir / f, f, 4);
        for (std::size_t r = 0; r < rows.size(); ++r) {
          FrictionConstraint fc;
          fc.nodes = {file_node(lattice, f, rows[r][0], static_cast<int>(r))};
          fc.dir = axis_column(f, rows[r][1], r, lattice.grid.dim);
          check(rows[r][2], rows[r][3], [&](const std::string& w) { throw common::InputError(f, "entry " + std::to_string(r) + ": " + w); });
          fc.sign_n = static_cast<int>(rows[r][2]);
          fc.friction = rows[r][3];
          fc.lag_slip_distance = lag_slip;
          fc.lag_reference_velocity = lag_speed;
          deck.friction_constraints.push_back(fc);
        }
      } else {
        FrictionConstraint fc;
        fc.nodes = node_set(c);
        fc.dir = read_axis(c, lattice.grid.dim);
        const long long sign = c.integer("sign_n");
        if (sign != 1 && sign != -1) c.fail("sign_n", "expected -1 or 1, got " + std::to_string(sign));
        fc.sign_n = static_cast<int>(sign);
        fc.friction = c.number_in("friction", kFrictionCoefficientRange);
        fc.lag_slip_distance = lag_slip;
        fc.lag_reference_velocity = lag_speed;
        deck.friction_constraints.push_back(std::move(fc));
      }
      c.finish();
    }
  }
  bc.finish();
}

/// external_loading_conditions.base_acceleration: {"dir": 0 or 1, "acceleration": m/s2, "math_function_id"}.
BaseAcceleration read_base_acceleration(StrictObject& b, const std::map<unsigned, MathFunction>& functions, int dim) {
  BaseAcceleration out;
  out.dir = read_axis(b, dim);
  out.acceleration = b.number_in("acceleration", kFiniteRange);
  out.history = math_function_of(b, functions);
  b.finish();
  return out;
}

/// `rows` in `order` (rows[order[k]] becomes row k); an empty `rows` stays empty.
template <class Row>
void permute(std::vector<Row>& rows, const std::vector<std::size_t>& order) {
  if (rows.empty()) return;
  std::vector<Row> sorted;
  sorted.reserve(order.size());
  for (std::size_t k : order) sorted.push_back(rows[k]);
  rows = std::move(sorted);
}

/// Sorts deck.particles by id, and deck.particle_affine(_3d) and deck.particle_pore_pressure (when given) with them.
void sort_by_id(Deck& deck) {
  std::vector<std::size_t> order(deck.particles.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return deck.particles[a].id < deck.particles[b].id; });
  permute(deck.particles, order);
  if (deck.particle_pore_pressure) permute(*deck.particle_pore_pressure, order);
  permute(deck.particle_affine, order);
  permute(deck.particle_affine_3d, order);
}

/// external_loading_conditions: gravity, CB-Geo's nodal forces and particle tractions (external_loads.hpp)
/// and (extension) a base acceleration, with the math functions they name.
void read_loads(StrictObject& root, Deck& deck, const Lattice& lattice, const EntitySets& sets,
                const std::map<std::string, std::vector<int>>& named, const GeneratedParticles& gen, bool resumed,
                const fs::path& dir) {
  const auto math_functions = read_math_functions(root);
  const json* loads = root.optional("external_loading_conditions");
  if (loads == nullptr) return;
  StrictObject l(*loads, root.file(), "external_loading_conditions");
  read_gravity(l, deck.grid.dim, deck.analysis);
  if (l.has("base_acceleration")) {
    StrictObject b = l.object("base_acceleration");
    deck.base_acceleration = read_base_acceleration(b, math_functions, deck.grid.dim);
  }
  LoadSets load_sets;
  load_sets.dim = deck.grid.dim;
  load_sets.nodes = [&](StrictObject& c) { return nodes_of_set(c, lattice, sets, named); };
  load_sets.file_node = [&](const std::string& shown, double id, int entry) { return file_node(lattice, shown, id, entry); };
  load_sets.particles = [&](StrictObject& c) {
    const long long pset = c.integer("pset_id");
    std::vector<std::int64_t> ids;
    if (pset == -1) {  // CB-Geo: set -1 is every particle
      for (const auto& p : deck.particles) ids.push_back(p.id);
      return ids;
    }
    const std::vector<long long>* members = nullptr;
    if (auto it = sets.particles.find(pset); it != sets.particles.end()) members = &it->second;
    else if (auto jt = gen.psets.find(pset); jt != gen.psets.end()) members = &jt->second;
    if (!members)
      c.fail("pset_id", "particle set " + std::to_string(pset) + " is not defined" +
                            (resumed ? " (on resume the particle_sets of the entity sets and of gauss generators are known, "
                                       "not those of file generators)"
                                     : ""));
    ids.assign(members->begin(), members->end());
    return ids;
  };
  deck.nodal_forces = read_nodal_forces(l, math_functions, load_sets, dir);
  deck.particle_tractions = read_particle_tractions(l, math_functions, load_sets);
  l.finish();
}

}  // namespace

Deck read_deck(const fs::path& working_dir, const std::string& input_file) {
  const fs::path dir = working_dir;
  const std::string shown = input_file;
  const json j = parse_json_file(dir / input_file, shown);
  StrictObject root(j, shown, "");
  Deck deck;
  deck.working_dir = dir;
  root.string_or("title", "");

  // analysis first: nsteps names the resume file.
  ResumeSpec resume;
  std::string uuid;
  {
    StrictObject a = root.object("analysis");
    read_analysis(a, deck, resume, uuid);
  }
  deck.materials = read_materials(root, deck.grid.dim);

  // post_processing.
  {
    StrictObject pp = root.object("post_processing");
    deck.output.path = pp.string_or("path", "results/");
    deck.output.output_steps = pp.integer("output_steps");
    if (deck.output.output_steps <= 0)
      pp.fail("output_steps", "expected an integer > 0, got " + std::to_string(deck.output.output_steps));
    read_vtk_keys(pp, deck.output);
    read_particle_output_steps(pp, deck.analysis.nsteps, deck.output);
    pp.finish();
  }

  // mesh.
  StrictObject mesh = root.object("mesh");
  const int dim = deck.grid.dim;
  mesh.boolean_or("isoparametric", false);  // cells are rectangles (boxes): both mappings are the same
  mesh.boolean_or("check_duplicates", false);  // the lattice check rejects duplicate nodes and cells always
  const CellType type = read_mesh_cell_type(mesh, dim);
  Lattice lattice;
  std::map<std::string, std::vector<int>> named_sets;
  if (const json* gen = mesh.optional("generator")) {  // extension: a generated grid, no mesh file
    if (mesh.has("mesh")) mesh.fail("mesh", "give a mesh file or a generator, not both");
    StrictObject g(*gen, shown, "mesh.generator");
    // [a, b] in 2D, [a, b, c] in 3D.
    auto tuple = [&](const char* key, bool integer) {
      const json& v = g.required(key);
      bool ok = v.is_array() && v.size() == static_cast<std::size_t>(dim);
      for (std::size_t k = 0; ok && k < v.size(); ++k) ok = v[k].is_number() && (!integer || v[k].is_number_integer());
      if (!ok)
        g.fail(key, dim == 3 ? std::string("expected [") + (integer ? "nx, ny, nz] (3 integers)" : "x, y, z] (3 numbers)")
                             : std::string("expected [") + (integer ? "nx, ny] (2 integers)" : "x, y] (2 numbers)"));
      std::array<double, kMaxDim> out{};
      for (int d = 0; d < dim; ++d) out[d] = v[d].get<double>();
      return out;
    };
    const auto origin = tuple("origin", false), h = tuple("cell_size", false), n = tuple("cells", true);
    double cells = 1;
    std::array<int, kMaxDim> counts{};
    for (int d = 0; d < dim; ++d)
      if (!(h[d] > 0)) g.fail("cell_size", "expected sizes > 0");
    for (int d = 0; d < dim; ++d) {
      cells *= n[d];
      if (!(n[d] >= 1 && cells <= 1e8)) g.fail("cells", "expected 1 to 1e8 cells");
      counts[d] = static_cast<int>(n[d]);
    }
    // The lattice holds ~16 (3D: 64) node ids and a few coordinates per cell.
    if (const auto problem = common::size_problem(cells, dim == 3 ? 1024 : 256, "cells"); !problem.empty()) g.fail("cells", problem);
    g.finish();
    lattice = generate_lattice(dim, origin, h, counts, type);
    named_sets = boundary_node_sets(lattice.grid);
  } else {
    const std::string mesh_file = mesh.string("mesh");
    const auto nodes_per_cell = static_cast<int>(cell_node_natural_coordinates(type, dim).size());
    const MeshFile mf = read_mesh_file(dir / mesh_file, mesh_file, dim, nodes_per_cell);
    lattice = recognise_lattice(mf, type, mesh_file);
  }
  deck.grid = lattice.grid;

  EntitySets sets;
  if (const json* es = mesh.optional("entity_sets")) {
    if (!es->is_string()) mesh.fail("entity_sets", "expected a file name");
    const std::string f = es->get<std::string>();
    sets = read_entity_sets(dir / f, f, static_cast<long long>(lattice.node_index.size()),
                            static_cast<long long>(lattice.cell_ij.size()));
  }
  if (const json* bc = mesh.optional("boundary_conditions")) {
    StrictObject b(*bc, shown, "mesh.boundary_conditions");
    read_boundary_conditions(b, lattice, sets, named_sets, deck, dir);
  }

  // particles: generators, or the resume file.
  GeneratedParticles gen = read_generators(root, deck.materials, lattice, sets.cells, dir, !resume.resume);
  const auto stresses_key = mesh.optional("particles_stresses");
  const auto volumes_key = mesh.optional("particles_volumes");
  const auto cells_key = mesh.optional("particle_cells");
  const bool update_materials = mesh.boolean_or("update_materials", false);
  mesh.finish();

  if (resume.resume) {
    const fs::path file = dir / deck.output.path / resume.uuid / particle_file_name(resume.step, deck.analysis.nsteps);
    const std::string rshown = (deck.output.path / resume.uuid / particle_file_name(resume.step, deck.analysis.nsteps)).string();
    if (!fs::exists(file))
      throw common::InputError(shown + ": analysis.resume", "resume file " + rshown + " not found (looked for " + file.string() + ")");
    deck.particles = read_particle_table(file);
    if (deck.particles.empty()) throw common::InputError(rshown, "the resume file holds no particles");
    for (const auto& p : deck.particles) {
      if (!find_material(deck.materials, p.material_id))
        throw common::InputError(rshown, "particle " + std::to_string(p.id) + ": material_id " + std::to_string(p.material_id) +
                                             " is not defined in " + shown + " materials");
      if (!inside_region(deck.grid, p))
        throw common::InputError(rshown, "particle " + std::to_string(p.id) + " at " + position_text(p, deck.grid.dim) +
                                             " is outside the grid's cells");
      if (!(p.mass > 0) || !(p.volume > 0))
        throw common::InputError(rshown, "particle " + std::to_string(p.id) + ": mass and volume must be > 0");
      // CB-Geo's 2D tables hold z = 0 (coordinate, displacement, velocity, size); a 3D table's particles do not.
      if (deck.grid.dim == 2 && (p.coord_z != 0 || p.displacement_z != 0 || p.velocity_z != 0 || p.nsize_z != 0))
        throw common::InputError(rshown, "particle " + std::to_string(p.id) + " has a z coordinate, displacement, velocity or size (z " +
                                             num(p.coord_z) + ", nsize_z " + num(p.nsize_z) +
                                             "): a 3D particle table on a 2D deck (MPMExplicit2D reads x and y)");
      // and a 2D table's particles have a size in x and y but none in z (CB-Geo's 3D tables: 2/ppd on each axis).
      if (deck.grid.dim == 3 && p.nsize_z == 0 && (p.nsize_x != 0 || p.nsize_y != 0))
        throw common::InputError(rshown, "particle " + std::to_string(p.id) + " has a size in x and y but none in z (nsize_x " +
                                             num(p.nsize_x) + ", nsize_z 0): a 2D particle table on a 3D deck");
    }
    read_resume_extras(file, shown, rshown, deck);
    sort_by_id(deck);
    for (std::size_t k = 1; k < deck.particles.size(); ++k)
      if (deck.particles[k].id == deck.particles[k - 1].id)
        throw common::InputError(rshown, "particle id " + std::to_string(deck.particles[k].id) + " appears twice");
    deck.resumed = true;
    deck.first_step = resume.step + 1;
    // CB-Geo writes the resumed run's outputs under the resume uuid.
    deck.output.uuid = resume.uuid;
  } else {
    deck.particles = std::move(gen.records);
    check_no_duplicates(deck.particles, "particles");
    const std::size_t n = deck.particles.size();
    if (n == 0) throw common::InputError(shown + ": particles", "the generators produced no particles");
    if (stresses_key) {
      if (!stresses_key->is_string()) throw common::InputError(shown + ": mesh.particles_stresses", "expected a file name");
      const std::string f = stresses_key->get<std::string>();
      const auto s = read_particle_stresses(dir / f, f);
      if (s.size() != n)
        throw common::InputError(f, "has " + std::to_string(s.size()) + " stress lines for " + std::to_string(n) + " particles");
      for (std::size_t k = 0; k < n; ++k) {
        auto& p = deck.particles[k];
        p.stress_xx = s[k][0]; p.stress_yy = s[k][1]; p.stress_zz = s[k][2];
        p.tau_xy = s[k][3]; p.tau_yz = s[k][4]; p.tau_xz = s[k][5];
      }
    }
    // Per-cell counts (CB-Geo's default volume and size use them).
    std::map<long, int> per_cell;
    for (const auto& p : deck.particles) ++per_cell[cell_of(deck.grid, position_of(p))];
    if (volumes_key) {
      if (!volumes_key->is_string()) throw common::InputError(shown + ": mesh.particles_volumes", "expected a file name");
      const std::string f = volumes_key->get<std::string>();
      for (const auto& row : read_columns(dir / f, f, 2)) {
        const double id = row[0];
        if (id != std::round(id) || id < 0 || id >= static_cast<double>(n))
          throw common::InputError(f, "particle id " + num(id) + " is not a particle of the deck (0.." + std::to_string(n - 1) + ")");
        if (!(row[1] > 0)) throw common::InputError(f, "particle " + num(id) + ": volume must be > 0, got " + num(row[1]));
        auto& p = deck.particles[static_cast<std::size_t>(id)];
        p.volume = row[1];
        p.mass = find_material(deck.materials, p.material_id)->density * p.volume;
        // 2 / (particles per direction): the square (3D: cube) root of the particles in the cell.
        const double count = static_cast<double>(per_cell[cell_of(deck.grid, position_of(p))]);
        const double nsize = 2.0 / (deck.grid.dim == 3 ? std::cbrt(count) : std::sqrt(count));
        p.nsize_x = p.nsize_y = nsize;
        if (deck.grid.dim == 3) p.nsize_z = nsize;
      }
    }
    if (cells_key) {
      if (!cells_key->is_string()) throw common::InputError(shown + ": mesh.particle_cells", "expected a file name");
      const std::string f = cells_key->get<std::string>();
      for (const auto& row : read_columns(dir / f, f, 2)) {
        const double pid = row[0], cid = row[1];
        if (pid != std::round(pid) || pid < 0 || pid >= static_cast<double>(n))
          throw common::InputError(f, "particle id " + num(pid) + " is not a particle of the deck");
        if (cid != std::round(cid) || cid < 0 || cid >= static_cast<double>(lattice.cell_ij.size()))
          throw common::InputError(f, "cell id " + num(cid) + " is not a cell of the mesh");
        const auto& p = deck.particles[static_cast<std::size_t>(pid)];
        const LatticeCell& cell = lattice.cell_ij[static_cast<std::size_t>(cid)];
        const auto& h = deck.grid.spacing;
        const auto x = position_of(p);
        const double eps = 1e-9 * *std::max_element(h.begin(), h.begin() + deck.grid.dim);
        for (int d = 0; d < deck.grid.dim; ++d) {
          const double lo = deck.grid.origin[d] + cell[d] * h[d];
          if (x[d] < lo - eps || x[d] > lo + h[d] + eps)
            throw common::InputError(f, "particle " + num(pid) + " at " + position_text(p, deck.grid.dim) + " is not inside cell " +
                                            num(cid));
        }
      }
    }
  }

  // material_sets: applied (as in CB-Geo) only with mesh.update_materials true; never ignored silently.
  if (const json* ms = root.optional("material_sets")) {
    if (!ms->is_array()) root.fail("material_sets", "expected an array of {\"material_id\", \"pset_id\"}");
    if (!ms->empty() && !update_materials)
      root.fail("material_sets", "given but mesh.update_materials is not true (CB-Geo would ignore them silently)");
    if (!ms->empty() && resume.resume)
      root.fail("material_sets", "cannot be applied on resume (the resume file carries each particle's material_id)");
    for (std::size_t k = 0; k < ms->size(); ++k) {
      StrictObject s((*ms)[k], shown, "material_sets[" + std::to_string(k) + "]");
      const long long mid = s.integer("material_id");
      s.accept_only("phase_id", {0}, "one phase (the solid) is modelled");
      if (!find_material(deck.materials, mid)) s.fail("material_id", "material " + std::to_string(mid) + " is not defined in materials");
      const long long pset = s.integer("pset_id");
      const std::vector<long long>* members = nullptr;
      if (auto it = sets.particles.find(pset); it != sets.particles.end()) members = &it->second;
      else if (auto jt = gen.psets.find(pset); jt != gen.psets.end()) members = &jt->second;
      if (!members) s.fail("pset_id", "particle set " + std::to_string(pset) + " is not defined");
      for (long long id : *members) {
        if (id >= static_cast<long long>(deck.particles.size()))
          s.fail("pset_id", "particle set " + std::to_string(pset) + " names particle " + std::to_string(id) + ", which does not exist");
        const auto& m = *find_material(deck.materials, mid);
        auto& p = deck.particles[id];
        p.material_id = m.id;
        if (p.volume > 0) p.mass = m.density * p.volume;
      }
      s.finish();
    }
  } else if (update_materials) {
    throw common::InputError(shown + ": mesh.update_materials", "true but no material_sets are given");
  }
  if (!resume.resume) {
    for (const auto& [id, members] : sets.particles)
      for (long long m : members)
        if (m >= static_cast<long long>(deck.particles.size()))
          throw common::InputError(shown + ": mesh.entity_sets", "particle set " + std::to_string(id) + " names particle " +
                                                                    std::to_string(m) + ", which does not exist");
  }

  read_loads(root, deck, lattice, sets, named_sets, gen, resume.resume, dir);

  if (deck.output.uuid.empty()) deck.output.uuid = uuid.empty() ? fs::path(input_file).stem().string() : uuid;
  if (const auto problem = run_name_problem(deck.output.uuid); !problem.empty())
    throw common::InputError(shown + (resume.resume ? ": analysis.resume.uuid" : ": analysis.uuid"), problem);
  root.finish();
  return deck;
}

}  // namespace mpm::io
