#include "fem_tcl/elements/ssp_quad.hpp"

#include <Eigen/LU>
#include <cmath>

namespace fem::elements {

namespace {
constexpr double kXi[4] = {-1.0, 1.0, 1.0, -1.0};
constexpr double kEta[4] = {-1.0, -1.0, 1.0, 1.0};
}  // namespace

SSPquad::SSPquad(int tag, std::array<domain::Node*, 4> nodes, const materials::NDMaterial& material,
                 materials::PlaneType plane, double thickness, double b1, double b2)
    : Element(tag, nodes), material_(material.copy_for(plane)), material_tag_(material.tag()),
      thickness_(thickness), body_(b1, b2) {
  const auto x = [&](int a) { return nodes[a]->crd[0]; };
  const auto y = [&](int a) { return nodes[a]->crd[1]; };
  // Jacobian determinant J = J0 + J1 xi + J2 eta (bilinear map), McGann et al. 2012, eq. 14.
  J0_ = ((x(1) - x(3)) * (y(2) - y(0)) + (x(2) - x(0)) * (y(3) - y(1))) / 8.0;
  J1_ = ((x(1) - x(0)) * (y(2) - y(3)) + (x(2) - x(3)) * (y(0) - y(1))) / 24.0;
  J2_ = ((x(0) - x(3)) * (y(2) - y(1)) + (x(2) - x(1)) * (y(3) - y(0))) / 24.0;
  // The map is one-to-one iff J > 0 at the four corners.
  for (int i = 0; i < 4; ++i) {
    if (!(J0_ + 3.0 * (J1_ * kXi[i] + J2_ * kEta[i]) > 0.0) || !(J0_ > 0.0)) {
      throw common::InputError("element SSPquad " + std::to_string(tag),
                               "nodes are collapsed, clockwise or form a non-convex quadrilateral "
                               "(give them counter-clockwise)");
    }
  }
  if (!(thickness > 0.0)) throw common::InputError("element SSPquad " + std::to_string(tag), "expected thickness > 0");
  compute_stabilization();
  refresh_mass();
}

void SSPquad::refresh_mass() {
  const double rho = material_->density();
  for (int i = 0; i < 4; ++i) {
    mass_[2 * i] = mass_[2 * i + 1] = rho * thickness_ * (J0_ + J1_ * kXi[i] + J2_ * kEta[i]);
  }
}

void SSPquad::compute_stabilization() {
  Eigen::Matrix<double, 2, 4> X;
  for (int a = 0; a < 4; ++a) X.col(a) = nodes()[a]->crd;
  Eigen::Matrix<double, 4, 2> dN_local;
  dN_local << -0.25, -0.25, 0.25, -0.25, 0.25, 0.25, -0.25, 0.25;
  const Eigen::Matrix2d J = X * dN_local;
  const Eigen::Matrix2d Jinv = J.inverse();
  const Eigen::Matrix<double, 4, 2> dN = dN_local * Jinv;
  // Hourglass vector gamma = (h - (h.x) b_x - (h.y) b_y) / 4, h = (1, -1, 1, -1) (paper eq. 22).
  const double h[4] = {1.0, -1.0, 1.0, -1.0};
  const double hx = X(0, 0) - X(0, 1) + X(0, 2) - X(0, 3);
  const double hy = X(1, 0) - X(1, 1) + X(1, 2) - X(1, 3);
  Eigen::Matrix<double, 2, 8> Mben = Eigen::Matrix<double, 2, 8>::Zero();
  B0_.setZero();
  for (int a = 0; a < 4; ++a) {
    const double gamma = 0.25 * (h[a] - hx * dN(a, 0) - hy * dN(a, 1));
    gamma_[a] = gamma;
    B0_(0, 2 * a) = dN(a, 0);
    B0_(1, 2 * a + 1) = dN(a, 1);
    B0_(2, 2 * a) = dN(a, 1);
    B0_(2, 2 * a + 1) = dN(a, 0);
    Mben(0, 2 * a) = gamma;
    Mben(1, 2 * a + 1) = gamma;
  }
  // Second moment of area in the element's normalized base vectors (paper eq. 33).
  const Eigen::Vector2d g1 = J.col(0).normalized();
  const Eigen::Vector2d g2 = J.col(1).normalized();
  const Eigen::Matrix2d I = (4.0 / 3.0) * thickness_ * J0_ * (g1 * g1.transpose() + g2 * g2.transpose());
  const double Hss = 0.25 * (I(0, 0) * Jinv(1, 0) * Jinv(1, 0) + I(0, 1) * Jinv(0, 0) * Jinv(1, 0) +
                             I(1, 1) * Jinv(0, 0) * Jinv(0, 0));
  const double Htt = 0.25 * (I(0, 0) * Jinv(1, 1) * Jinv(1, 1) + I(0, 1) * Jinv(0, 1) * Jinv(1, 1) +
                             I(1, 1) * Jinv(0, 1) * Jinv(0, 1));
  const double Hst = 0.25 * (I(0, 0) * Jinv(1, 1) * Jinv(1, 0) +
                             I(0, 1) * (Jinv(1, 0) * Jinv(0, 1) + Jinv(1, 1) * Jinv(0, 0)) +
                             I(1, 1) * Jinv(0, 1) * Jinv(0, 0));
  const materials::Matrix3 C = material_->initial_tangent();
  Eigen::Matrix2d FCF;
  FCF(0, 0) = (C(0, 0) - (C(0, 1) + C(1, 0)) + C(1, 1)) * Hss;
  FCF(0, 1) = (C(0, 1) - (C(0, 0) + C(1, 1)) + C(1, 0)) * Hst;
  FCF(1, 0) = (C(1, 0) - (C(0, 0) + C(1, 1)) + C(0, 1)) * Hst;
  FCF(1, 1) = (C(1, 1) - (C(0, 1) + C(1, 0)) + C(0, 0)) * Htt;
  Kstab_ = Mben.transpose() * FCF * Mben;
  FCF_ = FCF;
  dN_ = dN;
}

void SSPquad::update() {
  // strain B0 u, with B0's structure (rows dN_x, dN_y and the shear row)
  materials::Vector3 strain = materials::Vector3::Zero();
  for (int a = 0; a < 4; ++a) {
    const domain::Vector2& u = nodes()[a]->disp;
    strain[0] += dN_(a, 0) * u[0];
    strain[1] += dN_(a, 1) * u[1];
    strain[2] += dN_(a, 1) * u[0] + dN_(a, 0) * u[1];
  }
  material_->set_trial_strain(strain);
}

const Matrix8& SSPquad::tangent_stiffness() {
  K_.noalias() = Kstab_;
  K_.noalias() += (4.0 * J0_ * thickness_) * (B0_.transpose() * material_->tangent() * B0_);
  return K_;
}

const Matrix8& SSPquad::elastic_stiffness() {
  // Kstab is fixed at construction; rebuild only when the material's initial tangent changed.
  const materials::Matrix3 C = material_->initial_tangent();
  if (!elastic_valid_ || C != elastic_C_) {
    Kel_.noalias() = Kstab_;
    Kel_.noalias() += (4.0 * J0_ * thickness_) * (B0_.transpose() * C * B0_);
    elastic_C_ = C;
    elastic_valid_ = true;
  }
  return Kel_;
}

const Vector8& SSPquad::lumped_mass() { return mass_; }

const Vector8& SSPquad::resisting_force() {
  // Kstab u = Mben^T (FCF (Mben u)) and 4 J0 t B0^T sigma, each with its matrix's structure
  Eigen::Vector2d hourglass = Eigen::Vector2d::Zero();
  for (int a = 0; a < 4; ++a) hourglass += gamma_[a] * nodes()[a]->disp;
  const Eigen::Vector2d q = FCF_ * hourglass;
  const materials::Vector3 s = (4.0 * thickness_ * J0_) * material_->stress();
  const domain::Vector2 b = self_weight_applied() ? applied_body() : body_;
  for (int a = 0; a < 4; ++a) {
    const double w = thickness_ * (J0_ + J1_ * kXi[a] + J2_ * kEta[a]);
    force_[2 * a] = gamma_[a] * q[0] + dN_(a, 0) * s[0] + dN_(a, 1) * s[2] - b[0] * w;
    force_[2 * a + 1] = gamma_[a] * q[1] + dN_(a, 1) * s[1] + dN_(a, 0) * s[2] - b[1] * w;
  }
  force_ -= element_load();
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
