// APIC's initial matrices written by fem2mpm (bridge/affine_state.hpp): the FEM velocity gradient at each
// particle, and B_p = L_p D_p with APIC's inertia tensor of the MPM grid (Jiang et al. 2015, D_p =
// sum_i w_ip (x_i - x_p)(x_i - x_p)^T).
#include <gtest/gtest.h>

#include <cmath>

#include "bridge/affine_state.hpp"
#include "support/tolerance.hpp"

namespace {

using Vec2 = bridge::Vec2;

/// Two distorted quads (materials 1, 0: the particles of element 1 come first) under the affine
/// velocity field v(x) = v0 + L x, L = [[0.3, -0.7], [0.5, -0.1]] (1/s).
bridge::TransferState affine_field_state() {
  bridge::TransferState s;
  s.reference = {{0, 0}, {1.2, 0.1}, {2.1, -0.1}, {-0.1, 0.9}, {1.0, 1.1}, {2.0, 1.0}};
  s.displacement.assign(6, Vec2(0.05, -0.02));
  for (const auto& x : s.reference) {
    const Vec2 c = x + Vec2(0.05, -0.02);
    s.velocity.push_back(Vec2(0.2 + 0.3 * c.x() - 0.7 * c.y(), -0.4 + 0.5 * c.x() - 0.1 * c.y()));
  }
  s.materials.resize(2);
  s.materials[0].id = 0;
  s.materials[1].id = 1;
  bridge::TransferElement a, b;
  a.nodes = {0, 1, 4, 3};
  a.material = 1;
  b.nodes = {1, 2, 5, 4};
  b.material = 0;
  s.elements = {a, b};
  return s;
}

TEST(AffineState, VelocityGradientOfAnAffineFieldIsExactAtEveryParticle) {
  const auto state = affine_field_state();
  bridge::MappingOptions mo;
  mo.particles_per_direction = 2;
  const auto L = bridge::particle_velocity_gradients(state, mo);
  ASSERT_EQ(L.size(), 8u);
  for (const auto& g : L) {  // bilinear elements reproduce a linear field exactly, distorted or not
    EXPECT_CLOSE(g[0], 0.3, 1e-13, 0);
    EXPECT_CLOSE(g[1], -0.7, 1e-13, 0);
    EXPECT_CLOSE(g[2], 0.5, 1e-13, 0);
    EXPECT_CLOSE(g[3], -0.1, 1e-13, 0);
  }
}

TEST(AffineState, MatricesAreTheGradientTimesApicsInertiaTensor) {
  // One particle per case; L = [[1, 2], [3, 4]]; grid cells of 0.5 m from (0, 0).
  bridge::GridSpec grid;
  grid.h = 0.5;
  grid.nx = grid.ny = 8;
  mpm::ParticleRecord p{};
  p.coord_x = 1.1;   // s = 2.2: 0.2 of a cell from node 2
  p.coord_y = 0.75;  // s = 1.5: mid-cell
  p.nsize_x = p.nsize_y = 0.5;  // 4 x 4 particles per cell: lp = h / 8, l = 1/8
  const bridge::Matrix2 L = {1, 2, 3, 4};
  // uGIMP, l = 1/8: at r = 0.2 from node 2 only nodes 2 (1 - 0.2) and 3 (0.2) have weight (l < r < 1 - l):
  // D/h^2 = 0.8 * 0.04 + 0.2 * 0.64 = 0.16. At mid-cell (r = 0.5 from both): 0.25.
  grid.gimp = true;
  auto B = bridge::apic_matrices(std::span(&p, 1), std::span(&L, 1), grid)[0];
  const double dxx = 0.16 * 0.25, dyy = 0.25 * 0.25;
  EXPECT_CLOSE(B[0], 1 * dxx, 1e-15, 0);
  EXPECT_CLOSE(B[1], 2 * dyy, 1e-15, 0);
  EXPECT_CLOSE(B[2], 3 * dxx, 1e-15, 0);
  EXPECT_CLOSE(B[3], 4 * dyy, 1e-15, 0);
  // Near a node (r = 0.05 < l) uGIMP's D keeps the particle's own extent (bilinear: 0.0475): weights
  // 1 - (r^2 + l^2) / (2 l) = 0.9275 (node 2), (1 + l - 0.95)^2 / (4 l) = 0.06125 (node 3), 0.01125 (node 1):
  // D/h^2 = 0.9275 * 0.05^2 + 0.06125 * 0.95^2 + 0.01125 * 1.05^2 = 0.07.
  p.coord_x = 1.025;
  B = bridge::apic_matrices(std::span(&p, 1), std::span(&L, 1), grid)[0];
  EXPECT_CLOSE(B[0], 0.07 * 0.25, 1e-15, 0);
  // Bilinear: D/h^2 = t (1 - t): 0.16 at t = 0.2, 0 on a grid line.
  grid.gimp = false;
  p.coord_x = 1.1;
  B = bridge::apic_matrices(std::span(&p, 1), std::span(&L, 1), grid)[0];
  EXPECT_CLOSE(B[0], 0.16 * 0.25, 1e-15, 0);
  p.coord_x = 1.0;
  B = bridge::apic_matrices(std::span(&p, 1), std::span(&L, 1), grid)[0];
  EXPECT_CLOSE(B[0], 0.0, 1e-15, 0);
}

}  // namespace
