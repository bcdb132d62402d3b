#include "bridge/drained_strength.hpp"

#include "common/number_text.hpp"

namespace bridge {

std::optional<DrainedStrength> drained_strength(const FemMaterial& m) {
  const auto fmt = [](double v) { return common::number_text(v, 6); };
  DrainedStrength d;
  d.rho = m.rho;
  if (m.type == "PM4Sand" || m.type == "PM4Silt") {
    if (!m.pm4_G0 || !m.pm4_P_atm || !m.phi_cv_deg || !m.nu) return std::nullopt;
    const double G = *m.pm4_G0 * *m.pm4_P_atm;
    d.nu = *m.nu;
    d.E = 2 * G * (1 + d.nu);
    d.phi_deg = *m.phi_cv_deg;
    d.note = m.type + " -> MohrCoulomb2D drained: phi = phi_cv " + fmt(d.phi_deg) + " deg, c 0, psi 0; E " + fmt(d.E) +
             " = 2 G (1 + nu) with the elastic stage's G = G0 P_atm = " + fmt(*m.pm4_G0) + " x " + fmt(*m.pm4_P_atm) +
             ", nu " + fmt(d.nu);
    return d;
  }
  if (m.type == "PressureDependMultiYield02") {
    if (!m.E || !m.nu || !m.multi_yield_friction_deg) return std::nullopt;
    d.E = *m.E;
    d.nu = *m.nu;
    d.phi_deg = *m.multi_yield_friction_deg;
    d.cohesion = m.multi_yield_cohesion.value_or(0.0);
    d.note = "PressureDependMultiYield02 -> MohrCoulomb2D drained: phi = frictionAng " + fmt(d.phi_deg) + " deg, c " +
             fmt(d.cohesion) + ", psi 0; E " + fmt(d.E) + ", nu " + fmt(d.nu) +
             " from refShearModul and refBulkModul (the moduli at refPress)";
    return d;
  }
  return std::nullopt;
}

}  // namespace bridge
