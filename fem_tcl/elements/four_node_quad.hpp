#pragma once
// FourNodeQuad (`element quad`): bilinear isoparametric quadrilateral, 2 x 2 Gauss quadrature at
// +-1/sqrt(3) in the order (-,-), (+,-), (+,+), (-,+), lumped mass (row sums of N rho detJ), as OpenSees 3.8
// SRC/element/fourNodeQuad/FourNodeQuad.cpp (Zienkiewicz & Taylor, The Finite Element Method vol. 1,
// 6th ed., ch. 9). The optional block "p rho b1 b2" gives a surface pressure (not supported), an element
// density that replaces the material's when nonzero (quirk 3), and body forces per unit volume.
#include <memory>

#include "common/command_args.hpp"
#include "fem_tcl/domain/domain.hpp"
#include "fem_tcl/elements/element_registry.hpp"
#include "fem_tcl/elements/material_state.hpp"
#include "fem_tcl/elements/quad_gauss_points.hpp"
#include "fem_tcl/materials/nd_material.hpp"

namespace fem::elements {

using domain::Matrix8;
using domain::Vector8;

class FourNodeQuad final : public domain::SolidElement {
 public:
  /// Throws common::InputError when detJ <= 0 at a Gauss point (collapsed or clockwise nodes).
  FourNodeQuad(int tag, std::array<domain::Node*, 4> nodes, const materials::NDMaterial& material,
               materials::PlaneType plane, double thickness, double pressure, double rho, double b1, double b2);

  std::string type_name() const override { return "FourNodeQuad"; }
  void update() override;
  const Matrix8& tangent_stiffness() override;
  const Matrix8& initial_stiffness() override;
  bool linear_terms_fixed() const override {
    for (int g = 0; g < 4; ++g)
      if (!points_->material(g).initial_tangent_fixed()) return false;
    return true;
  }
  const Vector8& lumped_mass() override;
  const Vector8& resisting_force() override;
  void commit_state() override;
  void revert_to_last_commit() override;
  void revert_to_start() override;
  domain::Vector2 body_force() const override { return body_; }

  std::optional<std::vector<double>> response(const std::vector<std::string>& args) override;
  bool set_parameter(std::string_view name, double value) override;
  bool update_material_stage(int stage) override;
  bool reduce_strength(double factor) override;
  std::unique_ptr<domain::ElementState> save_state() const override;
  void restore_state(const domain::ElementState& state) override;
  nlohmann::ordered_json to_json() const override;
  int material_tag() const override { return material_tag_; }

 private:
  Matrix8 stiffness_from(bool initial);

  std::optional<QuadMaterialPoints> points_;  ///< set in the constructor, after the checks of the arguments
  int material_tag_;
  double thickness_;
  double pressure_;
  double rho_;
  domain::Vector2 body_;
  Matrix8 K_ = Matrix8::Zero();
  Matrix8 Ki_ = Matrix8::Zero();
  bool have_Ki_ = false;
  Vector8 mass_ = Vector8::Zero();
  Vector8 force_ = Vector8::Zero();
};

/// `element quad tag i j k l thick PlaneStrain|PlaneStress matTag <p rho b1 b2>` (args start at the tag).
std::unique_ptr<domain::Element> parse_four_node_quad(common::CommandArgs& args, const ElementBuildContext& ctx);

}  // namespace fem::elements
