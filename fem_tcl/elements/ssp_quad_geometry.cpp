#include "fem_tcl/elements/ssp_quad_geometry.hpp"

#include <Eigen/LU>

#include "common/input_error.hpp"

namespace fem::elements {

namespace {
constexpr double kXi[4] = {-1.0, 1.0, 1.0, -1.0};
constexpr double kEta[4] = {-1.0, -1.0, 1.0, 1.0};
}  // namespace

SspQuadGeometry::SspQuadGeometry(const std::array<domain::Node*, 4>& nodes, double thickness,
                                 const std::string& where) {
  const auto x = [&](int a) { return nodes[a]->crd[0]; };
  const auto y = [&](int a) { return nodes[a]->crd[1]; };
  // Jacobian determinant J = J0 + J1 xi + J2 eta (bilinear map), McGann et al. 2012, eq. 14.
  J0 = ((x(1) - x(3)) * (y(2) - y(0)) + (x(2) - x(0)) * (y(3) - y(1))) / 8.0;
  J1 = ((x(1) - x(0)) * (y(2) - y(3)) + (x(2) - x(3)) * (y(0) - y(1))) / 24.0;
  J2 = ((x(0) - x(3)) * (y(2) - y(1)) + (x(2) - x(1)) * (y(3) - y(0))) / 24.0;
  // The map is one-to-one iff J > 0 at the four corners.
  for (int i = 0; i < 4; ++i) {
    if (!(J0 + 3.0 * (J1 * kXi[i] + J2 * kEta[i]) > 0.0) || !(J0 > 0.0)) {
      throw common::InputError(where, "nodes are collapsed, clockwise or form a non-convex quadrilateral "
                                      "(give them counter-clockwise)");
    }
  }
  if (!(thickness > 0.0)) throw common::InputError(where, "expected thickness > 0");

  Eigen::Matrix<double, 2, 4> X;
  for (int a = 0; a < 4; ++a) X.col(a) = nodes[a]->crd;
  Eigen::Matrix<double, 4, 2> dN_local;
  dN_local << -0.25, -0.25, 0.25, -0.25, 0.25, 0.25, -0.25, 0.25;
  const Eigen::Matrix2d J = X * dN_local;
  const Eigen::Matrix2d Jinv = J.inverse();
  dN = dN_local * Jinv;
  // Hourglass vector gamma = (h - (h.x) b_x - (h.y) b_y) / 4, h = (1, -1, 1, -1) (paper eq. 22).
  const double h[4] = {1.0, -1.0, 1.0, -1.0};
  const double hx = X(0, 0) - X(0, 1) + X(0, 2) - X(0, 3);
  const double hy = X(1, 0) - X(1, 1) + X(1, 2) - X(1, 3);
  for (int a = 0; a < 4; ++a) {
    gamma[a] = 0.25 * (h[a] - hx * dN(a, 0) - hy * dN(a, 1));
    B0(0, 2 * a) = dN(a, 0);
    B0(1, 2 * a + 1) = dN(a, 1);
    B0(2, 2 * a) = dN(a, 1);
    B0(2, 2 * a + 1) = dN(a, 0);
  }
  // Second moment of area in the element's normalized base vectors (paper eq. 33).
  const Eigen::Vector2d g1 = J.col(0).normalized();
  const Eigen::Vector2d g2 = J.col(1).normalized();
  const Eigen::Matrix2d I = (4.0 / 3.0) * thickness * J0 * (g1 * g1.transpose() + g2 * g2.transpose());
  Hss = 0.25 * (I(0, 0) * Jinv(1, 0) * Jinv(1, 0) + I(0, 1) * Jinv(0, 0) * Jinv(1, 0) +
                I(1, 1) * Jinv(0, 0) * Jinv(0, 0));
  Htt = 0.25 * (I(0, 0) * Jinv(1, 1) * Jinv(1, 1) + I(0, 1) * Jinv(0, 1) * Jinv(1, 1) +
                I(1, 1) * Jinv(0, 1) * Jinv(0, 1));
  Hst = 0.25 * (I(0, 0) * Jinv(1, 1) * Jinv(1, 0) + I(0, 1) * (Jinv(1, 0) * Jinv(0, 1) + Jinv(1, 1) * Jinv(0, 0)) +
                I(1, 1) * Jinv(0, 1) * Jinv(0, 0));
}

double SspQuadGeometry::nodal_jacobian(int a) const { return J0 + J1 * kXi[a] + J2 * kEta[a]; }

Eigen::Matrix2d SspQuadGeometry::stabilization_factors(const Eigen::Matrix3d& C) const {
  Eigen::Matrix2d FCF;
  FCF(0, 0) = (C(0, 0) - (C(0, 1) + C(1, 0)) + C(1, 1)) * Hss;
  FCF(0, 1) = (C(0, 1) - (C(0, 0) + C(1, 1)) + C(1, 0)) * Hst;
  FCF(1, 0) = (C(1, 0) - (C(0, 0) + C(1, 1)) + C(0, 1)) * Hst;
  FCF(1, 1) = (C(1, 1) - (C(0, 1) + C(1, 0)) + C(0, 0)) * Htt;
  return FCF;
}

Eigen::Matrix<double, 8, 8> SspQuadGeometry::stabilization_stiffness(const Eigen::Matrix2d& FCF) const {
  Eigen::Matrix<double, 2, 8> Mben = Eigen::Matrix<double, 2, 8>::Zero();
  for (int a = 0; a < 4; ++a) {
    Mben(0, 2 * a) = gamma[a];
    Mben(1, 2 * a + 1) = gamma[a];
  }
  return Mben.transpose() * FCF * Mben;
}

Eigen::Vector3d SspQuadGeometry::strain(const std::array<domain::Node*, 4>& nodes) const {
  // B0 u with B0's structure (rows dN_x, dN_y and the shear row)
  Eigen::Vector3d e = Eigen::Vector3d::Zero();
  for (int a = 0; a < 4; ++a) {
    const auto u = nodes[a]->solid_disp();
    e[0] += dN(a, 0) * u[0];
    e[1] += dN(a, 1) * u[1];
    e[2] += dN(a, 1) * u[0] + dN(a, 0) * u[1];
  }
  return e;
}

Eigen::Matrix<double, 8, 8> SspQuadGeometry::stiffness(const Eigen::Matrix<double, 8, 8>& Kstab,
                                                       const Eigen::Matrix3d& C, double thickness) const {
  Eigen::Matrix<double, 8, 8> K = Kstab;
  K.noalias() += (4.0 * J0 * thickness) * (B0.transpose() * C * B0);
  return K;
}

Eigen::Matrix<double, 8, 1> SspQuadGeometry::internal_force(const std::array<domain::Node*, 4>& nodes,
                                                            const Eigen::Matrix2d& FCF, const Eigen::Vector3d& sigma,
                                                            double thickness) const {
  Eigen::Vector2d hourglass = Eigen::Vector2d::Zero();
  for (int a = 0; a < 4; ++a) hourglass += gamma[a] * nodes[a]->solid_disp();
  const Eigen::Vector2d q = FCF * hourglass;
  const Eigen::Vector3d s = (4.0 * thickness * J0) * sigma;
  Eigen::Matrix<double, 8, 1> f;
  for (int a = 0; a < 4; ++a) {
    f[2 * a] = gamma[a] * q[0] + dN(a, 0) * s[0] + dN(a, 1) * s[2];
    f[2 * a + 1] = gamma[a] * q[1] + dN(a, 1) * s[1] + dN(a, 0) * s[2];
  }
  return f;
}

}  // namespace fem::elements
