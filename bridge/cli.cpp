#include "bridge/cli.hpp"

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>
#include <thread>

#include "bridge/affine_state.hpp"
#include "bridge/boundary_extraction.hpp"
#include "bridge/deck_boundaries.hpp"
#include "bridge/fem_model.hpp"
#include "bridge/fem_state_reader.hpp"
#include "bridge/liquefaction_report.hpp"
#include "bridge/liquefied_strength.hpp"
#include "bridge/material_exclusion.hpp"
#include "bridge/mpm_deck.hpp"
#include "bridge/nodal_loads.hpp"
#include "bridge/particle_mapping.hpp"
#include "bridge/pore_pressure.hpp"
#include "bridge/up_options.hpp"
#include "bridge/transfer_report.hpp"
#include "common/atomic_file.hpp"
#include "common/input_error.hpp"
#include "common/number_text.hpp"
#include "common/printable_text.hpp"
#include "mpm/io/deck_reader.hpp"
#include "mpm/io/deck_rules.hpp"

namespace bridge {
namespace {

struct CliOptions {
  std::string model, disp, vel, stress, loads, out;
  std::optional<double> time;
  std::optional<long> row;
  std::string nodes, elements;
  std::string units = "SI";
  std::string material_type;
  std::optional<double> E, nu, density, phi, cohesion, psi, tension, gravity;
  int ppd = 4;
  std::string recovery = "idw";
  std::string volume_split = "jacobian";
  std::string cell_type = "ED2Q16G";
  std::vector<std::string> material;           ///< --material NAME:key=value,... (per FEM material)
  std::vector<std::string> exclude_material;   ///< --exclude-material NAME[,NAME...]
  /// Unset: from the FEM supports in the model file, else roller, roller, friction.
  std::optional<std::string> left_wall, right_wall, base;
  bool ignore_supports = false;
  std::vector<double> extent;
  std::vector<double> base_lag;
  DeckOptions deck;
  /// --ground-motion FILE with -dt, -factor, -dir (OpenSees Path -dt -filePath -factor, UniformExcitation dir).
  std::string ground_motion;
  std::optional<double> ground_motion_dt;
  double ground_motion_factor = 1.0;
  int ground_motion_dir = 1;
  bool quiet = false;
  bool check_options = false;
  bool plane_stress = false;
  UpOptionText up;  ///< u-p models (up_options.hpp)
};

/// The u-p options (up_options.hpp); without --pore-pressure every other u-p option is refused.
std::optional<PorePressureOptions> checked_pore_pressure_options(const UpOptionText& up, const CLI::App& app) {
  if (up.pore_pressure.empty())
    for (const char* name : kUpOptionsNeedingPorePressure)
      if (app.get_option(name)->count() > 0)
        throw common::InputError(name, "needs --pore-pressure (a u-p model's pore pressure recorder)");
  return pore_pressure_options(up);
}

Wall parse_wall(const std::string& s, const char* option) {
  if (s == "roller") return Wall::Roller;
  if (s == "fixed") return Wall::Fixed;
  if (s == "none") return Wall::None;
  throw common::InputError(option, "expected roller, fixed or none, got '" + s + "'");
}

Base parse_base(const std::string& s) {
  if (s == "contact") return Base::Contact;
  if (s == "friction") return Base::Friction;
  if (s == "roller") return Base::Roller;
  if (s == "fixed") return Base::Fixed;
  throw common::InputError("--base", "expected contact, friction, roller or fixed, got '" + s + "'");
}

std::string fmt(double v, int precision = 6) { return common::number_text(v, precision); }
std::string comma_list(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

std::string relative_change(double before, double after) {
  if (before == 0) return after == 0 ? "0" : "n/a";
  return fmt((after - before) / std::abs(before), 3);
}

nlohmann::ordered_json totals_json(const TransferTotals& t) {
  return {{"mass", t.mass},
          {"momentum", {t.momentum.x(), t.momentum.y()}},
          {"kinetic_energy", t.kinetic_energy},
          {"potential_energy", t.potential_energy}};
}

/// Wall-clock seconds of the phases, for the report.
struct Timing {
  double read = 0, map = 0, report_deck = 0, write_text = 0, write_h5 = 0;
};

/// What --loads carried over: loaded FEM nodes and their total, and the particles that carry it.
struct LoadSummary {
  std::size_t nodes = 0, particles = 0;
  Vec2 fem_total = Vec2::Zero(), particle_total = Vec2::Zero();  ///< N per unit thickness
};
LoadSummary summarize_loads(const TransferState& state, const std::vector<ParticleLoad>& loads) {
  LoadSummary s;
  for (const Vec2& f : state.load)
    if (!f.isZero(0.0)) {
      ++s.nodes;
      s.fem_total += f;
    }
  s.particles = loads.size();
  for (const auto& l : loads) s.particle_total += l.force;
  return s;
}

void print_report(std::ostream& out, const AssembledState& a, const TransferReport& r, const DeckText& d,
                  const CliOptions& o, const std::vector<BoundaryChoice>& boundaries, const std::filesystem::path& outdir,
                  const Timing& t, const LoadSummary& loads, const std::optional<LiquefactionReport>& up) {
  out << "fem2mpm: FEM state at t = " << fmt(a.state.time, 9) << " s -> " << r.particle_count << " particles ("
      << a.state.elements.size() << " elements x " << o.ppd << "x" << o.ppd
      << (a.triangles_split ? ", " + std::to_string(a.triangles_split) + " of the FEM's triangles as 3 quads each" : std::string())
      << "), stress recovery "
      << (o.recovery == "spr" ? "SPR (Zienkiewicz-Zhu)" : "inverse-distance weighting") << "\n";
  for (const auto& n : a.notes) out << "  note: " << n << "\n";
  out << "                        FEM (lumped nodes)    particles        relative change\n";
  auto row = [&](const char* name, double fem, double mpm, const char* unit) {
    out << "  " << std::left << std::setw(20) << name << std::right << std::setw(16) << fmt(fem, 9) << "  "
        << std::setw(16) << fmt(mpm, 9) << "  " << std::setw(10) << relative_change(fem, mpm) << "  " << unit << "\n";
  };
  row("mass", r.fem.mass, r.particles.mass, "kg/m");
  row("momentum x", r.fem.momentum.x(), r.particles.momentum.x(), "kg m/s /m");
  row("momentum y", r.fem.momentum.y(), r.particles.momentum.y(), "kg m/s /m");
  row("kinetic energy", r.fem.kinetic_energy, r.particles.kinetic_energy, "J/m");
  row("potential energy", r.fem.potential_energy, r.particles.potential_energy, "J/m (m g y)");
  out << "  stress difference FEM Gauss points vs particle field: RMS " << fmt(100 * r.stress_rms_relative, 4)
      << " %, max " << fmt(100 * r.stress_max_relative, 4) << " % of max |sigma| (" << fmt(r.stress_max_abs, 6)
      << " Pa, element " << r.stress_max_element << ")\n";
  out << "  min det J (current mesh): " << fmt(r.min_jacobian, 6) << " m2 (element " << r.min_jacobian_element << ")\n";
  out << "  grid: " << d.grid.nx << " x " << d.grid.ny << " " << (d.grid.gimp ? "ED2Q16G" : "ED2Q4") << " cells of "
      << fmt(d.grid.h) << " m from (" << fmt(d.grid.x0) << ", " << fmt(d.grid.y0) << "); dt " << fmt(d.dt)
      << " s, nsteps " << d.nsteps << ", output every " << d.output_steps << " steps\n";
  for (const auto& b : boundaries) out << "  boundary: " << boundary_text(b, d) << "\n";
  if (!d.base_motion.t.empty())
    out << "  ground motion: " << o.ground_motion << " from FEM t = " << fmt(a.state.time, 9) << " s as base_acceleration (dir "
        << o.ground_motion_dir << "), " << d.base_motion.t.size() << " points to MPM t = " << fmt(d.base_motion.t.back(), 6)
        << " s\n";
  if (!o.loads.empty())
    out << "  loads: " << loads.nodes << " loaded FEM nodes, total (" << fmt(loads.fem_total.x(), 6) << ", "
        << fmt(loads.fem_total.y(), 6) << ") N/m, carried by " << loads.particles << " particles (total ("
        << fmt(loads.particle_total.x(), 6) << ", " << fmt(loads.particle_total.y(), 6)
        << ") N/m) as particle_surface_traction, held at their transfer-time value\n";
  if (up) out << liquefaction_text(*up);
  out << "  wrote " << (outdir / d.particle_file).string() << " and mpm.json, mesh.txt, entity_sets.json, ";
  for (const auto& f : d.particle_files) out << f.first << ", ";
  out << "report.json in " << outdir.string() << "\n";
  out << "  time: read " << fmt(t.read, 3) << " s, map " << fmt(t.map, 3) << " s, report + deck " << fmt(t.report_deck, 3)
      << " s, write text " << fmt(t.write_text, 3) << " s; write HDF5 " << fmt(t.write_h5, 3) << " s (concurrently)\n";
  out << "  run: mpm -f " << outdir.string() << "/ -i mpm.json\n";
}

int run(const CliOptions& o, const CLI::App& app, std::ostream& out, std::ostream& err) {
  ReadOptions ro;
  ro.pore_pressure = checked_pore_pressure_options(o.up, app);
  const LiquefiedOptions lo = ro.pore_pressure ? liquefied_options(o.up) : LiquefiedOptions{};
  ro.disp = o.disp;
  ro.vel = o.vel;
  ro.loads = o.loads;
  ro.stress = o.stress;
  ro.time = o.time;
  ro.row = o.row;
  if (!o.nodes.empty()) ro.nodes = parse_tag_list(o.nodes, "--nodes");
  if (!o.elements.empty()) ro.elements = parse_tag_list(o.elements, "--elements");
  if (o.units == "SI") ro.units = Units::SI;
  else if (o.units == "kN") ro.units = Units::kN;
  else throw common::InputError("--units", "expected SI or kN, got '" + o.units + "'");
  if (!o.material_type.empty()) {
    check_material_type(o.material_type, "--material-type");
    ro.material.type = o.material_type;
  }
  ro.material.E = o.E;
  ro.material.nu = o.nu;
  ro.material.density = o.density;
  ro.material.phi_deg = o.phi;
  ro.material.cohesion = o.cohesion;
  ro.material.psi_deg = o.psi;
  ro.material.tension = o.tension;
  for (const auto& text : o.material) parse_material_override(text, "--material", ro.per_material);
  ro.gravity = o.gravity;
  ro.plane_stress = o.plane_stress;

  MappingOptions mo;
  if (o.ppd < 1 || o.ppd > 32) throw common::InputError("--ppd", "expected 1 to 32 particles per direction");
  mo.particles_per_direction = o.ppd;
  if (o.recovery == "idw") mo.recovery = Recovery::InverseDistance;
  else if (o.recovery == "spr") mo.recovery = Recovery::PatchRecovery;
  else throw common::InputError("--recovery", "expected idw or spr, got '" + o.recovery + "'");
  if (o.volume_split == "jacobian") mo.volume_split = VolumeSplit::Jacobian;
  else if (o.volume_split == "area") mo.volume_split = VolumeSplit::Area;
  else throw common::InputError("--volume-split", "expected jacobian or area, got '" + o.volume_split + "'");

  DeckOptions deck = o.deck;
  if (o.cell_type == "ED2Q16G") deck.gimp = true;
  else if (o.cell_type == "ED2Q4") deck.gimp = false;
  else throw common::InputError("--cell-type", "expected ED2Q16G or ED2Q4, got '" + o.cell_type + "'");
  if (o.left_wall) deck.left = parse_wall(*o.left_wall, "--left-wall");
  if (o.right_wall) deck.right = parse_wall(*o.right_wall, "--right-wall");
  if (o.base) deck.base = parse_base(*o.base);
  if (!o.extent.empty()) deck.extent = std::array<double, 4>{o.extent[0], o.extent[1], o.extent[2], o.extent[3]};
  if (!o.base_lag.empty()) deck.base_lag = std::array<double, 2>{o.base_lag[0], o.base_lag[1]};
  if (const auto problem = mpm::io::run_name_problem(deck.uuid); !problem.empty()) throw common::InputError("--uuid", problem);
  if (o.ground_motion.empty() && (o.ground_motion_dt || o.ground_motion_factor != 1.0 || o.ground_motion_dir != 1))
    throw common::InputError("--ground-motion", "the record file is missing (--ground-motion-dt, -factor and -dir describe it)");
  if (!o.ground_motion.empty()) {
    if (!o.ground_motion_dt) throw common::InputError("--ground-motion-dt", "required with --ground-motion (the record's time step, s)");
    deck.ground_motion = read_ground_motion(o.ground_motion, *o.ground_motion_dt, o.ground_motion_factor,
                                            o.ground_motion_dir, "--ground-motion");
  }

  using Clock = std::chrono::steady_clock;
  auto lap = [last = Clock::now()]() mutable {
    const auto now = Clock::now();
    const double s = std::chrono::duration<double>(now - last).count();
    last = now;
    return s;
  };
  Timing timing;
  if (!o.loads.empty() && deck.ground_motion)
    throw common::InputError("--loads", "not with --ground-motion: OpenSees' unbalance holds UniformExcitation's inertia "
                                        "load -M a_g besides the patterns' loads, which cannot be told apart");
  check_deck_options(deck);
  if (std::error_code ec; std::filesystem::exists(o.out, ec) && !std::filesystem::is_directory(o.out, ec))
    throw common::InputError("--out", "'" + o.out + "' is a file; give a folder (created when missing)");
  if (o.check_options) {
    out << "fem2mpm: the options are valid (the FEM files were not read)\n";
    return 0;
  }
  // 1. Read and check everything (no output yet).
  const FemModel model = read_fem_model(o.model);
  AssembledState assembled = read_fem_state(model, ro);
  std::optional<ExcludedMaterials> excluded;
  if (!o.exclude_material.empty()) {
    excluded = exclude_materials(assembled.state, o.exclude_material, "--exclude-material");
    assembled.notes.push_back("--exclude-material: " + std::to_string(excluded->elements) + " elements of FEM material(s) " +
                              comma_list(excluded->names) + " (" + fmt(excluded->mass, 6) + " kg/m) not carried into MPM; their top at y = " +
                              fmt(excluded->top, 6) + " m" + (o.deck.base_y ? ", the MPM base at y = " + fmt(*o.deck.base_y, 6) + " m"
                                                                              : " (the MPM base stays where the options put it: give --base-y to put it there)"));
  }
  const ExtractedBoundaries supports = o.ignore_supports ? ExtractedBoundaries{} : extract_boundaries(model);
  const BoundaryOptionsGiven given{o.left_wall.has_value(), o.right_wall.has_value(), o.base.has_value(), o.deck.base_y.has_value()};
  const std::vector<BoundaryChoice> boundaries = apply_supports(supports, given, deck);
  const TransferState& state = assembled.state;
  auto tag_list = [](const std::vector<long>& tags) {
    std::string list;
    for (std::size_t i = 0; i < tags.size() && i < 20; ++i) list += (i ? " " : "") + std::to_string(tags[i]);
    if (tags.size() > 20) list += " ... (" + std::to_string(tags.size()) + " in all)";
    return list;
  };
  if (const auto bad = inverted_elements(state, true); !bad.empty())
    throw common::InputError(o.model, "elements whose nodes are not counterclockwise around a convex quad in the "
                                               "model's own coordinates (OpenSees lists a quad's nodes counterclockwise): " +
                                                   tag_list(bad));
  if (const auto bad = inverted_elements(state); !bad.empty())
    throw common::InputError(assembled.source_row, "at t = " + fmt(state.time, 9) + " the mesh has elements with non-positive Jacobian "
                                         "(too distorted to transfer; choose an earlier --time): " + tag_list(bad));

  timing.read = lap();
  // 2. Map.
  const auto nodal = recover_nodal_stress(state, mo.recovery);
  auto particles = generate_particles(state, nodal, mo);
  deck.particle_loads = particle_loads(state, mo.particles_per_direction);
  // u-p: total stress, p / sigma'v0 / r_u per particle, and the liquefied particles' strength; the particles
  // are then regrouped by material (the deck's one particle file per material), their rows with them.
  ParticlePorePressure pore;
  LiquefiedSummary liquefied;
  std::vector<std::size_t> regrouped;  // empty: the particles are in generate_particles' order
  if (ro.pore_pressure) {
    pore = particle_pore_pressure(state, mo);
    apply_total_stress(particles, pore.rows);
    liquefied = assign_liquefied_strength(assembled.state, particles, pore.rows, pore.shear_strain, lo);
    if (!liquefied.materials.empty()) {
      regrouped = group_by_material(particles);
      std::vector<mpm::PorePressureRecord> rows(regrouped.size());
      std::vector<std::int64_t> new_id(regrouped.size());
      for (std::size_t k = 0; k < regrouped.size(); ++k) {
        rows[k] = pore.rows[regrouped[k]];
        new_id[regrouped[k]] = static_cast<std::int64_t>(k);
      }
      pore.rows = std::move(rows);
      for (auto& load : deck.particle_loads) load.id = new_id[static_cast<std::size_t>(load.id)];
    }
  }
  const LoadSummary load_summary = summarize_loads(state, deck.particle_loads);
  timing.map = lap();
  DeckText d = plan_deck(state, particles, deck);  // the last check that can fail on user input
  // APIC: the particles' affine matrices from the FEM velocity gradient (affine_state.hpp).
  const bool apic = deck.transfer == "apic" && !deck.velocity_update;
  std::vector<Matrix2> gradients = apic ? particle_velocity_gradients(state, mo) : std::vector<Matrix2>{};
  if (apic && !regrouped.empty()) {
    std::vector<Matrix2> reordered(regrouped.size());
    for (std::size_t k = 0; k < regrouped.size(); ++k) reordered[k] = gradients[regrouped[k]];
    gradients = std::move(reordered);
  }
  const std::vector<Matrix2> affine = apic ? apic_matrices(particles, gradients, d.grid) : std::vector<Matrix2>{};
  // Warnings only now: a failed run prints its one error line and nothing else.
  std::vector<std::string> warnings = assembled.warnings;
  warnings.insert(warnings.end(), liquefied.warnings.begin(), liquefied.warnings.end());
  for (const auto& skipped : model.skipped) assembled.notes.push_back(skipped);
  warnings.insert(warnings.end(), supports.warnings.begin(), supports.warnings.end());
  warnings.insert(warnings.end(), d.warnings.begin(), d.warnings.end());
  for (const auto& w : warnings) err << "fem2mpm: warning: " << w << "\n";
  assembled.notes.insert(assembled.notes.end(), supports.notes.begin(), supports.notes.end());

  // 3. Write. The HDF5 file is written (to a temporary name, then renamed) on a second thread while the
  // report and the text files are prepared; the text files are renamed only when both succeeded, and the
  // HDF5 file is removed again if anything else failed: a failed run leaves no output.
  const std::filesystem::path outdir = o.out;
  if (std::error_code ec; !std::filesystem::create_directories(outdir / "results" / deck.uuid, ec) && ec)
    throw common::OutputError("--out: cannot create " + (outdir / "results" / deck.uuid).string() + ": " + ec.message());
  const std::filesystem::path h5_path = outdir / d.particle_file;
  std::exception_ptr h5_error;
  double h5_seconds = 0;
  std::thread h5_writer([&] {
    try {
      const auto start = Clock::now();
      // Beside /table: the APIC matrices, and for a lagged base an empty friction memory (every base node
      // starts from its instantaneous normal force, which is what the MPM run should do at the transfer).
      mpm::io::write_particle_table(h5_path, particles, [&](std::int64_t file_id) {
        if (apic) mpm::io::write_affine_dataset(file_id, affine, h5_path.string());
        if (deck.base_lag) mpm::io::write_friction_memory_dataset(file_id, {}, h5_path.string());
        if (ro.pore_pressure) mpm::io::write_pore_pressure_dataset(file_id, pore.rows, h5_path.string());
      });
      h5_seconds = std::chrono::duration<double>(Clock::now() - start).count();
    } catch (...) {
      h5_error = std::current_exception();
    }
  });
  std::vector<std::unique_ptr<common::AtomicTextFile>> files;
  TransferReport report;
  std::optional<LiquefactionReport> up;
  try {
    report = make_report(state, nodal, particles);
    if (ro.pore_pressure) {
      up = make_liquefaction_report(state, particles, pore.rows, lo.threshold, pore.no_reference, liquefied);
      up->file = o.up.pore_pressure;
      up->reference_row = assembled.reference_row;
      up->reference_how = assembled.reference_how;
      up->reference_time = assembled.reference_time;
    }
    format_deck(state, particles, deck, d);
    timing.report_deck = lap();
    nlohmann::ordered_json rj;
    rj["time"] = state.time;
    rj["particles"] = report.particle_count;
    rj["elements"] = state.elements.size();
    rj["particles_per_direction"] = o.ppd;
    rj["recovery"] = o.recovery;
    rj["volume_split"] = o.volume_split;
    rj["stress_components_read"] = assembled.stress_components;
    rj["units"] = o.units;
    rj["gravity"] = state.gravity;
    rj["fem"] = totals_json(report.fem);
    rj["particle_totals"] = totals_json(report.particles);
    rj["stress_difference"] = {{"rms_relative", report.stress_rms_relative},
                               {"max_relative", report.stress_max_relative},
                               {"max_abs_pa", report.stress_max_abs},
                               {"max_element", report.stress_max_element}};
    rj["min_jacobian"] = {{"value", report.min_jacobian}, {"element", report.min_jacobian_element}};
    rj["particle_file"] = d.particle_file;
    if (excluded)
      rj["excluded_materials"] = {{"materials", excluded->names}, {"elements", excluded->elements},
                                  {"mass_kg_per_m", excluded->mass}, {"top_y", excluded->top}};
    rj["notes"] = assembled.notes;
    rj["warnings"] = warnings;
    rj["boundaries"] = boundaries_json(boundaries, d);
    if (!o.loads.empty())
      rj["loads"] = {{"file", o.loads}, {"nodes", load_summary.nodes}, {"particles", load_summary.particles},
                     {"fem_total", {load_summary.fem_total.x(), load_summary.fem_total.y()}},
                     {"particle_total", {load_summary.particle_total.x(), load_summary.particle_total.y()}}};
    if (up) rj["pore_pressure"] = liquefaction_json(*up);
    if (!d.base_motion.t.empty())
      rj["ground_motion"] = {{"file", o.ground_motion}, {"dir", o.ground_motion_dir}, {"points", d.base_motion.t.size()},
                             {"mpm_time", {d.base_motion.t.front(), d.base_motion.t.back()}}};
    auto text = [&](const char* name, const std::string& body) {
      files.push_back(std::make_unique<common::AtomicTextFile>(outdir / name));
      files.back()->stream() << body;
    };
    text("mpm.json", d.mpm_json);
    text("mesh.txt", d.mesh_txt);
    text("entity_sets.json", d.entity_sets_json);
    for (const auto& [name, body] : d.particle_files) text(name.c_str(), body);
    text("report.json", rj.dump(2) + "\n");
    for (auto& f : files) f->stream().flush();
    timing.write_text = lap();
  } catch (...) {
    h5_writer.join();
    std::error_code ec;
    std::filesystem::remove(h5_path, ec);
    throw;
  }
  h5_writer.join();
  timing.write_h5 = h5_seconds;
  if (h5_error) std::rethrow_exception(h5_error);
  try {
    for (auto& f : files) f->commit();
  } catch (...) {
    std::error_code ec;
    std::filesystem::remove(h5_path, ec);
    throw;
  }
  if (!o.quiet) print_report(out, assembled, report, d, o, boundaries, outdir, timing, load_summary, up);
  if (!out.flush()) throw common::OutputError("standard output: writing the report failed (the deck in " + outdir.string() + " is complete)");
  return 0;
}

}  // namespace

int run_cli(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  CliOptions o;
  CLI::App app{
      "fem2mpm: transfer an OpenSees / fem_tcl FEM state to CB-Geo MPM material points (the paper's hybrid FEM-MPM "
      "transfer).\nReads the model (print -JSON), Node recorder files (disp, vel; with -time) and the Element stress "
      "recorder; writes <out>/results/<uuid>/particles<step>.h5, mpm.json, mesh.txt, entity_sets.json, particles.txt "
      "and report.json.\nExample: fem2mpm --model model.json --disp disp.out --vel vel.out --stress stress.out "
      "--time 1.0 --units kN --out mpm_deck",
      "fem2mpm"};
  app.get_formatter()->column_width(34);
  // Inputs.
  app.add_option("--model", o.model, "model description written by `print -JSON -file f`")->required()->group("Inputs");
  app.add_option("--disp", o.disp, "Node recorder file: -time ... -dof 1 2 disp")->required()->group("Inputs");
  app.add_option("--loads", o.loads,
                 "Node recorder file: -time ... -dof 1 2 unbalance (the applied nodal loads, e.g. a surcharge): carried by the "
                 "particles around each loaded node as particle_surface_traction, held at the transfer-time value")
      ->group("Inputs");
  app.add_option("--vel", o.vel, "Node recorder file: -time ... -dof 1 2 vel (optional: without it the particles start at rest)")->group("Inputs");
  app.add_option("--stress", o.stress,
                 "Element recorder file: -time ... stress (3 values per Gauss point: szz = nu (sxx + syy) is derived) "
                 "or stress3D (6 values: sxx syy szz sxy syz sxz); SSPquad 1 Gauss point, quad 4")->required()->group("Inputs");
  auto* time_opt = app.add_option("--time", o.time, "transfer time: the row whose time equals it (to the printed precision); default: the last row")->group("Inputs");
  app.add_option("--row", o.row, "use row N of the displacement file instead (1 first, -1 last)")->excludes(time_opt)->group("Inputs");
  app.add_option("--nodes", o.nodes, "node order of the Node recorders, e.g. '1-35' or '1,2,5-9' (default: all nodes in tag order, as -nodeRange)")->group("Inputs");
  app.add_option("--elements", o.elements, "element order of the Element recorder (default: all elements in tag order, as -eleRange)")->group("Inputs");
  app.add_flag("--plane-stress", o.plane_stress, "the FEM model is plane stress: with 3 stress components, szz = 0 instead of nu (sxx + syy)")
      ->group("Inputs");
  app.add_option("--units", o.units, "units of the FEM files: SI (N, m, Pa, kg/m3) or kN (kN, m, kPa, Mg/m3; stresses, moduli and densities x 1000)")
      ->capture_default_str()->group("Inputs");
  // Materials.
  app.add_option("--material-type", o.material_type, "MPM material for every FEM material: elastic (LinearElastic2D) or mohr-coulomb (MohrCoulomb2D); default: from the model file")->group("Material (FEM units; override the model file)");
  app.add_option("--E", o.E, "Young's modulus")->group("Material (FEM units; override the model file)");
  app.add_option("--nu", o.nu, "Poisson's ratio")->group("Material (FEM units; override the model file)");
  app.add_option("--density", o.density, "mass density")->group("Material (FEM units; override the model file)");
  app.add_option("--phi", o.phi, "friction angle, degrees")->group("Material (FEM units; override the model file)");
  app.add_option("--cohesion", o.cohesion, "cohesion")->group("Material (FEM units; override the model file)");
  app.add_option("--psi", o.psi, "dilation angle, degrees (default 0)")->group("Material (FEM units; override the model file)");
  app.add_option("--tension", o.tension, "tension cutoff (default: the Mohr-Coulomb apex, c cot(phi))")->group("Material (FEM units; override the model file)");
  app.add_option("--exclude-material", o.exclude_material,
                 "FEM materials (their tags in the model file) not carried into MPM, e.g. a stiff foundation that does not "
                 "flow: its particles would cost every step and its P-wave speed would set the time step; put the MPM base at "
                 "its top with --base-y (the report gives the top and the mass left out)")
      ->delimiter(',')->group("Material (FEM units; override the model file)");
  app.add_option("--material", o.material, "per FEM material (its tag in the model file), after the options above: NAME:key=value[,key=value...], keys type (elastic|mohr-coulomb), E, nu, density, phi, cohesion, psi, tension; repeatable, e.g. --material 2:phi=30,cohesion=5")->group("Material (FEM units; override the model file)");
  app.add_option("--gravity", o.gravity, "gravity, m/s2, acting in -y (default: from the elements' body forces / density, else 9.81)")->group("Material (FEM units; override the model file)");
  // Mapping.
  app.add_option("--ppd", o.ppd, "particles per direction per element, at the Gauss-Legendre points")->capture_default_str()->group("Mapping");
  app.add_option("--recovery", o.recovery, "Gauss point -> node stress recovery: idw (inverse-distance weighting, the paper) or spr (superconvergent patch recovery, Zienkiewicz & Zhu 1992)")
      ->capture_default_str()->group("Mapping");
  app.add_option("--volume-split", o.volume_split, "particle volume: jacobian (det J x Gauss weight, current mesh) or area (element area x Gauss weight / 4)")
      ->capture_default_str()->group("Mapping");
  // Deck.
  app.add_option("--out", o.out, "output folder (created); run the result with mpm -f <out>/ -i mpm.json")->required()->group("MPM deck");
  app.add_option("--uuid", o.deck.uuid, "run name: the particle file goes to results/<uuid>/")->capture_default_str()->group("MPM deck");
  app.add_option("--step", o.deck.step, "step number of the particle file (resume.step)")->capture_default_str()->group("MPM deck");
  app.add_option("--cell-size", o.deck.cell_size, "background cell size, m (default: sqrt of the mean element area, adjusted to a whole number of cells between two FEM walls)")->group("MPM deck");
  app.add_option("--extent", o.extent, "grid extent xmin xmax ymin ymax, m (default: the deformed model's bounding box with its FEM walls and base on grid lines, one cell row below the base, extended 3 widths beyond each free side and 0.25 heights up; without FEM supports: 3 widths to the right)")
      ->expected(4)->group("MPM deck");
  app.add_option("--cell-type", o.cell_type, "ED2Q16G (GIMP, with CB-Geo's halo node ring) or ED2Q4")->capture_default_str()->group("MPM deck");
  app.add_option("--left-wall", o.left_wall, "grid's left boundary: roller (x-velocity 0), fixed or none (default: from the FEM supports, else roller)")->group("MPM deck");
  app.add_option("--right-wall", o.right_wall, "grid's right boundary: roller, fixed or none (default: from the FEM supports, else roller at the far end of the runout area)")->group("MPM deck");
  app.add_option("--base", o.base, "grid's base: contact (one-sided frictional contact: stops the approach, Coulomb friction; the soil may leave it), friction (CB-Geo's: y-velocity 0 + Coulomb friction), roller or fixed (default: from the FEM supports: a roller line -> roller, a fixed line -> contact; else contact)")->group("MPM deck");
  app.add_flag("--ignore-supports", o.ignore_supports, "do not carry the FEM supports over: walls, base and grid from the options and the legacy defaults")->group("MPM deck");
  app.add_option("--base-friction", o.deck.base_friction, "base friction coefficient mu (CB-Geo friction_constraints)")->capture_default_str()->group("MPM deck");
  app.add_option("--base-lag", o.base_lag, "L V*: the base friction's strength follows its normal force over a slip distance L (m) plus a reference speed V* (m/s), the simplified Prakash-Clifton law that regularises the flutter of elastic bodies on frictional walls (friction_constraints[].normal_lag; mpm/README.md \"Friction with a lag\"); default: none")
      ->expected(2)->group("MPM deck");
  app.add_option("--base-y", o.deck.base_y, "height of the base, m: the base constraint acts on every node at or below it (default: the FEM base support line, else the grid's bottom edge; with GIMP and --extent give the FEM base and an extent one cell lower)")->group("MPM deck");
  app.add_option("--dt", o.deck.dt, "MPM time step, s (default: --cfl x cell size / P-wave speed)")->group("MPM deck");
  app.add_option("--cfl", o.deck.cfl, "Courant number for the default time step")->capture_default_str()->group("MPM deck");
  app.add_option("--duration", o.deck.duration, "MPM time to run after the transfer, s (nsteps = duration / dt + 1)")->capture_default_str()->group("MPM deck");
  app.add_option("--nsteps", o.deck.nsteps, "number of steps (overrides --duration)")->group("MPM deck");
  app.add_option("--output-steps", o.deck.output_steps, "write particles every N steps (default: every 0.5 s, at most nsteps - 1)")->group("MPM deck");
  app.add_option("--scheme", o.deck.scheme, "mpm_scheme: usf, usl or musl")->capture_default_str()->group("MPM deck");
  app.add_option("--transfer", o.deck.transfer, "velocity transfer (analysis.transfer): apic, flip or pic")
      ->check(CLI::IsMember({"apic", "flip", "pic"}))->capture_default_str()->group("MPM deck");
  app.add_flag("--pic", o.deck.velocity_update, "velocity_update true (PIC): the same as --transfer pic")->group("MPM deck");
  app.add_option("--damping", o.deck.damping, "Cundall damping factor")->capture_default_str()->group("MPM deck");
  app.add_option("--stress-smoothing", o.deck.stress_smoothing,
                 "checkerboard remedy (analysis.stress_smoothing): none, cell_strain (the one that works at full "
                 "resolution, mpm/README.md), cell_volumetric, nodal_strain or nodal_volumetric")
      ->check(CLI::IsMember(mpm::io::stress_smoothing_methods()))->capture_default_str()->group("MPM deck");
  app.add_option("--ground-motion", o.ground_motion,
                 "keep shaking the MPM run after a transfer during an earthquake: the acceleration record of the FEM "
                 "script's UniformExcitation (an OpenSees Path -filePath file: numbers, any per line), cut at the transfer "
                 "time and written as the deck's base_acceleration (the MPM run in the ground's frame, as UniformExcitation's "
                 "relative responses)")->group("Ground motion");
  app.add_option("--ground-motion-dt", o.ground_motion_dt, "time step of the record, s (Path -dt; required with --ground-motion)")->group("Ground motion");
  app.add_option("--ground-motion-factor", o.ground_motion_factor, "factor on the record (Path -factor, e.g. 9.81 for a record in g)")->capture_default_str()->group("Ground motion");
  app.add_option("--ground-motion-dir", o.ground_motion_dir, "direction (UniformExcitation dir): 1 = x, 2 = y")->capture_default_str()->group("Ground motion");
  // u-p models (issue 36).
  const char* up_group = "Pore pressure and liquefaction (u-p models; bridge/README.md)";
  app.add_option("--pore-pressure", o.up.pore_pressure,
                 "Node recorder file: -time ... -dof 3 vel (the pore pressure of a u-p model, compression positive): the "
                 "particles get the total stress sigma' - p I and /pore_pressure (p, sigma'v0, r_u) beside /table")->group(up_group);
  app.add_option("--pp-nodes", o.up.pp_nodes, "node order of --pore-pressure, e.g. '1-35' (default: every 3-dof node in tag order)")->group(up_group);
  app.add_option("--reference-time", o.up.reference_time,
                 "time of the reference row (sigma'v0 = -sigma'yy and the hydrostatic p0 there; default: the end of the "
                 "gravity stage, the last row before the time column restarts lower, e.g. after setTime 0)")->group(up_group);
  app.add_option("--strain", o.up.strain,
                 "Element recorder file: -time ... strain (exx eyy gxy per Gauss point, the stress file's element order): the "
                 "equivalent deviatoric strain since the reference row starts the liquefied particles' softening (default 0)")->group(up_group);
  app.add_option("--liquefied", o.up.liquefied, "r_u above which a particle is liquefied")->capture_default_str()->group(up_group);
  app.add_option("--liquefied-table", o.up.liquefied_table,
                 "the liquefied strength by bins of sigma'v0 (CSV: sigma_v0_upper_kPa,peak_cohesion_kPa,residual_cohesion_kPa,"
                 "peak_pdstrain,residual_pdstrain; bridge/README.md)")->group(up_group);
  app.add_option("--residual-ratio", o.up.residual_ratio,
                 "the liquefied strength Sr = R sigma'v0 (Olson & Stark 2002: R about 0.05 to 0.12)")->group(up_group);
  app.add_option("--residual-n160cs", o.up.n160cs,
                 "the liquefied strength from (N1)60cs-Sr per FEM material, MATERIAL:N[,MATERIAL:N...] (Idriss & Boulanger "
                 "2008)")->group(up_group);
  app.add_option("--void-redistribution", o.up.void_redistribution,
                 "with --residual-n160cs: significant (the lower Idriss & Boulanger curve) or negligible")
      ->capture_default_str()->group(up_group);
  app.add_option("--liquefied-softening", o.up.liquefied_softening,
                 "K E1 E2: with --residual-ratio or --residual-n160cs, the peak cohesion K Sr softens to Sr between plastic "
                 "deviatoric strains E1 and E2 (default: no softening)")->expected(3)->group(up_group);
  app.add_option("--strength-step", o.up.strength_step,
                 "relative step of the grid Sr is rounded to, so that equal strengths share an MPM material")
      ->capture_default_str()->group(up_group);
  app.add_option("--max-liquefied-materials", o.up.max_liquefied_materials,
                 "at most this many liquefied materials from --residual-ratio / --residual-n160cs (the grid step is widened)")
      ->capture_default_str()->group(up_group);
  app.add_flag("--effective-friction", o.up.effective_friction,
               "the particles below the threshold: their drained friction on the effective stress of the transfer, "
               "tan(phi) = (1 - p / sigma_m) tan(phi') (default: phi' on the total stress)")->group(up_group);
  app.add_flag("--check-options", o.check_options,
               "check the options (and the --ground-motion record) and stop, before reading the FEM files: "
               "a driver runs this before the FEM analysis")->group("Inputs");
  app.add_flag("--quiet", o.quiet, "print nothing on success (the report is still written to report.json)");
  app.footer("Exit status: 0 done; 2 bad input (one line naming the option, file, line or key; nothing written); "
             "1 an output could not be written (disk full, permissions); an output target that exists and is not a regular "
             "file is refused (2). "
             "SIGTERM/SIGINT remove the temporary *.tmp.<pid> files.");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) {
      out << app.help();
      return 0;
    }
    err << "fem2mpm: error: " << common::printable(e.what()) << " (see fem2mpm --help)\n";
    return 2;
  }
  try {
    return run(o, app, out, err);
  } catch (const common::InputError& e) {
    err << "fem2mpm: error: " << common::printable(e.what()) << "\n";
    return 2;
  } catch (const std::exception& e) {
    err << "fem2mpm: error: " << common::printable(e.what()) << "\n";
    return 1;
  }
}

}  // namespace bridge
