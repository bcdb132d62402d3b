#include "fem_tcl/analysis/algorithm.hpp"

#include <Eigen/Dense>
#include <algorithm>
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
    if (args.flag("-initial")) c.initial_tangent = true;
    else if (args.flag("-elasticTangent")) c.elastic_tangent = true;
    else if (args.flag("-initialThenCurrent") || args.flag("-factorOnce")) {}  // same converged result
    else if (args.flag("-secant") || args.flag("-current")) {}
    else if (args.flag("-maxDim")) c.krylov_max_dim = args.integer("-maxDim value");
    else if (args.flag("-iterate") || args.flag("-increment") || args.flag("-iterateTangent") ||
             args.flag("-incrementTangent")) {
      // KrylovNewton: the tangent of the first iteration (-increment) and of the restarts (-iterate); fem_tcl
      // uses one choice for both: `initial` (the initial stiffness, factored once while dt is unchanged) when
      // either asks for it, else the current tangent (noTangent is taken as current).
      const std::string t = args.word("tangent type (current, initial or noTangent)");
      if (t == "initial" || t == "Initial") c.initial_tangent = true;
      else if (t != "current" && t != "Current" && t != "noTangent" && t != "NoTangent") {
        args.fail("unknown tangent type '" + t + "' (current, initial or noTangent)");
      }
    }
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

void AlgorithmWorkspace::resize(int n, int krylov_dim) {
  if (dU.size() == n && static_cast<int>(d.size()) == krylov_dim) return;
  dU.setZero(n); step.setZero(n); r.setZero(n); r_new.setZero(n);
  d.assign(krylov_dim, Eigen::VectorXd::Zero(n));
  w.assign(krylov_dim, Eigen::VectorXd::Zero(n));
  W.setZero(n, krylov_dim);
  least_squares.reset(n, std::min(krylov_dim, std::max(n, 1)));
}

namespace {

bool newton(StepProblem& p, ConvergenceTest& test, AlgorithmWorkspace& ws, int& iterations, bool modified) {
  Eigen::VectorXd& dU = ws.dU;
  p.form_unbalance();
  test.start();
  if (modified) p.form_tangent();
  for (;;) {
    if (!modified) p.form_tangent();
    p.solve(p.unbalance(), dU);
    p.update(dU);
    p.form_unbalance();
    ++iterations;
    const TestResult r = test.test(p.tested_increment(dU), p.unbalance());
    if (r != TestResult::Continue) return r == TestResult::Converged;
  }
}

/// Krylov subspace acceleration of modified Newton (Carlson & Miller 1998): with preconditioned
/// residuals r_k = A0^-1 R_k, increments d_j and w_j = r_j - r_{j+1}, choose c = argmin ||r_k - W c||
/// and take d_k = r_k + sum_j c_j (d_j - w_j).
bool krylov_newton(const AlgorithmConfig& config, StepProblem& p, ConvergenceTest& test, AlgorithmWorkspace& ws,
                   int& iterations) {
  const int m = std::min(config.krylov_max_dim, p.equations());  // as OpenSees: at most numEqns
  Eigen::VectorXd& r = ws.r;
  Eigen::VectorXd& r_new = ws.r_new;
  Eigen::VectorXd& dU = ws.dU;
  int k = 0;  // current subspace dimension
  p.form_unbalance();
  test.start();
  p.form_tangent();
  p.solve(p.unbalance(), r);
  dU = r;
  for (;;) {
    p.update(dU);
    p.form_unbalance();
    ++iterations;
    // OpenSees' tests read the system's solution x, which for KrylovNewton is the plain solve r = A0^-1 R of
    // this iteration, not the accelerated increment dU applied (KrylovNewton::solveCurrentStep).
    const TestResult result = test.test(p.tested_increment(r), p.unbalance());
    if (result != TestResult::Continue) return result == TestResult::Converged;
    if (k >= m) {  // restart the subspace with a fresh tangent (one solve, on the fresh tangent only)
      k = 0;
      p.form_tangent();
      p.solve(p.unbalance(), r_new);
      r = r_new;
      dU = r_new;
      continue;
    }
    p.solve(p.unbalance(), r_new);
    ws.d[k] = dU;
    ws.w[k] = r - r_new;
    if (k == 0) ws.least_squares.clear();
    ws.least_squares.add_column(ws.w[k]);
    ++k;
    if (!ws.least_squares.solve(r_new, ws.c)) {  // W rank deficient to round-off: the pivoted QR's basic solution
      for (int j = 0; j < k; ++j) ws.W.col(j) = ws.w[j];
      ws.c = ws.W.leftCols(k).colPivHouseholderQr().solve(r_new);
    }
    dU = r_new;
    for (int j = 0; j < k; ++j) dU += ws.c[j] * (ws.d[j] - ws.w[j]);
    r = r_new;
  }
}

bool newton_line_search(const AlgorithmConfig& config, StepProblem& p, ConvergenceTest& test, AlgorithmWorkspace& ws,
                        int& iterations) {
  Eigen::VectorXd& dU = ws.dU;
  Eigen::VectorXd& step = ws.step;
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
    const TestResult r = test.test(p.tested_increment(step), p.unbalance());
    if (r != TestResult::Continue) return r == TestResult::Converged;
  }
}

}  // namespace

bool solve_step(const AlgorithmConfig& config, StepProblem& p, ConvergenceTest& test, AlgorithmWorkspace& ws,
                int& iterations) {
  ws.resize(p.equations(), config.krylov_max_dim);
  switch (config.type) {
    case AlgorithmType::Linear: {
      Eigen::VectorXd& dU = ws.dU;
      p.form_tangent();
      p.form_unbalance();
      p.solve(p.unbalance(), dU);
      p.update(dU);
      ++iterations;
      return true;
    }
    case AlgorithmType::Newton: return newton(p, test, ws, iterations, config.initial_tangent || config.elastic_tangent);
    case AlgorithmType::ModifiedNewton: return newton(p, test, ws, iterations, true);
    case AlgorithmType::KrylovNewton: return krylov_newton(config, p, test, ws, iterations);
    case AlgorithmType::NewtonLineSearch: return newton_line_search(config, p, test, ws, iterations);
  }
  return false;
}

}  // namespace fem::analysis
