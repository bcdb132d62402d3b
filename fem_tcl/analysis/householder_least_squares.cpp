#include "fem_tcl/analysis/householder_least_squares.hpp"

#include <cmath>

namespace fem::analysis {

namespace {
constexpr double kDependent = 1e-13;
}  // namespace

void HouseholderLeastSquares::reset(int n, int max_columns) {
  V_.setZero(n, max_columns);
  R_.setZero(max_columns, max_columns);
  tau_.setZero(max_columns);
  column_norm_.setZero(max_columns);
  a_.setZero(n);
  k_ = 0;
}

void HouseholderLeastSquares::reflect(int j, Eigen::VectorXd& a) const {
  if (tau_[j] == 0.0) return;
  const int m = static_cast<int>(a.size()) - j - 1;
  const double s = tau_[j] * (a[j] + V_.col(j).tail(m).dot(a.tail(m)));
  a[j] -= s;
  a.tail(m).noalias() -= s * V_.col(j).tail(m);
}

void HouseholderLeastSquares::add_column(const Eigen::VectorXd& w) {
  const int j = k_;
  const int n = static_cast<int>(w.size());
  a_ = w;
  column_norm_[j] = w.norm();
  for (int i = 0; i < j; ++i) reflect(i, a_);
  R_.col(j).head(j) = a_.head(j);
  // dlarfg: H (alpha, x) = (beta, 0) with beta = -sign(alpha) ||(alpha, x)||, v = x / (alpha - beta)
  const int m = n - j - 1;
  const double alpha = a_[j];
  const double xnorm = a_.tail(m).norm();
  if (xnorm == 0.0) {
    tau_[j] = 0.0;
    R_(j, j) = alpha;
    V_.col(j).tail(m).setZero();
  } else {
    const double beta = -std::copysign(std::hypot(alpha, xnorm), alpha);
    tau_[j] = (beta - alpha) / beta;
    V_.col(j).tail(m) = a_.tail(m) / (alpha - beta);
    R_(j, j) = beta;
  }
  ++k_;
}

bool HouseholderLeastSquares::solve(const Eigen::VectorXd& b, Eigen::VectorXd& c) {
  // column j numerically dependent on columns 0..j-1: what is left of it after their reflections (|R(j, j)|)
  // is round-off of its own norm
  for (int j = 0; j < k_; ++j) {
    if (!(std::abs(R_(j, j)) > kDependent * column_norm_[j])) return false;
  }
  a_ = b;
  for (int j = 0; j < k_; ++j) reflect(j, a_);  // Q^T b
  c = R_.topLeftCorner(k_, k_).triangularView<Eigen::Upper>().solve(a_.head(k_));
  return true;
}

}  // namespace fem::analysis
