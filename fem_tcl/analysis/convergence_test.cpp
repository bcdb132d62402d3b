#include "fem_tcl/analysis/convergence_test.hpp"

#include <cmath>
#include <iostream>

namespace fem::analysis {

std::string test_name(TestType type) {
  switch (type) {
    case TestType::NormDispIncr: return "NormDispIncr";
    case TestType::NormUnbalance: return "NormUnbalance";
    case TestType::EnergyIncr: return "EnergyIncr";
    case TestType::RelativeNormDispIncr: return "RelativeNormDispIncr";
    case TestType::RelativeNormUnbalance: return "RelativeNormUnbalance";
    case TestType::RelativeEnergyIncr: return "RelativeEnergyIncr";
    case TestType::FixedNumIter: return "FixedNumIter";
  }
  return "?";
}

TestConfig parse_test(common::CommandArgs& args) {
  TestConfig c;
  const std::string type = args.word("type (NormDispIncr, NormUnbalance, EnergyIncr, their Relative* forms or FixedNumIter)");
  bool found = false;
  for (TestType t : {TestType::NormDispIncr, TestType::NormUnbalance, TestType::EnergyIncr, TestType::RelativeNormDispIncr,
                     TestType::RelativeNormUnbalance, TestType::RelativeEnergyIncr, TestType::FixedNumIter}) {
    if (type == test_name(t)) {
      c.type = t;
      found = true;
    }
  }
  if (!found) args.fail("unknown test type '" + type + "'");
  c.tol = c.type == TestType::FixedNumIter ? 0.0 : args.number("tol");
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
    case TestType::NormDispIncr:
    case TestType::RelativeNormDispIncr:
    case TestType::FixedNumIter: norm_ = dU.norm(); break;
    case TestType::NormUnbalance:
    case TestType::RelativeNormUnbalance: norm_ = R.norm(); break;
    case TestType::EnergyIncr:
    case TestType::RelativeEnergyIncr: norm_ = 0.5 * std::abs(dU.dot(R)); break;
  }
  const bool relative = config_.type == TestType::RelativeNormDispIncr ||
                        config_.type == TestType::RelativeNormUnbalance || config_.type == TestType::RelativeEnergyIncr;
  if (relative) {  // OpenSees CTestRelative*: norm0 at the first iteration, then norm / norm0 (norm0 != 0)
    if (iteration_ == 1) first_norm_ = norm_;
    if (first_norm_ != 0.0) norm_ /= first_norm_;
  }
  if (norms_.size() < static_cast<std::size_t>(config_.max_iter)) norms_.push_back(norm_);
  if (config_.type == TestType::FixedNumIter) {  // OpenSees CTestFixedNumIter: done after maxIter iterations
    if (iteration_ >= config_.max_iter) return TestResult::Converged;
    ++iteration_;
    return TestResult::Continue;
  }
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
