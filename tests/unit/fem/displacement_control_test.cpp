// Unit tests: `integrator DisplacementControl node dof dU <numIter dUmin dUmax>` (OpenSees 3.8
// DisplacementControl, Batoz & Dhatt 1979): the control dof moves by dU per step and the load factor is
// what equilibrium then needs: on an elastic column it is the LoadControl factor of that displacement, on a
// Tresca column it follows the load past its limit 2 c A (unconfined compression, where LoadControl
// cannot go), and the increment adapts by numIter over the iterations taken; bad input.
#include <gtest/gtest.h>

#include <string>

#include "fem_tcl/tcl/interpreter.hpp"
#include "support/tolerance.hpp"

namespace {

using fem::tcl::Interpreter;

std::string error_of(Interpreter& interp, const std::string& script) {
  std::string message;
  return interp.eval_script(script, "test", message) ? std::string() : message;
}

double value(Interpreter& interp, const std::string& expression) { return std::stod(interp.eval(expression)); }

// A 1 m x 1 m SSPquad column on a roller base (node 1 pinned), 1 kN down on each top node (the reference
// load: 2 kN/m over the 1 m width).
std::string column(const std::string& material) {
  return "model basic -ndm 2 -ndf 2\nnode 1 0 0\nnode 2 1 0\nnode 3 1 1\nnode 4 0 1\n" + material +
         "\nelement SSPquad 1 1 2 3 4 1 PlaneStrain 1.0\nfix 1 1 1\nfix 2 0 1\n"
         "timeSeries Linear 1\npattern Plain 1 1 { load 3 0.0 -1.0; load 4 0.0 -1.0 }\n"
         "constraints Plain; numberer Plain; system BandGeneral; test NormDispIncr 1e-12 20; algorithm Newton\n";
}

TEST(DisplacementControl, ElasticColumnMatchesLoadControl) {
  Interpreter dc;
  ASSERT_EQ(error_of(dc, column("nDMaterial ElasticIsotropic 1 1000.0 0.25") + R"tcl(
integrator DisplacementControl 3 2 -0.001
analysis Static
if {[analyze 5] != 0} { error "analyze failed" }
)tcl"), "");
  EXPECT_CLOSE(value(dc, "nodeDisp 3 2"), -0.005, 1e-12, 0.0);
  const std::string lambda = dc.eval("getLoadFactor 1");  // the pseudo-time (getTime prints 6 decimals)
  EXPECT_CLOSE(value(dc, "getTime"), std::stod(lambda), 1e-6, 0.0);
  Interpreter lc;
  ASSERT_EQ(error_of(lc, column("nDMaterial ElasticIsotropic 1 1000.0 0.25") + "integrator LoadControl " + lambda +
                             "\nanalysis Static\nanalyze 1\n"),
            "");
  EXPECT_CLOSE(value(lc, "nodeDisp 3 2"), -0.005, 0.0, 1e-12);
}

TEST(DisplacementControl, FollowsATrescaColumnPastItsLimitLoad) {
  // Unconfined plane-strain compression of Tresca (phi = 0, c = 10 kPa): syy reaches -2 c, the load factor
  // 2 c x 1 m / 2 kN = c = 10, and stays there while the top keeps moving (yield strain 2 c / E' ~ 1.9 %;
  // here 5 %). LoadControl past 10 cannot converge.
  Interpreter interp;
  ASSERT_EQ(error_of(interp, column("nDMaterial MohrCoulomb 1 1000.0 0.25 0.0 0.0 10.0 0.0") + R"tcl(
updateMaterialStage -material 1 -stage 1
integrator DisplacementControl 3 2 -0.001
analysis Static
set lambdas {}
for {set k 0} {$k < 50} {incr k} {
  if {[analyze 1] != 0} { error "step $k failed" }
  lappend lambdas [getLoadFactor 1]
}
)tcl"), "");
  EXPECT_CLOSE(value(interp, "nodeDisp 3 2"), -0.05, 1e-12, 0.0);
  EXPECT_CLOSE(value(interp, "getLoadFactor 1"), 10.0, 1e-9, 0.0);
  EXPECT_CLOSE(value(interp, "lindex $lambdas 4"), 5.0 * value(interp, "lindex $lambdas 0"), 1e-9, 0.0);  // elastic
  EXPECT_LT(value(interp, "lindex $lambdas 9"), 10.0);
  Interpreter lc;
  ASSERT_EQ(error_of(lc, column("nDMaterial MohrCoulomb 1 1000.0 0.25 0.0 0.0 10.0 0.0") +
                             "updateMaterialStage -material 1 -stage 1\nintegrator LoadControl 11.0\n"
                             "analysis Static\nset ok [analyze 1]\n"),
            "");
  EXPECT_LT(value(lc, "set ok"), 0.0);
}

TEST(DisplacementControl, IncrementAdaptsByNumIterOverTheIterationsTaken) {
  // On the elastic column the predictor is exact, so Newton converges at its first correction: numIter 4
  // takes dU x 4 / 1 per step, kept in [dUmin, dUmax] = [-0.004, -0.0001] (signed, as OpenSees): the steps
  // move the top by -0.001 (the first keeps dU: numIter / numIter), -0.004, then -0.004 again (-0.016 clamped).
  Interpreter interp;
  ASSERT_EQ(error_of(interp, column("nDMaterial ElasticIsotropic 1 1000.0 0.25") + R"tcl(
integrator DisplacementControl 3 2 -0.001 4 -0.004 -0.0001
analysis Static
set u {}
for {set k 0} {$k < 3} {incr k} { analyze 1; lappend u [nodeDisp 3 2] }
)tcl"), "");
  EXPECT_CLOSE(value(interp, "lindex $u 0"), -0.001, 1e-12, 0.0);
  EXPECT_CLOSE(value(interp, "lindex $u 1"), -0.005, 1e-12, 0.0);
  EXPECT_CLOSE(value(interp, "lindex $u 2"), -0.009, 1e-12, 0.0);
}

TEST(DisplacementControl, BadInput) {
  Interpreter interp;
  ASSERT_EQ(error_of(interp, column("nDMaterial ElasticIsotropic 1 1000.0 0.25")), "");
  EXPECT_NE(error_of(interp, "integrator DisplacementControl 3 3 -0.001").find("expected dof 1 or 2"),
            std::string::npos);
  EXPECT_NE(error_of(interp, "integrator DisplacementControl 3 2").find("dU"), std::string::npos);
  EXPECT_NE(error_of(interp, "integrator DisplacementControl 3 2 -0.001 2 -0.01").find("dUmax"), std::string::npos);
  ASSERT_EQ(error_of(interp, "integrator DisplacementControl 1 2 -0.001\nanalysis Static"), "");
  EXPECT_NE(error_of(interp, "analyze 1").find("node 1 dof 2 is fixed or constrained"), std::string::npos);
  EXPECT_NE(error_of(interp, "analyze 1").find("node 1 dof 2 is fixed or constrained"), std::string::npos);  // again
  ASSERT_EQ(error_of(interp, "integrator DisplacementControl 99 2 -0.001\nanalysis Static"), "");
  EXPECT_NE(error_of(interp, "analyze 1").find("node 99 does not exist"), std::string::npos);
  ASSERT_EQ(error_of(interp, "remove loadPattern 1\nintegrator DisplacementControl 3 2 -0.001\nanalysis Static"), "");
  EXPECT_NE(error_of(interp, "analyze 1").find("zero reference load"), std::string::npos);
}

}  // namespace
