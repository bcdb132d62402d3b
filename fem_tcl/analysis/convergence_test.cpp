#include "fem_tcl/analysis/convergence_test.hpp"

#include <cmath>
#include <iostream>

namespace fem::analysis {

std::string test_name(TestType type) {
  switch (type) {
    case TestType::NormDispIncr: return "NormDispIncr";
    case TestType::NormUnbalance: return "NormUnbalance";
    case TestType::EnergyIncr: return "EnergyIncr";
  }
  return "?";
}

TestConfig parse_test(common::CommandArgs& args) {
  TestConfig c;
  const std::string type = args.word("type (NormDispIncr, NormUnbalance or EnergyIncr)");
  if (type == "NormDispIncr") c.type = TestType::NormDispIncr;
  else if (type == "NormUnbalance") c.type = TestType::NormUnbalance;
  else if (type == "EnergyIncr") c.type = TestType::EnergyIncr;
  else args.fail("unknown test type '" + type + "'");
  c.tol = args.number("tol");
  c.max_iter = args.integer("maxIter");
  if (!(c.tol >= 0.0)) args.fail("expected tol >= 0");
  if (c.max_iter < 1) args.fail("expected maxIter >= 1");
  if (!args.empty()) c.print_flag = args.integer("printFlag");
  if (!args.empty()) {
    const int norm_type = args.integer("normType");
    if (norm_type != 2) args.fail("only the 2-norm (normType 2) is supported");
  }
  args.expect_end();
  return c;
}

TestResult ConvergenceTest::test(const Eigen::VectorXd& dU, const Eigen::VectorXd& R) {
  switch (config_.type) {
    case TestType::NormDispIncr: norm_ = dU.norm(); break;
    case TestType::NormUnbalance: norm_ = R.norm(); break;
    case TestType::EnergyIncr: norm_ = 0.5 * std::abs(dU.dot(R)); break;
  }
  if (norms_.size() < static_cast<std::size_t>(config_.max_iter)) norms_.push_back(norm_);
  if (config_.print_flag == 1 || config_.print_flag == 4) {
    std::cerr << "CTest" << test_name(config_.type) << "::test() - iteration: " << iteration_
              << " current Norm: " << norm_ << " (max: " << config_.tol << ")\n";
  }
  if (std::isfinite(norm_) && norm_ <= config_.tol) {
    if (config_.print_flag == 2) {
      std::cerr << "CTest" << test_name(config_.type) << "::test() - iteration: " << iteration_
                << " current Norm: " << norm_ << " (max: " << config_.tol << ")\n";
    }
    return TestResult::Converged;
  }
  if (!std::isfinite(norm_) || iteration_ >= config_.max_iter) {
    if (config_.print_flag != 5) {
      std::cerr << "WARNING: CTest" << test_name(config_.type) << "::test() - failed to converge after: "
                << iteration_ << " iterations; current Norm: " << norm_ << " (max: " << config_.tol << ")\n";
    }
    return TestResult::Failed;
  }
  ++iteration_;
  return TestResult::Continue;
}

}  // namespace fem::analysis
