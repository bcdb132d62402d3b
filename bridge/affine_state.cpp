#include "bridge/affine_state.hpp"

#include <cstddef>
#include <stdexcept>

#include "bridge/quad_geometry.hpp"
#include "mpm/core/velocity_transfer.hpp"

namespace bridge {

std::vector<Matrix2> particle_velocity_gradients(const TransferState& state, const MappingOptions& options) {
  const int n = options.particles_per_direction;
  const GaussRule rule = gauss_legendre(n);
  const std::size_t per_element = static_cast<std::size_t>(n * n);
  const std::vector<std::size_t> slot = particle_slots(state);
  std::vector<Matrix2> out(state.elements.size() * per_element);
  for (std::size_t e = 0; e < state.elements.size(); ++e) {
    const TransferElement& el = state.elements[e];
    const QuadNodes x = state.current_nodes(el);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const auto dN = shape_function_gradients(x, rule.points[static_cast<std::size_t>(i)], rule.points[static_cast<std::size_t>(j)]);
        Eigen::Matrix2d L = Eigen::Matrix2d::Zero();
        for (int a = 0; a < 4; ++a) L += state.velocity[static_cast<std::size_t>(el.nodes[a])] * dN[a].transpose();
        out[slot[e] * per_element + static_cast<std::size_t>(j * n + i)] = {L(0, 0), L(0, 1), L(1, 0), L(1, 1)};
      }
  }
  return out;
}

std::vector<Matrix2> apic_matrices(std::span<const mpm::ParticleRecord> particles, std::span<const Matrix2> gradients,
                                   const GridSpec& grid) {
  if (gradients.size() != particles.size()) throw std::logic_error("apic_matrices: one gradient per particle expected");
  std::vector<Matrix2> out(particles.size());
  const double h2 = grid.h * grid.h;
  for (std::size_t k = 0; k < particles.size(); ++k) {
    const auto& p = particles[k];
    const double sx = (p.coord_x - grid.x0) / grid.h, sy = (p.coord_y - grid.y0) / grid.h;
    using mpm::core::apic_inertia;
    const double Dxx = h2 * (grid.gimp ? apic_inertia(mpm::core::GimpShape{}, sx, p.nsize_x / 4.0, grid.nx - 1)
                                       : apic_inertia(mpm::core::LinearShape{}, sx, 0.0, grid.nx - 1));
    const double Dyy = h2 * (grid.gimp ? apic_inertia(mpm::core::GimpShape{}, sy, p.nsize_y / 4.0, grid.ny - 1)
                                       : apic_inertia(mpm::core::LinearShape{}, sy, 0.0, grid.ny - 1));
    const Matrix2& L = gradients[k];
    out[k] = {L[0] * Dxx, L[1] * Dyy, L[2] * Dxx, L[3] * Dyy};  // B = L D, D diagonal
  }
  return out;
}

}  // namespace bridge
