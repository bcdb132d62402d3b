#include "fem_tcl/elements/ssp_quad_up.hpp"

#include <cmath>

#include "common/input_error.hpp"
#include "fem_tcl/elements/material_state.hpp"

namespace fem::elements {

using domain::Matrix8;
using domain::Vector8;

SSPquadUP::SSPquadUP(int tag, std::array<domain::Node*, 4> nodes, const materials::NDMaterial& material,
                     double thickness, double fluid_bulk, const PoreFluid& fluid, double void_ratio, double alpha,
                     double b1, double b2, const SidePressures& pressures)
    : UpQuad(tag, nodes, fluid, b1, b2), material_(material.copy_for(materials::PlaneType::PlaneStrain)),
      material_tag_(material.tag()), thickness_(thickness),
      geometry_(nodes, thickness, "element SSPquadUP " + std::to_string(tag)), pressures_(pressures),
      fluid_bulk_(fluid_bulk), porosity_(void_ratio / (1.0 + void_ratio)), alpha_(alpha) {
  FCF_ = geometry_.stabilization_factors(material_->initial_tangent());
  Kstab_ = geometry_.stabilization_stiffness(FCF_);
  const double V = 4.0 * geometry_.J0 * thickness_;
  Matrix84 Q;
  for (int b = 0; b < 4; ++b) Q.col(b) = (0.25 * V) * geometry_.B0.topRows<2>().colwise().sum().transpose();
  // OpenSees' one-point storage and pressure stabilization, plus (fem_tcl) the exactly integrated storage of
  // the pressure hourglass mode h = (1 -1 1 -1), which they leave without any term (see the header)
  const Eigen::Vector4d h(1.0, -1.0, 1.0, -1.0);
  const double storage = porosity_ / fluid_bulk_;
  const Eigen::Matrix4d S = (V / 16.0) * storage * Eigen::Matrix4d::Ones() +
                            (alpha_ * V) * (geometry_.dN * geometry_.dN.transpose()) +
                            (V / 144.0) * storage * (h * h.transpose());
  set_fluid_matrices(Q, S);
  set_pressure_loads();
}

void SSPquadUP::form_flow_matrices(Eigen::Matrix4d& H, Eigen::Matrix<double, 4, 2>& G) const {
  const double V = 4.0 * geometry_.J0 * thickness_;
  const Eigen::Vector2d k(fluid().hydraulic_x, fluid().hydraulic_y);
  H = V * (geometry_.dN * k.asDiagonal() * geometry_.dN.transpose());
  G = V * geometry_.dN;
}

void SSPquadUP::set_pressure_loads() {
  // OpenSees SSPquadUP::setPressureLoadAtNodes: on side (i, j) of direction (dx, dy), P t / 2 (dy, -dx) at
  // both nodes; the sides are 1-2 (lower), 2-3 (right), 3-4 (upper), 4-1 (left).
  pressure_load_.setZero();
  const double side_pressure[4] = {pressures_.lower, pressures_.right, pressures_.upper, pressures_.left};
  for (int side = 0; side < 4; ++side) {
    const int i = side, j = (side + 1) % 4;
    const domain::Vector2 d = nodes()[j]->crd - nodes()[i]->crd;
    const double half = side_pressure[side] * thickness_ / 2.0;
    for (int n : {i, j}) {
      pressure_load_[2 * n] += half * d[1];
      pressure_load_[2 * n + 1] += -half * d[0];
    }
  }
}

void SSPquadUP::update() { material_->set_trial_strain(geometry_.strain(nodes())); }

const Matrix8& SSPquadUP::solid_stiffness(domain::StiffnessKind kind) {
  // OpenSees' getInitialStiff returns the current tangent (as SSPquad's, quirk 8)
  K_ = geometry_.stiffness(
      Kstab_, kind == domain::StiffnessKind::Elastic ? material_->initial_tangent() : material_->tangent(), thickness_);
  return K_;
}

bool SSPquadUP::system_matrix_fixed(const domain::SystemWeights& w) const {
  const domain::RayleighFactors& r = rayleigh();
  return w.stiffness == domain::StiffnessKind::Elastic && material_->initial_tangent_fixed() &&
         (w.c2 == 0.0 || (r.beta_k == 0.0 && r.beta_k0 == 0.0 && r.beta_kc == 0.0));
}

const Matrix8& SSPquadUP::solid_mass() {
  const double rho = material_->density();
  mass_.setZero();
  for (int a = 0; a < 4; ++a) mass_(2 * a, 2 * a) = mass_(2 * a + 1, 2 * a + 1) = rho * thickness_ * geometry_.nodal_jacobian(a);
  return mass_;
}

Vector8 SSPquadUP::solid_force() {
  Vector8 f = geometry_.internal_force(nodes(), FCF_, material_->stress(), thickness_);
  const double rho = material_->density();
  const domain::Vector2 b = active_body();
  for (int a = 0; a < 4; ++a) {
    const double w = rho * geometry_.nodal_weight(a, thickness_);
    f[2 * a] -= b[0] * w;
    f[2 * a + 1] -= b[1] * w;
  }
  return f - pressure_load_;
}

void SSPquadUP::commit_state() {
  material_->commit_state();
  update_committed_tangent();
}

std::optional<std::vector<double>> SSPquadUP::response(const std::vector<std::string>& args) {
  if (args.empty()) return std::nullopt;
  const std::string& name = args[0];
  if (name == "stress2D3") return std::vector<double>(material_->stress().data(), material_->stress().data() + 3);
  if (name == "strain2D3") return std::vector<double>(material_->strain().data(), material_->strain().data() + 3);
  if (name == "forces" || name == "force") {
    domain::ElementVector f;
    form_resisting_force(f);
    return std::vector<double>(f.data(), f.data() + f.size());
  }
  if (name == "minJacobian") return std::vector<double>{min_corner_jacobian()};
  // Every other response is forwarded to the material (OpenSees SSPquadUP::setResponse).
  return material_->response(name);
}

bool SSPquadUP::set_parameter(std::string_view name, double value) {
  if (set_element_parameter(name, value)) return true;
  double* side = name == "pressureUpperSide"   ? &pressures_.upper
                 : name == "pressureLowerSide" ? &pressures_.lower
                 : name == "pressureLeftSide"  ? &pressures_.left
                 : name == "pressureRightSide" ? &pressures_.right
                                               : nullptr;
  if (side != nullptr) {
    *side = value;
    set_pressure_loads();
    return true;
  }
  return material_->set_parameter(name, value);
}

bool SSPquadUP::update_material_stage(int stage) { return material_->update_stage(stage); }

bool SSPquadUP::reduce_strength(double factor) {
  return reduce_material_points_strength(std::span(&material_, 1), factor);
}

std::unique_ptr<domain::ElementState> SSPquadUP::save_state() const {
  return save_material_points(std::span(&material_, 1));
}

void SSPquadUP::restore_state(const domain::ElementState& state) {
  restore_material_points(std::span(&material_, 1), state);
}

nlohmann::ordered_json SSPquadUP::to_json() const {
  nlohmann::ordered_json j;
  j["name"] = tag();
  j["type"] = "SSPquadUP";
  j["nodes"] = {nodes()[0]->tag, nodes()[1]->tag, nodes()[2]->tag, nodes()[3]->tag};
  j["thickness"] = thickness_;
  j["bodyForces"] = {body_force()[0], body_force()[1]};
  j["material"] = std::to_string(material_tag_);
  // fem_tcl's additions (OpenSees 3.8 prints only the keys above): the pore fluid, for fem2mpm
  j["fluidBulkModulus"] = fluid_bulk_;
  j["fluidDensity"] = fluid().density;
  j["permeability"] = {fluid().hydraulic_x, fluid().hydraulic_y};
  j["porosity"] = porosity_;
  return j;
}

std::unique_ptr<domain::Element> parse_ssp_quad_up(common::CommandArgs& args, const ElementBuildContext& ctx) {
  // OpenSees reads 13, 15 or 19 arguments (and ignores any other optional count silently): here another
  // count is an error.
  const std::size_t count = args.remaining();
  if (count != 13 && count != 15 && count != 19) {
    args.fail("expected 13 arguments, 15 with b1 b2, or 19 with b1 b2 Pup Plow Pleft Pright; got " +
              std::to_string(count));
  }
  const int tag = args.integer("eleTag");
  std::array<int, 4> tags{};
  for (int i = 0; i < 4; ++i) tags[i] = args.integer("node tag");
  const int mat = args.integer("matTag");
  const double thick = args.number("t");
  const double fluid_bulk = args.number("fBulk");
  if (!(fluid_bulk > 0.0)) args.fail("expected fBulk > 0 (the pore fluid's bulk modulus)");
  PoreFluid fluid;
  fluid.density = args.number("fDen");
  if (fluid.density < 0.0) args.fail("expected fDen >= 0 (the pore fluid's mass density)");
  fluid.hydraulic_x = read_permeability(args, "k1");
  fluid.hydraulic_y = read_permeability(args, "k2");
  const double e = args.number("e");
  if (!(e > 0.0)) args.fail("expected e > 0 (the void ratio)");
  const double alpha = args.number("alpha");
  if (alpha < 0.0) args.fail("expected alpha >= 0 (the pressure stabilization parameter)");
  double b1 = 0.0, b2 = 0.0;
  SidePressures p;
  if (count >= 15) {
    b1 = args.number("b1");
    b2 = args.number("b2");
  }
  if (count == 19) {
    p.upper = args.number("Pup");
    p.lower = args.number("Plow");
    p.left = args.number("Pleft");
    p.right = args.number("Pright");
  }
  args.expect_end();
  const auto nodes = ctx.quad_nodes(args, tags);
  ctx.require_dofs(args, nodes, 3);
  const auto& material = ctx.material(args, mat);
  return std::make_unique<SSPquadUP>(tag, nodes, material, thick, fluid_bulk, fluid, e, alpha, b1, b2, p);
}

}  // namespace fem::elements
