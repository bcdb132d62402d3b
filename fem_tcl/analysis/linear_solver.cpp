#include "fem_tcl/analysis/linear_solver.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/UmfPackSupport>
#include <algorithm>
#include <cmath>
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

namespace {
/// Eigen's CHOLMOD wrapper with its factor reachable, for cholmod_solve2 (reused workspace, see solve).
struct Cholmod : Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>, Eigen::Lower> {
  cholmod_factor* factor() { return m_cholmodFactor; }
};
}  // namespace

struct LinearSolver::Impl {
  Eigen::UmfPackLU<Eigen::SparseMatrix<double>> lu;
  Cholmod llt;
  // cholmod_solve2's solution and workspace, allocated by the first solve and reused (CHOLMOD resizes them)
  cholmod_dense* x = nullptr;
  cholmod_dense* y = nullptr;
  cholmod_dense* e = nullptr;
  ~Impl() {
    cholmod_free_dense(&x, &llt.cholmod());
    cholmod_free_dense(&y, &llt.cholmod());
    cholmod_free_dense(&e, &llt.cholmod());
  }
};

LinearSolver::LinearSolver(SolverKind kind) : kind_(kind), impl_(std::make_unique<Impl>()) {
  // No iterative refinement in UMFPACK's solve: a direct LU solve, as OpenSees' UmfPack/BandGeneral do.
  impl_->lu.umfpackControl()(UMFPACK_IRSTEP) = 0;
}
LinearSolver::~LinearSolver() = default;

void LinearSolver::set_pattern(Eigen::SparseMatrix<double> pattern) {
  A_ = std::move(pattern);
  A_.makeCompressed();
  analyzed_lu_ = analyzed_llt_ = factored_ = use_cholesky_ = false;
  factored_values_.clear();
  // LL^T: simplicial below ~20000 equations, supernodal above (measured with the reference BLAS of the
  // target machine: simplicial is up to 2x faster on small 2D meshes, supernodal wins on large ones).
  impl_->llt.setMode(A_.rows() < 20000 ? Eigen::CholmodSimplicialLLt : Eigen::CholmodSupernodalLLt);
  transpose_position_.assign(static_cast<std::size_t>(A_.nonZeros()), -1);
  for (int col = 0; col < A_.outerSize(); ++col) {
    for (int k = A_.outerIndexPtr()[col]; k < A_.outerIndexPtr()[col + 1]; ++k) {
      const int row = A_.innerIndexPtr()[k];
      const int* begin = A_.innerIndexPtr() + A_.outerIndexPtr()[row];
      const int* end = A_.innerIndexPtr() + A_.outerIndexPtr()[row + 1];
      const int* it = std::lower_bound(begin, end, col);
      if (it != end && *it == col) transpose_position_[k] = static_cast<int>(it - A_.innerIndexPtr());
    }
  }
}

bool LinearSolver::values_symmetric() const {
  // Symmetric up to round-off: element tangents computed as B^T D B differ from their transposes by a
  // few ulps (measured 7e-18 of max|A| for the DruckerPrager column); 1e-14 of max|A| accepts those and
  // nothing else. Cholesky reads the lower triangle, so the solution differs from LU's at round-off level,
  // and with Newton-type algorithms the tangent only steers the iterations, not the converged state.
  const double* v = A_.valuePtr();
  double max_abs = 0.0;
  for (std::size_t k = 0; k < transpose_position_.size(); ++k) max_abs = std::max(max_abs, std::abs(v[k]));
  const double tol = 1e-14 * max_abs;
  for (std::size_t k = 0; k < transpose_position_.size(); ++k) {
    const int t = transpose_position_[k];
    if (std::abs(v[k] - (t < 0 ? 0.0 : v[t])) > tol) return false;
  }
  return true;
}

bool LinearSolver::diagonal_positive() const {
  const double* v = A_.valuePtr();
  for (int col = 0; col < A_.outerSize(); ++col) {
    const int* begin = A_.innerIndexPtr() + A_.outerIndexPtr()[col];
    const int* end = A_.innerIndexPtr() + A_.outerIndexPtr()[col + 1];
    const int* it = std::lower_bound(begin, end, col);
    if (it == end || *it != col || !(v[it - A_.innerIndexPtr()] > 0.0)) return false;
  }
  return true;
}

bool LinearSolver::try_cholesky() {
  if (!analyzed_llt_) { impl_->llt.analyzePattern(A_); analyzed_llt_ = true; }
  impl_->llt.factorize(A_);
  return impl_->llt.info() == Eigen::Success;
}

void LinearSolver::factor_lu() {
  if (!analyzed_lu_) { impl_->lu.analyzePattern(A_); analyzed_lu_ = true; }
  impl_->lu.factorize(A_);
  if (impl_->lu.info() != Eigen::Success) {
    throw common::NumericalError("the system matrix is singular (UMFPACK); check supports and connectivity");
  }
}

void LinearSolver::mirror_upper_triangle() {
  double* v = A_.valuePtr();
  for (int col = 0; col < A_.outerSize(); ++col)
    for (int k = A_.outerIndexPtr()[col]; k < A_.outerIndexPtr()[col + 1]; ++k)
      if (A_.innerIndexPtr()[k] > col) {  // below the diagonal: its transpose's value, or 0 when that is absent
        const int t = transpose_position_[static_cast<std::size_t>(k)];
        v[k] = t < 0 ? 0.0 : v[t];
      }
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
    // a non-positive diagonal rules LL^T out before trying it (u-p systems: the pore-pressure block is
    // negative definite, the matrix symmetric indefinite)
    use_cholesky_ = diagonal_positive() && values_symmetric() && try_cholesky();
    if (!use_cholesky_) factor_lu();
  } else {
    use_cholesky_ = true;
    // OpenSees' SPD systems assemble the upper triangle only (ProfileSPDLinSOE, BandSPDLinSOE::addA: row
    // <= column), so a non-symmetric tangent is solved as the symmetric matrix of its upper triangle:
    // mirrored here into the lower one, which CHOLMOD reads. A symmetric matrix is left as assembled.
    const bool symmetric = values_symmetric();
    if (!symmetric) mirror_upper_triangle();
    if (!try_cholesky()) {
      if (!symmetric)
        throw common::NumericalError(
            "the tangent is not symmetric (non-associated plasticity: psi != phi, or rho_bar != rho) and the "
            "symmetric matrix of its upper triangle, which this SPD system solves as OpenSees does, is not positive "
            "definite; use system UmfPack or BandGeneral");
      throw common::NumericalError(
          diagonal_positive()
              ? "the system matrix is singular or not positive definite (CHOLMOD); check supports and connectivity"
              : "the system matrix has a negative diagonal entry, so it is not positive definite (u-p elements give "
                "symmetric indefinite systems): use system UmfPack, SparseGeneral, BandGeneral or FullGeneral");
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
  if (use_cholesky_) {
    // cholmod_solve2 as Eigen's solve calls it through cholmod_solve (the same arithmetic), without
    // allocating the solution and workspace at every solve.
    cholmod_dense rhs{};
    rhs.nrow = rhs.nzmax = rhs.d = static_cast<std::size_t>(b.size());
    rhs.ncol = 1;
    rhs.x = const_cast<double*>(b.data());
    rhs.xtype = CHOLMOD_REAL;
    rhs.dtype = CHOLMOD_DOUBLE;
    if (!cholmod_solve2(CHOLMOD_A, impl_->llt.factor(), &rhs, nullptr, &impl_->x, nullptr, &impl_->y, &impl_->e,
                        &impl_->llt.cholmod())) {
      throw common::NumericalError("CHOLMOD could not solve the linear system");
    }
    x.resize(b.size());
    std::memcpy(x.data(), impl_->x->x, static_cast<std::size_t>(b.size()) * sizeof(double));
  } else {
    x = impl_->lu.solve(b);
  }
  if (!x.allFinite()) throw common::NumericalError("the solution of the linear system is not finite (singular system)");
}

}  // namespace fem::analysis
