#include "fem_tcl/analysis/integrator.hpp"

namespace fem::analysis {

IntegratorConfig parse_integrator(common::CommandArgs& args) {
  IntegratorConfig c;
  const std::string type = args.word("type (LoadControl, Newmark, HHT or CentralDifference)");
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
  } else {
    args.fail("unknown integrator '" + type + "'");
  }
  args.expect_end();
  return c;
}

}  // namespace fem::analysis
