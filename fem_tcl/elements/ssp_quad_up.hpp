#pragma once
// SSPquadUP: the stabilized single-point 4-node u-p quadrilateral for saturated porous media (McGann,
// Arduino & Mackenzie-Helnwein 2012, "Stabilized single-point 4-node quadrilateral element for dynamic
// analysis of fluid saturated porous media", Acta Geotechnica 7(4):297-311; McGann, Arduino &
// Mackenzie-Helnwein 2015, "A stabilized single-point finite element formulation for three-dimensional
// dynamic analysis of saturated soils", Computers and Geotechnics 66), as OpenSees 3.8 implements it
// (SRC/element/UWelements/SSPquadUP.cpp). The solid part is SSPquad's (ssp_quad_geometry.hpp); the blocks
// of up_quad.hpp are, with V = 4 J0 t the element's area times thickness and N_a = 1/4 at the centre:
//   Q(2a + k, b) = J0 t dN_a/dx_k                       (coupling, int B^T m N dV at one point)
//   H = V dN k dN^T                                      (permeability, k = diag(k1, k2))
//   S = (V / 16) (n / Kf) 1 1^T + alpha V dN dN^T        (fluid storage, n = e / (1 + e), and the
//       [+ (V / 144) (n / Kf) h h^T, below]               stabilization of the equal-order pressure field
//                                                          that McGann et al. 2012 add; OpenSees getMass)
//   Ms = rho t J_a at node a (lumped; rho the material's density, i.e. the mixture's)
// with the flow's gravity term rho_f V dN k b and the side pressures Pup Plow Pleft Pright (OpenSees' sign:
// force P t/2 (dy, -dx) on each end node of a counter-clockwise side (dx, dy), so a positive P pulls
// outwards), applied in full from the start like the body force.
//
// The one-point storage and stabilization leave the pressure hourglass mode h = (1 -1 1 -1) of every element
// without any term (1^T h = 0 and dN^T h = 0 for any quadrilateral, and Q h = 0): wherever that mode is not
// pinned by drainage or by neighbours (a single undrained element, the cyclic simple shear test) the system
// is singular and the nodal pressures take whatever the rounding gives. fem_tcl adds the storage the exact
// (2 x 2) integration gives that mode, (n / Kf) (V / 144) h h^T (int N N^T dV has eigenvalue V / 36 along
// h / 2). It is orthogonal to every other term of the element, so a pressure field without hourglass
// components (any 1D consolidation, Terzaghi's test) is unchanged.
//
// Two differences from OpenSees 3.8, both bugs fixed in OpenSees PR #1811:
//  - OpenSees' getMass returns zero when the material's density is 0, which drops the fluid storage S too
//    (a weightless soil skeleton then has an incompressible pore fluid); here S stays.
//  - OpenSees' lower-side pressure (Plow) adds node 2's vertical force into node 1's pore-pressure dof
//    (pressureLoad(2) instead of (4)); here it goes to node 2's uy.
// Also: OpenSees' Rayleigh betaKc uses the current tangent here (getDamp); fem_tcl uses the last committed
// one, as for every other element.
#include <memory>

#include "common/command_args.hpp"
#include "fem_tcl/elements/element_registry.hpp"
#include "fem_tcl/elements/ssp_quad_geometry.hpp"
#include "fem_tcl/elements/up_quad.hpp"
#include "fem_tcl/materials/nd_material.hpp"

namespace fem::elements {

/// The side pressures of SSPquadUP (Pup Plow Pleft Pright: sides 3-4, 1-2, 4-1, 2-3).
struct SidePressures {
  double upper = 0, lower = 0, left = 0, right = 0;
};

class SSPquadUP final : public UpQuad {
 public:
  /// Throws common::InputError for a collapsed or clockwise element, or a parameter out of range.
  SSPquadUP(int tag, std::array<domain::Node*, 4> nodes, const materials::NDMaterial& material, double thickness,
            double fluid_bulk, const PoreFluid& fluid, double void_ratio, double alpha, double b1, double b2,
            const SidePressures& pressures);

  std::string type_name() const override { return "SSPquadUP"; }
  void update() override;
  void commit_state() override;
  void revert_to_last_commit() override { material_->revert_to_last_commit(); }
  void revert_to_start() override { material_->revert_to_start(); }
  bool system_matrix_fixed(const domain::SystemWeights& w) const override;

  /// stress2D3 / strain2D3 (the material's 3 components), forces (12), minJacobian; every other response is
  /// forwarded to the material (OpenSees SSPquadUP::setResponse).
  std::optional<std::vector<double>> response(const std::vector<std::string>& args) override;
  /// hPerm xPerm vPerm yPerm b1 b2, pressureUpperSide .. pressureRightSide; else the material's.
  bool set_parameter(std::string_view name, double value) override;
  bool update_material_stage(int stage) override;
  bool reduce_strength(double factor) override;
  std::unique_ptr<domain::ElementState> save_state() const override;
  void restore_state(const domain::ElementState& state) override;
  nlohmann::ordered_json to_json() const override;
  int material_tag() const override { return material_tag_; }
  const materials::NDMaterial& material() const { return *material_; }

 protected:
  const domain::Matrix8& solid_stiffness(domain::StiffnessKind kind) override;
  const domain::Matrix8& solid_mass() override;
  domain::Vector8 solid_force() override;
  void form_flow_matrices(Eigen::Matrix4d& H, Eigen::Matrix<double, 4, 2>& G) const override;

 private:
  void set_pressure_loads();

  std::unique_ptr<materials::NDMaterial> material_;
  int material_tag_;
  double thickness_;
  SspQuadGeometry geometry_;
  Eigen::Matrix2d FCF_ = Eigen::Matrix2d::Zero();
  domain::Matrix8 Kstab_ = domain::Matrix8::Zero();
  domain::Matrix8 K_ = domain::Matrix8::Zero();
  domain::Matrix8 mass_ = domain::Matrix8::Zero();
  SidePressures pressures_;
  domain::Vector8 pressure_load_ = domain::Vector8::Zero();
  double fluid_bulk_, porosity_, alpha_;
};

/// `element SSPquadUP tag i j k l matTag t fBulk fDen k1 k2 e alpha <b1 b2> <Pup Plow Pleft Pright>`
/// (args start at the tag).
std::unique_ptr<domain::Element> parse_ssp_quad_up(common::CommandArgs& args, const ElementBuildContext& ctx);

}  // namespace fem::elements
