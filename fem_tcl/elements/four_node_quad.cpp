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
  points_.emplace(nodes, material, plane, thickness_, where);
}

void FourNodeQuad::update() { points_->update(nodes()); }

Matrix8 FourNodeQuad::stiffness_from(bool initial) { return points_->stiffness(initial); }

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
  const QuadGaussPoints& gp = points_->points();
  for (int g = 0; g < 4; ++g) {
    const double rho = rho_ != 0.0 ? rho_ : points_->material(g).density();
    const double rdv = rho * gp[g].dvol;
    for (int a = 0; a < 4; ++a) {
      mass_[2 * a] += gp[g].N[a] * rdv;
      mass_[2 * a + 1] += gp[g].N[a] * rdv;
    }
  }
  return mass_;
}

const Vector8& FourNodeQuad::resisting_force() {
  force_.setZero();
  const domain::Vector2 b = self_weight_applied() ? applied_body() : body_;
  const QuadGaussPoints& gp = points_->points();
  for (int g = 0; g < 4; ++g) {
    const materials::Vector3& s = points_->material(g).stress();
    const double dv = gp[g].dvol;
    for (int a = 0; a < 4; ++a) {
      force_[2 * a] += dv * (gp[g].dN(0, a) * s[0] + gp[g].dN(1, a) * s[2]);
      force_[2 * a + 1] += dv * (gp[g].dN(1, a) * s[1] + gp[g].dN(0, a) * s[2]);
      force_[2 * a] -= dv * gp[g].N[a] * b[0];
      force_[2 * a + 1] -= dv * gp[g].N[a] * b[1];
    }
  }
  force_.head(num_dofs()) -= element_load();
  return force_;
}

void FourNodeQuad::commit_state() {
  points_->commit_state();
  update_committed_tangent();
}
void FourNodeQuad::revert_to_last_commit() { points_->revert_to_last_commit(); }
void FourNodeQuad::revert_to_start() { points_->revert_to_start(); }

std::optional<std::vector<double>> FourNodeQuad::response(const std::vector<std::string>& args) {
  if (args.empty()) return std::nullopt;
  const std::string& what = args[0];
  if (what == "forces" || what == "force" || what == "globalForce" || what == "globalForces") {
    const Vector8& f = resisting_force();
    return std::vector<double>(f.data(), f.data() + 8);
  }
  if (what == "minJacobian") return std::vector<double>{min_corner_jacobian()};
  return points_->response(args);
}

bool FourNodeQuad::set_parameter(std::string_view name, double value) {
  const bool any = points_->set_parameter(name, value);
  if (any) have_Ki_ = false;
  return any;
}

bool FourNodeQuad::update_material_stage(int stage) { return points_->update_stage(stage); }

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

bool FourNodeQuad::reduce_strength(double factor) {
  return reduce_material_points_strength(points_->materials(), factor);
}

std::unique_ptr<domain::ElementState> FourNodeQuad::save_state() const {
  return save_material_points(points_->materials());
}

void FourNodeQuad::restore_state(const domain::ElementState& state) {
  restore_material_points(points_->materials(), state);
}

}  // namespace fem::elements
