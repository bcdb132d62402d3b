#pragma once
// The element protocol (OpenSees Element, in this project's style), in two layers:
//
// - Element: what the analysis, the domain and the commands need of any element: its nodes and dofs
//   (2 per node for solids, 3 for the u-p elements whose third dof is the pore pressure), the system matrix
//   c1 K + c2 C + c3 M of a step and the unbalance it works against (OpenSees' formEleTangent and
//   getResistingForceIncInertia), the resisting force (reactions), the lumped mass (eigen, ground-motion
//   inertia), trial / commit / revert, element loads, Rayleigh factors, responses and parameters.
//   Matrices and vectors are sized num_dofs() (at most 12), dofs in node order, each node's dofs together:
//   (u1x u1y [p1] u2x u2y [p2] ...).
// - SolidElement: the 2-dof-per-node solids (SSPquad, quad, tri31, zeroLength) with their fixed 8-dof
//   storage (tangent, initial and elastic stiffness, damping tangent, lumped mass, resisting force; up to 4
//   nodes, unused slots zero) from which it forms the Element protocol with the generic Rayleigh terms.
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

/// The most dofs an element has (4 nodes x (ux, uy, p)).
inline constexpr int kMaxElementDofs = 12;
/// An element matrix or vector of num_dofs() rows, without heap storage.
using ElementMatrix =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, kMaxElementDofs, kMaxElementDofs>;
using ElementVector = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxElementDofs, 1>;

/// Rayleigh damping factors: C = alphaM M + betaK K(current) + betaK0 K(initial) + betaKc K(last commit).
struct RayleighFactors {
  double alpha_m = 0.0;
  double beta_k = 0.0;
  double beta_k0 = 0.0;
  double beta_kc = 0.0;
  bool any() const { return alpha_m != 0.0 || beta_k != 0.0 || beta_k0 != 0.0 || beta_kc != 0.0; }
};

/// Which stiffness enters the system matrix (the algorithm's choice).
enum class StiffnessKind {
  Current,  ///< the current tangent (Newton)
  Initial,  ///< the initial stiffness (`algorithm Newton -initial`, OpenSees INITIAL_TANGENT)
  Elastic,  ///< the materials' initial tangents (fem_tcl's `-elasticTangent`)
};

/// The weights of a step's system matrix c1 K + c2 C + c3 M (static: 1, 0, 0) and its stiffness.
struct SystemWeights {
  double c1 = 1.0, c2 = 0.0, c3 = 0.0;
  StiffnessKind stiffness = StiffnessKind::Current;
};

/// An element's saved state (its materials' trial and committed states), opaque to the domain.
struct ElementState {
  virtual ~ElementState() = default;
};

class Element {
 public:
  /// `num_nodes` of the four node slots are used (quads 4, triangles 3, zero-length springs 2), each
  /// with `dofs_per_node` dofs (2 solids, 3 u-p).
  Element(int tag, std::array<Node*, 4> nodes, int num_nodes, int dofs_per_node)
      : tag_(tag), nodes_(nodes), num_nodes_(num_nodes), dofs_per_node_(dofs_per_node),
        load_(ElementVector::Zero(num_nodes * dofs_per_node)) {}
  virtual ~Element() = default;

  int tag() const { return tag_; }
  /// The node slots; only the first num_nodes() are set.
  const std::array<Node*, 4>& nodes() const { return nodes_; }
  int num_nodes() const { return num_nodes_; }
  int dofs_per_node() const { return dofs_per_node_; }
  int num_dofs() const { return num_nodes_ * dofs_per_node_; }
  /// A continuum element, quad or triangle (mesh-quality measures apply), as opposed to a zero-length spring.
  bool is_continuum() const { return num_nodes_ >= 3; }
  virtual std::string type_name() const = 0;

  /// Sets the materials' trial strains from the nodes' trial state.
  virtual void update() = 0;
  /// out = c1 K + c2 C + c3 M with C the damping (Rayleigh terms and the element's own) and M the mass
  /// (OpenSees TransientIntegrator::formEleTangent: addKtToTang, addCtoTang, addMtoTang).
  virtual void form_system_matrix(const SystemWeights& w, ElementMatrix& out) = 0;
  /// Whether form_system_matrix(w) with w.stiffness = Elastic changes only through commands (setParameter,
  /// updateMaterialStage, ...), not with the state: lets an analysis that iterates on the elastic matrix
  /// keep it between steps (Analysis::form_tangent). False unless said.
  virtual bool system_matrix_fixed(const SystemWeights& w) const { (void)w; return false; }
  /// The force the unbalance works against: the resisting force, plus M a + C v when `transient`
  /// (OpenSees getResistingForceIncInertia / getResistingForce).
  virtual void form_unbalance(bool transient, ElementVector& out) = 0;
  /// Internal force minus body forces minus element loads, no inertia or damping (OpenSees getResistingForce;
  /// reactions, quirk 7).
  virtual void form_resisting_force(ElementVector& out) = 0;
  /// Diagonal of the lumped mass of the solid dofs (zero at pore-pressure dofs): eigen's mass matrix and the
  /// inertia load of a ground motion.
  virtual void form_lumped_mass(ElementVector& out) = 0;
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
  /// Adds -M * (ground acceleration) to the element load vector at the solid dofs (UniformExcitation,
  /// relative formulation; OpenSees addInertiaLoadToUnbalance). Default: the lumped mass.
  virtual void add_inertia_load(const Vector2& ground_accel);
  virtual Vector2 body_force() const = 0;

  /// `rayleigh` command: stores the factors (OpenSees Element::setRayleighDampingFactors).
  virtual void set_rayleigh(const RayleighFactors& f) { rayleigh_ = rayleigh_damped() ? f : RayleighFactors{}; }
  const RayleighFactors& rayleigh() const { return rayleigh_; }
  /// Whether the `rayleigh` factors apply to this element (zeroLength: only with -doRayleigh 1).
  virtual bool rayleigh_damped() const { return true; }

  /// Element response by name, e.g. {"stress"}, {"stresses"}, {"forces"}, {"material","3","stress"};
  /// nullopt when unknown.
  virtual std::optional<std::vector<double>> response(const std::vector<std::string>& args) = 0;
  /// `setParameter` forwarded to the element and its materials; false when none knows `name`.
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
  double min_corner_jacobian() const;
  /// Minimum over the corners of det J(current) / det J(reference configuration): 1 for a rigid motion,
  /// <= 0 once a corner is inverted. A degenerate reference corner (det J = 0) gives -infinity.
  double min_corner_jacobian_ratio() const;

 protected:
  bool self_weight_applied() const { return self_weight_applied_; }
  const Vector2& applied_body() const { return applied_body_; }
  /// Element loads (inertia of a ground motion), num_dofs() entries.
  const ElementVector& element_load() const { return load_; }
  ElementVector& element_load() { return load_; }

 private:
  int tag_;
  std::array<Node*, 4> nodes_;
  int num_nodes_;
  int dofs_per_node_;
  ElementVector load_;
  bool self_weight_applied_ = false;
  Vector2 applied_body_ = Vector2::Zero();
  RayleighFactors rayleigh_;
};

/// A 2-dof-per-node solid: the 8-dof matrices of the element, and the Element protocol formed from them
/// with the Rayleigh terms of OpenSees' Element base class.
class SolidElement : public Element {
 public:
  SolidElement(int tag, std::array<Node*, 4> nodes) : Element(tag, nodes, 4, 2) {}
  /// A two-node element (the last two node slots stay empty).
  SolidElement(int tag, Node* i, Node* j) : Element(tag, {i, j, nullptr, nullptr}, 2, 2) {}
  /// A three-node element (the last node slot stays empty).
  SolidElement(int tag, Node* i, Node* j, Node* k) : Element(tag, {i, j, k, nullptr}, 3, 2) {}

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
  /// through commands (setParameter, updateMaterialStage, ...), not with the state. False unless said.
  virtual bool linear_terms_fixed() const { return false; }
  /// Diagonal of the lumped mass matrix.
  virtual const Vector8& lumped_mass() = 0;
  /// Internal force minus body forces minus element loads (OpenSees getResistingForce), no inertia/damping.
  virtual const Vector8& resisting_force() = 0;

  void form_system_matrix(const SystemWeights& w, ElementMatrix& out) override;
  bool system_matrix_fixed(const SystemWeights& w) const override;
  void form_unbalance(bool transient, ElementVector& out) override;
  void form_resisting_force(ElementVector& out) override;
  void form_lumped_mass(ElementVector& out) override;

  /// Stores the factors; betaKc takes the tangent of this moment (OpenSees Element).
  void set_rayleigh(const RayleighFactors& f) override {
    Element::set_rayleigh(f);
    if (f.beta_kc != 0.0) committed_tangent_ = tangent_stiffness();
  }
  const Matrix8& committed_tangent() const { return committed_tangent_; }

  /// Element displacement and velocity vectors from the nodes' trial state.
  Vector8 trial_displacement() const;
  Vector8 trial_velocity() const;

 protected:
  /// Called by commit_state of derived classes: Kc <- converged tangent (quirk 8).
  void update_committed_tangent() {
    if (rayleigh().beta_kc != 0.0) committed_tangent_ = tangent_stiffness();
  }

 private:
  Matrix8 committed_tangent_ = Matrix8::Zero();
};

}  // namespace fem::domain
