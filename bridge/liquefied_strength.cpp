#include "bridge/liquefied_strength.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <tuple>

#include "common/input_error.hpp"
#include "common/number_text.hpp"
#include "common/printable_text.hpp"

namespace bridge {
namespace {

std::string fmt(double v, int digits = 6) { return common::number_text(v, digits); }
std::string kpa(double pa) { return common::number_text(pa / 1000.0, 4) + " kPa"; }

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  const auto b = s.find_last_not_of(" \t\r");
  return s.substr(a, b - a + 1);
}

std::vector<std::string> split_commas(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  for (std::string item; std::getline(in, item, ',');) out.push_back(trim(item));
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}

/// The cohesion of a softening strength at plastic deviatoric strain `pd` (mpm/core/materials.cpp
/// MohrCoulomb::update_general: linear between peak_pdstrain and residual_pdstrain, CB-Geo's rule).
double softened_cohesion(const MpmMaterial& m, double pd) {
  if (!m.softening || !(pd > m.softening->peak_pdstrain)) return m.cohesion;
  const auto& s = *m.softening;
  if (pd >= s.residual_pdstrain) return s.residual_cohesion;
  const double t = (pd - s.residual_pdstrain) / (s.peak_pdstrain - s.residual_pdstrain);
  return s.residual_cohesion + (m.cohesion - s.residual_cohesion) * t;
}

}  // namespace

std::vector<StrengthBin> parse_strength_table(const std::string& text, const std::string& shown) {
  std::istringstream in(text);
  std::vector<StrengthBin> bins;
  std::optional<double> unit;  // stress unit of the columns, Pa per unit (from the header)
  int line_no = 0;
  for (std::string raw; std::getline(in, raw);) {
    ++line_no;
    const std::string where = shown + ":" + std::to_string(line_no);
    const std::string line = trim(raw);
    if (line.empty() || line[0] == '#') continue;
    const auto items = split_commas(line);
    if (!unit) {
      for (const auto& [suffix, factor] : {std::pair<std::string, double>{"kPa", 1000.0}, {"Pa", 1.0}})
        if (items == std::vector<std::string>{"sigma_v0_upper_" + suffix, "peak_cohesion_" + suffix,
                                              "residual_cohesion_" + suffix, "peak_pdstrain", "residual_pdstrain"})
          unit = factor;
      if (!unit)
        throw common::InputError(where, "expected the header sigma_v0_upper_kPa,peak_cohesion_kPa,residual_cohesion_kPa,"
                                        "peak_pdstrain,residual_pdstrain (or _Pa for the three stresses), got '" +
                                            common::printable(line.substr(0, 120)) + "'");
      continue;
    }
    if (items.size() != 5)
      throw common::InputError(where, "expected 5 comma-separated values (sigma_v0_upper, peak_cohesion, residual_cohesion, "
                                      "peak_pdstrain, residual_pdstrain), got " + std::to_string(items.size()));
    static const char* const names[5] = {"sigma_v0_upper", "peak_cohesion", "residual_cohesion", "peak_pdstrain",
                                         "residual_pdstrain"};
    double v[5];
    for (int k = 0; k < 5; ++k) {
      const std::string& item = items[static_cast<std::size_t>(k)];
      try {
        std::size_t used = 0;
        v[k] = std::stod(item, &used);
        if (used != item.size()) throw std::invalid_argument(item);
      } catch (const std::exception&) {
        throw common::InputError(where, std::string(names[k]) + ": expected a number, got '" + common::printable(item) + "'");
      }
      const bool infinite_upper = k == 0 && v[k] == std::numeric_limits<double>::infinity();
      if (std::isnan(v[k]) || (std::isinf(v[k]) && !infinite_upper) || v[k] < 0)
        throw common::InputError(where, std::string(names[k]) + ": expected a finite number >= 0" +
                                            (k == 0 ? " (or inf for the last bin)" : "") + ", got '" +
                                            common::printable(item) + "'");
    }
    StrengthBin b{v[0] * *unit, v[1] * *unit, v[2] * *unit, v[3], v[4]};
    if (!(b.sigma_v0_upper > 0)) throw common::InputError(where, "sigma_v0_upper: expected > 0, got " + items[0]);
    if (!bins.empty() && !(b.sigma_v0_upper > bins.back().sigma_v0_upper))
      throw common::InputError(where, "unsorted bins: sigma_v0_upper " + items[0] + " is not above the previous row's " +
                                          fmt(bins.back().sigma_v0_upper / *unit) +
                                          " (rows in increasing sigma'v0, each bin from the previous upper bound to its own)");
    if (b.residual_cohesion > b.peak_cohesion)
      throw common::InputError(where, "residual_cohesion " + items[2] + " is above peak_cohesion " + items[1] +
                                          " (the strength softens from the peak to the residual)");
    if (b.residual_cohesion < b.peak_cohesion && !(b.residual_pdstrain > b.peak_pdstrain))
      throw common::InputError(where, "residual_pdstrain " + items[4] + " must be above peak_pdstrain " + items[3] +
                                          " when the cohesion softens (mpm's MohrCoulomb softening)");
    bins.push_back(b);
  }
  if (!unit) throw common::InputError(shown, "empty strength table: expected a header line and one row per bin");
  if (bins.empty()) throw common::InputError(shown, "the strength table has a header but no bins");
  return bins;
}

std::vector<StrengthBin> read_strength_table(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw common::InputError(file.string(), "cannot open the strength table (--liquefied-table)");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_strength_table(text.str(), file.string());
}

double idriss_boulanger_residual_ratio(double n, VoidRedistribution v) {
  const double base = std::exp(n / 16.0 + std::pow((n - 16.0) / 21.2, 3) - 3.0);
  return v == VoidRedistribution::Significant ? base : base * (1.0 + std::exp(n / 2.4 - 6.6));
}

void check_liquefied_options(const LiquefiedOptions& o) {
  if (!std::isfinite(o.threshold)) throw common::InputError("--liquefied", "expected a finite r_u threshold, got " + fmt(o.threshold));
  if (o.rule == LiquefiedOptions::Rule::Ratio && !(o.ratio > 0 && std::isfinite(o.ratio)))
    throw common::InputError("--residual-ratio", "expected Sr / sigma'v0 > 0 (finite), got " + fmt(o.ratio));
  for (const auto& [name, n] : o.n160cs)
    if (!(n >= 0 && n <= 60))
      throw common::InputError("--residual-n160cs " + name, "expected (N1)60cs-Sr from 0 to 60 blows/0.3 m, got " + fmt(n));
  if (!(o.peak_factor >= 1 && std::isfinite(o.peak_factor)))
    throw common::InputError("--liquefied-softening", "expected a peak factor K >= 1 (finite), got " + fmt(o.peak_factor));
  if (!(o.pd_peak >= 0 && std::isfinite(o.pd_peak)) || !(std::isfinite(o.pd_residual)) ||
      (o.peak_factor > 1 && !(o.pd_residual > o.pd_peak)))
    throw common::InputError("--liquefied-softening", "expected plastic deviatoric strains 0 <= E1 < E2 (finite), got " +
                                                          fmt(o.pd_peak) + " and " + fmt(o.pd_residual));
  if (!(o.strength_step > 0 && o.strength_step <= 1))
    throw common::InputError("--strength-step", "expected a relative step in (0, 1], got " + fmt(o.strength_step));
  if (o.max_materials < 1) throw common::InputError("--max-liquefied-materials", "expected at least 1");
}

namespace {

/// --effective-friction (liquefied_strength.hpp): the particles at or below the threshold whose material is
/// frictional get tan(phi_eq) = (1 - p / sigma_m) tan(phi'), rounded to a geometric grid (--strength-step,
/// widened to at most max_materials values), one material per FEM material and grid value.
void apply_effective_friction(TransferState& state, std::span<mpm::ParticleRecord> particles,
                              std::span<const mpm::PorePressureRecord> rows, const LiquefiedOptions& o,
                              LiquefiedSummary& out) {
  using Key = std::tuple<unsigned, long long>;
  std::vector<double> tan_eq(particles.size(), 0.0);
  std::size_t reduced = 0;
  for (std::size_t k = 0; k < particles.size(); ++k) {
    const mpm::ParticleRecord& r = particles[k];
    const MpmMaterial& m = state.materials[r.material_id];
    if (rows[k].ru > o.threshold || m.type != MpmMaterial::Type::MohrCoulomb2D || !(m.friction > 0)) continue;
    const double sigma_m = -(r.stress_xx + r.stress_yy + r.stress_zz) / 3.0;  // total, compression positive
    const double p = rows[k].pressure;
    if (!(p > 0) || !(sigma_m > 0)) continue;
    tan_eq[k] = std::max(1.0 - p / sigma_m, 1e-3) * std::tan(m.friction);  // p >= sigma_m: a nearly frictionless particle
    ++reduced;
  }
  double log_step = std::log1p(o.strength_step);
  const auto distinct = [&](double step) {
    std::set<Key> keys;
    for (std::size_t k = 0; k < particles.size(); ++k)
      if (tan_eq[k] > 0) keys.insert({particles[k].material_id, std::llround(std::log(tan_eq[k]) / step)});
    return keys.size();
  };
  while (distinct(log_step) > o.max_materials) log_step *= 1.25;
  std::map<Key, unsigned> id_of;
  for (std::size_t k = 0; k < particles.size(); ++k) {
    if (!(tan_eq[k] > 0)) continue;
    mpm::ParticleRecord& r = particles[k];
    const long long grid = std::llround(std::log(tan_eq[k]) / log_step);
    const Key key{r.material_id, grid};
    auto it = id_of.find(key);
    if (it == id_of.end()) {
      const MpmMaterial& src = state.materials[r.material_id];
      MpmMaterial m = src;
      m.id = static_cast<unsigned>(state.materials.size());
      m.friction = std::atan(std::exp(static_cast<double>(grid) * log_step));
      m.dilation = std::min(m.dilation, m.friction);
      m.origin = "particles of FEM material '" + src.fem_name + "' below the threshold with their pore pressure " +
                 "(--effective-friction): phi " + fmt(m.friction * 180.0 / M_PI, 4) + " deg from " +
                 fmt(src.friction * 180.0 / M_PI, 4) + " deg, c " + kpa(m.cohesion);
      it = id_of.emplace(key, m.id).first;
      out.effective_materials.push_back(m.id);
      state.materials.push_back(std::move(m));
    }
    r.material_id = it->second;
    const MpmMaterial& m = state.materials[it->second];
    const Stress6 s{r.stress_xx, r.stress_yy, r.stress_zz, r.tau_xy, r.tau_yz, r.tau_xz};
    const double pd = r.svars[6];
    r.nstate_vars = mohr_coulomb_state(m, s, r.svars);
    r.svars[6] = pd;
  }
  out.effective_friction = "the " + std::to_string(reduced) + " frictional particles at or below the threshold with a pore " +
                           "pressure: tan(phi) = (1 - p / sigma_m) tan(phi') on the total stress (the pore pressure of the " +
                           "transfer held; Bishop & Morgenstern 1960), rounded to a grid of step " +
                           fmt(100 * std::expm1(log_step), 3) + " %: " + std::to_string(out.effective_materials.size()) +
                           " materials";
}

}  // namespace

LiquefiedSummary assign_liquefied_strength(TransferState& state, std::span<mpm::ParticleRecord> particles,
                                           std::span<const mpm::PorePressureRecord> rows,
                                           std::span<const double> shear_strain, const LiquefiedOptions& o) {
  using Rule = LiquefiedOptions::Rule;
  LiquefiedSummary out;
  const std::string above = "r_u > " + fmt(o.threshold);
  switch (o.rule) {
    case Rule::None: out.rule = "none given: the liquefied particles keep their drained strength"; break;
    case Rule::Table: out.rule = "the strength table " + o.table_file + " (the authors' bins of sigma'v0; phi = 0)"; break;
    case Rule::Ratio:
      out.rule = "Sr = " + fmt(o.ratio) + " sigma'v0 (liquefied strength ratio, Olson & Stark 2002, Can. Geotech. J. 39, 629-647; phi = 0)";
      break;
    case Rule::Penetration:
      out.rule = std::string("Sr / sigma'v0 from (N1)60cs-Sr, Idriss & Boulanger 2008 (EERI MNO-12), void redistribution ") +
                 (o.void_redistribution == VoidRedistribution::Significant ? "could be significant" : "negligible") +
                 ", at most tan(phi'); phi = 0";
      break;
  }
  if ((o.rule == Rule::Ratio || o.rule == Rule::Penetration) && o.peak_factor > 1)
    out.rule += "; softening from " + fmt(o.peak_factor) + " Sr to Sr between pdstrain " + fmt(o.pd_peak) + " and " + fmt(o.pd_residual);

  // The FEM material names of --residual-n160cs must exist.
  if (o.rule == Rule::Penetration)
    for (const auto& [name, n] : o.n160cs) {
      const bool known = std::any_of(state.materials.begin(), state.materials.end(),
                                     [&](const MpmMaterial& m) { return m.fem_name == name; });
      if (!known) {
        std::string list;
        for (const auto& m : state.materials) list += (list.empty() ? "" : ", ") + m.fem_name;
        throw common::InputError("--residual-n160cs " + name, "the model's elements use no material '" + name +
                                                                  "' (they use: " + list + ")");
      }
    }

  // Each liquefied particle's strength key: (FEM material, bin or Sr grid index); materials made in key order.
  using Key = std::tuple<unsigned, long long>;
  struct Strength {
    double peak = 0, residual = 0, pd_peak = 0, pd_residual = 0;
    std::string origin;
  };
  std::map<Key, Strength> strengths;
  std::vector<std::optional<Key>> key_of(particles.size());
  // Rules Ratio and Penetration: each liquefied particle's Sr (Pa) first, then the grid it is rounded to.
  std::vector<double> sr(particles.size(), 0.0);
  for (std::size_t k = 0; k < particles.size(); ++k) {
    if (!(rows[k].ru > o.threshold)) continue;
    ++out.liquefied;
    if (o.rule != Rule::Ratio && o.rule != Rule::Penetration) continue;
    const mpm::ParticleRecord& r = particles[k];
    const MpmMaterial& fem = state.materials[r.material_id];
    double ratio = o.ratio;
    if (o.rule == Rule::Penetration) {
      const auto it = o.n160cs.find(fem.fem_name);
      if (it == o.n160cs.end())
        throw common::InputError("--residual-n160cs", "particles of FEM material '" + fem.fem_name + "' liquefy (" + above +
                                                          ", e.g. at (" + fmt(r.coord_x) + ", " + fmt(r.coord_y) +
                                                          ")) but no (N1)60cs-Sr is given for it: add " + fem.fem_name + ":N");
      ratio = idriss_boulanger_residual_ratio(it->second, o.void_redistribution);
      if (fem.friction > 0) ratio = std::min(ratio, std::tan(fem.friction));
    }
    sr[k] = ratio * rows[k].sigma_v0;  // sigma'v0 > 0: r_u is 0 where it is not
  }
  // The grid: --strength-step, widened by factors of 1.25 (in log) until at most max_materials strengths remain.
  double log_step = std::log1p(o.strength_step);
  if (o.rule == Rule::Ratio || o.rule == Rule::Penetration) {
    const auto distinct = [&](double step) {
      std::set<Key> keys;
      for (std::size_t k = 0; k < particles.size(); ++k)
        if (sr[k] > 0) keys.insert({particles[k].material_id, std::llround(std::log(sr[k]) / step)});
      return keys.size();
    };
    while (distinct(log_step) > o.max_materials) log_step *= 1.25;
    out.rule += "; Sr rounded to a geometric grid of step " + fmt(100 * std::expm1(log_step), 3) + " % (within " +
                fmt(100 * std::expm1(0.5 * log_step), 3) + " %)" +
                (std::expm1(log_step) > o.strength_step * (1 + 1e-12)
                     ? " widened from --strength-step " + fmt(100 * o.strength_step, 3) + " % to keep at most " +
                           std::to_string(o.max_materials) + " liquefied materials"
                     : std::string());
  }
  for (std::size_t k = 0; k < particles.size(); ++k) {
    if (!(rows[k].ru > o.threshold) || o.rule == Rule::None) continue;
    const mpm::ParticleRecord& r = particles[k];
    const unsigned src = r.material_id;
    const double sv0 = rows[k].sigma_v0;
    Key key;
    Strength s;
    if (o.rule == Rule::Table) {
      const auto bin = std::find_if(o.table.begin(), o.table.end(), [&](const StrengthBin& b) { return sv0 < b.sigma_v0_upper; });
      if (bin == o.table.end())
        throw common::InputError(o.table_file, "a liquefied particle at (" + fmt(r.coord_x) + ", " + fmt(r.coord_y) +
                                                   ") has sigma'v0 " + kpa(sv0) + ", not below the last bin's upper bound " +
                                                   kpa(o.table.back().sigma_v0_upper) + ": add a bin (inf is allowed)");
      const auto b = static_cast<long long>(bin - o.table.begin());
      key = {src, b};
      const double lower = b == 0 ? 0.0 : o.table[static_cast<std::size_t>(b - 1)].sigma_v0_upper;
      s = {bin->peak_cohesion, bin->residual_cohesion, bin->peak_pdstrain, bin->residual_pdstrain,
           "sigma'v0 " + kpa(lower) + " to " + (std::isinf(bin->sigma_v0_upper) ? std::string("inf") : kpa(bin->sigma_v0_upper)) +
               " (" + o.table_file + " row " + std::to_string(b + 1) + ")"};
    } else {
      const long long grid = std::llround(std::log(sr[k]) / log_step);
      const double sr_grid = std::exp(static_cast<double>(grid) * log_step);
      key = {src, grid};
      s = {o.peak_factor * sr_grid, sr_grid, o.peak_factor > 1 ? o.pd_peak : 0.0, o.peak_factor > 1 ? o.pd_residual : 0.0,
           "Sr " + kpa(sr_grid)};
    }
    strengths.emplace(key, s);
    key_of[k] = key;
  }
  if (o.rule == Rule::None && out.liquefied > 0)
    out.warnings.push_back(std::to_string(out.liquefied) + " particles are liquefied (" + above + ") but keep their "
                           "drained strength: give a residual strength rule (--liquefied-table, --residual-ratio or "
                           "--residual-n160cs)");

  // The materials, in key order (FEM material, then bin / strength), ids after the FEM materials'.
  std::map<Key, unsigned> id_of;
  for (const auto& [key, s] : strengths) {
    const MpmMaterial& src = state.materials[std::get<0>(key)];
    MpmMaterial m;
    m.id = static_cast<unsigned>(state.materials.size());
    m.fem_name = src.fem_name;
    m.type = MpmMaterial::Type::MohrCoulomb2D;
    m.density = src.density;
    m.youngs_modulus = src.youngs_modulus;
    m.poisson_ratio = src.poisson_ratio;
    m.friction = 0;
    m.dilation = 0;
    m.cohesion = s.peak;
    m.tension_cutoff = 0;
    if (s.residual < s.peak) m.softening = MpmMaterial::Softening{s.residual, s.pd_peak, s.pd_residual};
    m.origin = "liquefied (" + above + ") particles of FEM material '" + src.fem_name + "', " + s.origin + ": phi 0, c " +
               kpa(s.peak) + (m.softening ? " softening to " + kpa(s.residual) + " between pdstrain " + fmt(s.pd_peak) +
                                                " and " + fmt(s.pd_residual)
                                          : std::string());
    id_of.emplace(key, m.id);
    out.materials.push_back(m.id);
    state.materials.push_back(std::move(m));
  }
  for (std::size_t k = 0; k < particles.size(); ++k) {
    if (!key_of[k]) continue;
    mpm::ParticleRecord& r = particles[k];
    const MpmMaterial& m = state.materials[id_of.at(*key_of[k])];
    r.material_id = m.id;
    const Stress6 s{r.stress_xx, r.stress_yy, r.stress_zz, r.tau_xy, r.tau_yz, r.tau_xz};
    r.nstate_vars = mohr_coulomb_state(m, s, r.svars);
    const double pd = shear_strain.empty() ? 0.0 : shear_strain[k];
    r.svars[6] = pd;
    r.svars[2] = softened_cohesion(m, pd);
    if (m.softening && pd > m.softening->peak_pdstrain) ++out.softened_at_start;
  }
  if (o.effective_friction) apply_effective_friction(state, particles, rows, o, out);
  return out;
}

std::vector<std::size_t> group_by_material(ParticleList& particles) {
  std::vector<std::size_t> order(particles.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return particles[a].material_id < particles[b].material_id;
  });
  ParticleList sorted(particles.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    std::memcpy(static_cast<void*>(&sorted[k]), &particles[order[k]], sizeof(mpm::ParticleRecord));  // padding too
    sorted[k].id = static_cast<std::int64_t>(k);
  }
  particles = std::move(sorted);
  return order;
}

}  // namespace bridge
