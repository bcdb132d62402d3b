#pragma once
// SSPquad: stabilized single-point 4-node quadrilateral (McGann, Arduino & Mackenzie-Helnwein 2012,
// "Stabilized single-point 4-node quadrilateral element for dynamic analysis of fluid saturated porous
// media", Acta Geotechnica 7(4):297-311), as implemented in OpenSees 3.8 (SRC/element/UWelements/SSPquad.cpp):
//   K = Kstab + 4 t J0 B0^T C B0,   f_int = Kstab u + 4 t J0 B0^T sigma(B0 u)
// with B0 the strain-displacement matrix at the element centre and Kstab the hourglass stiffness built
// once from the material's initial tangent (paper eqs. 28-36). Lumped mass and body-force weights are the
// nodal Jacobian terms t (J0 + J1 xi_i + J2 eta_i).
#include <memory>

#include "common/command_args.hpp"
#include "fem_tcl/domain/domain.hpp"
#include "fem_tcl/elements/element_registry.hpp"
#include "fem_tcl/elements/material_state.hpp"
#include "fem_tcl/elements/ssp_quad_geometry.hpp"
#include "fem_tcl/materials/nd_material.hpp"

namespace fem::elements {

using domain::Matrix8;
using domain::Vector8;

class SSPquad final : public domain::SolidElement {
 public:
  /// Throws common::InputError for a collapsed or clockwise element (J0 <= 0).
  SSPquad(int tag, std::array<domain::Node*, 4> nodes, const materials::NDMaterial& material,
          materials::PlaneType plane, double thickness, double b1, double b2);

  std::string type_name() const override { return "SSPquad"; }
  void update() override;
  const Matrix8& tangent_stiffness() override;
  const Matrix8& initial_stiffness() override { return tangent_stiffness(); }  // as OpenSees (quirk 8)
  /// Kstab + 4 J0 t B0^T C0 B0 with the material's initial tangent C0.
  const Matrix8& elastic_stiffness() override;
  bool linear_terms_fixed() const override { return material_->initial_tangent_fixed(); }
  const Vector8& lumped_mass() override;
  const Vector8& resisting_force() override;
  void commit_state() override;
  void revert_to_last_commit() override { material_->revert_to_last_commit(); }
  void revert_to_start() override { material_->revert_to_start(); }
  domain::Vector2 body_force() const override { return body_; }

  std::optional<std::vector<double>> response(const std::vector<std::string>& args) override;
  // the lumped mass is kept (lumped_mass() is read every iteration) and refreshed wherever the
  // material's density may change (setParameter rho, a stage, a restored state)
  bool set_parameter(std::string_view name, double value) override {
    const bool known = material_->set_parameter(name, value);
    refresh_mass();
    return known;
  }
  bool update_material_stage(int stage) override {
    const bool known = material_->update_stage(stage);
    refresh_mass();
    return known;
  }
  bool reduce_strength(double factor) override;
  std::unique_ptr<domain::ElementState> save_state() const override;
  void restore_state(const domain::ElementState& state) override;
  nlohmann::ordered_json to_json() const override;
  int material_tag() const override { return material_tag_; }
  const materials::NDMaterial& material() const { return *material_; }

 private:
  void refresh_mass();

  std::unique_ptr<materials::NDMaterial> material_;
  int material_tag_;
  double thickness_;
  domain::Vector2 body_;
  // The factors of B0 and Kstab = Mben^T FCF Mben, for the products of every iteration (strain, internal
  // force) without the dense 3x8 and 8x8 matrices: B0 holds the shape-function gradients dN (x, y per
  // node), Mben the hourglass vector gamma in each direction (McGann et al. 2012, eqs. 22 and 33). They
  // and the other members read every iteration come before the 8x8 matrices (fewer cache lines per element).
  SspQuadGeometry geometry_;
  Eigen::Matrix2d FCF_ = Eigen::Matrix2d::Zero();
  Vector8 mass_ = Vector8::Zero();
  Vector8 force_ = Vector8::Zero();
  Matrix8 Kstab_ = Matrix8::Zero();
  Matrix8 K_ = Matrix8::Zero();
  Matrix8 Kel_ = Matrix8::Zero();
  materials::Matrix3 elastic_C_ = materials::Matrix3::Zero();  ///< the initial tangent Kel_ was built with
  bool elastic_valid_ = false;
};

/// `element SSPquad tag i j k l matTag PlaneStrain|PlaneStress thick <b1 b2>` (args start at the tag).
std::unique_ptr<domain::Element> parse_ssp_quad(common::CommandArgs& args, const ElementBuildContext& ctx);

}  // namespace fem::elements
