// Unit tests: the Tcl command layer. Bad input (wrong argument count, unknown command/option, missing or
// duplicate tags, clockwise or collapsed elements, singular systems) gives a Tcl error whose message
// names the command and tag and carries the usage line; fem_tcl itself reports uncaught errors as
// "file:line: message" with exit status 2 (bad input) after flushing the recorders.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>

#include "fem_tcl/tcl/interpreter.hpp"
#include "support/recorder_compare.hpp"
#include "support/scratch.hpp"
#include "support/tolerance.hpp"

namespace {

using fem::tcl::Interpreter;

constexpr const char* kTwoElementModel = R"tcl(
model basic -ndm 2 -ndf 2
node 1 0 0
node 2 1 0
node 3 2 0
node 4 0 1
node 5 1 1
node 6 2 1
fix 1 1 1
fix 4 1 1
nDMaterial ElasticIsotropic 1 1000.0 0.25 2.0
element quad 1 1 2 5 4 1.0 PlaneStrain 1
element SSPquad 2 2 3 6 5 1 PlaneStrain 1.0
)tcl";

/// Evaluates `script` and returns the error message ("" when it succeeded).
std::string error_of(Interpreter& interp, const std::string& script) {
  std::string message;
  return interp.eval_script(script, "test", message) ? std::string() : message;
}

TEST(TclCommands, WrongArgumentCountNamesCommandTagAndUsage) {
  Interpreter interp;
  ASSERT_EQ(error_of(interp, kTwoElementModel), "");
  const std::string e = error_of(interp, "node 7 1.0");
  EXPECT_NE(e.find("node 7"), std::string::npos) << e;
  EXPECT_NE(e.find("usage: node tag x y"), std::string::npos) << e;
  const std::string e2 = error_of(interp, "element SSPquad 9 1 2 5 4 1 PlaneStrain");
  EXPECT_NE(e2.find("element SSPquad 9"), std::string::npos) << e2;
  EXPECT_NE(e2.find("usage: element SSPquad tag"), std::string::npos) << e2;
  EXPECT_NE(error_of(interp, "fix 2 1").find("usage: fix nodeTag f1 f2"), std::string::npos);
}

TEST(TclCommands, UnknownCommandOptionAndTypes) {
  Interpreter interp;
  ASSERT_EQ(error_of(interp, kTwoElementModel), "");
  EXPECT_NE(error_of(interp, "nodeDisplacement 1").find("invalid command name"), std::string::npos);
  EXPECT_NE(error_of(interp, "recorder Node -file x.out -bogus -node 1 -dof 1 disp").find("unknown option '-bogus'"),
            std::string::npos);
  EXPECT_NE(error_of(interp, "nDMaterial Elastic 5 1 0.3").find("unknown material type 'Elastic'"), std::string::npos);
  EXPECT_NE(error_of(interp, "element SSPquad 9 1 2 5 4 1 PlaneStrainX 1.0").find("PlaneStrain or PlaneStress"),
            std::string::npos);
  EXPECT_NE(error_of(interp, "system Magic").find("unknown system 'Magic'"), std::string::npos);
  EXPECT_EQ(error_of(interp, "numberer ParallelRCM"), "");  // OpenSees' parallel numberers, on one process
  EXPECT_NE(error_of(interp, "numberer ParallelMetis").find("unknown numberer 'ParallelMetis'"), std::string::npos);
  EXPECT_NE(error_of(interp, "algorithm Newtonian").find("unknown algorithm"), std::string::npos);
}

TEST(TclCommands, MissingAndDuplicateTags) {
  Interpreter interp;
  ASSERT_EQ(error_of(interp, kTwoElementModel), "");
  EXPECT_NE(error_of(interp, "node 3 5 5").find("node 3 already exists"), std::string::npos);
  EXPECT_NE(error_of(interp, "element quad 1 1 2 5 4 1.0 PlaneStrain 1").find("element 1 already exists"),
            std::string::npos);
  EXPECT_NE(error_of(interp, "nDMaterial ElasticIsotropic 1 10 0.2").find("nDMaterial 1 already exists"),
            std::string::npos);
  const std::string missing_node = error_of(interp, "element quad 3 1 2 50 4 1.0 PlaneStrain 1");
  EXPECT_NE(missing_node.find("element quad 3"), std::string::npos) << missing_node;
  EXPECT_NE(missing_node.find("node 50 does not exist"), std::string::npos) << missing_node;
  EXPECT_NE(error_of(interp, "element quad 3 1 2 5 4 1.0 PlaneStrain 8").find("nDMaterial 8 does not exist"),
            std::string::npos);
  EXPECT_NE(error_of(interp, "nodeDisp 77").find("node 77 does not exist"), std::string::npos);
  EXPECT_NE(error_of(interp, "eleResponse 77 stress").find("element 77 does not exist"), std::string::npos);
  EXPECT_NE(error_of(interp, "pattern Plain 1 42 {}").find("timeSeries 42 does not exist"), std::string::npos);
  EXPECT_NE(error_of(interp, "load 1 1 1").find("only allowed inside"), std::string::npos);
  // a missing tag found after parsing still gets the usage line
  const std::string mass = error_of(interp, "mass 9 1.0 1.0");
  EXPECT_NE(mass.find("mass 9: node 9 does not exist; usage: mass nodeTag m1 m2"), std::string::npos) << mass;
  EXPECT_NE(error_of(interp, "node 9 nan 0.0").find("expected x (a finite number), got 'nan'"), std::string::npos);
}

TEST(TclCommands, ClockwiseAndCollapsedElementsAreRejected) {
  Interpreter interp;
  ASSERT_EQ(error_of(interp, kTwoElementModel), "");
  const std::string cw = error_of(interp, "element SSPquad 3 1 4 5 2 1 PlaneStrain 1.0");
  EXPECT_NE(cw.find("element SSPquad 3"), std::string::npos) << cw;
  EXPECT_NE(cw.find("clockwise"), std::string::npos) << cw;
  EXPECT_NE(cw.find("usage:"), std::string::npos) << cw;
  EXPECT_NE(error_of(interp, "element quad 3 1 4 5 2 1.0 PlaneStrain 1").find("clockwise"), std::string::npos);
  EXPECT_NE(error_of(interp, "element quad 3 1 2 2 4 1.0 PlaneStrain 1").find("collapsed"), std::string::npos);
  EXPECT_NE(error_of(interp, "element tri31 3 1 4 2 1.0 PlaneStrain 1").find("clockwise"), std::string::npos);
  EXPECT_NE(error_of(interp, "element tri31 3 1 2 2 1.0 PlaneStrain 1").find("collapsed"), std::string::npos);
  // OpenSees reads tri31's optional block only when all four values are given; two of them are an error here
  const std::string partial = error_of(interp, "element tri31 3 1 2 5 1.0 PlaneStrain 1 0.0 2.0");
  EXPECT_NE(partial.find("element tri31 3"), std::string::npos) << partial;
  EXPECT_NE(partial.find("pressure rho b1 b2, all four"), std::string::npos) << partial;
  // the failed commands left no element behind
  std::string message;
  ASSERT_TRUE(interp.eval_script("set tags [getEleTags]", "test", message)) << message;
  EXPECT_EQ(error_of(interp, "if {$tags ne {1 2}} { error \"tags $tags\" }"), "");
}

TEST(TclCommands, SingularSystemReturnsNegativeAndKeepsTheLastState) {
  Interpreter interp;
  ASSERT_EQ(error_of(interp, R"tcl(
model basic -ndm 2 -ndf 2
node 1 0 0
node 2 1 0
node 3 1 1
node 4 0 1
nDMaterial ElasticIsotropic 1 1000.0 0.25
element SSPquad 1 1 2 3 4 1 PlaneStrain 1.0
fix 1 0 1
fix 2 0 1
timeSeries Linear 1
pattern Plain 1 1 { load 3 1.0 0.0 }
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1e-10 5
algorithm Newton
integrator LoadControl 1.0
analysis Static
set ok [analyze 1]
)tcl"), "");
  std::string message;
  EXPECT_TRUE(interp.eval_script("if {$ok >= 0} { error \"analyze returned $ok\" }", "test", message)) << message;
  // the state is the last committed one (zero), not garbage
  ASSERT_TRUE(interp.eval_script("set u [nodeDisp 3 1]", "test", message));
  EXPECT_TRUE(interp.eval_script("if {$u != 0.0} { error \"u = $u\" }", "test", message)) << message;
  EXPECT_TRUE(interp.eval_script("if {[getTime] != 0.0} { error \"time [getTime]\" }", "test", message)) << message;
}

TEST(TclCommands, TestIterAndTestNormReportTheLastStep) {
  Interpreter interp;
  ASSERT_EQ(error_of(interp, std::string(kTwoElementModel) + R"tcl(
timeSeries Linear 1
pattern Plain 1 1 { load 6 0.0 -1.0 }
constraints Plain; numberer Plain; system UmfPack; test NormUnbalance 1e-9 10; algorithm Newton
integrator LoadControl 1.0; analysis Static
analyze 1
set it [testIter]
set norms [testNorm]
if {$it < 1 || [llength $norms] != $it || [lindex $norms end] > 1e-9} { error "testIter $it testNorm $norms" }
)tcl"), "");
}

// analysis VariableTransient (OpenSees VariableTimeStepDirectIntegrationAnalysis): after each step
// dt *= Jd / (tests of the step), kept in [dtMin, dtMax]; a failed step counts max_iter + 1 tests, is
// reverted and retried with the smaller dt; the analysis ends once numIncr * dt of time is done.
constexpr const char* kOneQuadUnderRisingLoad = R"tcl(
model basic -ndm 2 -ndf 2
node 1 0 0
node 2 1 0
node 3 1 1
node 4 0 1
nDMaterial ElasticIsotropic 1 1000.0 0.25 2.0
element SSPquad 1 1 2 3 4 1 PlaneStrain 1.0
fix 1 1 1
fix 2 1 1
timeSeries Linear 1
pattern Plain 1 1 { load 3 1.0 0.0; load 4 1.0 0.0 }
constraints Plain; numberer Plain; system BandGeneral
algorithm Newton
integrator Newmark 0.5 0.25
analysis VariableTransient
)tcl";

TEST(TclCommands, VariableTransientGrowsTheStepByJdOverTheIterations) {
  // Linear model, Newton: 2 tests per step (the second sees a zero increment), Jd = 4: dt doubles up to
  // dtMax = 0.05: steps end at 0.01, 0.03, 0.07, 0.12 (the last passes numIncr dt = 0.1, as OpenSees').
  Interpreter interp;
  ASSERT_EQ(error_of(interp, std::string(kOneQuadUnderRisingLoad) + R"tcl(
test NormDispIncr 1e-12 10
set ok [analyze 10 0.01 0.001 0.05 4]
if {$ok != 0} { error "analyze returned $ok" }
if {abs([getTime] - 0.12) > 1e-12} { error "time [getTime]" }
)tcl"), "");
}

TEST(TclCommands, VariableTransientRetriesAFailedStepWithASmallerStep) {
  // One test allowed (maxIter 1): the first step, from rest, passes NormDispIncr 1e-7 at dt = 0.005
  // (6.2e-8) but not at 0.01 (7.0e-7). It fails at 0.01, counts 2 tests, is retried at 0.01 * 1 / 2 and
  // committed at t = 0.005. As the motion grows, steps keep failing until dt <= dtMin: the analysis then
  // returns the failure with the last converged state kept.
  Interpreter interp;
  const std::string dir = test_support::fresh_scratch_folder("unit_fem_tcl_commands", "variable_dt").string();
  ASSERT_EQ(error_of(interp, std::string(kOneQuadUnderRisingLoad) + "recorder Node -file " + dir +
                                 "/variable_dt.out -time -node 3 -dof 1 disp\n" + R"tcl(
test NormDispIncr 1e-7 1
set ok [analyze 10 0.01 1e-5 0.01 1]
remove recorders
if {$ok >= 0} { error "analyze returned $ok" }
if {[getTime] <= 0.005 || [getTime] >= 0.1} { error "time [getTime]" }
)tcl"), "");
  std::ifstream in(dir + "/variable_dt.out");
  double t = 0, u = 0;
  ASSERT_TRUE(in >> t >> u);
  EXPECT_CLOSE(t, 0.005, 1e-12, 0.0);
  EXPECT_TRUE(in >> t >> u);
  EXPECT_CLOSE(t, 0.00625, 1e-12, 0.0);  // 0.005 and 0.0025 failed, 0.00125 passed
}

TEST(TclCommands, VariableTransientNeverRetriesAFailedStepWithTheSameStep) {
  // Jd = 5 > max_iter + 1 = 2: OpenSees would retry at 0.01 * 5 / 2 (capped at dtMax) for ever; here the
  // failed step is halved until dtMin, and analyze returns the failure.
  Interpreter interp;
  ASSERT_EQ(error_of(interp, std::string(kOneQuadUnderRisingLoad) + R"tcl(
test NormDispIncr 1e-30 1
set ok [analyze 10 0.01 1e-4 0.01 5]
if {$ok >= 0} { error "analyze returned $ok" }
if {[getTime] != 0.0} { error "time [getTime]" }
)tcl"), "");
}

TEST(TclCommands, AStepWhoseTimeWouldNotBeFiniteFails) {
  // Found by fuzzing: LoadControl -1e308 is a finite increment, but its second step's load factor is -inf,
  // which the recorders wrote as the time. That step now fails like a diverged one: analyze returns < 0
  // and the domain stays at the last committed step.
  Interpreter interp;
  ASSERT_EQ(error_of(interp, std::string(kTwoElementModel) + R"tcl(
constraints Plain; numberer Plain; system BandGeneral
test NormDispIncr 1e-12 10
algorithm Newton
integrator LoadControl -1e308
analysis Static
set ok [analyze 2]
if {$ok >= 0} { error "analyze returned $ok" }
if {[getTime] != -1e308} { error "time [getTime]" }
)tcl"), "");
}

TEST(TclCommands, AStepWhoseElementForcesAreNotFiniteFails) {
  // Found by fuzzing: an undrained DSS element whose solid dofs were all prescribed kept a NaN PM4Silt stress
  // through 6,000 converged steps, because the residual holds only the free dofs. Here the same situation in its
  // simplest form: element 1 sits on fixed and prescribed nodes only and its stress overflows (E = 1e308), while
  // element 2 carries the free dofs and stays finite. A step whose element forces (constrained dofs included) are
  // not finite fails and the domain stays at the last committed step.
  Interpreter interp;
  ASSERT_EQ(error_of(interp, R"tcl(
model basic -ndm 2 -ndf 2
node 1 0 0; node 2 1 0; node 3 1 1; node 4 0 1; node 5 2 0; node 6 2 1
fix 1 1 1; fix 2 1 1; fix 4 1 1; fix 3 0 1
nDMaterial ElasticIsotropic 1 1.0e308 0.25
nDMaterial ElasticIsotropic 2 1000.0 0.25
element quad 1 1 2 3 4 1.0 PlaneStrain 1
element quad 2 2 5 6 3 1.0 PlaneStrain 2
timeSeries Linear 1
pattern Plain 1 1 { sp 3 1 1.0 }
constraints Transformation; numberer Plain; system FullGeneral
test NormDispIncr 1e-10 10
algorithm Newton
integrator LoadControl 1.0
analysis Static
if {[analyze 1] != 0} { error "the first step (a stress of ~1e308, still finite) failed" }
set ok [analyze 1]
if {$ok >= 0} { error "analyze returned $ok with element 1's stress [eleResponse 1 stress]" }
if {[getTime] != 1.0} { error "time [getTime]" }
)tcl"), "");
}

/// One PM4Silt element, all its nodes fixed, never loaded (zero effective stress), in its plastic stage;
/// `su` is the material's S_u argument (0: S_u = Su_Rat sigma'yy at FirstCall).
std::string unconsolidated_pm4silt(const std::string& su) {
  return R"tcl(
model basic -ndm 2 -ndf 2
node 1 0 0; node 2 1 0; node 3 1 1; node 4 0 1
fix 1 1 1; fix 2 1 1; fix 3 1 1; fix 4 1 1
nDMaterial PM4Silt 1 )tcl" + su + R"tcl( 0.25 500.0 4.0 1.7
element SSPquad 1 1 2 3 4 1 PlaneStrain 1.0
updateMaterialStage -material 1 -stage 1
)tcl";
}

TEST(TclCommands, PM4SiltFirstCallWithoutEffectiveStressIsAnError) {
  // S_u = Su_Rat sigma'yy at FirstCall: at zero effective stress OpenSees takes the log of p_cs = 0 and every
  // stress after it is NaN (the fuzz case above, in its PM4Silt form). One line naming the material.
  Interpreter interp;
  ASSERT_EQ(error_of(interp, unconsolidated_pm4silt("0.0")), "");
  const std::string e = error_of(interp, "setParameter -val 0 -ele 1 FirstCall 1");
  EXPECT_NE(e.find("nDMaterial PM4Silt 1"), std::string::npos) << e;
  EXPECT_NE(e.find("needs a compressive vertical effective stress"), std::string::npos) << e;
  // With S_u given, the same unconsolidated element initialises.
  Interpreter given;
  ASSERT_EQ(error_of(given, unconsolidated_pm4silt("1.0")), "");
  EXPECT_EQ(error_of(given, "setParameter -val 0 -ele 1 FirstCall 1"), "");
}

TEST(TclCommands, VariableTransientAnalyzeNeedsDtMinDtMaxAndJd) {
  Interpreter interp;
  ASSERT_EQ(error_of(interp, std::string(kOneQuadUnderRisingLoad) + "test NormDispIncr 1e-12 10\n"), "");
  EXPECT_NE(error_of(interp, "analyze 10 0.01").find("dtMin"), std::string::npos);
  EXPECT_NE(error_of(interp, "analyze 10 0.01 0.02 0.01 4").find("dtMin <= dtMax"), std::string::npos);
  EXPECT_NE(error_of(interp, "analyze 10 0.01 0.001 0.05 0").find("Jd >= 1"), std::string::npos);
}

// `remove sp nodeTag dofTag <patternTag>` (OpenSees Domain::removeSP_Constraint): the support is gone from
// the next step on, so the force it carried moves the model (a support taken away, an excavation).
TEST(TclCommands, RemoveSpFreesTheDofForTheNextStep) {
  Interpreter interp;
  ASSERT_EQ(error_of(interp, std::string(kTwoElementModel) + R"tcl(
fix 6 1 0
timeSeries Constant 1
pattern Plain 1 1 { load 6 1.0 0.0 }
pattern Plain 2 1 { sp 3 1 0.0 }
constraints Transformation; numberer Plain; system UmfPack; test NormDispIncr 1e-12 10; algorithm Newton
integrator LoadControl 1.0; analysis Static
analyze 1
set held [nodeDisp 6 1]
remove sp 6 1
analyze 1
set free [nodeDisp 6 1]
set u3 [nodeDisp 3 1]
remove sp 3 1 2
analyze 1
)tcl"), "");
  EXPECT_EQ(std::stod(interp.eval("set held")), 0.0);
  EXPECT_GT(std::stod(interp.eval("set free")), 1e-6);  // the load now pushes the free node
  EXPECT_EQ(std::stod(interp.eval("set u3")), 0.0);     // still held by pattern 2's sp
  EXPECT_GT(std::abs(std::stod(interp.eval("nodeDisp 3 1"))), 1e-6);
  EXPECT_NE(error_of(interp, "remove sp 6 3").find("expected dofTag 1..2 (node 6 has 2), got 3"), std::string::npos);
  EXPECT_NE(error_of(interp, "remove sp 99 1").find("99"), std::string::npos);
  EXPECT_NE(error_of(interp, "remove sp 6 1 7").find("load pattern 7 does not exist"), std::string::npos);
  EXPECT_EQ(error_of(interp, "remove sp 6 1"), "");  // nothing left to remove: a warning, as OpenSees goes on
}

// A column of two stacked 1 m SSPquads under their own weight (10 each), base fixed, sides on rollers.
constexpr const char* kTwoStackedElements = R"tcl(
model basic -ndm 2 -ndf 2
node 1 0 0
node 2 1 0
node 3 1 1
node 4 0 1
node 5 1 2
node 6 0 2
nDMaterial ElasticIsotropic 1 1000.0 0.0 2.0
element SSPquad 1 1 2 3 4 1 PlaneStrain 1.0 0.0 -10.0
element SSPquad 2 4 3 5 6 1 PlaneStrain 1.0 0.0 -10.0
fix 1 1 1
fix 2 1 1
fixX 0.0 1 0
fixX 1.0 1 0
)tcl";

// `remove element tag` (an excavation): the element's weight and stiffness are gone from the next step on;
// an Element recorder keeps its columns, written as zeros; a node left without stiffness is named.
TEST(TclCommands, RemoveElementTakesItsWeightAndKeepsTheRecorderColumns) {
  Interpreter interp;
  const std::string dir = test_support::fresh_scratch_folder("unit_fem_tcl_commands", "remove_element").string();
  ASSERT_EQ(error_of(interp, std::string(kTwoStackedElements) +
                             "recorder Element -file " + dir + "/s.out -ele 1 2 stress\n" + R"tcl(
constraints Plain; numberer Plain; system UmfPack; test NormDispIncr 1e-12 10; algorithm Newton
integrator LoadControl 1.0; analysis Static
analyze 1
set before [lindex [eleResponse 1 stress] 1]
remove element 2
set ok [analyze 1]
)tcl"), "");
  // node 5 and 6 hang free: the system is singular and the step fails, naming the node
  EXPECT_LT(std::stod(interp.eval("set ok")), 0.0);
  ASSERT_EQ(error_of(interp, "fix 5 1 1\nfix 6 1 1\nset ok [analyze 1]\nset after [lindex [eleResponse 1 stress] 1]\n"
                             "remove recorders"),
            "");
  EXPECT_EQ(std::stod(interp.eval("set ok")), 0.0);
  // syy of the lower (constant-stress) element: the force through it, the upper element's weight 10 and the
  // half of its own lumped on its top nodes, 5; then only those 5
  EXPECT_CLOSE(std::stod(interp.eval("set before")), -15.0, 1e-9, 0.0);
  EXPECT_CLOSE(std::stod(interp.eval("set after")), -5.0, 1e-9, 0.0);
  std::ifstream in(dir + "/s.out");
  std::string line, last;
  int rows = 0;
  while (std::getline(in, line)) { ++rows; last = line; }
  EXPECT_EQ(rows, 2);  // the failed step recorded nothing
  std::istringstream words(last);
  std::vector<double> v;
  for (double x; words >> x;) v.push_back(x);
  ASSERT_EQ(v.size(), 6u);
  EXPECT_CLOSE(v[1], -5.0, 1e-9, 0.0);
  EXPECT_EQ(v[3], 0.0);
  EXPECT_EQ(v[4], 0.0);
  EXPECT_EQ(v[5], 0.0);
  EXPECT_NE(error_of(interp, "remove element 2").find("element 2 does not exist"), std::string::npos);
}

// `remove node tag` after its elements: the free nodes of an excavation go, so the next step runs; a Node
// recorder writes zeros in its columns; a node an element still uses cannot go.
TEST(TclCommands, RemoveNodeAfterItsElements) {
  Interpreter interp;
  const std::string dir = test_support::fresh_scratch_folder("unit_fem_tcl_commands", "remove_node").string();
  ASSERT_EQ(error_of(interp, std::string(kTwoStackedElements) + "equalDOF 5 6 2\n"
                             "recorder Node -file " + dir + "/u.out -node 3 5 -dof 2 disp\n" + R"tcl(
constraints Transformation; numberer Plain; system UmfPack; test NormDispIncr 1e-12 10; algorithm Newton
integrator LoadControl 1.0; analysis Static
analyze 1
remove element 2
remove node 5
remove node 6
set ok [analyze 1]
remove recorders
)tcl"), "");
  EXPECT_EQ(std::stod(interp.eval("set ok")), 0.0);
  EXPECT_NE(error_of(interp, "remove node 3").find("node 3 is a node of element 1"), std::string::npos);
  EXPECT_NE(error_of(interp, "remove node 5").find("node 5 does not exist"), std::string::npos);
  std::ifstream in(dir + "/u.out");
  double u3a = 0, u5a = 0, u3b = 0, u5b = 1;
  ASSERT_TRUE(in >> u3a >> u5a >> u3b >> u5b);
  EXPECT_LT(u5a, u3a);         // the top settles more than the middle under both weights
  EXPECT_GT(u3b, u3a);         // the middle rises once the upper element is gone
  EXPECT_EQ(u5b, 0.0);         // the removed node's column
}

TEST(FemTclExecutable, UncaughtErrorGivesFileLineMessageExitTwoAndFlushedRecorders) {
  test_support::ScratchDir dir("fem_tcl_uncaught");
  {
    std::ofstream script(dir.path() / "bad.tcl");
    script << kTwoElementModel
           << "recorder Node -file d.out -time -node 3 6 -dof 1 2 disp\n"
              "timeSeries Linear 1\n"
              "pattern Plain 1 1 { load 6 0.0 -1.0 }\n"
              "constraints Plain; numberer Plain; system UmfPack; test NormDispIncr 1e-12 5; algorithm Newton\n"
              "integrator LoadControl 0.5\n"
              "analysis Static\n"
              "analyze 2\n"
              "nodeDisp 99\n";
  }
  const int status = test_support::run_fem_tcl(GEOFLOW_BIN_DIR, dir.path(), "bad.tcl");
  EXPECT_EQ(status, 2);
  const std::string err = test_support::read_text(dir.path() / "stderr.txt");
  EXPECT_NE(err.find("bad.tcl:21: nodeDisp 99: node 99 does not exist"), std::string::npos) << err;
  const auto rows = test_support::read_numeric_table(dir.path() / "d.out");
  ASSERT_EQ(rows.size(), 2u);  // both committed steps are on disk
  EXPECT_EQ(rows[1].size(), 5u);
}

TEST(FemTclExecutable, ArgvStdinPutsAndNodeRecorderWithoutDof) {
  test_support::ScratchDir dir("fem_tcl_argv");
  {
    std::ofstream script(dir.path() / "args.tcl");
    script << "puts stdout \"argc=$argc argv=$argv argv0=[file tail $argv0]\"\n"
              "puts \"to stderr\"\n"
              "model basic -ndm 2 -ndf 2\nnode 1 0 0\n"
              "recorder Node -file none.out -node 1 disp\n"
              "record\n";
  }
  ASSERT_EQ(test_support::run_fem_tcl(GEOFLOW_BIN_DIR, dir.path(), "args.tcl", "a b"), 0);
  EXPECT_EQ(test_support::read_text(dir.path() / "stdout.txt"), "argc=2 argv=a b argv0=args.tcl\n");
  const std::string err = test_support::read_text(dir.path() / "stderr.txt");
  EXPECT_NE(err.find("to stderr"), std::string::npos);
  EXPECT_NE(err.find("no -dof given"), std::string::npos) << err;
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "none.out"));
  EXPECT_EQ(std::filesystem::file_size(dir.path() / "none.out"), 0u);
  // no script: commands come from standard input
  const std::string cmd = "cd '" + dir.path().string() + "' && echo 'puts stdout [expr {6*7}]' | '" +
                          std::string(GEOFLOW_BIN_DIR) + "/fem_tcl' > stdin_out.txt";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  EXPECT_EQ(test_support::read_text(dir.path() / "stdin_out.txt"), "42\n");
}

}  // namespace

namespace {

/// Two SSPquads side by side: either sharing nodes 2 and 5, or with duplicated interface nodes (7, 8) tied
/// by equalDOF. Returns the tip displacement (node 6 uy) under a tip load.
double tied_tip(const std::string& handler, bool tied) {
  Interpreter interp;
  std::string script = R"tcl(
model basic -ndm 2 -ndf 2
node 1 0 0; node 2 1 0; node 3 2 0; node 4 0 1; node 5 1 1; node 6 2 1
fix 1 1 1; fix 4 1 1
nDMaterial ElasticIsotropic 1 1000.0 0.25
element SSPquad 1 1 2 5 4 1 PlaneStrain 1.0
)tcl";
  script += tied ? "node 7 1 0; node 8 1 1\nequalDOF 2 7 1 2\nequalDOF 5 8 1 2\nelement SSPquad 2 7 3 6 8 1 PlaneStrain 1.0\n"
                 : "element SSPquad 2 2 3 6 5 1 PlaneStrain 1.0\n";
  script += "timeSeries Linear 1\npattern Plain 1 1 { load 6 0.0 -1.0 }\nconstraints " + handler +
            "\nnumberer Plain; system UmfPack; test NormDispIncr 1e-14 10; algorithm Newton\n"
            "integrator LoadControl 1.0; analysis Static\nif {[analyze 1] != 0} { error failed }\n";
  std::string message;
  EXPECT_TRUE(interp.eval_script(script, "tied", message)) << message;
  return interp.context().domain.find_node(6)->disp[1];
}

TEST(TclCommands, ConstraintHandlersEnforceEqualDofAndSupports) {
  const double shared = tied_tip("Transformation", false);
  ASSERT_LT(shared, 0.0);
  EXPECT_CLOSE(tied_tip("Transformation", true), shared, 0.0, 1e-12);
  EXPECT_CLOSE(tied_tip("Plain", true), shared, 0.0, 1e-12);  // enforced by transformation, with a warning
  // penalty numbers 1e12 against stiffnesses ~1e3: the constraint error is ~1e-9 relative
  EXPECT_CLOSE(tied_tip("Penalty 1.0e12 1.0e12", true), shared, 0.0, 1e-6);
  EXPECT_CLOSE(tied_tip("Penalty 1.0e12 1.0e12", false), shared, 0.0, 1e-6);
}

TEST(TclCommands, RecorderTagsAndRemoval) {
  test_support::ScratchDir dir("fem_tcl_rectags");
  Interpreter interp;
  ASSERT_EQ(error_of(interp, kTwoElementModel), "");
  std::string message;
  const std::string a = (dir.path() / "a.out").string(), b = (dir.path() / "b.out").string();
  ASSERT_TRUE(interp.eval_script("set r0 [recorder Node -file " + a + " -node 3 -dof 1 disp]\n"
                                 "set r1 [recorder Node -file " + b + " -node 3 -dof 2 disp]\n"
                                 "if {$r0 != 0 || $r1 != 1} { error \"tags $r0 $r1\" }\n"
                                 "remove recorder 0\nrecord\n",
                                 "test", message))
      << message;
  EXPECT_NE(error_of(interp, "remove recorder 5").find("recorder 5 does not exist"), std::string::npos);
  interp.context().domain.flush_recorders();
  EXPECT_EQ(test_support::read_numeric_table(a).size(), 0u);
  EXPECT_EQ(test_support::read_numeric_table(b).size(), 1u);
}

TEST(TclCommands, ConflictingTieAndMasslessExplicitStepAreSaid) {
  // fix on the constrained dof of an equalDOF: the tie cannot hold (Transformation), so a warning says so;
  // CentralDifference on a massless model names the missing mass, not a missing support.
  Interpreter interp;
  ASSERT_EQ(error_of(interp, std::string(kTwoElementModel) + "fix 3 1 0\nequalDOF 6 3 1 2\n"), "");
  testing::internal::CaptureStderr();
  EXPECT_EQ(interp.eval("constraints Transformation; numberer Plain; system UmfPack; test NormUnbalance 1e-10 5\n"
                        "algorithm Newton; integrator LoadControl 1.0; analysis Static; analyze 1"),
            "0");
  const std::string tie = testing::internal::GetCapturedStderr();
  EXPECT_NE(tie.find("WARNING equalDOF 6 3: dof 1 of the constrained node 3 is also fixed"), std::string::npos) << tie;
  Interpreter explicit_step;
  ASSERT_EQ(error_of(explicit_step, "model basic -ndm 2 -ndf 2\nnode 1 0 0; node 2 1 0; node 3 1 1; node 4 0 1\n"
                                    "fix 1 1 1; fix 2 1 1\nnDMaterial ElasticIsotropic 1 1000.0 0.25\n"
                                    "element quad 1 1 2 3 4 1.0 PlaneStrain 1\n"),
            "");
  testing::internal::CaptureStderr();
  EXPECT_EQ(explicit_step.eval("constraints Plain; numberer Plain; system UmfPack; test NormUnbalance 1e-10 5\n"
                               "algorithm Linear; integrator CentralDifference; analysis Transient; analyze 1 0.01"),
            "-3");
  const std::string massless = testing::internal::GetCapturedStderr();
  EXPECT_NE(massless.find("node 3 dof 1 has no mass"), std::string::npos) << massless;
}

TEST(TclCommands, EnvelopeRecordersWriteMinMaxAndAbsMaxRows) {
  // OpenSees' EnvelopeNode / EnvelopeElement: three rows (min, max, max |.|) of each column over the
  // steps recorded, with -time the time of each before it. A spring-mass released from u0 = 0.01 swings
  // between -u0 and +u0 (undamped trapezoidal rule: the amplitude is kept).
  test_support::ScratchDir dir("fem_tcl_envelope");
  Interpreter interp;
  const std::string node = (dir.path() / "env_node.out").string(), ele = (dir.path() / "env_ele.out").string();
  std::string message;
  ASSERT_TRUE(interp.eval_script("model basic -ndm 2 -ndf 2\nnode 1 0 0; node 2 0 0\nfix 1 1 1; fix 2 0 1\n"
                                 "mass 2 1.0 1.0\nuniaxialMaterial Elastic 1 100.0\n"
                                 "element zeroLength 1 1 2 -mat 1 -dir 1\n"
                                 "recorder EnvelopeNode -file " + node + " -time -node 2 -dof 1 disp\n"
                                 "recorder EnvelopeElement -file " + ele + " -ele 1 force\n",
                                 "test", message))
      << message;
  // u0 = 0.01 by a static step under a unit load, then free vibration
  ASSERT_TRUE(interp.eval_script("timeSeries Constant 1\npattern Plain 1 1 { load 2 1.0 0.0 }\n"
                                 "constraints Plain; numberer Plain; system UmfPack; test NormUnbalance 1e-10 5\n"
                                 "algorithm Linear; integrator LoadControl 1.0; analysis Static; analyze 1\n"
                                 "loadConst -time 0.0; remove loadPattern 1; wipeAnalysis\n"
                                 "constraints Plain; numberer Plain; system UmfPack; test NormUnbalance 1e-10 5\n"
                                 "algorithm Linear; integrator Newmark 0.5 0.25; analysis Transient; analyze 200 0.01\n",
                                 "test", message))
      << message;
  interp.context().domain.flush_recorders();
  const auto rows = test_support::read_numeric_table(node);
  ASSERT_EQ(rows.size(), 3u);
  ASSERT_EQ(rows[0].size(), 2u);  // time, value
  EXPECT_NEAR(rows[0][1], -0.01, 2e-4);  // min (the 200 steps of 0.01 s sample the 0.63 s period finely)
  EXPECT_NEAR(rows[1][1], 0.01, 1e-12);  // max: the start (the static state, recorded at t = 0)
  EXPECT_EQ(rows[2][1], std::max(std::abs(rows[0][1]), rows[1][1]));
  EXPECT_GT(rows[0][0], 0.0);  // the time of the minimum, about half a period in
  const auto forces = test_support::read_numeric_table(ele);
  ASSERT_EQ(forces.size(), 3u);
  ASSERT_EQ(forces[0].size(), 4u);  // the forces at the two nodes (x, y)
  EXPECT_NEAR(forces[2][2], 1.0, 1e-12);  // largest |force| at node 2 along x: k u0 = 1, at the start
  EXPECT_NEAR(forces[0][2], -1.0, 2e-2);
}

TEST(TclCommands, NodeRecorderTimeSeriesAddsTheGroundMotion) {
  // OpenSees' -timeSeries: the series factor is added to the recorded response (absolute acceleration =
  // relative + ground under UniformExcitation); one series per -dof entry.
  test_support::ScratchDir dir("fem_tcl_abs_accel");
  Interpreter interp;
  const std::string rel = (dir.path() / "rel.out").string(), abs = (dir.path() / "abs.out").string();
  std::string message;
  ASSERT_TRUE(interp.eval_script("model basic -ndm 2 -ndf 2\nnode 1 0 0; node 2 0 0\nfix 1 1 1; fix 2 0 1\n"
                                 "mass 2 1.0 1.0\nuniaxialMaterial Elastic 1 100.0\n"
                                 "element zeroLength 1 1 2 -mat 1 -dir 1\n"
                                 "timeSeries Path 2 -dt 0.1 -values {0.0 1.0 -2.0 0.5 0.0} -factor 9.81\n"
                                 "pattern UniformExcitation 3 1 -accel 2\n"
                                 "recorder Node -file " + rel + " -time -node 2 -dof 1 accel\n"
                                 "recorder Node -file " + abs + " -time -timeSeries 2 -node 2 -dof 1 accel\n"
                                 "constraints Plain; numberer Plain; system UmfPack; test NormUnbalance 1e-10 5\n"
                                 "algorithm Linear; integrator Newmark 0.5 0.25; analysis Transient; analyze 4 0.1\n",
                                 "test", message))
      << message;
  interp.context().domain.flush_recorders();
  const auto r = test_support::read_numeric_table(rel), a = test_support::read_numeric_table(abs);
  ASSERT_EQ(r.size(), 4u);
  ASSERT_EQ(a.size(), 4u);
  const double ground[] = {9.81, -19.62, 4.905, 0.0};  // the series at t = 0.1 .. 0.4
  for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(a[k][1] - r[k][1], ground[k], 1e-4) << "row " << k;
  EXPECT_NE(error_of(interp, "recorder Node -file " + abs + " -timeSeries 9 -node 2 -dof 1 accel").find(
                "timeSeries 9 does not exist"),
            std::string::npos);
}

TEST(TclCommands, PrintNodesAndElementsAsText) {
  // OpenSees' `print -node tags`, `print -ele tags`, `print file`: text to stderr (opserr) or the file.
  test_support::ScratchDir dir("fem_tcl_print");
  Interpreter interp;
  ASSERT_EQ(error_of(interp, kTwoElementModel), "");
  testing::internal::CaptureStderr();
  EXPECT_EQ(interp.eval("print -node 5 6; print -ele -flag 1 2"), "");
  const std::string text = testing::internal::GetCapturedStderr();
  EXPECT_NE(text.find(" Node: 5\n\tCoordinates  : 1 1\n"), std::string::npos) << text;
  EXPECT_NE(text.find(" Node: 6\n"), std::string::npos) << text;
  EXPECT_EQ(text.find(" Node: 4\n"), std::string::npos) << text;
  EXPECT_NE(text.find("Element: 2 type: SSPquad\n\tConnected Nodes: 2 3 6 5\n"), std::string::npos) << text;
  const std::string file = (dir.path() / "model.txt").string();
  EXPECT_EQ(interp.eval("print " + file), "");
  std::ifstream in(file);
  const std::string whole((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(whole.find(" Node: 1\n"), std::string::npos);
  EXPECT_NE(whole.find("Element: 1 type: FourNodeQuad"), std::string::npos) << whole;
  EXPECT_NE(error_of(interp, "print -node 99").find("node 99"), std::string::npos);
}

TEST(TclCommands, AnErrorInsideLoopsNamesItsOwnLine) {
  // Meshes are built in loops: the line named is the failing command's, not the outer loop's first
  // (errorInfo's '("for" body line N)' frames summed), also through a procedure called in a loop.
  Interpreter interp;
  std::string message;
  EXPECT_FALSE(interp.eval_script("model basic -ndm 2 -ndf 2\n"                         // 1
                                  "for {set j 0} {$j < 2} {incr j} {\n"                 // 2
                                  "  for {set i 0} {$i < 2} {incr i} {\n"               // 3
                                  "    set n [expr {$i + 1}]\n"                         // 4
                                  "    element quad 1 1 2 3 4 1.0 PlaneStrain 7\n"      // 5
                                  "  }\n}\n",
                                  "mesh.tcl", message));
  EXPECT_EQ(message.rfind("mesh.tcl:5: element quad 1", 0), 0u) << message;
  EXPECT_FALSE(interp.eval_script("proc fail {} {\n  error boom\n}\n"                  // 1-3
                                  "foreach k {1 2} {\n"                                 // 4
                                  "  set m $k\n"                                        // 5
                                  "  if {$k == 2} {\n"                                  // 6
                                  "    fail\n"                                          // 7
                                  "  }\n}\n",
                                  "calls.tcl", message));
  EXPECT_EQ(message, "calls.tcl:7: boom");
}

TEST(TclCommands, RecordersWithoutASelectionRecordEveryNodeAndElement) {
  // OpenSees: a Node recorder without -node/-nodeRange/-region records every node of the domain at its
  // first row (NodeRecorder::initialize), an Element recorder without -ele every element (and -ele all).
  test_support::ScratchDir dir("fem_tcl_recall");
  Interpreter interp;
  ASSERT_EQ(error_of(interp, kTwoElementModel), "");
  const std::string nodes = (dir.path() / "nodes.out").string(), all = (dir.path() / "all.out").string(),
                    listed = (dir.path() / "listed.out").string(), some = (dir.path() / "some.out").string();
  std::string message;
  ASSERT_TRUE(interp.eval_script("recorder Node -file " + nodes + " -time -dof 1 2 disp\n"
                                 "recorder Element -file " + all + " stress\n"
                                 "recorder Element -file " + listed + " -ele all stress\n"
                                 "recorder Element -file " + some + " -ele 2 stress\n"
                                 "node 7 3 0; fix 7 1 1\n"  // defined after the recorder, before its first row
                                 "timeSeries Linear 1\npattern Plain 1 1 { load 6 0.0 -1.0 }\n"
                                 "constraints Plain; numberer Plain; system UmfPack; test NormUnbalance 1e-10 5\n"
                                 "algorithm Newton; integrator LoadControl 1.0; analysis Static; analyze 1\n",
                                 "test", message))
      << message;
  interp.context().domain.flush_recorders();
  const auto node_rows = test_support::read_numeric_table(nodes);
  ASSERT_EQ(node_rows.size(), 1u);
  EXPECT_EQ(node_rows[0].size(), 1u + 7u * 2u);  // time, then ux uy of nodes 1..7
  EXPECT_NE(node_rows[0][1 + 2 * 5 + 1], 0.0);   // uy of node 6, loaded
  const auto all_rows = test_support::read_numeric_table(all), some_rows = test_support::read_numeric_table(some);
  ASSERT_EQ(all_rows.size(), 1u);
  ASSERT_EQ(some_rows.size(), 1u);
  EXPECT_EQ(all_rows[0].size(), 4u * 3u + 3u);  // quad: 4 points x 3 values, SSPquad: 3 values
  EXPECT_EQ(test_support::read_numeric_table(listed), all_rows);
  EXPECT_EQ(std::vector<double>(all_rows[0].end() - 3, all_rows[0].end()), some_rows[0]);
}

}  // namespace

namespace {

constexpr const char* kOneSSPquad = R"tcl(
model basic -ndm 2 -ndf 2
node 1 0 0; node 2 1 0; node 3 1 1; node 4 0 1
fix 1 1 1; fix 2 1 1
nDMaterial ElasticIsotropic 1 1000.0 0.0
)tcl";

/// Base reaction Ry (nodes 1 + 2) after each of two LoadControl 0.5 steps, with `pattern_body` in a
/// Linear pattern and an SSPquad whose body force is b2 = -10 (weight 10).
std::pair<double, double> base_reactions(const std::string& pattern_body) {
  Interpreter interp;
  interp.eval(std::string(kOneSSPquad) + R"tcl(
element SSPquad 1 1 2 3 4 1 PlaneStrain 1.0 0.0 -10.0
timeSeries Linear 1
pattern Plain 1 1 {)tcl" + pattern_body + R"tcl(}
constraints Plain; numberer Plain; system UmfPack; test NormUnbalance 1e-10 5; algorithm Newton
integrator LoadControl 0.5; analysis Static
)tcl");
  const auto step = [&] {
    interp.eval("analyze 1; reactions");
    return std::stod(interp.eval("expr {[nodeReaction 1 2] + [nodeReaction 2 2]}"));
  };
  const double r1 = step();
  return {r1, step()};
}

TEST(TclCommands, BodyForceIsAlwaysOnUnlessSelfWeightIsPatterned) {
  // quirk 1: the element body force is applied in full from the first step
  const auto plain = base_reactions("");
  EXPECT_CLOSE(plain.first, 10.0, 1e-12, 1e-12);
  EXPECT_CLOSE(plain.second, 10.0, 1e-12, 1e-12);
  // eleLoad -selfWeight replaces it by the pattern-scaled body force
  const auto ramped = base_reactions("eleLoad -ele 1 -type -selfWeight 0.0 1.0");
  EXPECT_CLOSE(ramped.first, 5.0, 1e-12, 1e-12);
  EXPECT_CLOSE(ramped.second, 10.0, 1e-12, 1e-12);
}

TEST(TclCommands, UniformExcitationLoadsNodalMassesAsMinusMAg) {
  // Nodal masses only (no element density); a constant ground acceleration ag in x acts as -m ag on the
  // free nodes. With mass-proportional damping (about critical for the slow mode) the relative response settles on the static
  // solution under nodal loads -m ag.
  Interpreter stat;
  stat.eval(std::string(kOneSSPquad) + R"tcl(
element SSPquad 1 1 2 3 4 1 PlaneStrain 1.0
timeSeries Constant 1
pattern Plain 1 1 { load 3 -2.0 0.0; load 4 -2.0 0.0 }
constraints Plain; numberer Plain; system BandSPD; test NormDispIncr 1e-12 5; algorithm Linear
integrator LoadControl 1.0; analysis Static
analyze 1
)tcl");
  const double u_static = std::stod(stat.eval("nodeDisp 3 1"));
  ASSERT_LT(u_static, 0.0);
  Interpreter dyn;
  dyn.eval(std::string(kOneSSPquad) + R"tcl(
element SSPquad 1 1 2 3 4 1 PlaneStrain 1.0
mass 3 1.0 1.0
node 5 5 5 -mass 7.0 7.0
fix 5 1 1
mass 4 1.0 1.0
timeSeries Constant 2 -factor 2.0
pattern UniformExcitation 2 1 -accel 2
rayleigh 10.0 0.0 0.0 0.0
constraints Plain; numberer Plain; system BandSPD; test NormDispIncr 1e-12 5; algorithm Linear
integrator Newmark 0.5 0.25; analysis Transient
analyze 1200 0.005
)tcl");
  EXPECT_CLOSE(std::stod(dyn.eval("nodeDisp 3 1")), u_static, 0.0, 1e-6);
  EXPECT_CLOSE(std::stod(dyn.eval("nodeDisp 4 1")), std::stod(stat.eval("nodeDisp 4 1")), 0.0, 1e-6);
}

}  // namespace

namespace {

// recorder Node ... unbalance: the applied nodal loads of the step (OpenSees Node::getUnbalancedLoad), here
// a Linear pattern's load at 0.5 and 1.0 of its factor; fem2mpm --loads reads it.
TEST(TclCommands, NodeRecorderUnbalanceHoldsTheAppliedLoads) {
  test_support::ScratchDir dir("fem_tcl_unbalance");
  Interpreter interp;
  const std::string f = (dir.path() / "loads.out").string();
  ASSERT_EQ(error_of(interp, std::string(kOneSSPquad) + R"tcl(
element SSPquad 1 1 2 3 4 1 PlaneStrain 1.0
timeSeries Linear 1
pattern Plain 1 1 { load 3 2.0 -6.0; load 4 0.0 -4.0 }
recorder Node -file )tcl" + f + R"tcl( -time -node 3 4 -dof 1 2 unbalance
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1e-10 5
algorithm Newton
integrator LoadControl 0.5
analysis Static
analyze 2
)tcl"), "");
  interp.context().domain.flush_recorders();
  const auto rows = test_support::read_numeric_table(f);
  ASSERT_EQ(rows.size(), 2u);
  const std::vector<double> half = {0.5, 1.0, -3.0, 0.0, -2.0}, full = {1.0, 2.0, -6.0, 0.0, -4.0};
  EXPECT_EQ(rows[0], half);
  EXPECT_EQ(rows[1], full);
  EXPECT_NE(error_of(interp, "recorder Node -file x.out -node 3 -dof 1 loads").find("unbalance"), std::string::npos);
}

}  // namespace

namespace {
// `-elasticTangent` algorithms keep the factored elastic matrix from step to step (Analysis::KeptMatrix);
// any command in between makes the next step form it again. algorithm Linear takes one solve per step on
// that matrix, so a kept matrix of the old modulus would give a wrong displacement (u1 + K1^-1 (F2 - K2 u1)
// instead of K2^-1 F2).
TEST(ElasticTangentReuse, AParameterChangedBetweenAnalyzeCallsIsSeen) {
  Interpreter interp;
  interp.eval(R"tcl(
    model basic -ndm 2 -ndf 2
    node 1 0 0; node 2 1 0; node 3 1 1; node 4 0 1
    fix 1 1 1; fix 2 1 1
    nDMaterial ElasticIsotropic 1 1000.0 0.25
    element quad 1 1 2 3 4 1.0 PlaneStrain 1
    timeSeries Linear 1
    pattern Plain 1 1 { load 3 1.0 0.0; load 4 1.0 0.0 }
    constraints Plain; numberer Plain; system UmfPack
    test NormDispIncr 1e-12 5; algorithm Linear -elasticTangent
    integrator LoadControl 1.0; analysis Static
    analyze 1
  )tcl");
  const double u1 = std::stod(interp.eval("nodeDisp 3 1"));
  interp.eval("analyze 1");  // load factor 2, nothing changed: the kept matrix is right
  EXPECT_CLOSE(std::stod(interp.eval("nodeDisp 3 1")), 2.0 * u1, 1e-12, 0.0);
  interp.eval("setParameter -val 4000.0 -ele 1 E\nanalyze 1");  // load factor 3 on a 4x stiffer element
  EXPECT_CLOSE(std::stod(interp.eval("nodeDisp 3 1")), 3.0 * u1 / 4.0, 1e-12, 0.0);
}
}  // namespace
