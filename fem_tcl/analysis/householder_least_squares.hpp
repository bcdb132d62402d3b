#pragma once
// Least squares min ||W c - b|| for a matrix W that grows by one column at a time (KrylovNewton's subspace
// of residual changes): the Householder QR of W (Golub & Van Loan 2013, Matrix Computations, 4th ed.,
// algs. 5.1.1 and 5.2.1; the reflectors of LAPACK dgeqr2/dlarfg, which OpenSees' dgels call uses) kept from
// column to column, so adding the k-th column costs O(n k) (the k - 1 reflectors applied to it) and a
// solve O(n k), instead of factoring W anew, O(n k^2), at every iteration.
#include <Eigen/Core>

namespace fem::analysis {

class HouseholderLeastSquares {
 public:
  /// Room for n rows and up to max_columns columns; empties W.
  void reset(int n, int max_columns);
  void clear() { k_ = 0; }
  int columns() const { return k_; }
  /// Appends the column w (length n) to W.
  void add_column(const Eigen::VectorXd& w);
  /// c = argmin ||W c - b||; false (c untouched) when W is rank deficient to round-off (a column whose
  /// part orthogonal to the columns before it, |R(j, j)|, is below 1e-13 of its norm).
  bool solve(const Eigen::VectorXd& b, Eigen::VectorXd& c);

 private:
  /// a = H_j a for the reflector H_j = I - tau_j v_j v_j^T of column j (v_j(j) = 1, zero above j).
  void reflect(int j, Eigen::VectorXd& a) const;
  Eigen::MatrixXd V_;    ///< reflector j in column j below the diagonal (its unit diagonal implicit)
  Eigen::MatrixXd R_;    ///< upper triangular factor
  Eigen::VectorXd tau_;  ///< reflector factors
  Eigen::VectorXd column_norm_;
  Eigen::VectorXd a_;    ///< work vector (n)
  int k_ = 0;
};

}  // namespace fem::analysis
