#pragma once
// The 2-dof-per-node element protocol (OpenSees Element, in this project's style): trial / commit /
// revert, tangent, initial stiffness, damping tangent, lumped mass, resisting force, element loads and
// Rayleigh damping. Up to 4 nodes: continuum quads use all 4 (counter-clockwise), triangles (Tri31) the
// first 3, two-node elements (zeroLength) the first 2, and their matrices and vectors fill the leading
// 2 x num_nodes() dofs of the fixed 8-dof storage (the rest stays zero). Dof order (u1x u1y u2x u2y u3x
// u3y u4x u4y).
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "fem_tcl/domain/node.hpp"

namespace fem::domain {

using Vector8 = Eigen::Matrix<double, 8, 1>;
using Matrix8 = Eigen::Matrix<double, 8, 8>;

/// Rayleigh damping factors: C = alphaM M + betaK K(current) + betaK0 K(initial) + betaKc K(last commit).
struct RayleighFactors {
  double alpha_m = 0.0;
  double beta_k = 0.0;
  double beta_k0 = 0.0;
  double beta_kc = 0.0;
  bool any() const { return alpha_m != 0.0 || beta_k != 0.0 || beta_k0 != 0.0 || beta_kc != 0.0; }
};

/// An element's saved state (its materials' trial and committed states), opaque to the domain.
struct ElementState {
  virtual ~ElementState() = default;
};

class Element {
 public:
  Element(int tag, std::array<Node*, 4> nodes) : tag_(tag), nodes_(nodes) {}
  /// A two-node element (the last two node slots stay empty).
  Element(int tag, Node* i, Node* j) : tag_(tag), nodes_{i, j, nullptr, nullptr}, num_nodes_(2) {}
  /// A three-node element (the last node slot stays empty).
  Element(int tag, Node* i, Node* j, Node* k) : tag_(tag), nodes_{i, j, k, nullptr}, num_nodes_(3) {}
  virtual ~Element() = default;

  int tag() const { return tag_; }
  /// The node slots; only the first num_nodes() are set.
  const std::array<Node*, 4>& nodes() const { return nodes_; }
  int num_nodes() const { return num_nodes_; }
  /// A continuum element, quad or triangle (mesh-quality measures apply), as opposed to a zero-length spring.
  bool is_continuum() const { return num_nodes_ >= 3; }
  virtual std::string type_name() const = 0;

  /// Sets the materials' trial strains from the nodes' trial displacements.
  virtual void update() = 0;
  virtual const Matrix8& tangent_stiffness() = 0;
  virtual const Matrix8& initial_stiffness() = 0;
  /// Stiffness from the materials' initial (elastic) tangents (fem_tcl's `-elasticTangent` algorithms); the
  /// same as initial_stiffness() except where that follows an OpenSees quirk (SSPquad: current tangent).
  virtual const Matrix8& elastic_stiffness() { return initial_stiffness(); }
  /// The element's own damping tangent d(resisting force)/d(velocity), without Rayleigh terms (OpenSees
  /// getDamp of elements whose materials are rate dependent, e.g. zeroLength with a Viscous material);
  /// nullptr when the element has none.
  virtual const Matrix8* damping_tangent() { return nullptr; }
  /// Whether elastic_stiffness(), initial_stiffness(), damping_tangent() and lumped_mass() change only
  /// through commands (setParameter, updateMaterialStage, ...), not with the state: lets an analysis that
  /// iterates on the elastic matrix keep it between steps (Analysis::form_tangent). False unless said.
  virtual bool linear_terms_fixed() const { return false; }
  /// Whether the `rayleigh` factors apply to this element (zeroLength: only with -doRayleigh 1).
  virtual bool rayleigh_damped() const { return true; }
  /// Diagonal of the lumped mass matrix.
  virtual const Vector8& lumped_mass() = 0;
  /// Internal force minus body forces minus element loads (OpenSees getResistingForce), no inertia/damping.
  virtual const Vector8& resisting_force() = 0;
  virtual void commit_state() = 0;
  virtual void revert_to_last_commit() = 0;
  virtual void revert_to_start() = 0;

  /// Element loads (Domain::applyLoad zeroes them, then patterns add).
  virtual void zero_load() { load_.setZero(); self_weight_applied_ = false; applied_body_.setZero(); }
  /// `eleLoad -type -selfWeight xf yf`: replaces the always-on body force by factor*(xf b1, yf b2).
  void add_self_weight(double factor, double xf, double yf) {
    self_weight_applied_ = true;
    applied_body_[0] += factor * xf * body_force()[0];
    applied_body_[1] += factor * yf * body_force()[1];
  }
  /// Adds -M * (ground acceleration) to the element load vector (UniformExcitation, relative formulation).
  void add_inertia_load(const Vector2& ground_accel) {
    const Vector8& m = lumped_mass();
    for (int i = 0; i < 8; ++i) load_[i] -= m[i] * ground_accel[i % 2];
  }
  virtual Vector2 body_force() const = 0;

  /// `rayleigh` command: stores the factors; betaKc takes the tangent of this moment (OpenSees Element).
  void set_rayleigh(const RayleighFactors& f) {
    rayleigh_ = rayleigh_damped() ? f : RayleighFactors{};
    if (f.beta_kc != 0.0) committed_tangent_ = tangent_stiffness();
  }
  const RayleighFactors& rayleigh() const { return rayleigh_; }
  const Matrix8& committed_tangent() const { return committed_tangent_; }
  /// Called by commit_state of derived classes: Kc <- converged tangent (quirk 8).
  void update_committed_tangent() {
    if (rayleigh_.beta_kc != 0.0) committed_tangent_ = tangent_stiffness();
  }

  /// Element response by name, e.g. {"stress"}, {"stresses"}, {"forces"}, {"material","3","stress"};
  /// nullopt when unknown.
  virtual std::optional<std::vector<double>> response(const std::vector<std::string>& args) = 0;
  /// `setParameter` forwarded to the materials; false when no material knows `name`.
  virtual bool set_parameter(std::string_view name, double value) = 0;
  virtual bool update_material_stage(int stage) = 0;
  /// Sets the strength reduction factor of every material point whose material has a reducible strength
  /// (materials/reducible_strength.hpp); false when the element's material has none.
  virtual bool reduce_strength(double factor) = 0;
  /// A copy of the material states, and putting it back (`strengthReduction` tries and undoes).
  virtual std::unique_ptr<ElementState> save_state() const = 0;
  virtual void restore_state(const ElementState& state) = 0;
  /// Tag of the nDMaterial the element was built from.
  virtual int material_tag() const = 0;
  virtual nlohmann::ordered_json to_json() const = 0;

  /// Minimum over the corners of the element map's Jacobian determinant in the current configuration
  /// (coordinates + trial displacements): at corner a, (x_{a+1} - x_a) x (x_{a-1} - x_a), times 1/4 for
  /// the bilinear quad (natural coordinates in [-1, 1]); a triangle's is twice its area at every corner.
  /// Non-positive means the element is inverted or degenerate (mesh distortion monitor).
  double min_corner_jacobian() const {
    const int n = num_nodes_;
    const double scale = n == 4 ? 0.25 : 1.0;
    double m = 0.0;
    for (int a = 0; a < n; ++a) {
      const Vector2 xa = nodes_[a]->crd + nodes_[a]->disp;
      const Vector2 e1 = nodes_[(a + 1) % n]->crd + nodes_[(a + 1) % n]->disp - xa;
      const Vector2 e2 = nodes_[(a + n - 1) % n]->crd + nodes_[(a + n - 1) % n]->disp - xa;
      const double det = scale * (e1[0] * e2[1] - e1[1] * e2[0]);
      m = a == 0 ? det : std::min(m, det);
    }
    return m;
  }

  /// Minimum over the corners of det J(current) / det J(reference configuration): 1 for a rigid motion,
  /// <= 0 once a corner is inverted. A degenerate reference corner (det J = 0) gives -infinity.
  double min_corner_jacobian_ratio() const {
    const int n = num_nodes_;
    double m = 0.0;
    for (int a = 0; a < n; ++a) {
      const int b = (a + 1) % n, c = (a + n - 1) % n;
      const Vector2 r1 = nodes_[b]->crd - nodes_[a]->crd, r2 = nodes_[c]->crd - nodes_[a]->crd;
      const Vector2 e1 = r1 + nodes_[b]->disp - nodes_[a]->disp, e2 = r2 + nodes_[c]->disp - nodes_[a]->disp;
      const double ref = r1[0] * r2[1] - r1[1] * r2[0];
      const double cur = e1[0] * e2[1] - e1[1] * e2[0];
      const double ratio = ref > 0.0 ? cur / ref : -std::numeric_limits<double>::infinity();
      m = a == 0 ? ratio : std::min(m, ratio);
    }
    return m;
  }

  /// Element displacement vector from the nodes' trial displacements.
  Vector8 trial_displacement() const {
    Vector8 u = Vector8::Zero();
    for (int i = 0; i < num_nodes_; ++i) { u[2 * i] = nodes_[i]->disp[0]; u[2 * i + 1] = nodes_[i]->disp[1]; }
    return u;
  }
  Vector8 trial_velocity() const {
    Vector8 v = Vector8::Zero();
    for (int i = 0; i < num_nodes_; ++i) { v[2 * i] = nodes_[i]->vel[0]; v[2 * i + 1] = nodes_[i]->vel[1]; }
    return v;
  }

 protected:
  bool self_weight_applied() const { return self_weight_applied_; }
  const Vector2& applied_body() const { return applied_body_; }
  const Vector8& element_load() const { return load_; }

 private:
  int tag_;
  std::array<Node*, 4> nodes_;
  int num_nodes_ = 4;
  Vector8 load_ = Vector8::Zero();
  bool self_weight_applied_ = false;
  Vector2 applied_body_ = Vector2::Zero();
  RayleighFactors rayleigh_;
  Matrix8 committed_tangent_ = Matrix8::Zero();
};

}  // namespace fem::domain
