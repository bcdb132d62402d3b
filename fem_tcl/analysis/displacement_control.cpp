#include "fem_tcl/analysis/displacement_control.hpp"

#include "common/input_error.hpp"

namespace fem::analysis {

double DisplacementControl::control_component(const Eigen::VectorXd& dUhat) const {
  const double c = dUhat[equation_];
  if (c == 0.0) {
    throw common::NumericalError(
        "DisplacementControl: dUahat is zero -- zero reference displacement at the control node's dof");
  }
  return c;
}

double DisplacementControl::predictor(const Eigen::VectorXd& dUhat) {
  increment_ *= wanted_iterations_ / last_iterations_;
  if (increment_ < min_) increment_ = min_;
  else if (increment_ > max_) increment_ = max_;
  last_iterations_ = 0.0;
  return increment_ / control_component(dUhat);
}

double DisplacementControl::corrector(const Eigen::VectorXd& dUbar, const Eigen::VectorXd& dUhat) {
  last_iterations_ += 1.0;
  return -dUbar[equation_] / control_component(dUhat);
}

}  // namespace fem::analysis
