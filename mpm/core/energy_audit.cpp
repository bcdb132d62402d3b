#include "mpm/core/energy_audit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/input_error.hpp"
#include "common/number_text.hpp"

namespace mpm::core {

namespace {
std::string num(double v) { return common::number_text(v, 4); }

/// What does work on the body from outside, or "" when nothing does.
std::string external_work(const Deck& deck) {
  if (!deck.nodal_forces.empty()) return "nodal forces";
  if (!deck.particle_tractions.empty()) return "particle tractions";
  if (deck.base_acceleration) return "a base acceleration";
  for (const auto& c : deck.velocity_constraints)
    if (c.velocity != 0.0) return "a moving velocity constraint";
  return "";
}
}  // namespace

EnergyAudit::EnergyAudit(const Deck& deck)
    : reason_(external_work(deck)), gravity_(deck.analysis.gravity), materials_(deck.materials) {
  const double g = gravity_.norm();
  if (g > 0) {  // the grid's lowest corner along g: the largest g . x over the corners
    const Grid& grid = deck.grid;
    lowest_ = std::numeric_limits<double>::infinity();
    for (const double x : {grid.region_min[0], grid.region_max[0]})
      for (const double y : {grid.region_min[1], grid.region_max[1]}) lowest_ = std::min(lowest_, -(gravity_.x() * x + gravity_.y() * y) / g);
  }
}

MechanicalEnergy EnergyAudit::measure(std::span<const ParticleRecord> particles) const {
  MechanicalEnergy e;
  const double g = gravity_.norm();
  for (const auto& p : particles) {
    e.kinetic += 0.5 * p.mass * (p.velocity_x * p.velocity_x + p.velocity_y * p.velocity_y);
    if (g > 0) e.potential += p.mass * (-(gravity_.x() * p.coord_x + gravity_.y() * p.coord_y) - g * lowest_);
    const auto m = std::find_if(materials_.begin(), materials_.end(), [&](const auto& s) { return s.id == p.material_id; });
    if (m == materials_.end() || !(m->youngs_modulus > 0)) continue;
    const double E = m->youngs_modulus, nu = m->poisson_ratio;
    const double trace = p.stress_xx + p.stress_yy + p.stress_zz;
    const double ss = p.stress_xx * p.stress_xx + p.stress_yy * p.stress_yy + p.stress_zz * p.stress_zz +
                      2.0 * p.tau_xy * p.tau_xy;
    e.strain += p.volume * ((1.0 + nu) / (2.0 * E) * ss - nu / (2.0 * E) * trace * trace);
  }
  return e;
}

std::string EnergyAudit::check(double time, std::span<const ParticleRecord> particles) {
  if (!active()) return "";
  const double energy = measure(particles).total();
  if (!started_) {
    started_ = true;
    start_time_ = time;
    start_ = energy;
    return "";
  }
  if (!(start_ > 0)) return "";  // a body at rest at the datum without stress: nothing to compare with
  const double growth = energy / start_ - 1.0;
  const std::string what = "the mechanical energy (kinetic + gravitational + elastic) grew by " + num(100.0 * growth) +
                           " % from t = " + num(start_time_) + " s to t = " + num(time) +
                           " s with nothing doing work on the body";
  const std::string remedy = "a smaller time step (analysis.cfl 0.2 or less, or analysis.dt), the musl scheme or "
                             "the apic transfer";
  if (growth > kGrowthLimit) throw common::NumericalError(what + ": the explicit step is unstable here; try " + remedy);
  if (growth > kWarningGrowth && !warned_) {
    warned_ = true;
    return what + " (the run stops beyond " + num(100.0 * kGrowthLimit) + " %); if it keeps growing, try " + remedy;
  }
  return "";
}

}  // namespace mpm::core
