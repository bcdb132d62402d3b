#pragma once
// zeroLength: a two-node element of uniaxial springs / dashpots (OpenSees 3.8
// SRC/element/zeroLength/ZeroLength.cpp), in 2D with 2 dofs per node:
//   element zeroLength tag iNode jNode -mat m1 .. -dir d1 .. <-orient x1 x2 x3 <yp1 yp2 yp3>> <-doRayleigh <0|1>>
// Material k acts along local axis d_k (1 = x', 2 = y'); its "strain" is the deformation
//   e_k = t_k . (u_j - u_i - d0),  rate r_k = t_k . (v_j - v_i - v0),
// t_k = the first two direction cosines of local axis d_k (row d_k of OpenSees' transformation matrix),
// d0, v0 = the nodes' relative displacement and velocity when the element was created (OpenSees setDomain).
//   K = sum_k B_k^T E_k B_k,  f = sum_k B_k^T s_k,  B_k = [-t_k, t_k],
//   C = sum_k B_k^T eta_k B_k (materials' damping tangents; OpenSees getDamp with doRayleigh 0),
// or, with -doRayleigh 1, the Rayleigh matrix of the `rayleigh` factors and no material damping tangent
// (OpenSees' getDamp returns only the Rayleigh part then; the viscous force stays in the residual).
// 2D orientation as OpenSees: x' from -orient (3 values; yp is read but not used in 2D), y' = z cross x'.
// No mass.
#include <memory>
#include <vector>

#include "common/command_args.hpp"
#include "fem_tcl/domain/element.hpp"
#include "fem_tcl/elements/element_registry.hpp"
#include "fem_tcl/materials/uniaxial_material.hpp"

namespace fem::elements {

using domain::Matrix8;
using domain::Vector8;

class ZeroLength final : public domain::SolidElement {
 public:
  /// `dirs` 0-based local axes (0 or 1); `x_axis` the -orient x vector. Throws common::InputError for a
  /// singular orientation (x' zero or along z).
  ZeroLength(int tag, domain::Node* i, domain::Node* j, std::vector<std::unique_ptr<materials::UniaxialMaterial>> mats,
             std::vector<int> dirs, const Eigen::Vector3d& x_axis, int do_rayleigh);

  std::string type_name() const override { return "ZeroLength"; }
  void update() override;
  const Matrix8& tangent_stiffness() override;
  const Matrix8& initial_stiffness() override;
  bool linear_terms_fixed() const override {
    for (const auto& m : mats_)
      if (!m->tangents_fixed()) return false;
    return true;
  }
  const Matrix8* damping_tangent() override;
  bool rayleigh_damped() const override { return do_rayleigh_ == 1; }
  const Vector8& lumped_mass() override { return mass_; }
  const Vector8& resisting_force() override;
  void commit_state() override;
  void revert_to_last_commit() override;
  void revert_to_start() override;
  domain::Vector2 body_force() const override { return domain::Vector2::Zero(); }

  std::optional<std::vector<double>> response(const std::vector<std::string>& args) override;
  bool set_parameter(std::string_view, double) override { return false; }
  bool update_material_stage(int) override { return false; }
  bool reduce_strength(double) override { return false; }  ///< springs and dashpots have no strength
  /// The materials' trial strains and rates: Elastic and Viscous are path-independent, so these are their state.
  std::unique_ptr<domain::ElementState> save_state() const override;
  void restore_state(const domain::ElementState& state) override;
  int material_tag() const override { return -1; }  ///< no nDMaterial
  nlohmann::ordered_json to_json() const override;

 private:
  /// Sum over materials of B_k^T w_k B_k with w_k = weight(material k), into `out` (leading 4 x 4).
  template <class Weight>
  void assemble(Matrix8& out, Weight weight) const;
  Vector8 rayleigh_force();

  std::vector<std::unique_ptr<materials::UniaxialMaterial>> mats_;
  std::vector<int> dirs_;
  Eigen::Matrix3d transformation_;                 ///< rows: local x', y', z' (OpenSees transformation)
  std::vector<Eigen::Vector2d> axis_;              ///< t_k per material
  Eigen::Vector2d d0_ = Eigen::Vector2d::Zero();   ///< relative displacement at creation
  Eigen::Vector2d v0_ = Eigen::Vector2d::Zero();   ///< relative velocity at creation
  int do_rayleigh_;
  Matrix8 K_ = Matrix8::Zero();
  Matrix8 C_ = Matrix8::Zero();
  Vector8 force_ = Vector8::Zero();
  Vector8 mass_ = Vector8::Zero();
};

/// `element zeroLength tag iNode jNode -mat .. -dir .. <-orient ..> <-doRayleigh <flag>>` (args at the tag).
std::unique_ptr<domain::Element> parse_zero_length(common::CommandArgs& args, const ElementBuildContext& ctx);

}  // namespace fem::elements
