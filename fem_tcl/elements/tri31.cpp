#include "fem_tcl/elements/tri31.hpp"

#include "fem_tcl/elements/material_state.hpp"

namespace fem::elements {

namespace {
// OpenSees' integration point (15 digits of 1/3, so N_3 = 1 - 2 x 0.333333333333333) and weight.
constexpr double kPoint = 0.333333333333333;
constexpr double kWeight = 0.5;
}  // namespace

Tri31::Tri31(int tag, std::array<domain::Node*, 3> nodes, const materials::NDMaterial& material,
             materials::PlaneType plane, double thickness, double pressure, double rho, double b1, double b2)
    : SolidElement(tag, nodes[0], nodes[1], nodes[2]), material_(material.copy_for(plane)),
      material_tag_(material.tag()), thickness_(thickness), pressure_(pressure), rho_(rho), body_(b1, b2) {
  const std::string where = "element tri31 " + std::to_string(tag);
  if (!(thickness > 0.0)) throw common::InputError(where, "expected thickness > 0");
  // Area coordinates (xi, eta) of nodes 1 and 2, N_3 = 1 - xi - eta: J = [x1 - x3, x2 - x3; y1 - y3, y2 - y3],
  // detJ = twice the signed area (Fish & Belytschko, A First Course in Finite Elements, p. 180).
  const domain::Vector2 &x1 = nodes[0]->crd, &x2 = nodes[1]->crd, &x3 = nodes[2]->crd;
  const double j00 = x1[0] - x3[0], j01 = x2[0] - x3[0], j10 = x1[1] - x3[1], j11 = x2[1] - x3[1];
  const double detJ = j00 * j11 - j01 * j10;
  if (!(detJ > 0.0))
    throw common::InputError(where, "nodes are collapsed or clockwise (detJ <= 0; give them counter-clockwise)");
  // dN/dx = inv(J)^T dN/d(xi, eta), N_1,x = J11 / detJ etc. (Cook, Malkus & Plesha, p. 169).
  dN_ << j11 / detJ, -j10 / detJ, -(j11 / detJ - j10 / detJ),  //
      -j01 / detJ, j00 / detJ, -(-j01 / detJ + j00 / detJ);
  N_ << kPoint, kPoint, 1.0 - kPoint - kPoint;
  dvol_ = detJ * thickness_ * kWeight;
  // Consistent nodal loads of the pressure on the three sides, p/2 (dy, -dx) per side end.
  if (pressure_ != 0.0) {
    const double half = pressure_ / 2.0;
    for (int a = 0; a < 3; ++a) {
      const int b = (a + 1) % 3;
      const domain::Vector2 d = nodes[b]->crd - nodes[a]->crd;
      for (int end : {a, b}) {
        pressure_load_[2 * end] += half * d[1];
        pressure_load_[2 * end + 1] += half * -d[0];
      }
    }
  }
}

void Tri31::update() {
  materials::Vector3 eps = materials::Vector3::Zero();
  for (int a = 0; a < 3; ++a) {
    const auto u = nodes()[a]->solid_disp();
    eps[0] += dN_(0, a) * u[0];
    eps[1] += dN_(1, a) * u[1];
    eps[2] += dN_(0, a) * u[1] + dN_(1, a) * u[0];
  }
  material_->set_trial_strain(eps);
}

Matrix8 Tri31::stiffness_from(bool initial) const {
  const materials::Matrix3 D = initial ? material_->initial_tangent() : material_->tangent();
  Eigen::Matrix<double, 3, 8> B = Eigen::Matrix<double, 3, 8>::Zero();
  for (int a = 0; a < 3; ++a) {
    B(0, 2 * a) = dN_(0, a);
    B(1, 2 * a + 1) = dN_(1, a);
    B(2, 2 * a) = dN_(1, a);
    B(2, 2 * a + 1) = dN_(0, a);
  }
  return dvol_ * (B.transpose() * D * B);
}

const Matrix8& Tri31::tangent_stiffness() {
  K_ = stiffness_from(false);
  return K_;
}

const Matrix8& Tri31::initial_stiffness() {
  if (!have_Ki_) {
    Ki_ = stiffness_from(true);
    have_Ki_ = true;
  }
  return Ki_;
}

const Vector8& Tri31::lumped_mass() {
  mass_.setZero();
  const double rdv = (rho_ != 0.0 ? rho_ : material_->density()) * dvol_;
  for (int a = 0; a < 3; ++a) mass_[2 * a] = mass_[2 * a + 1] = N_[a] * rdv;
  return mass_;
}

const Vector8& Tri31::resisting_force() {
  force_.setZero();
  const domain::Vector2 b = self_weight_applied() ? applied_body() : body_;
  const materials::Vector3& s = material_->stress();
  for (int a = 0; a < 3; ++a) {
    force_[2 * a] += dvol_ * (dN_(0, a) * s[0] + dN_(1, a) * s[2]);
    force_[2 * a + 1] += dvol_ * (dN_(1, a) * s[1] + dN_(0, a) * s[2]);
    force_[2 * a] -= dvol_ * N_[a] * b[0];
    force_[2 * a + 1] -= dvol_ * N_[a] * b[1];
  }
  force_ -= pressure_load_;
  force_.head(num_dofs()) -= element_load();
  return force_;
}

void Tri31::commit_state() {
  material_->commit_state();
  update_committed_tangent();
}
void Tri31::revert_to_last_commit() { material_->revert_to_last_commit(); }
void Tri31::revert_to_start() { material_->revert_to_start(); }

std::optional<std::vector<double>> Tri31::response(const std::vector<std::string>& args) {
  if (args.empty()) return std::nullopt;
  const std::string& what = args[0];
  if (what == "forces" || what == "force") {
    const Vector8& f = resisting_force();
    return std::vector<double>(f.data(), f.data() + 6);
  }
  if (what == "stress" || what == "stresses" || what == "strain" || what == "strains") {
    const materials::Vector3& v = what.rfind("stress", 0) == 0 ? material_->stress() : material_->strain();
    return std::vector<double>(v.data(), v.data() + 3);
  }
  if (what == "stressAtNodes" || what == "stressesAtNodes") {  // the one point's stress at each node
    const materials::Vector3& v = material_->stress();
    std::vector<double> out;
    for (int a = 0; a < 3; ++a) out.insert(out.end(), v.data(), v.data() + 3);
    return out;
  }
  if (what == "stress3D" || what == "fullStress") {
    const materials::Vector6 v = material_->stress_3d();
    return std::vector<double>(v.data(), v.data() + 6);
  }
  if (what == "minJacobian") return std::vector<double>{min_corner_jacobian()};
  if ((what == "material" || what == "integrPoint") && args.size() >= 3) {
    const auto k = common::CommandArgs::parse_integer(args[1]);
    if (!k || *k != 1) return std::nullopt;
    return material_->response(args[2]);
  }
  return std::nullopt;
}

bool Tri31::set_parameter(std::string_view name, double value) {
  const bool any = material_->set_parameter(name, value);
  if (any) have_Ki_ = false;
  return any;
}

bool Tri31::update_material_stage(int stage) { return material_->update_stage(stage); }

bool Tri31::reduce_strength(double factor) { return reduce_material_points_strength(std::span(&material_, 1), factor); }

std::unique_ptr<domain::ElementState> Tri31::save_state() const { return save_material_points(std::span(&material_, 1)); }

void Tri31::restore_state(const domain::ElementState& state) { restore_material_points(std::span(&material_, 1), state); }

nlohmann::ordered_json Tri31::to_json() const {
  return continuum_element_json(*this, "Tri31", thickness_, pressure_, rho_, body_, material_tag_);
}

std::unique_ptr<domain::Element> parse_tri31(common::CommandArgs& args, const ElementBuildContext& ctx) {
  const int tag = args.integer("eleTag");
  std::array<int, 3> tags{};
  for (int i = 0; i < 3; ++i) tags[i] = args.integer("node tag");
  const double thick = args.number("thickness");
  const std::string type_word = args.word("type (PlaneStrain or PlaneStress)");
  const materials::PlaneType plane = parse_plane_type(args, type_word);
  const int mat = args.integer("matTag");
  // OpenSees reads the optional block only when all four values are there (and ignores a partial one,
  // which here is an error: a script that gives two of them means something).
  double p = 0.0, rho = 0.0, b1 = 0.0, b2 = 0.0;
  if (!args.empty()) {
    const std::string block = " (the optional block is: pressure rho b1 b2, all four)";
    p = args.number("pressure" + block);
    rho = args.number("rho" + block);
    b1 = args.number("b1" + block);
    b2 = args.number("b2" + block);
  }
  args.expect_end();
  std::array<domain::Node*, 3> nodes{};
  ctx.find_nodes(args, tags, nodes);
  ctx.require_dofs(args, nodes, 2);
  const auto& material = ctx.material(args, mat);
  return std::make_unique<Tri31>(tag, nodes, material, plane, thick, p, rho, b1, b2);
}

}  // namespace fem::elements
