#include "fem_tcl/elements/ssp_quad.hpp"

#include <cmath>

namespace fem::elements {

SSPquad::SSPquad(int tag, std::array<domain::Node*, 4> nodes, const materials::NDMaterial& material,
                 materials::PlaneType plane, double thickness, double b1, double b2)
    : SolidElement(tag, nodes), material_(material.copy_for(plane)), material_tag_(material.tag()),
      thickness_(thickness), body_(b1, b2), geometry_(nodes, thickness, "element SSPquad " + std::to_string(tag)) {
  FCF_ = geometry_.stabilization_factors(material_->initial_tangent());
  Kstab_ = geometry_.stabilization_stiffness(FCF_);
  refresh_mass();
}

void SSPquad::refresh_mass() {
  const double rho = material_->density();
  for (int i = 0; i < 4; ++i) mass_[2 * i] = mass_[2 * i + 1] = rho * thickness_ * geometry_.nodal_jacobian(i);
}

void SSPquad::update() { material_->set_trial_strain(geometry_.strain(nodes())); }

const Matrix8& SSPquad::tangent_stiffness() {
  K_ = geometry_.stiffness(Kstab_, material_->tangent(), thickness_);
  return K_;
}

const Matrix8& SSPquad::elastic_stiffness() {
  // Kstab is fixed at construction; rebuild only when the material's initial tangent changed.
  const materials::Matrix3 C = material_->initial_tangent();
  if (!elastic_valid_ || C != elastic_C_) {
    Kel_ = geometry_.stiffness(Kstab_, C, thickness_);
    elastic_C_ = C;
    elastic_valid_ = true;
  }
  return Kel_;
}

const Vector8& SSPquad::lumped_mass() { return mass_; }

const Vector8& SSPquad::resisting_force() {
  force_ = geometry_.internal_force(nodes(), FCF_, material_->stress(), thickness_);
  const domain::Vector2 b = self_weight_applied() ? applied_body() : body_;
  for (int a = 0; a < 4; ++a) {
    const double w = geometry_.nodal_weight(a, thickness_);
    force_[2 * a] -= b[0] * w;
    force_[2 * a + 1] -= b[1] * w;
  }
  force_.head(num_dofs()) -= element_load();
  return force_;
}

void SSPquad::commit_state() {
  material_->commit_state();
  update_committed_tangent();
}

std::optional<std::vector<double>> SSPquad::response(const std::vector<std::string>& args) {
  if (args.empty()) return std::nullopt;
  if (args[0] == "forces" || args[0] == "force" || args[0] == "globalForce" || args[0] == "globalForces") {
    const Vector8& f = resisting_force();
    return std::vector<double>(f.data(), f.data() + 8);
  }
  if (args[0] == "minJacobian") return std::vector<double>{min_corner_jacobian()};
  // Every other response is forwarded to the material (OpenSees SSPquad::setResponse).
  return material_->response(args[0]);
}

nlohmann::ordered_json SSPquad::to_json() const {
  nlohmann::ordered_json j;
  j["name"] = tag();
  j["type"] = "SSPquad";
  j["nodes"] = {nodes()[0]->tag, nodes()[1]->tag, nodes()[2]->tag, nodes()[3]->tag};
  j["thickness"] = thickness_;
  j["bodyForces"] = {body_[0], body_[1]};
  j["material"] = std::to_string(material_tag_);
  return j;
}

std::unique_ptr<domain::Element> parse_ssp_quad(common::CommandArgs& args, const ElementBuildContext& ctx) {
  const int tag = args.integer("eleTag");
  std::array<int, 4> tags{};
  for (int i = 0; i < 4; ++i) tags[i] = args.integer("node tag");
  const int mat = args.integer("matTag");
  const std::string type_word = args.word("type (PlaneStrain or PlaneStress)");
  const materials::PlaneType plane = parse_plane_type(args, type_word);
  const double thick = args.number("thickness");
  double b1 = 0.0, b2 = 0.0;
  if (!args.empty()) {
    b1 = args.number("b1");
    b2 = args.number("b2");
  }
  args.expect_end();
  const auto nodes = ctx.quad_nodes(args, tags);
  ctx.require_dofs(args, nodes, 2);
  const auto& material = ctx.material(args, mat);
  return std::make_unique<SSPquad>(tag, nodes, material, plane, thick, b1, b2);
}

}  // namespace fem::elements

namespace fem::elements {

bool SSPquad::reduce_strength(double factor) {
  return reduce_material_points_strength(std::span(&material_, 1), factor);
}

std::unique_ptr<domain::ElementState> SSPquad::save_state() const {
  return save_material_points(std::span(&material_, 1));
}

void SSPquad::restore_state(const domain::ElementState& state) {
  restore_material_points(std::span(&material_, 1), state);
  refresh_mass();
}

}  // namespace fem::elements
