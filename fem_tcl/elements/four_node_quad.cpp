#include "fem_tcl/elements/four_node_quad.hpp"

#include <Eigen/LU>
#include <cmath>

namespace fem::elements {


FourNodeQuad::FourNodeQuad(int tag, std::array<domain::Node*, 4> nodes, const materials::NDMaterial& material,
                           materials::PlaneType plane, double thickness, double pressure, double rho, double b1,
                           double b2)
    : SolidElement(tag, nodes), material_tag_(material.tag()), thickness_(thickness), pressure_(pressure), rho_(rho),
      body_(b1, b2) {
  const std::string where = "element quad " + std::to_string(tag);
  if (!(thickness > 0.0)) throw common::InputError(where, "expected thickness > 0");
  if (pressure != 0.0) throw common::InputError(where, "surface pressure p != 0 is not supported; use nodal loads");
  for (int g = 0; g < 4; ++g) materials_[g] = material.copy_for(plane);
  gp_ = quad_gauss_points(nodes, thickness_, where);
}

void FourNodeQuad::update() {
  for (int g = 0; g < 4; ++g) {
    materials::Vector3 eps = materials::Vector3::Zero();
    for (int a = 0; a < 4; ++a) {
      const auto u = nodes()[a]->solid_disp();
      eps[0] += gp_[g].dN(0, a) * u[0];
      eps[1] += gp_[g].dN(1, a) * u[1];
      eps[2] += gp_[g].dN(0, a) * u[1] + gp_[g].dN(1, a) * u[0];
    }
    materials_[g]->set_trial_strain(eps);
  }
}

Matrix8 FourNodeQuad::stiffness_from(bool initial) {
  return quad_stiffness(gp_, [&](int g) { return initial ? materials_[g]->initial_tangent() : materials_[g]->tangent(); });
}

const Matrix8& FourNodeQuad::tangent_stiffness() {
  K_ = stiffness_from(false);
  return K_;
}

const Matrix8& FourNodeQuad::initial_stiffness() {
  if (!have_Ki_) {
    Ki_ = stiffness_from(true);
    have_Ki_ = true;
  }
  return Ki_;
}

const Vector8& FourNodeQuad::lumped_mass() {
  mass_.setZero();
  for (int g = 0; g < 4; ++g) {
    const double rho = rho_ != 0.0 ? rho_ : materials_[g]->density();
    const double rdv = rho * gp_[g].dvol;
    for (int a = 0; a < 4; ++a) {
      mass_[2 * a] += gp_[g].N[a] * rdv;
      mass_[2 * a + 1] += gp_[g].N[a] * rdv;
    }
  }
  return mass_;
}

const Vector8& FourNodeQuad::resisting_force() {
  force_.setZero();
  const domain::Vector2 b = self_weight_applied() ? applied_body() : body_;
  for (int g = 0; g < 4; ++g) {
    const materials::Vector3& s = materials_[g]->stress();
    const double dv = gp_[g].dvol;
    for (int a = 0; a < 4; ++a) {
      force_[2 * a] += dv * (gp_[g].dN(0, a) * s[0] + gp_[g].dN(1, a) * s[2]);
      force_[2 * a + 1] += dv * (gp_[g].dN(1, a) * s[1] + gp_[g].dN(0, a) * s[2]);
      force_[2 * a] -= dv * gp_[g].N[a] * b[0];
      force_[2 * a + 1] -= dv * gp_[g].N[a] * b[1];
    }
  }
  force_.head(num_dofs()) -= element_load();
  return force_;
}

void FourNodeQuad::commit_state() {
  for (auto& m : materials_) m->commit_state();
  update_committed_tangent();
}
void FourNodeQuad::revert_to_last_commit() {
  for (auto& m : materials_) m->revert_to_last_commit();
}
void FourNodeQuad::revert_to_start() {
  for (auto& m : materials_) m->revert_to_start();
}

std::optional<std::vector<double>> FourNodeQuad::response(const std::vector<std::string>& args) {
  if (args.empty()) return std::nullopt;
  const std::string& what = args[0];
  if (what == "forces" || what == "force" || what == "globalForce" || what == "globalForces") {
    const Vector8& f = resisting_force();
    return std::vector<double>(f.data(), f.data() + 8);
  }
  if (what == "stress" || what == "stresses" || what == "strain" || what == "strains") {
    const bool stress = what.rfind("stress", 0) == 0;
    std::vector<double> out;
    out.reserve(12);
    for (const auto& m : materials_) {
      const materials::Vector3& v = stress ? m->stress() : m->strain();
      out.insert(out.end(), v.data(), v.data() + 3);
    }
    return out;
  }
  if (what == "minJacobian") return std::vector<double>{min_corner_jacobian()};
  if (what == "stress3D" || what == "fullStress") {  // 4 Gauss points x (sxx syy szz sxy syz sxz)
    std::vector<double> out;
    out.reserve(24);
    for (const auto& m : materials_) {
      const materials::Vector6 v = m->stress_3d();
      out.insert(out.end(), v.data(), v.data() + 6);
    }
    return out;
  }
  if ((what == "material" || what == "integrPoint") && args.size() >= 3) {
    const auto k = common::CommandArgs::parse_integer(args[1]);
    if (!k || *k < 1 || *k > 4) return std::nullopt;
    return materials_[*k - 1]->response(args[2]);
  }
  return std::nullopt;
}

bool FourNodeQuad::set_parameter(std::string_view name, double value) {
  bool any = false;
  for (auto& m : materials_) any = m->set_parameter(name, value) || any;
  if (any) have_Ki_ = false;
  return any;
}

bool FourNodeQuad::update_material_stage(int stage) {
  bool any = false;
  for (auto& m : materials_) any = m->update_stage(stage) || any;
  return any;
}

nlohmann::ordered_json FourNodeQuad::to_json() const {
  return continuum_element_json(*this, "FourNodeQuad", thickness_, pressure_, rho_, body_, material_tag_);
}

std::unique_ptr<domain::Element> parse_four_node_quad(common::CommandArgs& args, const ElementBuildContext& ctx) {
  const int tag = args.integer("eleTag");
  std::array<int, 4> tags{};
  for (int i = 0; i < 4; ++i) tags[i] = args.integer("node tag");
  const double thick = args.number("thickness");
  const std::string type_word = args.word("type (PlaneStrain or PlaneStress)");
  const materials::PlaneType plane = parse_plane_type(args, type_word);
  const int mat = args.integer("matTag");
  double p = 0.0, rho = 0.0, b1 = 0.0, b2 = 0.0;
  // OpenSees reads up to four optional numbers in the order p rho b1 b2.
  if (!args.empty()) p = args.number("p");
  if (!args.empty()) rho = args.number("rho");
  if (!args.empty()) b1 = args.number("b1");
  if (!args.empty()) b2 = args.number("b2");
  args.expect_end();
  const auto nodes = ctx.quad_nodes(args, tags);
  ctx.require_dofs(args, nodes, 2);
  const auto& material = ctx.material(args, mat);
  return std::make_unique<FourNodeQuad>(tag, nodes, material, plane, thick, p, rho, b1, b2);
}

}  // namespace fem::elements

namespace fem::elements {

bool FourNodeQuad::reduce_strength(double factor) { return reduce_material_points_strength(materials_, factor); }

std::unique_ptr<domain::ElementState> FourNodeQuad::save_state() const { return save_material_points(materials_); }

void FourNodeQuad::restore_state(const domain::ElementState& state) { restore_material_points(materials_, state); }

}  // namespace fem::elements
