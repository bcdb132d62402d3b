#include "fem_tcl/analysis/linear_solver.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/UmfPackSupport>
#include <algorithm>
#include <cstring>

#include "common/input_error.hpp"

namespace fem::analysis {

bool solver_kind_for(std::string_view name, SolverKind& kind) {
  static constexpr std::string_view general[] = {"BandGeneral", "SparseGeneral", "UmfPack", "FullGeneral",
                                                 "SuperLU", "SparseSPD", "Mumps", "Umfpack"};
  static constexpr std::string_view spd[] = {"BandSPD", "ProfileSPD", "SparseSYM", "Cholesky"};
  for (auto g : general) {
    if (g == name) { kind = SolverKind::General; return true; }
  }
  for (auto s : spd) {
    if (s == name) { kind = SolverKind::SymmetricPositiveDefinite; return true; }
  }
  return false;
}

struct LinearSolver::Impl {
  Eigen::UmfPackLU<Eigen::SparseMatrix<double>> lu;
  Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>, Eigen::Lower> llt;
};

LinearSolver::LinearSolver(SolverKind kind) : kind_(kind), impl_(std::make_unique<Impl>()) {
  // Plain LL^T (supernodal where CHOLMOD chooses), as a banded/profile Cholesky would compute.
  impl_->llt.setMode(Eigen::CholmodSupernodalLLt);
  // No iterative refinement in UMFPACK's solve: a direct LU solve, as OpenSees' UmfPack/BandGeneral do.
  impl_->lu.umfpackControl()(UMFPACK_IRSTEP) = 0;
}
LinearSolver::~LinearSolver() = default;

void LinearSolver::set_pattern(Eigen::SparseMatrix<double> pattern) {
  A_ = std::move(pattern);
  A_.makeCompressed();
  analyzed_ = factored_ = false;
  factored_values_.clear();
}

void LinearSolver::zero_values() { std::fill(A_.valuePtr(), A_.valuePtr() + A_.nonZeros(), 0.0); }

void LinearSolver::factor() {
  const std::size_t nnz = static_cast<std::size_t>(A_.nonZeros());
  if (A_.rows() == 0) {  // every dof is constrained: nothing to factor
    factored_ = true;
    return;
  }
  if (factored_ && factored_values_.size() == nnz &&
      std::memcmp(factored_values_.data(), A_.valuePtr(), nnz * sizeof(double)) == 0) {
    return;  // same matrix as the last factorization
  }
  factored_ = false;
  if (kind_ == SolverKind::General) {
    if (!analyzed_) { impl_->lu.analyzePattern(A_); analyzed_ = true; }
    impl_->lu.factorize(A_);
    if (impl_->lu.info() != Eigen::Success) {
      throw common::NumericalError("the system matrix is singular (UMFPACK); check supports and connectivity");
    }
  } else {
    if (!analyzed_) { impl_->llt.analyzePattern(A_); analyzed_ = true; }
    impl_->llt.factorize(A_);
    if (impl_->llt.info() != Eigen::Success) {
      throw common::NumericalError(
          "the system matrix is singular or not positive definite (CHOLMOD); check supports and connectivity");
    }
  }
  factored_values_.assign(A_.valuePtr(), A_.valuePtr() + nnz);
  factored_ = true;
  ++factorizations_;
}

void LinearSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  if (A_.rows() == 0) {
    x.resize(0);
    return;
  }
  if (kind_ == SolverKind::General) x = impl_->lu.solve(b);
  else x = impl_->llt.solve(b);
  if (!x.allFinite()) throw common::NumericalError("the solution of the linear system is not finite (singular system)");
}

}  // namespace fem::analysis
