#pragma once
// The kinematics of the stabilized single-point 4-node quadrilateral that SSPquad and SSPquadUP share
// (McGann, Arduino & Mackenzie-Helnwein 2012, "Stabilized single-point 4-node quadrilateral element for
// dynamic analysis of fluid saturated porous media", Acta Geotechnica 7(4):297-311; OpenSees 3.8
// SRC/element/UWelements/SSPquad.cpp and SSPquadUP.cpp):
//   J = J0 + J1 xi + J2 eta                       (the bilinear map's Jacobian determinant, eq. 14)
//   B0: the strain-displacement matrix at the centre, rows (exx, eyy, gxy), from the gradients dN
//   Kstab = Mben^T FCF Mben                       (the hourglass stiffness, eqs. 28-36, from the material's
//                                                  initial tangent C0; Mben holds the vector gamma, eq. 22)
// Node order counter-clockwise; the nodal integration weights are t (J0 + J1 xi_a + J2 eta_a).
#include <Eigen/Core>
#include <array>
#include <string>

#include "fem_tcl/domain/node.hpp"

namespace fem::elements {

struct SspQuadGeometry {
  double J0 = 0, J1 = 0, J2 = 0;
  Eigen::Matrix<double, 4, 2> dN = Eigen::Matrix<double, 4, 2>::Zero();  ///< dN_a/dx, dN_a/dy at the centre
  Eigen::Vector4d gamma = Eigen::Vector4d::Zero();                       ///< hourglass vector (eq. 22)
  Eigen::Matrix<double, 3, 8> B0 = Eigen::Matrix<double, 3, 8>::Zero();   ///< (exx eyy gxy) = B0 (u1x u1y .. u4y)
  /// The second-moment factors of eq. 33 (Hss, Htt, Hst), for FCF of any initial tangent.
  double Hss = 0, Htt = 0, Hst = 0;

  /// From the reference coordinates; throws common::InputError naming `where` (e.g. "element SSPquad 3") when
  /// the quadrilateral is collapsed, clockwise or non-convex (J <= 0 at a corner), or `thickness` <= 0.
  SspQuadGeometry(const std::array<domain::Node*, 4>& nodes, double thickness, const std::string& where);

  /// J at node a's natural coordinates, J0 + J1 xi_a + J2 eta_a.
  double nodal_jacobian(int a) const;
  /// The nodal integration weight of node a, t (J0 + J1 xi_a + J2 eta_a) (lumped mass, body forces).
  double nodal_weight(int a, double thickness) const { return thickness * nodal_jacobian(a); }
  /// FCF of eq. 36 for the initial tangent C0 (exx eyy gxy); Kstab = Mben^T FCF Mben.
  Eigen::Matrix2d stabilization_factors(const Eigen::Matrix3d& C0) const;
  /// Kstab for the factors FCF.
  Eigen::Matrix<double, 8, 8> stabilization_stiffness(const Eigen::Matrix2d& FCF) const;

  /// The centre strain (exx eyy gxy) = B0 u of the nodes' trial solid displacements.
  Eigen::Vector3d strain(const std::array<domain::Node*, 4>& nodes) const;
  /// Kstab + 4 J0 t B0^T C B0.
  Eigen::Matrix<double, 8, 8> stiffness(const Eigen::Matrix<double, 8, 8>& Kstab, const Eigen::Matrix3d& C,
                                        double thickness) const;
  /// Kstab u + 4 J0 t B0^T sigma, from the factors (Kstab u = Mben^T (FCF (Mben u))) without the dense
  /// matrices; sigma = (sxx syy sxy).
  Eigen::Matrix<double, 8, 1> internal_force(const std::array<domain::Node*, 4>& nodes, const Eigen::Matrix2d& FCF,
                                             const Eigen::Vector3d& sigma, double thickness) const;
};

}  // namespace fem::elements
