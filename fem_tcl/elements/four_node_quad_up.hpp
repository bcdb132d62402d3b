#pragma once
// FourNodeQuadUP (`quadUP`): the bilinear 4-node u-p quadrilateral with 2 x 2 Gauss points for saturated
// porous media (Zienkiewicz & Shiomi 1984; Yang, Lu & Elgamal, the UCSD u-p elements of OpenSees), as OpenSees
// 3.8 implements it (SRC/element/UP-ucsd/FourNodeQuadUP.cpp): one material point per Gauss point, and the
// blocks of up_quad.hpp summed over the points g with weights dvol_g = det J_g t:
//   Ms = sum rho_g N N^T (consistent, in x and y), Q = sum dvol B^T m N^T, H = sum dvol (k1 dNx dNx^T +
//   k2 dNy dNy^T), S = sum dvol N N^T / B  (B = `bulk`, the combined bulk modulus of the pore fluid, Kf / n)
// with rho_g the material's density (the mixture's), the flow's gravity term rho_f sum dvol grad N k b, and a
// surface pressure on all four sides (OpenSees' `t`, the same sign as SSPquadUP's side pressures).
//
// fem_tcl's additions: the `stress`/`stresses` and `strain`/`strains` responses of the four Gauss points
// (12 values, as `quad`), which OpenSees' quadUP does not offer (its `stress` recorder writes nothing); an
// element added into displaced nodes does not take their displacement as its reference (OpenSees 3.8 stores
// it but with an indexing slip, end1InitDisp[0] twice).
#include <array>
#include <memory>

#include "common/command_args.hpp"
#include "fem_tcl/elements/element_registry.hpp"
#include "fem_tcl/elements/quad_gauss_points.hpp"
#include "fem_tcl/elements/up_quad.hpp"
#include "fem_tcl/materials/nd_material.hpp"

namespace fem::elements {

class FourNodeQuadUP final : public UpQuad {
 public:
  /// Throws common::InputError for a collapsed or clockwise element, or a parameter out of range.
  FourNodeQuadUP(int tag, std::array<domain::Node*, 4> nodes, const materials::NDMaterial& material, double thickness,
                 double combined_bulk, const PoreFluid& fluid, double b1, double b2, double pressure);

  std::string type_name() const override { return "FourNodeQuadUP"; }
  void update() override;
  void commit_state() override;
  void revert_to_last_commit() override;
  void revert_to_start() override;

  /// forces (12), stiff (144), minJacobian, and the points' (QuadMaterialPoints::response: stress/stresses and
  /// strain/strains 4 x 3, stress3D, material k <response>).
  std::optional<std::vector<double>> response(const std::vector<std::string>& args) override;
  /// hPerm xPerm vPerm yPerm b1 b2, pressure; else the materials'.
  bool set_parameter(std::string_view name, double value) override;
  bool update_material_stage(int stage) override;
  bool reduce_strength(double factor) override;
  std::unique_ptr<domain::ElementState> save_state() const override;
  void restore_state(const domain::ElementState& state) override;
  nlohmann::ordered_json to_json() const override;
  int material_tag() const override { return material_tag_; }

 protected:
  const domain::Matrix8& solid_stiffness(domain::StiffnessKind kind) override;
  const domain::Matrix8& solid_mass() override;
  domain::Vector8 solid_force() override;
  void form_flow_matrices(Eigen::Matrix4d& H, Eigen::Matrix<double, 4, 2>& G) const override;

 private:
  void set_pressure_load();

  std::optional<QuadMaterialPoints> points_;  ///< set in the constructor
  int material_tag_;
  double thickness_;
  double combined_bulk_;
  double pressure_;
  domain::Matrix8 K_ = domain::Matrix8::Zero();
  domain::Matrix8 Ki_ = domain::Matrix8::Zero();
  bool have_Ki_ = false;
  domain::Matrix8 mass_ = domain::Matrix8::Zero();
  domain::Vector8 pressure_load_ = domain::Vector8::Zero();
};

/// `element quadUP tag i j k l thick matTag bulk fmass hPerm vPerm <b1 <b2 <t>>>` (args start at the tag).
std::unique_ptr<domain::Element> parse_four_node_quad_up(common::CommandArgs& args, const ElementBuildContext& ctx);

}  // namespace fem::elements
