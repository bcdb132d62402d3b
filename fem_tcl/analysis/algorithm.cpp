#include "fem_tcl/analysis/algorithm.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace fem::analysis {

AlgorithmConfig parse_algorithm(common::CommandArgs& args) {
  AlgorithmConfig c;
  const std::string type = args.word("type (Linear, Newton, ModifiedNewton, KrylovNewton or NewtonLineSearch)");
  if (type == "Linear") c.type = AlgorithmType::Linear;
  else if (type == "Newton") c.type = AlgorithmType::Newton;
  else if (type == "ModifiedNewton") c.type = AlgorithmType::ModifiedNewton;
  else if (type == "KrylovNewton") c.type = AlgorithmType::KrylovNewton;
  else if (type == "NewtonLineSearch") c.type = AlgorithmType::NewtonLineSearch;
  else args.fail("unknown algorithm '" + type + "'");
  while (!args.empty()) {
    if (args.flag("-initial") || args.flag("-initialThenCurrent") || args.flag("-factorOnce")) c.initial_tangent = true;
    else if (args.flag("-secant") || args.flag("-current")) {}
    else if (args.flag("-maxDim")) c.krylov_max_dim = args.integer("-maxDim value");
    else if (args.flag("-iterateTangent") || args.flag("-incrementTangent")) args.word("tangent type");
    else if (args.flag("-tol")) c.line_search_tol = args.number("-tol value");
    else if (args.flag("-maxIter")) c.line_search_max_iter = args.integer("-maxIter value");
    else if (args.flag("-minEta")) c.min_eta = args.number("-minEta value");
    else if (args.flag("-maxEta")) c.max_eta = args.number("-maxEta value");
    else if (args.flag("-type")) args.word("line search type");
    else if (type == "NewtonLineSearch" && args.optional_number()) {}  // legacy positional ratio
    else args.fail("unknown option '" + args.peek() + "'");
  }
  if (c.krylov_max_dim < 1) args.fail("expected -maxDim >= 1");
  return c;
}

namespace {

bool newton(const AlgorithmConfig& config, StepProblem& p, ConvergenceTest& test, int& iterations, bool modified) {
  Eigen::VectorXd dU(p.equations());
  p.form_unbalance();
  test.start();
  if (modified) p.form_tangent();
  for (;;) {
    if (!modified) p.form_tangent();
    p.solve(p.unbalance(), dU);
    p.update(dU);
    p.form_unbalance();
    ++iterations;
    const int r = test.test(dU, p.unbalance());
    if (r > 0) return true;
    if (r == -2) return false;
  }
  (void)config;
}

/// Krylov subspace acceleration of modified Newton (Carlson & Miller 1998): with preconditioned
/// residuals r_k = A0^-1 R_k, increments d_j and w_j = r_j - r_{j+1}, choose c = argmin ||r_k - W c||
/// and take d_k = r_k + sum_j c_j (d_j - w_j).
bool krylov_newton(const AlgorithmConfig& config, StepProblem& p, ConvergenceTest& test, int& iterations) {
  const int n = p.equations();
  const int m = config.krylov_max_dim;
  std::vector<Eigen::VectorXd> d, w;
  Eigen::VectorXd r(n), dU(n);
  p.form_unbalance();
  test.start();
  p.form_tangent();
  p.solve(p.unbalance(), r);
  dU = r;
  for (;;) {
    p.update(dU);
    p.form_unbalance();
    ++iterations;
    const int result = test.test(dU, p.unbalance());
    if (result > 0) return true;
    if (result == -2) return false;
    Eigen::VectorXd r_new(n);
    p.solve(p.unbalance(), r_new);
    if (static_cast<int>(d.size()) >= m) {  // restart the subspace with a fresh tangent
      d.clear();
      w.clear();
      p.form_tangent();
      p.solve(p.unbalance(), r_new);
      r = r_new;
      dU = r_new;
      continue;
    }
    d.push_back(dU);
    w.push_back(r - r_new);
    const int k = static_cast<int>(d.size());
    Eigen::MatrixXd W(n, k);
    for (int j = 0; j < k; ++j) W.col(j) = w[j];
    const Eigen::VectorXd c = W.colPivHouseholderQr().solve(r_new);
    dU = r_new;
    for (int j = 0; j < k; ++j) dU += c[j] * (d[j] - w[j]);
    r = r_new;
  }
}

bool newton_line_search(const AlgorithmConfig& config, StepProblem& p, ConvergenceTest& test, int& iterations) {
  const int n = p.equations();
  Eigen::VectorXd dU(n), step(n);
  p.form_unbalance();
  test.start();
  for (;;) {
    p.form_tangent();
    p.solve(p.unbalance(), dU);
    const double s0 = -dU.dot(p.unbalance());
    p.update(dU);
    p.form_unbalance();
    double s = -dU.dot(p.unbalance());
    double eta = 1.0;
    if (s0 != 0.0 && std::abs(s) > config.line_search_tol * std::abs(s0)) {
      for (int i = 0; i < config.line_search_max_iter; ++i) {
        double eta_new = (s0 - s) != 0.0 ? eta * s0 / (s0 - s) : eta;
        eta_new = std::clamp(eta_new, config.min_eta, config.max_eta);
        if (!std::isfinite(eta_new)) break;
        step = (eta_new - eta) * dU;
        p.update(step);
        p.form_unbalance();
        s = -dU.dot(p.unbalance());
        eta = eta_new;
        if (std::abs(s) <= config.line_search_tol * std::abs(s0)) break;
      }
    }
    ++iterations;
    step = eta * dU;
    const int r = test.test(step, p.unbalance());
    if (r > 0) return true;
    if (r == -2) return false;
  }
}

}  // namespace

bool solve_step(const AlgorithmConfig& config, StepProblem& p, ConvergenceTest& test, int& iterations) {
  switch (config.type) {
    case AlgorithmType::Linear: {
      Eigen::VectorXd dU(p.equations());
      p.form_tangent();
      p.form_unbalance();
      p.solve(p.unbalance(), dU);
      p.update(dU);
      ++iterations;
      return true;
    }
    case AlgorithmType::Newton: return newton(config, p, test, iterations, config.initial_tangent);
    case AlgorithmType::ModifiedNewton: return newton(config, p, test, iterations, true);
    case AlgorithmType::KrylovNewton: return krylov_newton(config, p, test, iterations);
    case AlgorithmType::NewtonLineSearch: return newton_line_search(config, p, test, iterations);
  }
  return false;
}

}  // namespace fem::analysis
