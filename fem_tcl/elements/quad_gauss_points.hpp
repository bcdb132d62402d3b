#pragma once
// The 2 x 2 Gauss points of the bilinear 4-node quadrilateral that FourNodeQuad and FourNodeQuadUP share
// (OpenSees FourNodeQuad::shapeFunction, FourNodeQuadUP::shapeFunction; Zienkiewicz & Taylor, The Finite
// Element Method vol. 1, sec. 9.5): points at (+-1/sqrt 3, +-1/sqrt 3) in the order (-,-), (+,-), (+,+), (-,+),
// unit weights, shape functions N_a, their gradients dN_a/dx, dN_a/dy and dvol = det J * thickness.
#include <Eigen/Core>
#include <array>
#include <functional>
#include <string>

#include "fem_tcl/domain/node.hpp"

namespace fem::elements {

struct QuadGaussPoint {
  Eigen::Matrix<double, 2, 4> dN;  ///< dN/dx (row 0), dN/dy (row 1)
  Eigen::Vector4d N;
  double dvol;  ///< detJ * weight * thickness
};
using QuadGaussPoints = std::array<QuadGaussPoint, 4>;

/// The Gauss points of the quadrilateral `nodes` (counter-clockwise); throws common::InputError naming `where`
/// when det J <= 0 at a point (collapsed, clockwise or non-convex) or the thickness is not > 0.
QuadGaussPoints quad_gauss_points(const std::array<domain::Node*, 4>& nodes, double thickness,
                                  const std::string& where);

/// The strain-displacement matrix of point g, rows (exx, eyy, gxy), columns (u1x u1y .. u4y).
Eigen::Matrix<double, 3, 8> quad_strain_matrix(const QuadGaussPoint& g);

/// sum_g dvol_g B_g^T D_g B_g with D_g = tangent(g).
Eigen::Matrix<double, 8, 8> quad_stiffness(const QuadGaussPoints& points,
                                           const std::function<Eigen::Matrix3d(int)>& tangent);

}  // namespace fem::elements
