#include "fem_tcl/elements/four_node_quad_up.hpp"

#include "common/input_error.hpp"
#include "fem_tcl/elements/material_state.hpp"

namespace fem::elements {

using domain::Matrix8;
using domain::Vector8;

FourNodeQuadUP::FourNodeQuadUP(int tag, std::array<domain::Node*, 4> nodes, const materials::NDMaterial& material,
                               double thickness, double combined_bulk, const PoreFluid& fluid, double b1, double b2,
                               double pressure)
    : UpQuad(tag, nodes, fluid, b1, b2), material_tag_(material.tag()), thickness_(thickness),
      combined_bulk_(combined_bulk), pressure_(pressure) {
  points_.emplace(nodes, material, materials::PlaneType::PlaneStrain, thickness, "element quadUP " + std::to_string(tag));
  Matrix84 Q = Matrix84::Zero();
  Eigen::Matrix4d S = Eigen::Matrix4d::Zero();
  for (const QuadGaussPoint& g : points_->points()) {
    const Eigen::Matrix<double, 1, 8> mB = quad_strain_matrix(g).topRows<2>().colwise().sum();  // m^T B
    Q.noalias() += g.dvol * (mB.transpose() * g.N.transpose());
    S.noalias() += (g.dvol / combined_bulk_) * (g.N * g.N.transpose());
  }
  set_fluid_matrices(Q, S);
  set_pressure_load();
}

void FourNodeQuadUP::form_flow_matrices(Eigen::Matrix4d& H, Eigen::Matrix<double, 4, 2>& G) const {
  H.setZero();
  G.setZero();
  for (const QuadGaussPoint& g : points_->points()) {
    H.noalias() += g.dvol * (fluid().hydraulic_x * g.dN.row(0).transpose() * g.dN.row(0) +
                             fluid().hydraulic_y * g.dN.row(1).transpose() * g.dN.row(1));
    G.noalias() += g.dvol * g.dN.transpose();
  }
}

void FourNodeQuadUP::set_pressure_load() {
  // OpenSees FourNodeQuadUP::setPressureLoadAtNodes: P t / 2 (dy, -dx) at both nodes of every side
  pressure_load_.setZero();
  const double half = pressure_ * thickness_ / 2.0;
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    const domain::Vector2 d = nodes()[j]->crd - nodes()[i]->crd;
    for (int n : {i, j}) {
      pressure_load_[2 * n] += half * d[1];
      pressure_load_[2 * n + 1] += -half * d[0];
    }
  }
}

void FourNodeQuadUP::update() { points_->update(nodes()); }

const Matrix8& FourNodeQuadUP::solid_stiffness(domain::StiffnessKind kind) {
  if (kind == domain::StiffnessKind::Current) {
    K_ = points_->stiffness(false);
    return K_;
  }
  // OpenSees getInitialStiff: from the initial tangents, kept after the first call
  if (!have_Ki_) {
    Ki_ = points_->stiffness(true);
    have_Ki_ = true;
  }
  return Ki_;
}

const Matrix8& FourNodeQuadUP::solid_mass() {
  mass_.setZero();
  const QuadGaussPoints& gp = points_->points();
  for (int g = 0; g < 4; ++g) {
    const Eigen::Matrix4d nn = (gp[g].dvol * points_->material(g).density()) * (gp[g].N * gp[g].N.transpose());
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        mass_(2 * a, 2 * b) += nn(a, b);
        mass_(2 * a + 1, 2 * b + 1) += nn(a, b);
      }
  }
  return mass_;
}

Vector8 FourNodeQuadUP::solid_force() {
  Vector8 f = Vector8::Zero();
  const domain::Vector2 b = active_body();
  const QuadGaussPoints& gp = points_->points();
  for (int g = 0; g < 4; ++g) {
    const Eigen::Vector3d& s = points_->material(g).stress();
    const double rho = points_->material(g).density();
    for (int a = 0; a < 4; ++a) {
      f[2 * a] += gp[g].dvol * (gp[g].dN(0, a) * s[0] + gp[g].dN(1, a) * s[2] - gp[g].N[a] * rho * b[0]);
      f[2 * a + 1] += gp[g].dvol * (gp[g].dN(1, a) * s[1] + gp[g].dN(0, a) * s[2] - gp[g].N[a] * rho * b[1]);
    }
  }
  return f - pressure_load_;
}

void FourNodeQuadUP::commit_state() {
  points_->commit_state();
  update_committed_tangent();
}
void FourNodeQuadUP::revert_to_last_commit() { points_->revert_to_last_commit(); }
void FourNodeQuadUP::revert_to_start() { points_->revert_to_start(); }

std::optional<std::vector<double>> FourNodeQuadUP::response(const std::vector<std::string>& args) {
  if (args.empty()) return std::nullopt;
  const std::string& name = args[0];
  if (name == "forces" || name == "force") {
    domain::ElementVector f;
    form_resisting_force(f);
    return std::vector<double>(f.data(), f.data() + f.size());
  }
  if (name == "stiff" || name == "stiffness") {
    domain::ElementMatrix k;
    form_system_matrix({}, k);
    return std::vector<double>(k.data(), k.data() + k.size());
  }
  if (name == "minJacobian") return std::vector<double>{min_corner_jacobian()};
  return points_->response(args);
}

bool FourNodeQuadUP::set_parameter(std::string_view name, double value) {
  if (set_element_parameter(name, value)) return true;
  if (name == "pressure") {
    pressure_ = value;
    set_pressure_load();
    return true;
  }
  return points_->set_parameter(name, value);
}

bool FourNodeQuadUP::update_material_stage(int stage) { return points_->update_stage(stage); }

bool FourNodeQuadUP::reduce_strength(double factor) {
  return reduce_material_points_strength(points_->materials(), factor);
}

std::unique_ptr<domain::ElementState> FourNodeQuadUP::save_state() const {
  return save_material_points(points_->materials());
}

void FourNodeQuadUP::restore_state(const domain::ElementState& state) {
  restore_material_points(points_->materials(), state);
}

nlohmann::ordered_json FourNodeQuadUP::to_json() const {
  nlohmann::ordered_json j;
  j["name"] = tag();
  j["type"] = "FourNodeQuadUP";
  j["nodes"] = {nodes()[0]->tag, nodes()[1]->tag, nodes()[2]->tag, nodes()[3]->tag};
  j["thickness"] = thickness_;
  j["surfacePressure"] = pressure_;
  j["bodyForces"] = {body_force()[0], body_force()[1]};
  j["material"] = std::to_string(material_tag_);
  // fem_tcl's additions: the pore fluid, for fem2mpm
  j["combinedBulkModulus"] = combined_bulk_;
  j["fluidDensity"] = fluid().density;
  j["permeability"] = {fluid().hydraulic_x, fluid().hydraulic_y};
  return j;
}

std::unique_ptr<domain::Element> parse_four_node_quad_up(common::CommandArgs& args, const ElementBuildContext& ctx) {
  const int tag = args.integer("eleTag");
  std::array<int, 4> tags{};
  for (int i = 0; i < 4; ++i) tags[i] = args.integer("node tag");
  const double thick = args.number("thick");
  const int mat = args.integer("matTag");
  const double bulk = args.number("bulk");
  if (!(bulk > 0.0)) args.fail("expected bulk > 0 (the combined bulk modulus of the pore fluid, Kf / n)");
  PoreFluid fluid;
  fluid.density = args.number("fmass");
  if (fluid.density < 0.0) args.fail("expected fmass >= 0 (the pore fluid's mass density)");
  fluid.hydraulic_x = read_permeability(args, "hPerm");
  fluid.hydraulic_y = read_permeability(args, "vPerm");
  // OpenSees' Tcl command reads b1, b2 and t one by one
  double b1 = 0.0, b2 = 0.0, pressure = 0.0;
  if (!args.empty()) b1 = args.number("b1");
  if (!args.empty()) b2 = args.number("b2");
  if (!args.empty()) pressure = args.number("t (surface pressure)");
  args.expect_end();
  const auto nodes = ctx.quad_nodes(args, tags);
  ctx.require_dofs(args, nodes, 3);
  const auto& material = ctx.material(args, mat);
  return std::make_unique<FourNodeQuadUP>(tag, nodes, material, thick, bulk, fluid, b1, b2, pressure);
}

}  // namespace fem::elements
