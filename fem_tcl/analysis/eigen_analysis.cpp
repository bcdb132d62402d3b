// Analysis::eigen_modes: OpenSees' `eigen` on the model's current tangent K and lumped mass M, by subspace
// iteration (Bathe & Wilson 1972; Bathe, "Finite Element Procedures", 2nd ed. 2014, section 11.6): q
// vectors X, then repeatedly Y = K^-1 M X, the projected problem (Y^T K Y) Q = (Y^T M Y) Q Lambda solved
// densely, X = Y Q, until the n lowest eigenvalues settle. q = min(max(2n, n + 8), equations with mass),
// the starting vectors Bathe's: M's diagonal, then unit vectors at the largest M_ii / K_ii. K is factored
// once (the analysis' own solver); equations without mass carry the infinite eigenvalues and are never
// found. The shapes are M-orthonormal.
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "common/input_error.hpp"
#include "fem_tcl/analysis/analysis.hpp"

namespace fem::analysis {


Eigen::VectorXd Analysis::equation_masses() const {
  Eigen::VectorXd m = Eigen::VectorXd::Zero(neq_);
  domain::ElementVector me;
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    elements_[e]->form_lumped_mass(me);
    const ElementEquations& ids = element_eq_[e];
    for (int i = 0; i < ids.count; ++i)
      if (ids.eq[i] >= 0) m[ids.eq[i]] += me[i];
  }
  for (std::size_t n = 0; n < nodes_.size(); ++n) {
    if (!nodes_[n]->has_mass) continue;
    for (int d = 0; d < nodes_[n]->ndf; ++d)
      if (eq_[first_dof_[n] + d] >= 0) m[eq_[first_dof_[n] + d]] += nodes_[n]->mass[d];
  }
  return m;
}

EigenModes Analysis::eigen_modes(int n) {
  setup();
  // K alone: the current tangent (OpenSees' eigen), whatever the algorithm's tangent option
  const AlgorithmConfig algorithm = config_.algorithm;
  const double c1 = c1_, c2 = c2_, c3 = c3_;
  config_.algorithm.elastic_tangent = config_.algorithm.initial_tangent = false;
  c1_ = 1.0;
  c2_ = c3_ = 0.0;
  kept_.valid = false;
  struct Restore {
    Analysis& a;
    AlgorithmConfig algorithm;
    double c1, c2, c3;
    ~Restore() {
      a.config_.algorithm = algorithm;
      a.c1_ = c1;
      a.c2_ = c2;
      a.c3_ = c3;
      a.kept_.valid = false;
    }
  } restore{*this, algorithm, c1, c2, c3};
  form_tangent();  // assembles and factors K; names a dof without stiffness

  const Eigen::VectorXd m = equation_masses();
  const int massive = static_cast<int>((m.array() > 0.0).count());
  if (n > massive)
    throw common::NumericalError("eigen: " + std::to_string(n) + " modes asked, but only " + std::to_string(massive) +
                                 " free dofs carry mass (define the materials' rho, element rho or nodal mass)");
  const int q = std::min(std::max(2 * n, n + 8), massive);

  // Starting vectors: M's diagonal, then unit vectors where M_ii / K_ii is largest.
  const double* kv = solver_->matrix().valuePtr();
  std::vector<int> order(static_cast<std::size_t>(neq_));
  std::iota(order.begin(), order.end(), 0);
  const auto ratio = [&](int i) { return m[i] / std::abs(kv[diag_pos_[i]]); };
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return ratio(a) > ratio(b); });
  Eigen::MatrixXd X = Eigen::MatrixXd::Zero(neq_, q);
  X.col(0) = m;
  for (int j = 1; j < q; ++j) X(order[static_cast<std::size_t>(j - 1)], j) = 1.0;

  Eigen::VectorXd lambda_old = Eigen::VectorXd::Constant(n, std::numeric_limits<double>::infinity());
  Eigen::MatrixXd Y(neq_, q), F(neq_, q);
  Eigen::VectorXd y;
  constexpr int kMaxIterations = 500;
  constexpr double kTolerance = 1e-12;
  for (int it = 0; it < kMaxIterations; ++it) {
    F = m.asDiagonal() * X;
    for (int j = 0; j < q; ++j) {
      solver_->solve(F.col(j), y);
      Y.col(j) = y;
    }
    Eigen::MatrixXd Kr = Y.transpose() * F, Mr = Y.transpose() * (m.asDiagonal() * Y);
    Kr = 0.5 * (Kr + Kr.transpose()).eval();
    Mr = 0.5 * (Mr + Mr.transpose()).eval();
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> projected(Kr, Mr);
    if (projected.info() != Eigen::Success)
      throw common::NumericalError("eigen: the projected eigenproblem failed (the mass matrix is not positive on the "
                                   "subspace)");
    X = Y * projected.eigenvectors();
    const Eigen::VectorXd lambda = projected.eigenvalues().head(n);
    const bool settled = ((lambda - lambda_old).array().abs() <= kTolerance * lambda.array().abs()).all();
    lambda_old = lambda;
    if (settled) break;
    if (it + 1 == kMaxIterations)
      throw common::NumericalError("eigen: the " + std::to_string(n) + " lowest eigenvalues did not settle in " +
                                   std::to_string(kMaxIterations) + " subspace iterations");
  }

  EigenModes modes;
  modes.eigenvalues.assign(lambda_old.data(), lambda_old.data() + n);
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    modes.node_tags.push_back(nodes_[i]->tag);
    modes.node_first_dof.push_back(first_dof_[i]);
  }
  for (int k = 0; k < n; ++k) {
    Eigen::VectorXd shape = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(eq_.size()));
    for (std::size_t d = 0; d < eq_.size(); ++d)
      if (eq_[d] >= 0) shape[static_cast<Eigen::Index>(d)] = X(eq_[d], k);
    modes.shapes.push_back(std::move(shape));
  }
  return modes;
}

}  // namespace fem::analysis
