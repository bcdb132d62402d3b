#include "bridge/particle_mapping.hpp"

#include <cmath>
#include <new>
#include <algorithm>

namespace bridge {

std::vector<long> inverted_elements(const TransferState& state, bool reference) {
  std::vector<long> bad;
  for (const auto& e : state.elements)
    if (!(min_jacobian_determinant(reference ? state.reference_nodes(e) : state.current_nodes(e)) > 0) &&
        (bad.empty() || bad.back() != e.tag))  // the three quads of a split triangle share its tag
      bad.push_back(e.tag);
  return bad;
}

unsigned mohr_coulomb_state(const MpmMaterial& m, const Stress6& s, double* svars) {
  const double p = (s[0] + s[1] + s[2]) / 3.0;
  const double dx = s[0] - p, dy = s[1] - p, dz = s[2] - p;
  const double txy = s[3], tyz = s[4], txz = s[5];
  // J2 = s:s / 2 and J3 = det(s) of the deviator (CB-Geo material_utility j2, j3).
  const double j2 = 0.5 * (dx * dx + dy * dy + dz * dz) + txy * txy + tyz * tyz + txz * txz;
  const double j3 = dx * dy * dz - dz * txy * txy + 2 * txy * tyz * txz - dx * tyz * tyz - dy * txz * txz;
  double cos3 = 0;
  if (j2 > 1e-12) cos3 = std::clamp(1.5 * std::sqrt(3.0) * j3 / (j2 * std::sqrt(j2)), -1.0, 1.0);
  svars[0] = m.friction;
  svars[1] = m.dilation;
  svars[2] = m.cohesion;
  svars[3] = std::sqrt(3.0) * p;           // epsilon
  svars[4] = std::sqrt(2.0 * j2);          // rho
  svars[5] = std::acos(cos3) / 3.0;        // theta (Lode angle, cos convention)
  svars[6] = 0;                            // pdstrain: the MPM stage starts unstrained
  return 7;
}

std::vector<std::size_t> particle_slots(const TransferState& state) {
  std::vector<std::size_t> count(state.materials.size(), 0);
  for (const auto& el : state.elements) ++count[el.material];
  std::vector<std::size_t> next(state.materials.size(), 0);
  for (std::size_t m = 1; m < count.size(); ++m) next[m] = next[m - 1] + count[m - 1];
  std::vector<std::size_t> slot(state.elements.size());
  for (std::size_t e = 0; e < state.elements.size(); ++e) slot[e] = next[state.elements[e].material]++;
  return slot;
}

std::vector<ParticlePoint> particle_points(int n) {
  const GaussRule rule = gauss_legendre(n);
  std::vector<ParticlePoint> points;
  points.reserve(static_cast<std::size_t>(n * n));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double xi = rule.points[static_cast<std::size_t>(i)], eta = rule.points[static_cast<std::size_t>(j)];
      points.push_back({xi, eta, rule.weights[static_cast<std::size_t>(i)] * rule.weights[static_cast<std::size_t>(j)],
                        shape_functions(xi, eta)});
    }
  return points;
}

ParticleList generate_particles(const TransferState& state,
                                                        const std::vector<Stress6>& nodal_stress,
                                                        const MappingOptions& options) {
  const int n = options.particles_per_direction;
  const std::size_t per_element = static_cast<std::size_t>(n * n);
  ParticleList out(state.elements.size() * per_element);  // not yet initialised: see the loop
  const double nsize = 2.0 / n;
  const std::vector<ParticlePoint> points = particle_points(n);  // computed once
  const std::vector<std::size_t> slot = particle_slots(state);

#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t ie = 0; ie < static_cast<std::ptrdiff_t>(state.elements.size()); ++ie) {
    const auto e = static_cast<std::size_t>(ie);
    const std::size_t first = slot[e] * per_element;
    const TransferElement& el = state.elements[e];
    const QuadNodes x = state.current_nodes(el);
    const QuadNodes X = state.reference_nodes(el);
    const MpmMaterial& mat = state.materials[el.material];
    const double area_cur = quad_area(x), area_ref = quad_area(X);
    std::array<const Stress6*, 4> sig{};
    std::array<Vec2, 4> u, v;
    for (int a = 0; a < 4; ++a) {
      const auto node = static_cast<std::size_t>(el.nodes[a]);
      sig[a] = &nodal_stress[node];
      u[a] = state.displacement[node];
      v[a] = state.velocity[node];
    }
    for (std::size_t q = 0; q < per_element; ++q) {
      const ParticlePoint& pt = points[q];
      const auto& N = pt.shape;
      // Value-initialisation zeroes the whole record, padding included (byte-reproducible files).
      mpm::ParticleRecord& r = *::new (static_cast<void*>(&out[first + q])) mpm::ParticleRecord{};
      r.id = static_cast<std::int64_t>(first + q);
      double volume = 0, ref_volume = 0;
      if (options.volume_split == VolumeSplit::Jacobian) {
        volume = jacobian_determinant(x, pt.xi, pt.eta) * pt.w;
        ref_volume = jacobian_determinant(X, pt.xi, pt.eta) * pt.w;
      } else {
        volume = area_cur * pt.w / 4.0;
        ref_volume = area_ref * pt.w / 4.0;
      }
      r.volume = volume;
      r.mass = el.density * ref_volume;
      const Vec2 pos = N[0] * x[0] + N[1] * x[1] + N[2] * x[2] + N[3] * x[3];
      const Vec2 dis = N[0] * u[0] + N[1] * u[1] + N[2] * u[2] + N[3] * u[3];
      const Vec2 vel = N[0] * v[0] + N[1] * v[1] + N[2] * v[2] + N[3] * v[3];
      r.coord_x = pos.x();
      r.coord_y = pos.y();
      r.displacement_x = dis.x();
      r.displacement_y = dis.y();
      r.velocity_x = vel.x();
      r.velocity_y = vel.y();
      r.nsize_x = r.nsize_y = nsize;
      const Stress6 s = interpolate(N, sig);
      r.stress_xx = s[0];
      r.stress_yy = s[1];
      r.stress_zz = s[2];
      r.tau_xy = s[3];
      r.tau_yz = s[4];
      r.tau_xz = s[5];
      r.cell_id = -1;
      r.status = 1;
      r.material_id = mat.id;
      r.nstate_vars = mat.type == MpmMaterial::Type::MohrCoulomb2D ? mohr_coulomb_state(mat, s, r.svars) : 0;
    }
  }
  return out;
}

}  // namespace bridge
