#include "fem_tcl/elements/up_quad.hpp"

#include <cmath>

#include "common/command_args.hpp"
#include "common/input_error.hpp"
#include "common/number_text.hpp"

namespace fem::elements {

using domain::ElementMatrix;
using domain::ElementVector;
using domain::Matrix8;
using domain::Vector8;

UpQuad::UpQuad(int tag, std::array<domain::Node*, 4> nodes, const PoreFluid& fluid, double b1, double b2)
    : Element(tag, nodes, 4, 3), fluid_(fluid), body_(b1, b2) {}

void UpQuad::set_fluid_matrices(const Matrix84& Q, const Eigen::Matrix4d& S) {
  Q_ = Q;
  S_ = S;
  form_flow_matrices(H_, G_);
}

bool UpQuad::set_element_parameter(std::string_view name, double value) {
  const std::string where = "setParameter " + std::string(name) + " (element " + type_name() + " " +
                            std::to_string(tag()) + ")";
  if (name == "hPerm" || name == "xPerm" || name == "vPerm" || name == "yPerm") {
    if (!(value > 0.0) || !std::isfinite(value)) {
      throw common::InputError(where, "expected a permeability > 0, got " + common::number_text(value, 6));
    }
    (name == "hPerm" || name == "xPerm" ? fluid_.hydraulic_x : fluid_.hydraulic_y) = value;
    form_flow_matrices(H_, G_);
    return true;
  }
  if (name == "b1" || name == "b2") {
    body_[name == "b1" ? 0 : 1] = value;
    return true;
  }
  return false;
}

Matrix8 UpQuad::solid_damping() {
  const domain::RayleighFactors& r = rayleigh();
  Matrix8 c = Matrix8::Zero();
  if (r.beta_k != 0.0) c.noalias() += r.beta_k * solid_stiffness(domain::StiffnessKind::Current);
  if (r.beta_k0 != 0.0) c.noalias() += r.beta_k0 * solid_stiffness(domain::StiffnessKind::Initial);
  if (r.beta_kc != 0.0) c.noalias() += r.beta_kc * Kc_;
  if (r.alpha_m != 0.0) c.noalias() += r.alpha_m * solid_mass();
  return c;
}

void UpQuad::form_system_matrix(const domain::SystemWeights& w, ElementMatrix& out) {
  out.setZero(12, 12);
  Matrix8 ks = w.c1 * solid_stiffness(w.stiffness);
  if (w.c3 != 0.0) ks.noalias() += w.c3 * solid_mass();
  if (w.c2 != 0.0 && rayleigh().any()) ks.noalias() += w.c2 * solid_damping();
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) out(u_dof(i), u_dof(j)) = ks(i, j);
  if (w.c2 == 0.0 && w.c3 == 0.0) return;  // static: the flow equations have no stiffness
  for (int a = 0; a < 4; ++a) {
    for (int i = 0; i < 8; ++i) {
      out(u_dof(i), p_dof(a)) = -w.c2 * Q_(i, a);
      out(p_dof(a), u_dof(i)) = -w.c2 * Q_(i, a);
    }
    for (int b = 0; b < 4; ++b) out(p_dof(a), p_dof(b)) = -w.c2 * H_(a, b) - w.c3 * S_(a, b);
  }
}

void UpQuad::form_resisting_force(ElementVector& out) {
  out.setZero(12);
  const Vector8 fs = solid_force();
  for (int i = 0; i < 8; ++i) out[u_dof(i)] = fs[i];
  // flow driven by gravity: -rho_f int grad N^T k b dV (OpenSees: added to the internal force with + sign of
  // its b, whose gravity is negative)
  const Eigen::Vector2d kb(fluid_.hydraulic_x * active_body()[0], fluid_.hydraulic_y * active_body()[1]);
  const Eigen::Vector4d fp = fluid_.density * (G_ * kb);
  for (int a = 0; a < 4; ++a) out[p_dof(a)] = fp[a];
  out -= element_load();
}

void UpQuad::form_unbalance(bool transient, ElementVector& out) {
  form_resisting_force(out);
  if (!transient) return;
  Vector8 a_u, v_u;
  Eigen::Vector4d a_p, v_p;
  for (int n = 0; n < 4; ++n) {
    const domain::Node& node = *nodes()[n];
    a_u.segment<2>(2 * n) = node.accel.head<2>();
    v_u.segment<2>(2 * n) = node.vel.head<2>();
    a_p[n] = node.accel[2];
    v_p[n] = node.vel[2];
  }
  // M a + C v, blockwise
  Vector8 fu = solid_mass() * a_u - Q_ * v_p;
  if (rayleigh().any()) fu.noalias() += solid_damping() * v_u;
  const Eigen::Vector4d fp = -(S_ * a_p) - Q_.transpose() * v_u - H_ * v_p;
  for (int i = 0; i < 8; ++i) out[u_dof(i)] += fu[i];
  for (int n = 0; n < 4; ++n) out[p_dof(n)] += fp[n];
}

void UpQuad::form_lumped_mass(ElementVector& out) {
  out.setZero(12);
  const Vector8 m = solid_mass().rowwise().sum();
  for (int i = 0; i < 8; ++i) out[u_dof(i)] = m[i];
}

void UpQuad::add_inertia_load(const domain::Vector2& ground_accel) {
  Vector8 ag;
  for (int n = 0; n < 4; ++n) ag.segment<2>(2 * n) = ground_accel;
  const Vector8 f = solid_mass() * ag;
  ElementVector& load = element_load();
  for (int i = 0; i < 8; ++i) load[u_dof(i)] -= f[i];
}

void UpQuad::set_rayleigh(const domain::RayleighFactors& f) {
  Element::set_rayleigh(f);
  if (f.beta_kc != 0.0) Kc_ = solid_stiffness(domain::StiffnessKind::Current);
}

void UpQuad::update_committed_tangent() {
  if (rayleigh().beta_kc != 0.0) Kc_ = solid_stiffness(domain::StiffnessKind::Current);
}

double read_permeability(common::CommandArgs& args, std::string_view what) {
  const double k = args.number(what);
  if (!(k > 0.0)) {
    args.fail("expected " + std::string(what) + " > 0 (hydraulic conductivity / unit weight of water), got " +
              common::number_text(k, 6));
  }
  return k;
}

}  // namespace fem::elements
