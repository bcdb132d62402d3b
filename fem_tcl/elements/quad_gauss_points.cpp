#include "fem_tcl/elements/quad_gauss_points.hpp"

#include <Eigen/LU>

#include "common/input_error.hpp"

namespace fem::elements {

namespace {
constexpr double kG = 0.5773502691896258;  // 1/sqrt(3)
constexpr double kPts[4][2] = {{-kG, -kG}, {kG, -kG}, {kG, kG}, {-kG, kG}};
constexpr double kXi[4] = {-1.0, 1.0, 1.0, -1.0};
constexpr double kEta[4] = {-1.0, -1.0, 1.0, 1.0};
}  // namespace

QuadGaussPoints quad_gauss_points(const std::array<domain::Node*, 4>& nodes, double thickness,
                                  const std::string& where) {
  if (!(thickness > 0.0)) throw common::InputError(where, "expected thickness > 0");
  QuadGaussPoints gp;
  for (int g = 0; g < 4; ++g) {
    const double xi = kPts[g][0], eta = kPts[g][1];
    Eigen::Matrix<double, 2, 4> dNloc;  // d N / d(xi, eta)
    Eigen::Vector4d N;
    for (int a = 0; a < 4; ++a) {
      N[a] = 0.25 * (1.0 + kXi[a] * xi) * (1.0 + kEta[a] * eta);
      dNloc(0, a) = 0.25 * kXi[a] * (1.0 + kEta[a] * eta);
      dNloc(1, a) = 0.25 * kEta[a] * (1.0 + kXi[a] * xi);
    }
    Eigen::Matrix2d J = Eigen::Matrix2d::Zero();  // J(i, j) = d x_j / d xi_i
    for (int a = 0; a < 4; ++a) {
      J(0, 0) += dNloc(0, a) * nodes[a]->crd[0];
      J(0, 1) += dNloc(0, a) * nodes[a]->crd[1];
      J(1, 0) += dNloc(1, a) * nodes[a]->crd[0];
      J(1, 1) += dNloc(1, a) * nodes[a]->crd[1];
    }
    const double detJ = J.determinant();
    if (!(detJ > 0.0)) {
      throw common::InputError(where, "nodes are collapsed, clockwise or form a non-convex quadrilateral "
                                      "(detJ <= 0 at a Gauss point; give them counter-clockwise)");
    }
    gp[g].dN = J.inverse() * dNloc;
    gp[g].N = N;
    gp[g].dvol = detJ * thickness;  // unit weights
  }
  return gp;
}

Eigen::Matrix<double, 3, 8> quad_strain_matrix(const QuadGaussPoint& g) {
  Eigen::Matrix<double, 3, 8> B = Eigen::Matrix<double, 3, 8>::Zero();
  for (int a = 0; a < 4; ++a) {
    B(0, 2 * a) = g.dN(0, a);
    B(1, 2 * a + 1) = g.dN(1, a);
    B(2, 2 * a) = g.dN(1, a);
    B(2, 2 * a + 1) = g.dN(0, a);
  }
  return B;
}

Eigen::Matrix<double, 8, 8> quad_stiffness(const QuadGaussPoints& points,
                                           const std::function<Eigen::Matrix3d(int)>& tangent) {
  Eigen::Matrix<double, 8, 8> K = Eigen::Matrix<double, 8, 8>::Zero();
  for (int g = 0; g < 4; ++g) {
    const Eigen::Matrix3d D = tangent(g);
    const Eigen::Matrix<double, 3, 8> B = quad_strain_matrix(points[g]);
    K.noalias() += points[g].dvol * (B.transpose() * D * B);
  }
  return K;
}

}  // namespace fem::elements
