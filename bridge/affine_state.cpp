#include "bridge/affine_state.hpp"

#include <Eigen/LU>
#include <cstddef>
#include <stdexcept>

#include "bridge/quad_geometry.hpp"
#include "mpm/core/shape_functions.hpp"

namespace bridge {

std::vector<Matrix2> particle_velocity_gradients(const TransferState& state, const MappingOptions& options) {
  const int n = options.particles_per_direction;
  const GaussRule rule = gauss_legendre(n);
  const std::size_t per_element = static_cast<std::size_t>(n * n);
  const std::vector<std::size_t> slot = particle_slots(state);
  std::vector<Matrix2> out(state.elements.size() * per_element);
  constexpr double xi_a[4] = {-1, 1, 1, -1}, eta_a[4] = {-1, -1, 1, 1};
  for (std::size_t e = 0; e < state.elements.size(); ++e) {
    const TransferElement& el = state.elements[e];
    const QuadNodes x = state.current_nodes(el);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double xi = rule.points[static_cast<std::size_t>(i)], eta = rule.points[static_cast<std::size_t>(j)];
        // dN_a/dxi, dN_a/deta; J = dx/dxi (columns), dN/dx = J^-T dN/dxi.
        double dxi[4], deta[4];
        Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
        for (int a = 0; a < 4; ++a) {
          dxi[a] = 0.25 * xi_a[a] * (1 + eta_a[a] * eta);
          deta[a] = 0.25 * eta_a[a] * (1 + xi_a[a] * xi);
          J.col(0) += dxi[a] * x[a];
          J.col(1) += deta[a] * x[a];
        }
        const Eigen::Matrix2d inv_jt = J.inverse().transpose();
        Eigen::Matrix2d L = Eigen::Matrix2d::Zero();
        for (int a = 0; a < 4; ++a) {
          const Vec2 dN = inv_jt * Vec2(dxi[a], deta[a]);
          L += state.velocity[static_cast<std::size_t>(el.nodes[a])] * dN.transpose();
        }
        out[slot[e] * per_element + static_cast<std::size_t>(j * n + i)] = {L(0, 0), L(0, 1), L(1, 0), L(1, 1)};
      }
  }
  return out;
}

namespace {

/// D_p / h^2 along one axis at lattice coordinate s (units of h from the cells' origin), as mpm's
/// p2g has it: sum_a w_a (s_a - s)^2 over the particle's stencil.
template <class Shape>
double inertia(double s, double l, int cells) {
  int base = 0;
  double w[Shape::kWidth], dw[Shape::kWidth];
  Shape::eval(s, l, cells - 1, base, w, dw);
  double D = 0.0;
  for (int a = 0; a < Shape::kWidth; ++a) D += w[a] * (base + a - s) * (base + a - s);
  return D;
}

}  // namespace

std::vector<Matrix2> apic_matrices(std::span<const mpm::io::ParticleRecord> particles, std::span<const Matrix2> gradients,
                                   const GridSpec& grid) {
  if (gradients.size() != particles.size()) throw std::logic_error("apic_matrices: one gradient per particle expected");
  std::vector<Matrix2> out(particles.size());
  const double h2 = grid.h * grid.h;
  for (std::size_t k = 0; k < particles.size(); ++k) {
    const auto& p = particles[k];
    const double sx = (p.coord_x - grid.x0) / grid.h, sy = (p.coord_y - grid.y0) / grid.h;
    const double Dxx = h2 * (grid.gimp ? inertia<mpm::core::GimpShape>(sx, p.nsize_x / 4.0, grid.nx)
                                       : inertia<mpm::core::LinearShape>(sx, 0.0, grid.nx));
    const double Dyy = h2 * (grid.gimp ? inertia<mpm::core::GimpShape>(sy, p.nsize_y / 4.0, grid.ny)
                                       : inertia<mpm::core::LinearShape>(sy, 0.0, grid.ny));
    const Matrix2& L = gradients[k];
    out[k] = {L[0] * Dxx, L[1] * Dyy, L[2] * Dxx, L[3] * Dyy};  // B = L D, D diagonal
  }
  return out;
}

}  // namespace bridge
