#pragma once
// Equilibrium solution algorithms (OpenSees EquiSolnAlgo): Linear, Newton, ModifiedNewton, KrylovNewton
// (Carlson & Miller 1998, "Design and application of a 1D GWMFE code", SIAM J. Sci. Comput. 19(3):728-765,
// accelerated inexact Newton as in OpenSees KrylovNewton), NewtonLineSearch (interpolated line search on
// s(eta) = dU . R(U + eta dU), Crisfield 1991, Non-linear FE analysis of solids and structures, vol. 1, 9.3).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "common/command_args.hpp"
#include "fem_tcl/analysis/convergence_test.hpp"
#include "fem_tcl/analysis/householder_least_squares.hpp"

namespace fem::analysis {

/// What an algorithm drives: the integrator + system of one step.
class StepProblem {
 public:
  virtual ~StepProblem() = default;
  virtual void form_tangent() = 0;    ///< assemble and factor A
  virtual void form_unbalance() = 0;  ///< assemble R at the trial state
  virtual const Eigen::VectorXd& unbalance() const = 0;
  /// x = A^-1 rhs with the current factorization.
  virtual void solve(const Eigen::VectorXd& rhs, Eigen::VectorXd& x) = 0;
  /// Applies a free-dof increment (and updates velocities/accelerations and element states).
  virtual void update(const Eigen::VectorXd& dU) = 0;
  /// What the convergence test reads after update(`solved`): `solved` itself, unless the integrator applied
  /// another increment (DisplacementControl: the correction plus its load-factor part, as OpenSees' setX).
  virtual const Eigen::VectorXd& tested_increment(const Eigen::VectorXd& solved) const { return solved; }
  virtual int equations() const = 0;
};

enum class AlgorithmType { Linear, Newton, ModifiedNewton, KrylovNewton, NewtonLineSearch };

struct AlgorithmConfig {
  AlgorithmType type = AlgorithmType::Newton;
  bool initial_tangent = false;  ///< -initial: the initial stiffness, factored once (Newton, ModifiedNewton)
  /// -elasticTangent (fem_tcl extension): every element's elastic stiffness (Element::elastic_stiffness), so
  /// the matrix stays the same from step to step while dt does and is factored once.
  bool elastic_tangent = false;
  int krylov_max_dim = 3;
  double line_search_tol = 0.8;
  int line_search_max_iter = 10;
  double min_eta = 0.1;
  double max_eta = 10.0;
};

/// `algorithm Linear|Newton|ModifiedNewton|KrylovNewton|NewtonLineSearch <options>` (args at the type).
AlgorithmConfig parse_algorithm(common::CommandArgs& args);

/// Vectors the algorithms reuse from step to step (sized once per model, no allocation per iteration).
struct AlgorithmWorkspace {
  Eigen::VectorXd dU, step, r, r_new;
  std::vector<Eigen::VectorXd> d, w;  ///< Krylov subspace: increments and residual changes
  Eigen::MatrixXd W;                  ///< the w as columns, for a rank-deficient least squares only
  HouseholderLeastSquares least_squares;  ///< QR of [w_0 .. w_k-1], grown by a column per iteration
  Eigen::VectorXd c;
  void resize(int n, int krylov_dim);
};

/// Solves the current step; returns false when the test fails (OpenSees: algorithm returns < 0).
/// Throws common::NumericalError for a singular system.
bool solve_step(const AlgorithmConfig& config, StepProblem& problem, ConvergenceTest& test,
                AlgorithmWorkspace& work, int& iterations);

}  // namespace fem::analysis
