#include "fem_tcl/analysis/integrator.hpp"

#include <iostream>

namespace fem::analysis {

IntegratorConfig parse_integrator(common::CommandArgs& args) {
  IntegratorConfig c;
  const std::string type = args.word("type (LoadControl, Newmark, HHT, CentralDifference or DisplacementControl)");
  if (type == "LoadControl") {
    c.type = IntegratorType::LoadControl;
    c.d_lambda = args.number("dLambda");
    if (!args.empty()) {
      c.desired_iter = args.integer("Jd");
      c.min_lambda = args.number("minLambda");
      c.max_lambda = args.number("maxLambda");
    }
  } else if (type == "Newmark") {
    c.type = IntegratorType::Newmark;
    c.gamma = args.number("gamma");
    c.beta = args.number("beta");
    if (args.flag("-form")) {
      const std::string form = args.word("form (D)");
      if (form != "D" && form != "d") args.fail("only -form D (displacement) is supported");
    }
    if (!(c.beta > 0.0)) args.fail("expected beta > 0");
  } else if (type == "HHT") {
    c.type = IntegratorType::HHT;
    c.alpha = args.number("alpha");
    c.gamma = 1.5 - c.alpha;
    c.beta = (2.0 - c.alpha) * (2.0 - c.alpha) * 0.25;
    if (!args.empty()) {
      c.gamma = args.number("gamma");
      c.beta = args.number("beta");
    }
    if (!(c.alpha > 0.0 && c.alpha <= 1.0)) args.fail("expected 0 < alpha <= 1 (OpenSees convention, 1 = Newmark)");
    if (!(c.beta > 0.0)) args.fail("expected beta > 0");
  } else if (type == "CentralDifference") {
    c.type = IntegratorType::CentralDifference;
  } else if (type == "DisplacementControl") {
    // OpenSees OPS_DisplacementControlIntegrator: node dof dU <numIter dUmin dUmax>
    c.type = IntegratorType::DisplacementControl;
    c.control_node = args.integer("node");
    const int dof = args.integer("dof");
    if (dof < 1 || dof > 2) args.fail("expected dof 1 or 2, got " + std::to_string(dof));
    c.control_dof = dof - 1;
    c.control_increment = args.number("dU");
    c.control_min = c.control_max = c.control_increment;
    if (!args.empty()) {
      c.control_num_iter = args.integer("numIter");
      c.control_min = args.number("dUmin");
      c.control_max = args.number("dUmax");
    }
    if (c.control_num_iter == 0) {  // OpenSees: "numIncr set to 0, 1 assumed"
      std::cerr << "WARNING DisplacementControl::DisplacementControl() - numIncr set to 0, 1 assumed\n";
      c.control_num_iter = 1;
    }
    if (c.control_num_iter < 0) args.fail("expected numIter >= 1");
  } else {
    args.fail("unknown integrator '" + type + "'");
  }
  args.expect_end();
  return c;
}

}  // namespace fem::analysis
