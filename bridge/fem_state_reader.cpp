#include "bridge/fem_state_reader.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <sstream>

#include "bridge/drained_strength.hpp"
#include "bridge/drucker_prager_match.hpp"
#include "bridge/multi_yield_match.hpp"
#include "bridge/recorder_file.hpp"
#include "bridge/recorder_rows.hpp"
#include "bridge/triangle_split.hpp"
#include "common/input_error.hpp"
#include "common/number_text.hpp"
#include "common/printable_text.hpp"
#include "mpm/io/deck_rules.hpp"

namespace bridge {
namespace {

/// Most tags a --nodes / --elements list may name (far above any 2D model a recorder file can hold).
constexpr double kMaxTags = 1e7;

/// A number quoted in a note or warning (9 significant digits).
std::string fmt(double v) { return common::number_text(v, 9); }

std::string tag_range_text(const std::vector<long>& tags) {
  if (tags.empty()) return "none";
  if (tags.size() <= 6) {
    std::string s;
    for (std::size_t i = 0; i < tags.size(); ++i) s += (i ? " " : "") + std::to_string(tags[i]);
    return s;
  }
  return std::to_string(tags.front()) + " .. " + std::to_string(tags.back()) + " (" + std::to_string(tags.size()) + ")";
}

/// Copies every value `o` sets into the working values (later overrides win).
struct MaterialValues {
  std::optional<double> E, nu, rho, phi, c, psi, tension;
  std::string type;
  void apply(const MaterialOverrides& o) {
    if (o.type) type = *o.type;
    if (o.E) E = o.E;
    if (o.nu) nu = o.nu;
    if (o.density) rho = o.density;
    if (o.phi_deg) phi = o.phi_deg;
    if (o.cohesion) c = o.cohesion;
    if (o.psi_deg) psi = o.psi_deg;
    if (o.tension) tension = o.tension;
  }
};

MpmMaterial resolve_material(const FemModel& model, const std::string& name, const ReadOptions& options,
                             double density_factor, double stress_factor, std::vector<std::string>& notes) {
  MpmMaterial m;
  m.fem_name = name;
  const auto it = model.materials.find(name);
  const FemMaterial* fem = it == model.materials.end() ? nullptr : &it->second;
  MaterialValues v;
  std::string mapping_failure;
  if (fem) {
    v.E = fem->E; v.nu = fem->nu; v.rho = fem->rho; v.phi = fem->phi_deg; v.c = fem->cohesion; v.psi = fem->psi_deg; v.tension = fem->tension;
    if (fem->type == "ElasticIsotropicMaterial" || fem->type == "ElasticIsotropic") v.type = "elastic";
    else if (fem->type == "MohrCoulomb") v.type = "mohr-coulomb";
    else if (fem->type == "PressureIndependMultiYield" && fem->multi_yield_cohesion) {
      if (fem->multi_yield_friction_deg.value_or(0.0) == 0.0) {
        v.type = "mohr-coulomb";
        v.phi = 0.0;
        v.psi = 0.0;
        v.c = multi_yield_tresca_cohesion(*fem->multi_yield_cohesion);
        notes.push_back("material '" + name + "': PressureIndependMultiYield (cohesi " + fmt(*fem->multi_yield_cohesion) +
                        ") -> MohrCoulomb2D phi 0, c " + fmt(*v.c) +
                        " = 2 cohesi / sqrt(3), its plane-strain strength (the backbone below it not carried over)");
      } else {
        mapping_failure = " (PressureIndependMultiYield with frictionAng " + fmt(*fem->multi_yield_friction_deg) +
                     " > 0 has a strength frozen at each point's confinement, no one Mohr-Coulomb: give --material " +
                     name + ":type=mohr-coulomb,phi=...,cohesion=...)";
      }
    } else if (const auto drained = drained_strength(*fem)) {
      v.type = "mohr-coulomb";
      v.E = drained->E;
      v.nu = drained->nu;
      if (drained->rho) v.rho = drained->rho;
      v.phi = drained->phi_deg;
      v.c = drained->cohesion;
      v.psi = drained->psi_deg;
      notes.push_back("material '" + name + "': " + drained->note);
    } else if (fem->type == "DruckerPrager" && fem->dp_sigma_y && fem->dp_rho && fem->dp_rho_bar) {
      if (const auto mc = plane_strain_mohr_coulomb(*fem->dp_sigma_y, *fem->dp_rho, *fem->dp_rho_bar)) {
        v.type = "mohr-coulomb";
        v.phi = mc->phi_deg;
        v.c = mc->cohesion;
        v.psi = mc->psi_deg;
        notes.push_back("material '" + name + "': DruckerPrager (sigma_y " + fmt(*fem->dp_sigma_y) + ", rho " + fmt(*fem->dp_rho) +
                        ", rho_bar " + fmt(*fem->dp_rho_bar) + ") -> MohrCoulomb2D by the plane-strain match: phi " +
                        fmt(mc->phi_deg) + " deg, c " + fmt(mc->cohesion) + ", psi " + fmt(mc->psi_deg) +
                        " deg (same apex; hardening not carried over)");
      } else {
        mapping_failure = " (DruckerPrager rho " + fmt(*fem->dp_rho) + " / rho_bar " + fmt(*fem->dp_rho_bar) +
                     " >= 1/sqrt(6) has no plane-strain Mohr-Coulomb match: give --material " + name + ":type=mohr-coulomb,phi=...,cohesion=...)";
      }
    }
  }
  v.apply(options.material);
  if (const auto own = options.per_material.find(name); own != options.per_material.end()) v.apply(own->second);
  auto& [E, nu, rho, phi, c, psi, tension, type] = v;
  const std::string src = model.source.string() + ": material '" + name + "'";
  const std::string why = !model.materials_readable
                              ? " (the file is not valid JSON, as OpenSees 3.8 writes it for DruckerPrager, PM4Sand, PM4Silt "
                                "and multi-yield materials: give the material with --material-type, --E, --nu, --density, --phi, --cohesion)"
                              : !mapping_failure.empty() ? mapping_failure
                              : (fem ? " (type '" + fem->type + "' has no MPM counterpart: give --material-type and its parameters)"
                                     : " (not in properties.ndMaterials: give --material-type and its parameters)");
  if (type.empty()) throw common::InputError(src, "unknown material" + why);
  check_material_type(type, "--material-type");
  auto need = [&](const std::optional<double>& v, const char* what, const char* option) {
    if (!v) throw common::InputError(src, std::string("no ") + what + "; give " + option + why);
    return *v;
  };
  // The MPM deck's rules (mpm/io/deck_rules.hpp), on the value as given (so the message quotes it) and
  // after the unit factor.
  auto rule = [&](double given, double factor, const common::NumberRange& range, const char* what, const char* option) {
    for (double v : {given, given * factor})
      if (const auto problem = common::number_problem(v, range); !problem.empty())
        throw common::InputError(src, std::string(what) + ": " + problem + " (" + option + ")");
    return given * factor;
  };
  m.youngs_modulus = rule(need(E, "Young's modulus", "--E"), stress_factor, mpm::io::kYoungsModulusRange, "Young's modulus", "--E");
  m.poisson_ratio = rule(need(nu, "Poisson's ratio", "--nu"), 1, mpm::io::kPoissonRatioRange, "Poisson's ratio", "--nu");
  // rho 0 is OpenSees' "no density" (the elements' masspervolume is used then).
  if (rho) m.density = rule(*rho, density_factor, common::NumberRange::non_negative(), "density", "--density");
  if (type == "elastic") {
    m.type = MpmMaterial::Type::LinearElastic2D;
    return m;
  }
  m.type = MpmMaterial::Type::MohrCoulomb2D;
  const double phi_deg = rule(need(phi, "friction angle", "--phi"), 1, mpm::io::kFrictionAngleRange, "friction angle", "--phi");
  const double psi_deg = rule(psi.value_or(0.0), 1, mpm::io::kFrictionAngleRange, "dilation angle", "--psi");
  if (const auto problem = mpm::io::dilation_problem(psi_deg, phi_deg); !problem.empty())
    throw common::InputError(src, "dilation angle: " + problem + " (--psi)");
  m.friction = phi_deg * std::numbers::pi / 180;
  m.dilation = psi_deg * std::numbers::pi / 180;
  m.cohesion = rule(need(c, "cohesion", "--cohesion"), stress_factor, mpm::io::kCohesionRange, "cohesion", "--cohesion");
  if (tension) rule(*tension, stress_factor, mpm::io::kTensionCutoffRange, "tension cutoff", "--tension");
  // No tension cutoff in the FEM material: CB-Geo's cutoff at the Mohr-Coulomb apex c cot(phi).
  if (tension) m.tension_cutoff = *tension * stress_factor;
  else m.tension_cutoff = m.friction > 0 ? m.cohesion / std::tan(m.friction) : 1e30;
  return m;
}

}  // namespace

void check_material_type(const std::string& type, const std::string& where, const std::string& key_prefix) {
  if (type != "elastic" && type != "mohr-coulomb")
    throw common::InputError(where, key_prefix + "expected elastic or mohr-coulomb, got '" + type + "'");
}

void parse_material_override(const std::string& text, const std::string& option,
                             std::map<std::string, MaterialOverrides>& into) {
  const auto colon = text.find(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == text.size())
    throw common::InputError(option, "expected NAME:key=value[,key=value...] (e.g. 2:phi=30,cohesion=5), got '" + text + "'");
  const std::string name = text.substr(0, colon);
  MaterialOverrides& o = into[name];
  std::istringstream items(text.substr(colon + 1));
  for (std::string item; std::getline(items, item, ',');) {
    const auto eq = item.find('=');
    const std::string key = item.substr(0, eq), value = eq == std::string::npos ? "" : item.substr(eq + 1);
    const std::string where = option + " " + text;
    if (eq == std::string::npos || value.empty()) throw common::InputError(where, "expected key=value, got '" + item + "'");
    if (key == "type") {
      check_material_type(value, where, "type: ");
      o.type = value;
      continue;
    }
    double number = 0;
    try {
      std::size_t used = 0;
      number = std::stod(value, &used);
      if (used != value.size() || !std::isfinite(number)) throw std::invalid_argument(value);
    } catch (const std::exception&) {
      throw common::InputError(where, key + ": expected a number, got '" + value + "'");
    }
    if (key == "E") o.E = number;
    else if (key == "nu") o.nu = number;
    else if (key == "density") o.density = number;
    else if (key == "phi") o.phi_deg = number;
    else if (key == "cohesion" || key == "c") o.cohesion = number;
    else if (key == "psi") o.psi_deg = number;
    else if (key == "tension") o.tension = number;
    else throw common::InputError(where, "unknown key '" + key + "' (expected type, E, nu, density, phi, cohesion, psi, tension)");
  }
}

std::vector<long> parse_tag_list(const std::string& text, const std::string& option) {
  std::vector<long> out;
  std::string s = text;
  std::replace(s.begin(), s.end(), ',', ' ');
  std::istringstream in(s);
  std::string word;
  while (in >> word) {
    const auto dash = word.find('-', 1);
    try {
      std::size_t used = 0;
      if (dash == std::string::npos) {
        out.push_back(std::stol(word, &used));
        if (used != word.size()) throw std::invalid_argument(word);
      } else {
        const long a = std::stol(word.substr(0, dash), &used);
        if (used != dash) throw std::invalid_argument(word);
        const std::string rest = word.substr(dash + 1);
        const long b = std::stol(rest, &used);
        if (used != rest.size() || b < a) throw std::invalid_argument(word);
        // Counted before expanding: "1-999999999" must be an error, not gigabytes of tags.
        if (static_cast<double>(b) - static_cast<double>(a) + 1 + static_cast<double>(out.size()) > kMaxTags)
          throw common::InputError(option, "'" + common::printable(word) + "' names " +
                                               fmt(static_cast<double>(b) - static_cast<double>(a) + 1) +
                                               " tags; at most " + fmt(kMaxTags) + " in all");
        for (long t = a; t <= b; ++t) out.push_back(t);
      }
    } catch (const common::InputError&) {
      throw;
    } catch (const std::exception&) {
      throw common::InputError(option, "expected tags or ranges like '1-35,40', got '" + common::printable(word) + "'");
    }
  }
  if (out.empty()) throw common::InputError(option, "empty tag list");
  return out;
}

AssembledState read_fem_state(const FemModel& model, const ReadOptions& options) {
  AssembledState out;
  TransferState& st = out.state;
  const double factor = options.units == Units::kN ? 1000.0 : 1.0;  // stress and density to SI

  // --- recorder files and the row at the transfer time
  // Row widths are checked against the layouts first (a file without its time column is caught
  // there), then the rows at the transfer time are picked.
  if (options.time) common::checked_number(*options.time, common::NumberRange::any(), "--time");
  const RecorderFile disp(options.disp);
  const RecorderFile stress(options.stress);

  // --- node layout of the Node recorders
  std::vector<long> node_tags;
  if (options.nodes) node_tags = *options.nodes;
  else for (const auto& [tag, idx] : model.node_by_tag) node_tags.push_back(tag);
  for (long tag : node_tags)
    if (model.node_index(tag) < 0) throw common::InputError("--nodes", "node " + std::to_string(tag) + " is not in " + model.source.string());
  auto check_node_width = [&](const RecorderFile& f, std::size_t row) {
    const std::size_t w = f.data_width();
    if (w == 2 * node_tags.size()) return;
    std::string detected = w % 2 == 0 ? std::to_string(w / 2) + " nodes x 2 dofs" : "not a whole number of nodes x 2 dofs (record -dof 1 2)";
    if (w + 1 == 2 * node_tags.size()) detected += "; the file seems to have no time column: record with -time";
    throw common::InputError(
        f.where(row), std::to_string(w) + " values after the time column (" + detected + "), but the layout has " +
                          std::to_string(node_tags.size()) + " nodes (" +
                          (options.nodes ? "--nodes " + tag_range_text(node_tags)
                                         : "all model nodes in tag order, " + tag_range_text(node_tags)) +
                          ") x 2 dofs; give the recorder's node order with --nodes");
  };
  check_node_width(disp, disp.rows().size() - 1);
  const TransferRow transfer = pick_transfer_row(disp, options.time, options.row, out.notes);
  const std::size_t disp_row = transfer.index;
  const double t = transfer.time;
  st.time = t;
  out.source_row = disp.where(disp_row);

  const std::size_t nn = model.nodes.size();
  st.reference.resize(nn);
  st.displacement.assign(nn, Vec2::Zero());
  st.velocity.assign(nn, Vec2::Zero());
  for (std::size_t i = 0; i < nn; ++i) st.reference[i] = model.nodes[i].crd;
  std::vector<char> recorded(nn, 0);
  {
    const auto u = disp.values(disp_row);
    for (std::size_t k = 0; k < node_tags.size(); ++k) {
      const auto i = static_cast<std::size_t>(model.node_index(node_tags[k]));
      st.displacement[i] = Vec2(u[2 * k], u[2 * k + 1]);
      recorded[i] = 1;
    }
  }
  // Another Node recorder of the same layout at the transfer time: per model node, times `scale`.
  const auto nodal_field = [&](const std::filesystem::path& file, double scale) {
    const RecorderFile f(file);
    check_node_width(f, f.rows().size() - 1);
    const auto v = f.values(matching_row(f, disp, transfer), scale);
    std::vector<Vec2> field(nn, Vec2::Zero());
    for (std::size_t k = 0; k < node_tags.size(); ++k)
      field[static_cast<std::size_t>(model.node_index(node_tags[k]))] = Vec2(v[2 * k], v[2 * k + 1]);
    return field;
  };
  if (!options.vel.empty()) st.velocity = nodal_field(options.vel, 1.0);
  else out.notes.push_back("no velocity file (--vel): the particles start at rest (zero velocity)");
  if (!options.loads.empty()) st.load = nodal_field(options.loads, factor);  // forces: kN -> N like the stresses

  // --- materials (ids in name order) and elements
  std::map<std::string, unsigned> material_ids;
  for (const auto& e : model.elements) material_ids.emplace(e.material, 0u);
  for (const auto& [name, values] : options.per_material)
    if (!material_ids.count(name)) {
      std::string known;
      for (const auto& [n, id] : material_ids) known += (known.empty() ? "" : ", ") + (n.empty() ? std::string("(none)") : n);
      throw common::InputError("--material " + name, "the model's elements use no material '" + name + "' (they use: " + known + ")");
    }
  unsigned next_id = 0;
  for (auto& [name, id] : material_ids) {
    id = next_id++;
    MpmMaterial m = resolve_material(model, name, options, factor, factor, out.notes);
    m.id = id;
    st.materials.push_back(m);
  }
  std::vector<long> element_tags;
  if (options.elements) element_tags = *options.elements;
  else for (const auto& [tag, idx] : model.element_by_tag) element_tags.push_back(tag);
  std::vector<double> gravity_samples;
  for (long tag : element_tags) {
    const int idx = model.element_index(tag);
    if (idx < 0) throw common::InputError("--elements", "element " + std::to_string(tag) + " is not in " + model.source.string());
    const FemElement& fe = model.elements[static_cast<std::size_t>(idx)];
    TransferElement e;
    e.tag = fe.tag;
    e.nodes = fe.nodes;
    e.node_count = node_count(fe.kind);
    e.gauss_points = gauss_point_count(fe.kind);
    e.material = material_ids.at(fe.material);
    const MpmMaterial& mat = st.materials[e.material];
    e.density = fe.mass_per_volume > 0 ? fe.mass_per_volume * factor : mat.density;
    if (!(e.density > 0))
      throw common::InputError(model.source.string() + ": element " + std::to_string(fe.tag),
                               "no density (material '" + fe.material + "' has no rho and the element no masspervolume); give --density");
    for (int k = 0; k < e.node_count; ++k)
      if (const int a = fe.nodes[static_cast<std::size_t>(k)]; !recorded[static_cast<std::size_t>(a)])
        throw common::InputError(options.disp.string(), "no column for node " + std::to_string(model.nodes[static_cast<std::size_t>(a)].tag) +
                                                            ", used by element " + std::to_string(fe.tag) + "; record all element nodes");
    // A u-p element's body force is an acceleration (OpenSees' SSPquadUP and FourNodeQuadUP multiply it by the
    // material density); a dry element's a force per unit volume.
    if (fe.body_force.norm() > 0)
      gravity_samples.push_back(fe.pore_pressure ? fe.body_force.norm() : fe.body_force.norm() * factor / e.density);
    st.elements.push_back(e);
  }
  if (element_tags.size() != model.elements.size())
    out.notes.push_back("only the " + std::to_string(element_tags.size()) + " recorded elements of " +
                        std::to_string(model.elements.size()) + " become particles");
  for (auto& m : st.materials)
    if (!(m.density > 0)) {
      // Material density only from the elements (quad masspervolume): their mean.
      double sum = 0; int count = 0;
      for (const auto& e : st.elements) if (e.material == m.id) { sum += e.density; ++count; }
      m.density = count ? sum / count : 0;
    }
  st.index_gauss_points();

  // --- stresses
  const std::size_t gp_total = st.gauss_offset.back();
  const std::size_t sw = stress.data_width();
  int comps = 0;
  for (int k : {3, 5, 6})
    if (sw == gp_total * static_cast<std::size_t>(k)) comps = k;
  if (comps == 0) {
    throw common::InputError(
        stress.where(stress.rows().size() - 1),
        std::to_string(sw) + " values after the time column, but the layout has " + std::to_string(element_tags.size()) +
            " elements (" + (options.elements ? "--elements " + tag_range_text(element_tags) : "all model elements in tag order, " + tag_range_text(element_tags)) +
            ") with " + std::to_string(gp_total) + " Gauss points: expected " + std::to_string(3 * gp_total) +
            " (stress: sxx syy sxy), " + std::to_string(5 * gp_total) + " (multi-yield stress) or " + std::to_string(6 * gp_total) +
            " (stress3D); give the recorder's element order with --elements" +
            ((sw + 1) % gp_total == 0 && ((sw + 1) / gp_total == 3 || (sw + 1) / gp_total == 6)
                 ? std::string("; the file seems to have no time column: record with -time")
                 : std::string()));
  }
  out.stress_components = comps;
  // The Gauss-point stresses of a row of the stress file (SI, the out-of-plane stress derived when not recorded).
  const auto gauss_stresses = [&](std::size_t row) {
    const auto sv = stress.values(row);
    std::vector<Stress6> gauss(gp_total);
    for (std::size_t e = 0; e < st.elements.size(); ++e) {
      const double nu = st.materials[st.elements[e].material].poisson_ratio;
      for (std::size_t g = st.gauss_offset[e]; g < st.gauss_offset[e + 1]; ++g) {
        const double* s = &sv[g * static_cast<std::size_t>(comps)];
        Stress6& out6 = gauss[g];
        if (comps == 3) out6 = {s[0], s[1], options.plane_stress ? 0.0 : nu * (s[0] + s[1]), s[2], 0, 0};
        else if (comps == 5) out6 = {s[0], s[1], s[2], s[3], 0, 0};
        else out6 = {s[0], s[1], s[2], s[3], s[4], s[5]};
        for (double& c : out6) {
          c *= factor;
          if (!std::isfinite(c))
            throw common::InputError(stress.where(row),
                                     "element " + std::to_string(st.elements[e].tag) + ", Gauss point " +
                                         std::to_string(g - st.gauss_offset[e] + 1) +
                                         ": its stress is not finite in Pa (values too large for double precision)");
        }
      }
    }
    return gauss;
  };
  st.gauss_stress = gauss_stresses(matching_row(stress, disp, transfer));
  if (options.pore_pressure) {
    // u-p: the pore pressure now and at the reference row, the reference row's effective stress (sigma'v0),
    // and the shear strain since then (pore_pressure.hpp).
    const PorePressureOptions& up = *options.pore_pressure;
    const TransferRow reference = pick_reference_row(disp, transfer, up.reference_time, "--reference-time", out.reference_how);
    out.reference_time = reference.time;
    out.reference_row = disp.where(reference.index);
    read_nodal_pore_pressure(model, up, disp, transfer, reference, factor, st, out.notes);
    st.reference_gauss_stress = gauss_stresses(matching_row(stress, disp, reference));
    if (!up.strain.empty()) {
      const RecorderFile strain(up.strain);
      const std::size_t w = strain.data_width();
      const int strain_comps = w == 3 * gp_total ? 3 : w == 6 * gp_total ? 6 : 0;
      if (strain_comps == 0)
        throw common::InputError(strain.where(strain.rows().size() - 1),
                                 std::to_string(w) + " values after the time column, but the stress file's layout has " +
                                     std::to_string(gp_total) + " Gauss points: expected " + std::to_string(3 * gp_total) +
                                     " (strain: exx eyy gxy) or " + std::to_string(6 * gp_total) + " (6 per Gauss point)");
      const auto now = strain.values(matching_row(strain, disp, transfer));
      const auto before = strain.values(matching_row(strain, disp, reference));
      st.gauss_shear_strain = equivalent_shear_strain(now, before, strain_comps);
      out.notes.push_back(strain.path().string() + ": the liquefied particles' softening starts at the equivalent deviatoric "
                          "strain sqrt(2/3 e:e) of the strain since the reference row (the total strain: its elastic part, "
                          "small after liquefaction, included)");
    }
  } else if (std::any_of(model.elements.begin(), model.elements.end(), [](const FemElement& e) { return e.pore_pressure; })) {
    out.warnings.push_back(model.source.string() + ": u-p elements (SSPquadUP / FourNodeQuadUP) but no --pore-pressure: "
                           "the particles carry the recorded effective stress as their stress, as if drained; give the "
                           "pore pressure recorder (-dof 3 vel) for the total stress and r_u");
  }
  if (comps == 3 && options.plane_stress)
    out.notes.push_back(stress.path().string() + ": 3 stress components per Gauss point (sxx syy sxy): szz = 0 "
                        "(--plane-stress; the MPM side is plane strain)");
  else if (comps == 3)
    out.notes.push_back(stress.path().string() + ": 3 stress components per Gauss point (sxx syy sxy): szz derived as "
                        "nu (sxx + syy), plane-strain elasticity (exact for elastic states, approximate after yield; "
                        "record `stress3D` for the full tensor)");
  if (comps == 5) out.notes.push_back(stress.path().string() + ": 5 values per Gauss point read as sxx syy szz sxy ratio (multi-yield `stress`)");
  out.triangles_split = split_triangles(st);
  if (out.triangles_split > 0)
    out.notes.push_back(std::to_string(out.triangles_split) + " Tri31 triangles each split into 3 quads (centroid to side "
                        "midpoints) for the particle mapping; each quad takes its triangle's stress");

  // --- gravity and unit sanity
  if (options.gravity) {
    // The magnitude: it acts in -y. A negative value (CB-Geo writes the vector [0, -9.81]) would
    // point it up, which no slope study means.
    st.gravity = common::checked_number(
        *options.gravity, common::NumberRange::non_negative().named("the magnitude of gravity in m/s2 (it acts in -y)"),
        "--gravity");
  } else if (!gravity_samples.empty()) {
    double sum = 0;
    for (double g : gravity_samples) sum += g;
    st.gravity = sum / static_cast<double>(gravity_samples.size());
    if (!std::isfinite(st.gravity))
      throw common::InputError(model.source.string() + ": bodyForces", "the gravity they give (body force / density) is " +
                                                                          fmt(st.gravity) + ", not finite; give --gravity");
    const bool up = std::any_of(model.elements.begin(), model.elements.end(), [](const FemElement& e) { return e.pore_pressure; });
    out.notes.push_back("gravity " + fmt(st.gravity) + " m/s2 from the elements' body forces / density" +
                        (up ? std::string("; a u-p element's body force is the acceleration itself") : std::string()) +
                        " (override with --gravity)");
  } else {
    st.gravity = 9.81;
    out.notes.push_back("gravity 9.81 m/s2 (default; the elements carry no body force; override with --gravity)");
  }
  for (const auto& m : st.materials) {
    const double rho_model = m.density / factor;
    if (options.units == Units::SI && m.density < 100)
      out.warnings.push_back("material '" + m.fem_name + "': density " + fmt(m.density) +
                             " kg/m3 looks like Mg/m3; are the FEM files in kN, m, kPa (use --units kN)?");
    if (options.units == Units::kN && rho_model > 100)
      out.warnings.push_back("material '" + m.fem_name + "': density " + fmt(rho_model) +
                             " Mg/m3 looks like kg/m3; are the FEM files in SI (use --units SI)?");
    // An associated DruckerPrager (rho_bar = rho) maps to psi = phi: plastic shearing then dilates at tan(psi)
    // per unit shear, and where the mass is confined that dilation is resisted and loads it; soils dilate
    // much less (0 for loose sand, roughly phi - 30 deg for dense; Bolton 1986).
    constexpr double kLargeDilation = 20.0 * std::numbers::pi / 180.0;
    if (m.type == MpmMaterial::Type::MohrCoulomb2D && m.dilation > kLargeDilation)
      out.warnings.push_back("material '" + m.fem_name + "': dilation angle " + fmt(m.dilation * 180.0 / std::numbers::pi) +
                             " deg (associated flow when it equals phi): confined plastic flow will dilate and load the "
                             "mass; soils dilate far less; give a smaller one with --psi or --material " + m.fem_name +
                             ":psi=...");
  }
  return out;
}

}  // namespace bridge
