#pragma once
// The linear system A x = b of an analysis: a sparse matrix whose pattern is built once per model change,
// assembled in place (precomputed value positions, no allocation per step), factored by SuiteSparse
// UMFPACK (general) or CHOLMOD (symmetric positive definite) through Eigen's wrappers. Every OpenSees
// `system` name maps onto one of the two (FORMATS.md section 1); the symbolic analysis is reused and the
// numeric factorization is skipped when the assembled values did not change (e.g. linear elastic steps).
// A general system whose values are symmetric up to round-off (1e-14 of max|A|) is first offered to
// CHOLMOD's LL^T (about twice as fast as LU with this machine's reference BLAS) unless a diagonal entry is
// not positive (a u-p system: symmetric indefinite); when that fails (not positive definite), UMFPACK
// factors it. Both are direct solvers: the solutions agree to round-off.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace fem::analysis {

enum class SolverKind { General, SymmetricPositiveDefinite };

/// OpenSees `system` name -> solver kind; nullopt-like `false` return when the name is unknown.
bool solver_kind_for(std::string_view system_name, SolverKind& kind);

class LinearSolver {
 public:
  explicit LinearSolver(SolverKind kind);
  ~LinearSolver();
  LinearSolver(const LinearSolver&) = delete;
  LinearSolver& operator=(const LinearSolver&) = delete;

  /// Sets the sparsity pattern (column-compressed, values zero); invalidates the factorization.
  void set_pattern(Eigen::SparseMatrix<double> pattern);
  Eigen::SparseMatrix<double>& matrix() { return A_; }
  void zero_values();
  /// Factors A unless its values equal those of the last factorization.
  /// Throws common::NumericalError when A is singular (or not positive definite for CHOLMOD).
  void factor();
  /// x = A^-1 b with the current factorization; throws common::NumericalError on a non-finite result.
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x);
  long factorizations() const { return factorizations_; }

 private:
  struct Impl;
  bool values_symmetric() const;
  /// Every diagonal entry present and > 0 (necessary for LL^T).
  bool diagonal_positive() const;
  bool try_cholesky();
  /// SPD systems: the lower triangle set to the transpose of the upper one (OpenSees assembles only that).
  void mirror_upper_triangle();
  void factor_lu();
  SolverKind kind_;
  Eigen::SparseMatrix<double> A_;
  std::vector<double> factored_values_;
  std::vector<int> transpose_position_;  ///< value index of (j, i) for the value at (i, j)
  bool use_cholesky_ = false;            ///< the current factorization is CHOLMOD's
  bool analyzed_lu_ = false;
  bool analyzed_llt_ = false;
  bool factored_ = false;
  long factorizations_ = 0;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fem::analysis
