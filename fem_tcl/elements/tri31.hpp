#pragma once
// Tri31 (`element tri31`): the three-node constant-strain triangle with one integration point at the
// centroid (area coordinates 1/3, weight 1/2), lumped mass (N rho detJ / 2 at that point: a third of the
// mass per node), as OpenSees 3.8 SRC/element/triangle/Tri31.cpp (Zienkiewicz & Taylor, The Finite Element
// Method vol. 1, 6th ed., section 4.2; Cook, Malkus & Plesha, Concepts and Applications of FEA, 4th ed.,
// section 3.4). The optional block "pressure rho b1 b2" is read only when all four are given, as
// OpenSees does: a surface pressure on the three sides (consistent nodal loads, not scaled by the
// thickness, as OpenSees; positive pulls the sides outward), an element density that replaces the
// material's when nonzero, and body forces per unit volume (scaled by `eleLoad -type -selfWeight`).
#include <memory>

#include "common/command_args.hpp"
#include "fem_tcl/domain/domain.hpp"
#include "fem_tcl/elements/element_registry.hpp"
#include "fem_tcl/materials/nd_material.hpp"

namespace fem::elements {

using domain::Matrix8;
using domain::Vector8;

class Tri31 final : public domain::SolidElement {
 public:
  /// Throws common::InputError when detJ <= 0 (collapsed or clockwise nodes).
  Tri31(int tag, std::array<domain::Node*, 3> nodes, const materials::NDMaterial& material,
        materials::PlaneType plane, double thickness, double pressure, double rho, double b1, double b2);

  std::string type_name() const override { return "Tri31"; }
  void update() override;
  const Matrix8& tangent_stiffness() override;
  const Matrix8& initial_stiffness() override;
  bool linear_terms_fixed() const override { return material_->initial_tangent_fixed(); }
  const Vector8& lumped_mass() override;
  const Vector8& resisting_force() override;
  void commit_state() override;
  void revert_to_last_commit() override;
  void revert_to_start() override;
  domain::Vector2 body_force() const override { return body_; }

  /// forces (6), stress/stresses and strain/strains (3, the one point), stressAtNodes (9: the point's
  /// stress at each node, as OpenSees), stress3D, minJacobian, material 1 <response>.
  std::optional<std::vector<double>> response(const std::vector<std::string>& args) override;
  bool set_parameter(std::string_view name, double value) override;
  bool update_material_stage(int stage) override;
  bool reduce_strength(double factor) override;
  std::unique_ptr<domain::ElementState> save_state() const override;
  void restore_state(const domain::ElementState& state) override;
  nlohmann::ordered_json to_json() const override;
  int material_tag() const override { return material_tag_; }

 private:
  Matrix8 stiffness_from(bool initial) const;

  std::unique_ptr<materials::NDMaterial> material_;
  Eigen::Matrix<double, 2, 3> dN_;  ///< dN/dx (row 0), dN/dy (row 1), constant
  Eigen::Vector3d N_;               ///< at the integration point (OpenSees' 0.333333333333333)
  double dvol_;                     ///< detJ * weight * thickness
  int material_tag_;
  double thickness_;
  double pressure_;
  double rho_;
  domain::Vector2 body_;
  Vector8 pressure_load_ = Vector8::Zero();
  Matrix8 K_ = Matrix8::Zero();
  Matrix8 Ki_ = Matrix8::Zero();
  bool have_Ki_ = false;
  Vector8 mass_ = Vector8::Zero();
  Vector8 force_ = Vector8::Zero();
};

/// `element tri31 tag i j k thick PlaneStrain|PlaneStress matTag <pressure rho b1 b2>` (args start at the tag).
std::unique_ptr<domain::Element> parse_tri31(common::CommandArgs& args, const ElementBuildContext& ctx);

}  // namespace fem::elements
