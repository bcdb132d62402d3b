#pragma once
// What the two u-p quadrilaterals (SSPquadUP, FourNodeQuadUP) share: the coupled solid-fluid system of a
// saturated porous medium in the u-p approximation (Zienkiewicz & Shiomi 1984, "Dynamic behaviour of
// saturated porous media; the generalized Biot formulation and its numerical solution", Int. J. Numer. Anal.
// Meth. Geomech. 8, 71-96, eqs. 13-14 with the fluid acceleration neglected), as OpenSees assembles it.
// Each node carries (ux, uy, p) and the integrator carries p as the *velocity* of dof 3, so that with
// x = (u, P), P-dot = p, the element's contribution is M x'' + C x' + f(u) = f_ext with
//
//   K = [Ks 0; 0 0],   C = [Cs  -Q; -Q^T  -H],   M = [Ms 0; 0 -S],   Cs = alphaM Ms + betaK Ks + ...
//
//   Ks the solid's tangent, Ms its mass (mixture density), Q = int B^T m N dV the coupling (m = (1 1 0)),
//   H = int grad N k grad N^T dV the permeability (k = hydraulic conductivity / unit weight of water),
//   S = int N (n / Kf) N dV the storage of the compressible pore fluid (plus the element's stabilization).
// The signs make the system symmetric (OpenSees' FourNodeQuadUP::getDamp / getMass, SSPquadUP::getDamp /
// getMass). The resisting force (OpenSees getResistingForce) is the solid's internal force minus the mixture's
// body force and surface loads, and at the p dofs minus rho_f int grad N^T k b dV (the flow gravity drives);
// the unbalance of a transient step adds M a + C v. Rayleigh damping applies to the solid block only.
// p is compression positive (a pore pressure); the material's stress is effective (tension positive).
#include <Eigen/Core>
#include <array>
#include <string>
#include <string_view>

#include "common/command_args.hpp"
#include "fem_tcl/domain/element.hpp"

namespace fem::elements {

using Matrix84 = Eigen::Matrix<double, 8, 4>;

/// The pore fluid and the flow of one u-p element.
struct PoreFluid {
  double hydraulic_x = 0;  ///< k1 (hPerm): hydraulic conductivity / unit weight of water in x (m/s / (kN/m3))
  double hydraulic_y = 0;  ///< k2 (vPerm): the same in y
  double density = 0;      ///< rho_f (fDen, fmass): the fluid's mass density, for the gravity term of the flow
};

class UpQuad : public domain::Element {
 public:
  UpQuad(int tag, std::array<domain::Node*, 4> nodes, const PoreFluid& fluid, double b1, double b2);

  void form_system_matrix(const domain::SystemWeights& w, domain::ElementMatrix& out) override;
  void form_unbalance(bool transient, domain::ElementVector& out) override;
  void form_resisting_force(domain::ElementVector& out) override;
  /// The solid mass's diagonal (row sums of a consistent mass) at the solid dofs, zero at the p dofs.
  void form_lumped_mass(domain::ElementVector& out) override;
  /// -Ms ag at the solid dofs, with the element's full solid mass (OpenSees addInertiaLoadToUnbalance).
  void add_inertia_load(const domain::Vector2& ground_accel) override;
  domain::Vector2 body_force() const override { return body_; }
  void set_rayleigh(const domain::RayleighFactors& f) override;

  /// hPerm / xPerm, vPerm / yPerm (the permeabilities, > 0), b1, b2; false for other names (the caller then
  /// tries the material).
  bool set_element_parameter(std::string_view name, double value);
  const PoreFluid& fluid() const { return fluid_; }

  // The blocks, for tests and the responses.
  const Matrix84& coupling() const { return Q_; }
  const Eigen::Matrix4d& permeability() const { return H_; }
  const Eigen::Matrix4d& storage() const { return S_; }

 protected:
  /// Ks of the solid for `kind` (current tangent, initial, elastic).
  virtual const domain::Matrix8& solid_stiffness(domain::StiffnessKind kind) = 0;
  /// Ms (8 x 8; diagonal for a lumped mass).
  virtual const domain::Matrix8& solid_mass() = 0;
  /// The solid's internal force minus body forces and surface loads (8 values, u1x u1y .. u4y).
  virtual domain::Vector8 solid_force() = 0;
  /// H of the current permeabilities, and G = int grad N dV (4 x 2) for the flow's gravity term; called at
  /// construction (by the derived class, once its geometry is set) and when a permeability changes.
  virtual void form_flow_matrices(Eigen::Matrix4d& H, Eigen::Matrix<double, 4, 2>& G) const = 0;
  /// Sets Q and S (the derived class, once at construction) and H, G.
  void set_fluid_matrices(const Matrix84& Q, const Eigen::Matrix4d& S);
  /// The body force in force now: b, or the self-weight of the load patterns (eleLoad -selfWeight).
  domain::Vector2 active_body() const { return self_weight_applied() ? applied_body() : body_; }
  void set_body(int direction, double value) { body_[direction] = value; }
  /// Called by the derived commit_state: Kc <- the converged solid tangent (betaKc).
  void update_committed_tangent();

  /// Full index of solid dof i (0..7) and of node a's pressure.
  static constexpr int u_dof(int i) { return 3 * (i / 2) + i % 2; }
  static constexpr int p_dof(int a) { return 3 * a + 2; }

 private:
  /// The solid's damping Cs (Rayleigh).
  domain::Matrix8 solid_damping();

  PoreFluid fluid_;
  domain::Vector2 body_;
  Matrix84 Q_ = Matrix84::Zero();
  Eigen::Matrix4d H_ = Eigen::Matrix4d::Zero();
  Eigen::Matrix4d S_ = Eigen::Matrix4d::Zero();
  Eigen::Matrix<double, 4, 2> G_ = Eigen::Matrix<double, 4, 2>::Zero();
  domain::Matrix8 Kc_ = domain::Matrix8::Zero();
};

/// Reads a permeability argument of a u-p element: finite and > 0 (a NaN, a zero or a negative value is an
/// error naming `what`).
double read_permeability(common::CommandArgs& args, std::string_view what);

}  // namespace fem::elements
