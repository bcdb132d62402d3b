#include "bridge/transfer_report.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "common/input_error.hpp"
#include "common/number_text.hpp"

namespace bridge {
namespace {

double norm2(const Stress6& s) {
  return s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + 2 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]);
}

/// Every figure of the report is finite, or the FEM values were too large for double precision (a
/// gravity or stress near 1e308 passes every range check and overflows in the sums): an InputError
/// naming the figure, so that no report or deck holds an infinity (JSON null).
void check_finite(const TransferReport& r, double gravity) {
  const std::pair<const char*, double> figures[] = {
      {"FEM mass", r.fem.mass},
      {"FEM momentum (x)", r.fem.momentum.x()},
      {"FEM momentum (y)", r.fem.momentum.y()},
      {"FEM kinetic energy", r.fem.kinetic_energy},
      {"FEM potential energy (m g y)", r.fem.potential_energy},
      {"particles' mass", r.particles.mass},
      {"particles' momentum (x)", r.particles.momentum.x()},
      {"particles' momentum (y)", r.particles.momentum.y()},
      {"particles' kinetic energy", r.particles.kinetic_energy},
      {"particles' potential energy (m g y)", r.particles.potential_energy},
      {"RMS relative stress difference", r.stress_rms_relative},
      {"largest relative stress difference", r.stress_max_relative},
      {"largest stress difference (Pa)", r.stress_max_abs}};
  for (const auto& [what, value] : figures)
    if (!std::isfinite(value))
      throw common::InputError("the transferred state",
                               std::string("its ") + what + " is not finite: the FEM values (gravity " +
                                   common::number_text(gravity, 6) +
                                   " m/s2, densities, stresses, velocities) are too large for double precision");
}

}  // namespace

TransferReport make_report(const TransferState& state, const std::vector<Stress6>& nodal_stress,
                           std::span<const mpm::ParticleRecord> particles) {
  TransferReport rep;
  const double g = state.gravity;
  // FEM side: row-sum lumped nodal masses m_a = sum_e rho_e int N_a dA_ref (2x2 Gauss, exact for
  // the bilinear integrand N_a det J).
  std::vector<double> nodal_mass(state.reference.size(), 0.0);
  const auto gp2 = opensees_gauss_points(4);
  for (const auto& e : state.elements) {
    const QuadNodes X = state.reference_nodes(e);
    for (const Vec2& q : gp2) {
      const auto n = shape_functions(q.x(), q.y());
      const double dv = jacobian_determinant(X, q.x(), q.y());  // weight 1 per point
      for (int a = 0; a < 4; ++a) nodal_mass[static_cast<std::size_t>(e.nodes[a])] += e.density * n[a] * dv;
    }
  }
  for (std::size_t i = 0; i < nodal_mass.size(); ++i) {
    const double m = nodal_mass[i];
    if (m == 0) continue;
    const Vec2& v = state.velocity[i];
    rep.fem.mass += m;
    rep.fem.momentum += m * v;
    rep.fem.kinetic_energy += 0.5 * m * v.squaredNorm();
    rep.fem.potential_energy += m * g * state.current(static_cast<int>(i)).y();
  }
  for (const auto& p : particles) {
    const Vec2 v(p.velocity_x, p.velocity_y);
    rep.particles.mass += p.mass;
    rep.particles.momentum += p.mass * v;
    rep.particles.kinetic_energy += 0.5 * p.mass * v.squaredNorm();
    rep.particles.potential_energy += p.mass * g * p.coord_y;
  }
  rep.particle_count = particles.size();

  // Stress difference at the FEM Gauss points.
  double sum_d2 = 0, sum_s2 = 0, max_s = 0;
  rep.min_jacobian = std::numeric_limits<double>::infinity();
  const auto one = opensees_gauss_points(1);
  for (std::size_t e = 0; e < state.elements.size(); ++e) {
    const auto& el = state.elements[e];
    const double jmin = min_jacobian_determinant(state.current_nodes(el));
    if (jmin < rep.min_jacobian) {
      rep.min_jacobian = jmin;
      rep.min_jacobian_element = el.tag;
    }
    std::array<const Stress6*, 4> sig{};
    for (int a = 0; a < 4; ++a) sig[a] = &nodal_stress[static_cast<std::size_t>(el.nodes[a])];
    const auto& pts = el.gauss_points == 1 ? one : gp2;
    for (std::size_t k = 0; k < pts.size(); ++k) {
      const Stress6& fem = state.gauss_stress[state.gauss_offset[e] + k];
      const Stress6 mapped = interpolate(shape_functions(pts[k].x(), pts[k].y()), sig);
      Stress6 d{};
      for (int c = 0; c < 6; ++c) d[c] = mapped[c] - fem[c];
      const double d2 = norm2(d), s2 = norm2(fem);
      sum_d2 += d2;
      sum_s2 += s2;
      max_s = std::max(max_s, std::sqrt(s2));
      if (std::sqrt(d2) > rep.stress_max_abs) {
        rep.stress_max_abs = std::sqrt(d2);
        rep.stress_max_element = el.tag;
      }
    }
  }
  rep.stress_rms_relative = sum_s2 > 0 ? std::sqrt(sum_d2 / sum_s2) : 0;
  rep.stress_max_relative = max_s > 0 ? rep.stress_max_abs / max_s : 0;
  check_finite(rep, g);
  return rep;
}

}  // namespace bridge
