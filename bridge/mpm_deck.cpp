#include "bridge/mpm_deck.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>
#include <sstream>
#include <stdexcept>

#include "common/finite_number.hpp"
#include "common/input_error.hpp"
#include "common/number_text.hpp"
#include "mpm/io/deck_rules.hpp"

namespace bridge {
namespace {

/// Most background cells a deck may have (mesh.txt of ED2Q16G cells is ~100 bytes per cell; mpm's
/// generated grids stop at 1e8 too).
constexpr double kMaxGridCells = 1e8;

/// A number quoted in an error message (9 significant digits, as the other bridge messages).
std::string num(double v) { return common::number_text(v, 9); }

using nlohmann::ordered_json;

/// Appends `v` in shortest round-trip form (fast, locale-free).
void append_number(std::string& out, double v) {
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, res.ptr);
}

void append_integer(std::string& out, long v) {
  char buf[24];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, res.ptr);
}

/// A particle coordinate file (CB-Geo's Ascii2D generator file): the count, then x and y per line.
std::string coordinate_file(std::span<const mpm::ParticleRecord> particles) {
  std::string out;
  out.reserve(particles.size() * 40 + 16);
  append_integer(out, static_cast<long>(particles.size()));
  out += '\n';
  for (const auto& p : particles) {
    append_number(out, p.coord_x);
    out += '\t';
    append_number(out, p.coord_y);
    out += '\n';
  }
  return out;
}

double p_wave_speed(const MpmMaterial& m) {
  const double nu = m.poisson_ratio;
  return std::sqrt(m.youngs_modulus * (1 - nu) / ((1 + nu) * (1 - 2 * nu) * m.density));
}

ordered_json material_json(const MpmMaterial& m) {
  ordered_json j;
  j["id"] = m.id;
  if (m.type == MpmMaterial::Type::LinearElastic2D) {
    j["type"] = "LinearElastic2D";
    j["density"] = m.density;
    j["youngs_modulus"] = m.youngs_modulus;
    j["poisson_ratio"] = m.poisson_ratio;
    return j;
  }
  const double deg = 180 / std::numbers::pi;
  j["type"] = "MohrCoulomb2D";
  j["density"] = m.density;
  j["youngs_modulus"] = m.youngs_modulus;
  j["poisson_ratio"] = m.poisson_ratio;
  j["friction"] = m.friction * deg;
  j["dilation"] = m.dilation * deg;
  j["cohesion"] = m.cohesion;
  j["residual_friction"] = m.friction * deg;
  j["residual_dilation"] = m.dilation * deg;
  j["residual_cohesion"] = m.softening ? m.softening->residual_cohesion : m.cohesion;
  j["peak_pdstrain"] = m.softening ? m.softening->peak_pdstrain : 0.0;
  j["residual_pdstrain"] = m.softening ? m.softening->residual_pdstrain : 0.0;
  j["tension_cutoff"] = m.tension_cutoff;
  j["softening"] = m.softening.has_value();
  return j;
}

}  // namespace

GridSpec choose_grid(const TransferState& state, std::span<const mpm::ParticleRecord> particles,
                     const DeckOptions& options, std::vector<std::string>* warnings) {
  GridSpec g;
  g.gimp = options.gimp;
  double area = 0;
  for (const auto& e : state.elements) area += std::abs(quad_area(state.reference_nodes(e)));
  g.h = options.cell_size ? *options.cell_size : std::sqrt(area / static_cast<double>(std::max<std::size_t>(1, state.elements.size())));
  if (!(g.h > 0) || !std::isfinite(g.h)) throw common::InputError("--cell-size", "expected a cell size > 0 (finite), got " + num(g.h));
  // Bounding box of the current nodes used by the elements.
  double xmin = std::numeric_limits<double>::infinity(), ymin = xmin, xmax = -xmin, ymax = -xmin;
  for (const auto& e : state.elements)
    for (int a : e.nodes) {
      const Vec2 p = state.current(a);
      xmin = std::min(xmin, p.x()); xmax = std::max(xmax, p.x());
      ymin = std::min(ymin, p.y()); ymax = std::max(ymax, p.y());
    }
  // Cell counts as doubles first: a huge extent or a tiny cell must be an error, not an int overflow
  // or std::bad_alloc while the mesh text is built.
  const char* culprit = options.extent ? (options.cell_size ? "--extent / --cell-size" : "--extent") : "--cell-size";
  auto set_cell_counts = [&](double width_m, double height_m) {
    const double nx = std::ceil(width_m / g.h - 1e-9), ny = std::ceil(height_m / g.h - 1e-9);
    if (!(nx * ny <= kMaxGridCells) || !(nx + 3 <= std::numeric_limits<int>::max() && ny + 3 <= std::numeric_limits<int>::max()))
      throw common::InputError(culprit, "the grid would have " + num(nx) + " x " + num(ny) + " cells of " + num(g.h) +
                                            " m (at most " + num(kMaxGridCells) + " cells)");
    if (const auto problem = common::size_problem(nx * ny, g.gimp ? 160 : 48, "grid cells"); !problem.empty())
      throw common::InputError(culprit, problem);
    g.nx = static_cast<int>(nx);
    g.ny = static_cast<int>(ny);
  };
  if (options.extent) {  // finite and ordered (check_deck_options)
    const auto& ext = *options.extent;
    g.x0 = ext[0];
    g.y0 = ext[2];
    set_cell_counts(ext[1] - ext[0], ext[3] - ext[2]);
    if (options.anchors && warnings) {
      auto off_line = [&](const std::optional<double>& line, double edge, const char* wall) {
        if (line && std::abs(*line - edge) > 1e-9 * g.h)
          warnings->push_back(std::string("--extent: the ") + wall + " lies on the grid's edge at x = " + num(edge) +
                              ", not on its FEM support line at x = " + num(*line));
      };
      off_line(options.anchors->left, g.x0, "left wall");
      off_line(options.anchors->right, g.x0 + g.nx * g.h, "right wall");
    }
  } else {
    // Walls and base on grid lines; the runout area (3 model widths) only beyond a free side, 0.25 heights
    // above the top. Without FEM supports: the legacy layout, a wall at the model's left side.
    const GridAnchors anchors = options.anchors ? *options.anchors : GridAnchors{xmin, std::nullopt, std::nullopt};
    const double width = xmax - xmin, height = ymax - ymin;
    const double left = anchors.left ? *anchors.left : xmin - 3 * width;
    const double right = anchors.right ? *anchors.right : xmax + 3 * width;
    if (anchors.left && anchors.right && !options.cell_size)  // a whole number of cells between the walls
      g.h = (right - left) / std::max(1.0, std::round((right - left) / g.h));
    const double bottom = anchors.base ? *anchors.base - g.h : ymin;  // one row below the base (GIMP support)
    const double top = ymax + 0.25 * height;
    set_cell_counts(right - left, top - bottom);
    g.x0 = anchors.left || !anchors.right ? left : right - g.nx * g.h;
    g.y0 = bottom;
    const double grid_right = g.x0 + g.nx * g.h;
    if (anchors.left && anchors.right && std::abs(grid_right - right) > 1e-9 * g.h && warnings)
      warnings->push_back("--cell-size " + num(g.h) + ": the right wall lies on the grid's edge at x = " + num(grid_right) +
                          ", " + num(grid_right - right) + " m beyond the FEM support line at x = " + num(right) +
                          "; a cell size that divides the wall distance " + num(right - left) + " m keeps it on the line");
  }
  const double x1 = g.x0 + g.nx * g.h, y1 = g.y0 + g.ny * g.h;
  for (const auto& p : particles)
    if (p.coord_x < g.x0 || p.coord_x > x1 || p.coord_y < g.y0 || p.coord_y > y1)
      throw common::InputError("--extent", "particle " + std::to_string(p.id) + " at (" + num(p.coord_x) + ", " +
                                               num(p.coord_y) + ") lies outside the grid [" + num(g.x0) + ", " + num(x1) +
                                               "] x [" + num(g.y0) + ", " + num(y1) + "]");
  return g;
}

void check_deck_options(const DeckOptions& options) {
  if (options.dt) common::checked_number(*options.dt, mpm::io::kTimeStepRange, "--dt");
  else common::checked_number(options.cfl, common::NumberRange::open_closed(0, 1).named("a Courant number"), "--cfl");
  if (options.nsteps) {
    if (*options.nsteps < 1) throw common::InputError("--nsteps", "expected at least 1 step");
  } else {
    common::checked_number(options.duration, common::NumberRange::positive(), "--duration");
  }
  if (options.output_steps && *options.output_steps < 1) throw common::InputError("--output-steps", "expected at least 1");
  if (options.step < 0) throw common::InputError("--step", "expected 0 <= step < nsteps");
  if (options.scheme != "usf" && options.scheme != "usl" && options.scheme != "musl")
    throw common::InputError("--scheme", "expected usf, usl or musl, got '" + options.scheme + "'");
  if (options.base == Base::Friction || options.base == Base::Contact)
    common::checked_number(options.base_friction, mpm::io::kFrictionCoefficientRange, "--base-friction");
  if (options.base_lag) {
    if (options.base != Base::Friction && options.base != Base::Contact)
      throw common::InputError("--base-lag", "needs a frictional base (--base contact or friction)");
    common::checked_number((*options.base_lag)[0], common::NumberRange::positive(), "--base-lag (slip distance, m)");
    common::checked_number((*options.base_lag)[1], common::NumberRange::non_negative(), "--base-lag (reference speed, m/s)");
  }
  common::checked_number(options.damping, mpm::io::kDampingFactorRange, "--damping");
  if (const auto problem = mpm::io::run_name_problem(options.uuid); !problem.empty()) throw common::InputError("--uuid", problem);
  if (options.cell_size && !(*options.cell_size > 0 && std::isfinite(*options.cell_size)))
    throw common::InputError("--cell-size", "expected a cell size > 0 (finite), got " + num(*options.cell_size));
  if (options.extent) {
    const auto& ext = *options.extent;
    for (double v : ext)
      if (!std::isfinite(v)) throw common::InputError("--extent", "expected finite numbers, got " + num(v));
    if (!(ext[1] > ext[0] && ext[3] > ext[2])) throw common::InputError("--extent", "expected xmin < xmax and ymin < ymax");
  }
}

DeckText plan_deck(const TransferState& state, std::span<const mpm::ParticleRecord> particles,
                   const DeckOptions& options) {
  check_deck_options(options);
  DeckText d;
  const GridSpec g = choose_grid(state, particles, options, &d.warnings);
  d.grid = g;
  if (options.dt) {
    d.dt = *options.dt;
  } else {
    double cmax = 0;
    for (const auto& m : state.materials) cmax = std::max(cmax, p_wave_speed(m));
    d.dt = options.cfl * g.h / cmax;
    if (!(d.dt > 0) || !std::isfinite(d.dt))
      throw common::InputError("--dt", "the default time step cfl h / c_p is " + num(d.dt) + "; give --dt");
  }
  if (options.nsteps) {
    d.nsteps = *options.nsteps;
  } else {
    const double steps = std::ceil(options.duration / d.dt - 1e-9) + 1;
    if (!(steps <= 1e15))
      throw common::InputError("--duration", num(options.duration) + " s at dt " + num(d.dt) + " s is " + num(steps) +
                                                 " steps (at most 1e15; give a larger --dt or a shorter --duration)");
    d.nsteps = static_cast<long long>(steps);
  }
  // Default: every 0.5 s, and at least the last step.
  d.output_steps = options.output_steps ? *options.output_steps
                                        : std::max<long long>(1, static_cast<long long>(std::min(
                                                                     std::round(0.5 / d.dt), static_cast<double>(d.nsteps - 1))));
  if (options.step >= d.nsteps) throw common::InputError("--step", "expected 0 <= step < nsteps");
  const double grid_top = g.y0 + g.ny * g.h;
  if (options.base_y && !(*options.base_y >= g.y0 && *options.base_y < grid_top))
    throw common::InputError("--base-y", "expected a height inside the grid [" + num(g.y0) + ", " +
                                             num(grid_top) + "), got " + num(*options.base_y));
  const std::optional<double> support_base = options.anchors ? options.anchors->base : std::nullopt;
  if (options.base_y) d.base_y = *options.base_y;
  else if (support_base && *support_base >= g.y0 && *support_base < grid_top) d.base_y = *support_base;
  else d.base_y = g.y0;
  d.particle_file = "results/" + options.uuid + "/" + mpm::io::particle_file_name(options.step, d.nsteps);
  if (options.ground_motion) {
    // The transferred state is the MPM state at t = (step + 1) dt (a resumed run's clock).
    d.base_motion = motion_after(*options.ground_motion, state.time, static_cast<double>(options.step + 1) * d.dt);
    if (d.base_motion.t.empty())
      d.warnings.push_back("the ground motion ends at " +
                           num(options.ground_motion->record.end_time()) +
                           " s, by the transfer time " + num(state.time) + " s: the deck has no base_acceleration");
  }
  return d;
}

void format_deck(const TransferState& state, std::span<const mpm::ParticleRecord> particles,
                 const DeckOptions& options, DeckText& d) {
  const GridSpec& g = d.grid;
  // mesh.txt: nnodes ncells, node coordinates, cells (CB-Geo Ascii2D).
  const int hal = g.halo();
  std::string& mesh = d.mesh_txt;
  mesh.reserve(static_cast<std::size_t>(g.nodes_x()) * g.nodes_y() * 24 + static_cast<std::size_t>(g.nx) * g.ny * (g.gimp ? 100 : 30));
  append_integer(mesh, static_cast<long>(g.nodes_x()) * g.nodes_y());
  mesh += '\t';
  append_integer(mesh, static_cast<long>(g.nx) * g.ny);
  mesh += '\n';
  for (int j = -hal; j <= g.ny + hal; ++j)
    for (int i = -hal; i <= g.nx + hal; ++i) {
      append_number(mesh, g.x0 + i * g.h);
      mesh += '\t';
      append_number(mesh, g.y0 + j * g.h);
      mesh += '\n';
    }
  // ED2Q16G local order: corners (-1,-1) (1,-1) (1,1) (-1,1), then the ring counter-clockwise from
  // (-3,-3) (FORMATS.md section 5); natural coordinate c -> lattice offset (c + 1) / 2.
  static constexpr int kGimp[16][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {-3, -3}, {-1, -3}, {1, -3}, {3, -3},
                                       {3, -1},  {3, 1},  {3, 3}, {1, 3},  {-1, 3}, {-3, 3}, {-3, 1}, {-3, -1}};
  static constexpr int kLinear[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int cj = 0; cj < g.ny; ++cj)
    for (int ci = 0; ci < g.nx; ++ci) {
      const int count = g.gimp ? 16 : 4;
      for (int k = 0; k < count; ++k) {
        const int* nat = g.gimp ? kGimp[k] : kLinear[k];
        if (k) mesh += '\t';
        append_integer(mesh, g.node_id(ci + (nat[0] + 1) / 2, cj + (nat[1] + 1) / 2));
      }
      mesh += '\n';
    }

  // entity_sets.json: 0 left wall (x <= x0), 1 base (y <= base_y, default y0), 2 right wall (x >= x0 + nx h),
  // halo included.
  ordered_json left = ordered_json::array(), base = ordered_json::array(), right = ordered_json::array();
  const double base_y = d.base_y;
  for (int j = -hal; j <= g.ny + hal; ++j)
    for (int i = -hal; i <= g.nx + hal; ++i) {
      if (i <= 0) left.push_back(g.node_id(i, j));
      if (g.y0 + j * g.h <= base_y + 1e-9 * g.h) base.push_back(g.node_id(i, j));
      if (i >= g.nx) right.push_back(g.node_id(i, j));
    }
  ordered_json sets;
  sets["node_sets"] = ordered_json::array({{{"id", 0}, {"set", left}}, {{"id", 1}, {"set", base}}, {{"id", 2}, {"set", right}}});
  // The FEM's loads: particle set k holds the k-th loaded particle; its traction t = f sqrt(V0) / V gives
  // mpm's force t V / sqrt(V0) = f (mpm/core/external_loads.hpp, V0 = m / rho).
  ordered_json tractions = ordered_json::array(), particle_sets = ordered_json::array();
  for (std::size_t k = 0; k < options.particle_loads.size(); ++k) {
    const ParticleLoad& load = options.particle_loads[k];
    const auto& p = particles[static_cast<std::size_t>(load.id)];
    if (p.id != load.id) throw std::logic_error("format_deck: particles are not in id order");
    const double rho = state.materials[p.material_id].density;
    particle_sets.push_back({{"id", k}, {"set", {load.id}}});
    for (int dir = 0; dir < 2; ++dir)
      if (load.force[dir] != 0.0)
        tractions.push_back({{"pset_id", k}, {"dir", dir}, {"traction", load.force[dir] * std::sqrt(p.mass / rho) / p.volume}});
  }
  if (!particle_sets.empty()) sets["particle_sets"] = particle_sets;
  d.entity_sets_json = sets.dump(1) + "\n";

  // Boundary conditions (CB-Geo velocity_constraints / friction_constraints).
  ordered_json vel = ordered_json::array(), fric = ordered_json::array();
  auto wall = [&](Wall w, int nset) {
    if (w == Wall::None) return;
    vel.push_back({{"nset_id", nset}, {"dir", 0}, {"velocity", 0.0}});
    if (w == Wall::Fixed) vel.push_back({{"nset_id", nset}, {"dir", 1}, {"velocity", 0.0}});
  };
  wall(options.left, 0);
  wall(options.right, 2);
  if (options.base != Base::Contact) vel.push_back({{"nset_id", 1}, {"dir", 1}, {"velocity", 0.0}});
  if (options.base == Base::Fixed) vel.push_back({{"nset_id", 1}, {"dir", 0}, {"velocity", 0.0}});
  if (options.base == Base::Friction || options.base == Base::Contact) {
    fric.push_back({{"nset_id", 1}, {"dir", 1}, {"sign_n", -1}, {"friction", options.base_friction}});
    if (options.base_lag)
      fric.back()["normal_lag"] = {{"slip_distance", (*options.base_lag)[0]}, {"reference_velocity", (*options.base_lag)[1]}};
  }

  ordered_json deck;
  std::ostringstream title;
  title << "fem2mpm: FEM state at t = " << state.time << " s transferred to material points";
  deck["title"] = title.str();
  ordered_json mesh_block;
  mesh_block["mesh"] = "mesh.txt";
  mesh_block["entity_sets"] = "entity_sets.json";
  mesh_block["cell_type"] = g.gimp ? "ED2Q16G" : "ED2Q4";
  mesh_block["isoparametric"] = false;
  mesh_block["check_duplicates"] = false;
  mesh_block["io_type"] = "Ascii2D";
  mesh_block["node_type"] = "N2D";
  ordered_json bc;
  bc["velocity_constraints"] = vel;
  if (!fric.empty()) bc["friction_constraints"] = fric;
  mesh_block["boundary_conditions"] = bc;
  deck["mesh"] = mesh_block;
  // One generator per material (CB-Geo gives a generator one material_id), each reading its own
  // coordinate file; the particles are grouped by material (generate_particles), so a fresh start
  // numbers them as the HDF5 file does.
  d.particle_files.clear();
  ordered_json generators = ordered_json::array();
  const std::size_t n = particles.size();
  const bool one_material =
      std::all_of(particles.begin(), particles.end(), [&](const auto& p) { return p.material_id == particles[0].material_id; });
  std::set<unsigned> seen;
  std::size_t first = 0;
  do {  // each run of equal material_id [first, last): one generator (one run, possibly empty, at least)
    const unsigned id = first < n ? particles[first].material_id : (state.materials.empty() ? 0u : state.materials.front().id);
    std::size_t last = first;
    while (last < n && particles[last].material_id == id) ++last;
    if (!seen.insert(id).second) throw std::logic_error("format_deck: the particles are not grouped by material");
    const std::string name = one_material ? "particles.txt" : "particles_material" + std::to_string(id) + ".txt";
    generators.push_back({{"generator",
                           {{"check_duplicates", false},
                            {"location", name},
                            {"io_type", "Ascii2D"},
                            {"pset_id", generators.size()},
                            {"particle_type", "P2D"},
                            {"material_id", id},
                            {"type", "file"}}}});
    d.particle_files.emplace_back(name, coordinate_file(particles.subspan(first, last - first)));
    first = last;
  } while (first < n);
  deck["particles"] = generators;
  ordered_json mats = ordered_json::array();
  for (const auto& m : state.materials) mats.push_back(material_json(m));
  deck["materials"] = mats;
  deck["external_loading_conditions"] = {{"gravity", {0.0, -state.gravity}}};
  if (!tractions.empty()) deck["external_loading_conditions"]["particle_surface_traction"] = tractions;
  if (!d.base_motion.t.empty()) {
    deck["math_functions"] = ordered_json::array(
        {{{"id", 0}, {"type", "Linear"}, {"xvalues", d.base_motion.t}, {"fxvalues", d.base_motion.a}}});
    deck["external_loading_conditions"]["base_acceleration"] = {
        {"dir", options.ground_motion->dof - 1}, {"acceleration", 1.0}, {"math_function_id", 0}};
  }
  ordered_json analysis;
  analysis["type"] = "MPMExplicit2D";
  analysis["mpm_scheme"] = options.scheme;
  analysis["dt"] = d.dt;
  analysis["nsteps"] = d.nsteps;
  analysis["uuid"] = options.uuid;
  const bool pic = options.velocity_update || options.transfer == "pic";
  analysis["velocity_update"] = pic;
  if (!pic) analysis["transfer"] = options.transfer;
  analysis["locate_particles"] = true;
  analysis["damping"] = {{"type", "Cundall"}, {"damping_factor", options.damping}};
  if (options.stress_smoothing != "none") analysis["stress_smoothing"] = options.stress_smoothing;
  analysis["resume"] = {{"resume", true}, {"uuid", options.uuid}, {"step", options.step}};
  deck["analysis"] = analysis;
  deck["post_processing"] = {{"path", "results/"}, {"output_steps", d.output_steps}};
  d.mpm_json = deck.dump(2) + "\n";

}

DeckText build_deck(const TransferState& state, std::span<const mpm::ParticleRecord> particles,
                    const DeckOptions& options) {
  DeckText d = plan_deck(state, particles, options);
  format_deck(state, particles, options, d);
  return d;
}

}  // namespace bridge
