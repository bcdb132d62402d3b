#pragma once
// `integrator DisplacementControl node dof dU <numIter dUmin dUmax>`: OpenSees' DisplacementControl
// (SRC/analysis/integrator/DisplacementControl.cpp; the method of Batoz & Dhatt 1979, "Incremental
// displacement algorithms for nonlinear problems", IJNME 14, 1262-1267). The load factor lambda (the
// domain's pseudo-time) is the unknown that makes the control dof move by dU per step:
//   reference load    phat = R(lambda + 1) at the start of the analysis (the unbalance with the loads one
//                     load factor further, taking the unbalance at lambda as zero, as OpenSees does)
//   predictor         dUhat = A^-1 phat,  dlambda = dU / dUhat_c,  du = dlambda dUhat
//   each correction   dUbar = A^-1 R (the algorithm's),  dUhat = A^-1 phat,  dlambda = -dUbar_c / dUhat_c,
//                     du = dUbar + dlambda dUhat (what the convergence test reads)
//   next step's dU    dU *= numIter / (corrections of the last step), kept in [dUmin, dUmax] (compared with
//                     their signs, as OpenSees; by default both are dU, which keeps it constant).
// A zero dUhat_c (the control dof does not move under the reference load) fails the step.
#include <Eigen/Core>

#include "fem_tcl/analysis/integrator.hpp"

namespace fem::analysis {

class DisplacementControl {
 public:
  explicit DisplacementControl(const IntegratorConfig& config)
      : increment_(config.control_increment), min_(config.control_min), max_(config.control_max),
        wanted_iterations_(config.control_num_iter), last_iterations_(config.control_num_iter) {}

  /// The reference load (free equations) and the control dof's equation, at the start of an analysis.
  void set_reference(const Eigen::VectorXd& phat, int control_equation) {
    phat_ = phat;
    equation_ = control_equation;
  }
  const Eigen::VectorXd& reference_load() const { return phat_; }

  /// newStep: adapts the step's increment and returns the predictor's dlambda for dUhat = A^-1 phat.
  double predictor(const Eigen::VectorXd& dUhat);
  /// update: the correction's dlambda for the algorithm's dUbar and dUhat = A^-1 phat (counts it).
  double corrector(const Eigen::VectorXd& dUbar, const Eigen::VectorXd& dUhat);

 private:
  double control_component(const Eigen::VectorXd& dUhat) const;

  double increment_, min_, max_;
  double wanted_iterations_, last_iterations_;
  Eigen::VectorXd phat_;
  int equation_ = -1;
};

}  // namespace fem::analysis
