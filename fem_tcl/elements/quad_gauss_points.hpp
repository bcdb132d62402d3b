#pragma once
// The 2 x 2 Gauss points of the bilinear 4-node quadrilateral that FourNodeQuad and FourNodeQuadUP share
// (OpenSees FourNodeQuad::shapeFunction, FourNodeQuadUP::shapeFunction; Zienkiewicz & Taylor, The Finite
// Element Method vol. 1, sec. 9.5): points at (+-1/sqrt 3, +-1/sqrt 3) in the order (-,-), (+,-), (+,+), (-,+),
// unit weights, shape functions N_a, their gradients dN_a/dx, dN_a/dy and dvol = det J * thickness.
#include <Eigen/Core>
#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fem_tcl/domain/node.hpp"
#include "fem_tcl/materials/nd_material.hpp"

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

/// The four material points of a 2 x 2 quadrilateral (quad and quadUP): their materials (one copy each), the
/// strains from the nodes, the stiffness, the commit protocol, parameters and the point responses.
class QuadMaterialPoints {
 public:
  /// Copies `material` for `plane` at each point; throws common::InputError naming `where` for a bad shape.
  QuadMaterialPoints(const std::array<domain::Node*, 4>& nodes, const materials::NDMaterial& material,
                     materials::PlaneType plane, double thickness, const std::string& where);

  const QuadGaussPoints& points() const { return gp_; }
  std::array<std::unique_ptr<materials::NDMaterial>, 4>& materials() { return materials_; }
  const std::array<std::unique_ptr<materials::NDMaterial>, 4>& materials() const { return materials_; }
  const materials::NDMaterial& material(int g) const { return *materials_[static_cast<std::size_t>(g)]; }

  /// Each point's trial strain (exx eyy gxy) from the nodes' trial solid displacements.
  void update(const std::array<domain::Node*, 4>& nodes);
  /// sum dvol B^T D B with the current (or, `initial`, the initial) tangents.
  Eigen::Matrix<double, 8, 8> stiffness(bool initial) const;
  void commit_state();
  void revert_to_last_commit();
  void revert_to_start();
  /// Forwarded to every point; whether any knows `name` / has stages.
  bool set_parameter(std::string_view name, double value);
  bool update_stage(int stage);
  /// stress/stresses, strain/strains (4 x 3), stress3D/fullStress (4 x 6), material|integrPoint k <response>;
  /// nullopt otherwise.
  std::optional<std::vector<double>> response(const std::vector<std::string>& args) const;

 private:
  std::array<std::unique_ptr<materials::NDMaterial>, 4> materials_;
  QuadGaussPoints gp_;
};

}  // namespace fem::elements
