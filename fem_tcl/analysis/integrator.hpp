#pragma once
// Integrator settings (OpenSees StaticIntegrator / TransientIntegrator):
//   LoadControl dLambda <Jd minLambda maxLambda>  : lambda_{n+1} = lambda_n + dLambda (pseudo-time = lambda)
//   Newmark gamma beta                            : Newmark 1959, displacement form as OpenSees (c1 = 1,
//                                                   c2 = gamma/(beta dt), c3 = 1/(beta dt^2))
//   HHT alpha <gamma beta>                        : Hilber, Hughes & Taylor 1977 in OpenSees' convention
//                                                   (alpha in [2/3, 1], alpha = 1 is Newmark; defaults
//                                                   gamma = 1.5 - alpha, beta = (2 - alpha)^2 / 4)
//   CentralDifference                             : explicit central differences, A = M/dt^2 + C/(2 dt)
//   DisplacementControl node dof dU <numIter dUmin dUmax> : static, the load factor follows from the
//                                                   displacement of one dof (displacement_control.hpp)
#include <string>

#include "common/command_args.hpp"

namespace fem::analysis {

enum class IntegratorType { LoadControl, Newmark, HHT, CentralDifference, DisplacementControl };

struct IntegratorConfig {
  IntegratorType type = IntegratorType::LoadControl;
  double d_lambda = 1.0;
  int desired_iter = 0;  ///< Jd (0: constant dLambda)
  double min_lambda = 0.0;
  double max_lambda = 0.0;
  double gamma = 0.5;
  double beta = 0.25;
  double alpha = 1.0;
  // DisplacementControl
  int control_node = 0;        ///< node tag
  int control_dof = 0;         ///< 0-based
  double control_increment = 0.0;
  int control_num_iter = 1;    ///< the iterations a step should take (the increment adapts by numIter / taken)
  double control_min = 0.0, control_max = 0.0;  ///< bounds of the increment (default: the increment itself)
  bool is_static() const { return type == IntegratorType::LoadControl || type == IntegratorType::DisplacementControl; }
};

/// `integrator LoadControl|Newmark|HHT|CentralDifference|DisplacementControl ...` (args at the type word).
IntegratorConfig parse_integrator(common::CommandArgs& args);

}  // namespace fem::analysis
