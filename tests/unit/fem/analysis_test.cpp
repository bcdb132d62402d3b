// Unit tests: the linear solver (UMFPACK / CHOLMOD, singular systems, factorization reuse), time series,
// convergence tests, the growing least squares of KrylovNewton and the parsers of the analysis chain.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "common/input_error.hpp"
#include "fem_tcl/analysis/convergence_test.hpp"
#include "fem_tcl/analysis/householder_least_squares.hpp"
#include "fem_tcl/analysis/integrator.hpp"
#include "fem_tcl/analysis/linear_solver.hpp"
#include "fem_tcl/domain/time_series.hpp"
#include "support/tolerance.hpp"

namespace {

using fem::analysis::LinearSolver;
using fem::analysis::SolverKind;

Eigen::SparseMatrix<double> tridiagonal(int n, double diag, double off) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, diag);
    if (i + 1 < n) { t.emplace_back(i, i + 1, off); t.emplace_back(i + 1, i, off); }
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

// KrylovNewton's least squares, grown a column at a time, against a QR of the whole matrix (Eigen's
// column-pivoting Householder QR): the same minimizer at each size, to round-off; and a dependent column
// reported as rank deficient instead of a meaningless solution.
TEST(HouseholderLeastSquares, GrowsToTheLeastSquaresSolutionOfTheWholeMatrix) {
  const int n = 40, m = 6;
  std::srand(7);
  const Eigen::MatrixXd W = Eigen::MatrixXd::Random(n, m);
  const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
  fem::analysis::HouseholderLeastSquares ls;
  ls.reset(n, m);
  Eigen::VectorXd c;
  for (int k = 1; k <= m; ++k) {
    ls.add_column(W.col(k - 1));
    ASSERT_EQ(ls.columns(), k);
    ASSERT_TRUE(ls.solve(b, c));
    const Eigen::VectorXd expected = W.leftCols(k).colPivHouseholderQr().solve(b);
    ASSERT_EQ(c.size(), k);
    for (int j = 0; j < k; ++j) EXPECT_CLOSE(c[j], expected[j], 1e-13, 1e-12) << "k = " << k << ", j = " << j;
    // the residual is orthogonal to the columns (normal equations)
    EXPECT_LT((W.leftCols(k).transpose() * (b - W.leftCols(k) * c)).norm(), 1e-12);
  }
  ls.clear();
  EXPECT_EQ(ls.columns(), 0);
  ls.add_column(W.col(0));
  ls.add_column(2.0 * W.col(0));  // dependent: R(1, 1) = 0 up to round-off
  EXPECT_FALSE(ls.solve(b, c));
  ls.clear();
  ls.add_column(W.col(0));
  ls.add_column(Eigen::VectorXd::Zero(n));  // exactly zero
  EXPECT_FALSE(ls.solve(b, c));
  ls.clear();
  ls.add_column(W.col(0));
  ls.add_column(1e-6 * W.col(1) + W.col(0));  // nearly parallel to the first, a real part of its own
  EXPECT_TRUE(ls.solve(b, c));
}

TEST(LinearSolver, BothKindsSolveAndReuseTheFactorization) {
  for (SolverKind kind : {SolverKind::General, SolverKind::SymmetricPositiveDefinite}) {
    LinearSolver s(kind);
    s.set_pattern(tridiagonal(5, 2.0, -1.0));
    s.factor();
    Eigen::VectorXd b = Eigen::VectorXd::Ones(5), x;
    s.solve(b, x);
    const Eigen::VectorXd expected = (Eigen::VectorXd(5) << 2.5, 4.0, 4.5, 4.0, 2.5).finished();
    EXPECT_LT((x - expected).norm(), 1e-12);
    s.factor();  // same values: no new factorization
    EXPECT_EQ(s.factorizations(), 1);
    s.matrix().valuePtr()[0] = 3.0;
    s.factor();
    EXPECT_EQ(s.factorizations(), 2);
  }
}

TEST(LinearSolver, SingularSystemIsANumericalError) {
  for (SolverKind kind : {SolverKind::General, SolverKind::SymmetricPositiveDefinite}) {
    LinearSolver s(kind);
    Eigen::SparseMatrix<double> A(2, 2);  // two equal rows
    A.insert(0, 0) = 1.0; A.insert(0, 1) = 1.0; A.insert(1, 0) = 1.0; A.insert(1, 1) = 1.0;
    s.set_pattern(A);
    EXPECT_THROW(s.factor(), common::NumericalError);
  }
}

TEST(LinearSolver, GeneralSymmetricIndefiniteAndUnsymmetricSystemsAreSolved) {
  // symmetric but indefinite: CHOLMOD's LL^T fails, UMFPACK takes over
  Eigen::SparseMatrix<double> S(2, 2);
  S.insert(0, 0) = 1.0; S.insert(0, 1) = 2.0; S.insert(1, 0) = 2.0; S.insert(1, 1) = 1.0;
  // unsymmetric
  Eigen::SparseMatrix<double> U(2, 2);
  U.insert(0, 0) = 4.0; U.insert(0, 1) = 1.0; U.insert(1, 0) = -2.0; U.insert(1, 1) = 3.0;
  for (const auto& A : {S, U}) {
    LinearSolver s(SolverKind::General);
    s.set_pattern(A);
    s.factor();
    const Eigen::VectorXd b = (Eigen::VectorXd(2) << 1.0, -1.0).finished();
    Eigen::VectorXd x;
    s.solve(b, x);
    EXPECT_LT((Eigen::MatrixXd(A) * x - b).norm(), 1e-14);
  }
  // BandSPD on an indefinite matrix is an error, not garbage
  LinearSolver spd(SolverKind::SymmetricPositiveDefinite);
  spd.set_pattern(S);
  EXPECT_THROW(spd.factor(), common::NumericalError);
}

TEST(LinearSolver, SpdSystemsSolveTheUpperTriangleAsOpenSees) {
  // OpenSees' ProfileSPD / BandSPD assemble only the upper triangle (row <= column) of a non-symmetric
  // tangent: U = [[4, 1], [-2, 3]] is solved as [[4, 1], [1, 3]].
  Eigen::SparseMatrix<double> U(2, 2);
  U.insert(0, 0) = 4.0; U.insert(0, 1) = 1.0; U.insert(1, 0) = -2.0; U.insert(1, 1) = 3.0;
  LinearSolver spd(SolverKind::SymmetricPositiveDefinite);
  spd.set_pattern(U);
  spd.factor();
  const Eigen::VectorXd b = (Eigen::VectorXd(2) << 1.0, -1.0).finished();
  Eigen::VectorXd x;
  spd.solve(b, x);
  const Eigen::Matrix2d upper = (Eigen::Matrix2d() << 4.0, 1.0, 1.0, 3.0).finished();
  EXPECT_LT((upper * x - b).norm(), 1e-14);
  // and when that symmetric matrix is indefinite, the error says why and what to use instead
  Eigen::SparseMatrix<double> N(2, 2);
  N.insert(0, 0) = 1.0; N.insert(0, 1) = 3.0; N.insert(1, 0) = 0.0; N.insert(1, 1) = 1.0;
  LinearSolver bad(SolverKind::SymmetricPositiveDefinite);
  bad.set_pattern(N);
  try {
    bad.factor();
    ADD_FAILURE() << "no error";
  } catch (const common::NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("the tangent is not symmetric"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("use system UmfPack or BandGeneral"), std::string::npos) << e.what();
  }
}

TEST(LinearSolver, SystemNamesMapOntoTwoSolvers) {
  SolverKind kind{};
  for (const char* name : {"BandGeneral", "SparseGeneral", "UmfPack", "FullGeneral"}) {
    ASSERT_TRUE(fem::analysis::solver_kind_for(name, kind));
    EXPECT_EQ(kind, SolverKind::General);
  }
  for (const char* name : {"BandSPD", "ProfileSPD", "SparseSYM"}) {
    ASSERT_TRUE(fem::analysis::solver_kind_for(name, kind));
    EXPECT_EQ(kind, SolverKind::SymmetricPositiveDefinite);
  }
  EXPECT_FALSE(fem::analysis::solver_kind_for("Magic", kind));
}

TEST(TimeSeries, PathInterpolatesAndIsZeroOutside) {
  common::CommandArgs args("timeSeries", "", {"Path", "3", "-time", "0 0.1 0.3", "-values", "0 1 -1", "-factor", "2"});
  auto ts = fem::domain::parse_time_series(args);
  EXPECT_EQ(ts->tag(), 3);
  EXPECT_CLOSE(ts->factor(0.05), 1.0, 1e-15, 1e-14);
  EXPECT_CLOSE(ts->factor(0.2), 0.0, 1e-15, 1e-14);
  EXPECT_CLOSE(ts->factor(0.25), -1.0, 1e-15, 1e-14);
  EXPECT_EQ(ts->factor(0.31), 0.0);
  EXPECT_EQ(ts->factor(-0.1), 0.0);
  common::CommandArgs dt("timeSeries", "", {"Path", "4", "-dt", "0.5", "-values", "1 3"});
  EXPECT_CLOSE(fem::domain::parse_time_series(dt)->factor(0.25), 2.0, 1e-15, 1e-14);
  common::CommandArgs lin("timeSeries", "", {"Linear", "1", "-factor", "3"});
  EXPECT_CLOSE(fem::domain::parse_time_series(lin)->factor(0.5), 1.5, 1e-15, 1e-14);
  common::CommandArgs bad("timeSeries", "", {"Path", "5", "-time", "0 1", "-values", "1 2 3"});
  EXPECT_THROW(fem::domain::parse_time_series(bad), common::InputError);
  common::CommandArgs unknown("timeSeries", "", {"Sine", "5"});
  EXPECT_THROW(fem::domain::parse_time_series(unknown), common::InputError);
}

TEST(ConvergenceTest, DefinitionsAndIterationLimit) {
  Eigen::VectorXd dU(2), R(2);
  dU << 3.0, 4.0;
  R << 1.0, -2.0;
  fem::analysis::ConvergenceTest disp({fem::analysis::TestType::NormDispIncr, 5.0, 3, 0});
  disp.start();
  EXPECT_EQ(disp.test(dU, R), fem::analysis::TestResult::Converged);
  EXPECT_DOUBLE_EQ(disp.last_norm(), 5.0);
  fem::analysis::ConvergenceTest energy({fem::analysis::TestType::EnergyIncr, 1e-3, 2, 5});
  energy.start();
  EXPECT_EQ(energy.test(dU, R), fem::analysis::TestResult::Continue);
  EXPECT_DOUBLE_EQ(energy.last_norm(), 0.5 * 5.0);
  EXPECT_EQ(energy.test(dU, R), fem::analysis::TestResult::Failed);  // maxIter reached
  fem::analysis::ConvergenceTest unbalance({fem::analysis::TestType::NormUnbalance, 1e-3, 2, 5});
  unbalance.start();
  unbalance.test(dU, R);
  EXPECT_DOUBLE_EQ(unbalance.last_norm(), std::sqrt(5.0));
}

TEST(ConvergenceTest, RelativeFormsAndFixedNumIter) {
  // OpenSees CTestRelativeNormDispIncr & co.: the norm over the first iteration's (1 at the first iteration).
  Eigen::VectorXd dU(2), R(2);
  dU << 3.0, 4.0;
  R << 1.0, -2.0;
  fem::analysis::ConvergenceTest rel({fem::analysis::TestType::RelativeNormDispIncr, 0.1, 5, 0});
  rel.start();
  EXPECT_EQ(rel.test(dU, R), fem::analysis::TestResult::Continue);
  EXPECT_DOUBLE_EQ(rel.last_norm(), 1.0);
  EXPECT_EQ(rel.test(0.2 * dU, R), fem::analysis::TestResult::Continue);
  EXPECT_DOUBLE_EQ(rel.last_norm(), 0.2);
  EXPECT_EQ(rel.test(0.05 * dU, R), fem::analysis::TestResult::Converged);
  rel.start();  // a new step measures against its own first iteration
  EXPECT_EQ(rel.test(0.05 * dU, R), fem::analysis::TestResult::Continue);
  fem::analysis::ConvergenceTest rel_r({fem::analysis::TestType::RelativeNormUnbalance, 0.5, 5, 0});
  rel_r.start();
  rel_r.test(dU, R);
  rel_r.test(dU, 0.25 * R);
  EXPECT_DOUBLE_EQ(rel_r.last_norm(), 0.25);
  // FixedNumIter: exactly maxIter iterations, converged whatever the norms
  fem::analysis::ConvergenceTest fixed({fem::analysis::TestType::FixedNumIter, 0.0, 3, 0});
  fixed.start();
  EXPECT_EQ(fixed.test(dU, R), fem::analysis::TestResult::Continue);
  EXPECT_EQ(fixed.test(1e-30 * dU, R), fem::analysis::TestResult::Continue);
  EXPECT_EQ(fixed.test(1e30 * dU, R), fem::analysis::TestResult::Converged);
  common::CommandArgs f("test", "", {"FixedNumIter", "4"});
  EXPECT_EQ(fem::analysis::parse_test(f).max_iter, 4);
  common::CommandArgs r("test", "", {"RelativeEnergyIncr", "1e-6", "10", "0", "2"});
  EXPECT_EQ(fem::analysis::parse_test(r).type, fem::analysis::TestType::RelativeEnergyIncr);
  common::CommandArgs bad("test", "", {"NormDispAndUnbalance", "1e-6", "1e-6", "10"});
  EXPECT_THROW(fem::analysis::parse_test(bad), common::InputError);
}

TEST(Integrator, HHTDefaultsAndBadInput) {
  common::CommandArgs hht("integrator", "", {"HHT", "0.9"});
  const auto c = fem::analysis::parse_integrator(hht);
  EXPECT_DOUBLE_EQ(c.gamma, 1.5 - 0.9);
  EXPECT_DOUBLE_EQ(c.beta, (2.0 - 0.9) * (2.0 - 0.9) / 4.0);
  common::CommandArgs bad("integrator", "", {"Newmark", "0.5"});
  EXPECT_THROW(fem::analysis::parse_integrator(bad), common::InputError);
  common::CommandArgs extra("integrator", "", {"LoadControl", "0.1", "junk"});
  EXPECT_THROW(fem::analysis::parse_integrator(extra), common::InputError);
}

}  // namespace
