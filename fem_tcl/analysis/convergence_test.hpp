#pragma once
// Convergence tests of OpenSees (SRC/analysis/algorithm/equiSolnAlgo/..., CTest*):
//   NormDispIncr   ||dU||_2            <= tol
//   NormUnbalance  ||R||_2             <= tol   (R: unbalance after the update)
//   EnergyIncr     0.5 |dU . R|        <= tol   (R as above; OpenSees reads the SOE's current B)
//   Relative*      the same norm over its value at the step's first iteration (1 there; CTestRelative*)
//   FixedNumIter   converged after exactly maxIter iterations, whatever the norms (`test FixedNumIter maxIter`)
#include <Eigen/Core>
#include <string>
#include <vector>

#include "common/command_args.hpp"

namespace fem::analysis {

enum class TestType {
  NormDispIncr, NormUnbalance, EnergyIncr,
  RelativeNormDispIncr, RelativeNormUnbalance, RelativeEnergyIncr,
  FixedNumIter
};

/// Outcome of one test: converged, iterate again, or maxIter reached without convergence.
enum class TestResult { Converged, Continue, Failed };

struct TestConfig {
  TestType type = TestType::NormUnbalance;
  double tol = 1e-6;
  int max_iter = 25;
  int print_flag = 0;
};

/// `test NormDispIncr|NormUnbalance|EnergyIncr|RelativeNormDispIncr|RelativeNormUnbalance|RelativeEnergyIncr
/// tol maxIter <printFlag> <normType>` or `test FixedNumIter maxIter <printFlag> <normType>` (args at the type word).
TestConfig parse_test(common::CommandArgs& args);
std::string test_name(TestType type);

class ConvergenceTest {
 public:
  explicit ConvergenceTest(TestConfig config) : config_(config) {}
  void start() {
    iteration_ = 1;
    norms_.clear();
    first_norm_ = 0.0;
  }
  TestResult test(const Eigen::VectorXd& dU, const Eigen::VectorXd& R);
  double last_norm() const { return norm_; }
  /// The norms of the last step's iterations (OpenSees `testNorm`).
  const std::vector<double>& norms() const { return norms_; }
  int iteration() const { return iteration_; }
  const TestConfig& config() const { return config_; }

 private:
  TestConfig config_;
  int iteration_ = 1;
  double norm_ = 0.0;
  double first_norm_ = 0.0;  ///< Relative*: the norm of the step's first iteration
  std::vector<double> norms_;
};

}  // namespace fem::analysis
