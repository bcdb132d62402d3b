#include "bridge/liquefaction_report.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>

#include "common/number_text.hpp"

namespace bridge {
namespace {

std::string fmt(double v, int digits = 6) { return common::number_text(v, digits); }
std::string kpa(double pa) { return fmt(pa / 1000.0, 4) + " kPa"; }

std::string material_text(const MpmMaterial& m) {
  if (m.type == MpmMaterial::Type::LinearElastic2D)
    return "LinearElastic2D E " + fmt(m.youngs_modulus / 1e6, 4) + " MPa, nu " + fmt(m.poisson_ratio, 3);
  return "MohrCoulomb2D phi " + fmt(m.friction * 180 / std::numbers::pi, 4) + " deg, c " + kpa(m.cohesion) + ", psi " +
         fmt(m.dilation * 180 / std::numbers::pi, 4) + " deg, E " + fmt(m.youngs_modulus / 1e6, 4) + " MPa, nu " +
         fmt(m.poisson_ratio, 3);
}

}  // namespace

GroundSurface::GroundSurface(const TransferState& state) {
  double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin;
  for (const auto& e : state.elements) {
    const QuadNodes x = state.current_nodes(e);
    for (int a = 0; a < 4; ++a) {
      const Vec2& p = x[static_cast<std::size_t>(a)];
      const Vec2& q = x[static_cast<std::size_t>((a + 1) % 4)];
      edges_.push_back(p.x() <= q.x() ? Edge{p.x(), p.y(), q.x(), q.y()} : Edge{q.x(), q.y(), p.x(), p.y()});
      xmin = std::min(xmin, p.x());
      xmax = std::max(xmax, p.x());
    }
  }
  if (edges_.empty()) return;
  const std::size_t count = std::max<std::size_t>(1, static_cast<std::size_t>(std::sqrt(static_cast<double>(edges_.size()))));
  x0_ = xmin;
  width_ = xmax > xmin ? (xmax - xmin) / static_cast<double>(count) : 1.0;
  buckets_.resize(count);
  const auto bucket = [&](double x) {
    return static_cast<std::size_t>(std::clamp((x - x0_) / width_, 0.0, static_cast<double>(count - 1)));
  };
  for (std::size_t k = 0; k < edges_.size(); ++k)
    for (std::size_t b = bucket(edges_[k].x0); b <= bucket(edges_[k].x1); ++b) buckets_[b].push_back(k);
}

double GroundSurface::height(double x) const {
  double top = -std::numeric_limits<double>::infinity();
  if (buckets_.empty()) return top;
  const auto b = static_cast<std::size_t>(
      std::clamp((x - x0_) / width_, 0.0, static_cast<double>(buckets_.size() - 1)));
  for (std::size_t k : buckets_[b]) {
    const Edge& e = edges_[k];
    if (x < e.x0 || x > e.x1) continue;
    const double y = e.x1 > e.x0 ? e.y0 + (e.y1 - e.y0) * (x - e.x0) / (e.x1 - e.x0) : std::max(e.y0, e.y1);
    top = std::max(top, y);
  }
  return top;
}

LiquefactionReport make_liquefaction_report(const TransferState& state, std::span<const mpm::ParticleRecord> particles,
                                            std::span<const mpm::PorePressureRecord> rows, double threshold,
                                            std::size_t no_reference, const LiquefiedSummary& strength) {
  LiquefactionReport r;
  r.threshold = threshold;
  r.no_reference = no_reference;
  r.strength = strength;
  const GroundSurface surface(state);
  std::vector<std::size_t> count(state.materials.size(), 0);
  std::vector<double> mass(state.materials.size(), 0.0);
  for (std::size_t k = 0; k < particles.size(); ++k) {
    const auto& p = particles[k];
    const auto& row = rows[k];
    r.mass += p.mass;
    ++count[p.material_id];
    mass[p.material_id] += p.mass;
    if (k == 0 || row.ru > r.max_ru) {
      r.max_ru = row.ru;
      r.max_ru_x = p.coord_x;
      r.max_ru_y = p.coord_y;
    }
    if (row.ru > threshold) {
      ++r.liquefied;
      r.liquefied_mass += p.mass;
    }
    if (row.ru >= threshold) {
      const double depth = std::max(0.0, surface.height(p.coord_x) - p.coord_y);
      if (!r.max_depth || depth > *r.max_depth) {
        r.max_depth = depth;
        r.max_depth_x = p.coord_x;
        r.max_depth_y = p.coord_y;
      }
    }
  }
  const std::set<unsigned> liquefied(strength.materials.begin(), strength.materials.end());
  const std::set<unsigned> effective(strength.effective_materials.begin(), strength.effective_materials.end());
  for (const auto& m : state.materials) {
    LiquefactionReport::MaterialCount c{m.id, "", count[m.id], mass[m.id]};
    if (liquefied.count(m.id)) {
      c.text = m.origin;
      r.liquefied_materials.push_back(c);
    } else if (effective.count(m.id)) {
      c.text = m.origin + ": " + material_text(m);
      r.drained.push_back(c);
    } else {
      c.text = "FEM material '" + m.fem_name + "': " + material_text(m);
      r.drained.push_back(c);
    }
  }
  return r;
}

std::string liquefaction_text(const LiquefactionReport& r) {
  std::string s;
  s += "  pore pressure: " + r.file + "; reference state (sigma'v0, hydrostatic p0) at t = " + fmt(r.reference_time, 9) +
       ", " + r.reference_how + "\n";
  s += "  particle stress = total stress sigma' - p I (CB-Geo: tension positive; p compression positive, from the "
       "element's nodes with its shape functions); /pore_pressure holds p, sigma'v0 (Pa, compression positive) and "
       "r_u = (p - p0) / sigma'v0\n";
  s += "  r_u: max " + fmt(r.max_ru, 4) + " at (" + fmt(r.max_ru_x, 5) + ", " + fmt(r.max_ru_y, 5) + "); liquefied (r_u > " +
       fmt(r.threshold) + "): " + std::to_string(r.liquefied) + " particles, " + fmt(r.liquefied_mass, 6) + " kg/m (" +
       fmt(r.mass > 0 ? 100 * r.liquefied_mass / r.mass : 0.0, 3) + " % of the mass); largest depth with r_u >= " +
       fmt(r.threshold) + ": " +
       (r.max_depth ? fmt(*r.max_depth, 4) + " m below the ground surface (at (" + fmt(r.max_depth_x, 5) + ", " +
                          fmt(r.max_depth_y, 5) + "))"
                    : std::string("none")) +
       "\n";
  if (r.no_reference > 0)
    s += "  note: " + std::to_string(r.no_reference) + " particles have sigma'v0 <= 0 (no effective stress at the reference "
         "state): r_u = 0 there\n";
  for (const auto& c : r.drained)
    s += "  material " + std::to_string(c.id) + " (below the threshold): " + c.text + "; " + std::to_string(c.particles) +
         " particles\n";
  if (!r.strength.effective_friction.empty()) s += "  effective friction (--effective-friction): " + r.strength.effective_friction + "\n";
  s += "  liquefied strength: " + r.strength.rule + "\n";
  for (const auto& c : r.liquefied_materials)
    s += "  material " + std::to_string(c.id) + ": " + c.text + "; " + std::to_string(c.particles) + " particles, " +
         fmt(c.mass, 6) + " kg/m\n";
  if (r.strength.softened_at_start > 0)
    s += "  note: " + std::to_string(r.strength.softened_at_start) + " liquefied particles start past their peak "
         "pdstrain (--strain): their cohesion starts softened\n";
  return s;
}

nlohmann::ordered_json liquefaction_json(const LiquefactionReport& r) {
  nlohmann::ordered_json j;
  j["file"] = r.file;
  j["reference"] = {{"time", r.reference_time}, {"row", r.reference_row}, {"how", r.reference_how}};
  j["sign_convention"] = "particle stress = sigma' - p I, tension positive (CB-Geo); p, sigma'v0 compression positive, Pa";
  j["dataset"] = "/pore_pressure: p, sigma_v0, r_u per /table row";
  j["threshold"] = r.threshold;
  j["max_ru"] = {{"value", r.max_ru}, {"at", {r.max_ru_x, r.max_ru_y}}};
  j["liquefied"] = {{"particles", r.liquefied}, {"mass", r.liquefied_mass}, {"mass_fraction", r.mass > 0 ? r.liquefied_mass / r.mass : 0.0}};
  // No null in report.json (a consumer reads every value as a number): "found" says whether a particle reached it.
  j["max_depth"] = {{"found", r.max_depth.has_value()}, {"depth", r.max_depth.value_or(0.0)},
                    {"at", {r.max_depth_x, r.max_depth_y}}};
  j["no_reference_particles"] = r.no_reference;
  j["strength_rule"] = r.strength.rule;
  j["effective_friction"] = r.strength.effective_friction;
  auto list = [](const std::vector<LiquefactionReport::MaterialCount>& v) {
    nlohmann::ordered_json a = nlohmann::ordered_json::array();
    for (const auto& c : v) a.push_back({{"id", c.id}, {"material", c.text}, {"particles", c.particles}, {"mass", c.mass}});
    return a;
  };
  j["drained_materials"] = list(r.drained);
  j["liquefied_materials"] = list(r.liquefied_materials);
  j["softened_at_start"] = r.strength.softened_at_start;
  return j;
}

}  // namespace bridge
