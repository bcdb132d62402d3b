#include "fem_tcl/domain/element.hpp"

namespace fem::domain {

void Element::add_inertia_load(const Vector2& ground_accel) {
  ElementVector m;
  form_lumped_mass(m);
  const int n = num_dofs();
  for (int i = 0; i < n; ++i) {
    const int d = i % dofs_per_node_;
    if (d < 2) load_[i] -= m[i] * ground_accel[d];
  }
}

double Element::min_corner_jacobian() const {
  const int n = num_nodes_;
  const double scale = n == 4 ? 0.25 : 1.0;
  double m = 0.0;
  const auto x = [&](int a) -> Vector2 { return nodes_[a]->crd + nodes_[a]->solid_disp(); };
  for (int a = 0; a < n; ++a) {
    const Vector2 xa = x(a);
    const Vector2 e1 = x((a + 1) % n) - xa;
    const Vector2 e2 = x((a + n - 1) % n) - xa;
    const double det = scale * (e1[0] * e2[1] - e1[1] * e2[0]);
    m = a == 0 ? det : std::min(m, det);
  }
  return m;
}

double Element::min_corner_jacobian_ratio() const {
  const int n = num_nodes_;
  double m = 0.0;
  for (int a = 0; a < n; ++a) {
    const int b = (a + 1) % n, c = (a + n - 1) % n;
    const Vector2 r1 = nodes_[b]->crd - nodes_[a]->crd, r2 = nodes_[c]->crd - nodes_[a]->crd;
    const Vector2 e1 = r1 + nodes_[b]->solid_disp() - nodes_[a]->solid_disp();
    const Vector2 e2 = r2 + nodes_[c]->solid_disp() - nodes_[a]->solid_disp();
    const double ref = r1[0] * r2[1] - r1[1] * r2[0];
    const double cur = e1[0] * e2[1] - e1[1] * e2[0];
    const double ratio = ref > 0.0 ? cur / ref : -std::numeric_limits<double>::infinity();
    m = a == 0 ? ratio : std::min(m, ratio);
  }
  return m;
}

void SolidElement::form_system_matrix(const SystemWeights& w, ElementMatrix& out) {
  Matrix8 ke;
  ke.noalias() = w.c1 * (w.stiffness == StiffnessKind::Elastic   ? elastic_stiffness()
                         : w.stiffness == StiffnessKind::Initial ? initial_stiffness()
                                                                 : tangent_stiffness());
  if (w.c2 != 0.0 || w.c3 != 0.0) {
    const RayleighFactors& f = rayleigh();
    if (w.c2 != 0.0) {
      if (f.beta_k != 0.0) ke.noalias() += (w.c2 * f.beta_k) * tangent_stiffness();
      if (f.beta_k0 != 0.0) ke.noalias() += (w.c2 * f.beta_k0) * initial_stiffness();
      if (f.beta_kc != 0.0) ke.noalias() += (w.c2 * f.beta_kc) * committed_tangent();
    }
    const double cm = w.c3 + w.c2 * f.alpha_m;
    if (cm != 0.0) ke.diagonal() += cm * lumped_mass();
    // rate-dependent materials (zeroLength + Viscous): OpenSees getDamp
    if (w.c2 != 0.0) {
      if (const Matrix8* c = damping_tangent()) ke.noalias() += w.c2 * *c;
    }
  }
  const int n = num_dofs();
  out = ke.topLeftCorner(n, n);
}

bool SolidElement::system_matrix_fixed(const SystemWeights& w) const {
  const RayleighFactors& f = rayleigh();
  return linear_terms_fixed() && (w.c2 == 0.0 || (f.beta_k == 0.0 && f.beta_kc == 0.0));
}

void SolidElement::form_unbalance(bool transient, ElementVector& out) {
  Vector8 f = resisting_force();
  if (transient) {
    const Vector8& m = lumped_mass();
    Vector8 a = Vector8::Zero();
    for (int i = 0; i < num_nodes(); ++i) a.segment<2>(2 * i) = nodes()[i]->accel.head<2>();
    f += m.cwiseProduct(a);
    const RayleighFactors& rf = rayleigh();
    if (rf.any()) {
      const Vector8 v = trial_velocity();
      if (rf.alpha_m != 0.0) f += rf.alpha_m * m.cwiseProduct(v);
      if (rf.beta_k != 0.0) f.noalias() += rf.beta_k * (tangent_stiffness() * v);
      if (rf.beta_k0 != 0.0) f.noalias() += rf.beta_k0 * (initial_stiffness() * v);
      if (rf.beta_kc != 0.0) f.noalias() += rf.beta_kc * (committed_tangent() * v);
    }
  }
  out = f.head(num_dofs());
}

void SolidElement::form_resisting_force(ElementVector& out) { out = resisting_force().head(num_dofs()); }

void SolidElement::form_lumped_mass(ElementVector& out) { out = lumped_mass().head(num_dofs()); }

Vector8 SolidElement::trial_displacement() const {
  Vector8 u = Vector8::Zero();
  for (int i = 0; i < num_nodes(); ++i) u.segment<2>(2 * i) = nodes()[i]->disp.head<2>();
  return u;
}

Vector8 SolidElement::trial_velocity() const {
  Vector8 v = Vector8::Zero();
  for (int i = 0; i < num_nodes(); ++i) v.segment<2>(2 * i) = nodes()[i]->vel.head<2>();
  return v;
}

}  // namespace fem::domain
