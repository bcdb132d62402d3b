// Unit tests: the commands of an OpenSees site-response script -- uniaxialMaterial Elastic / Viscous,
// element zeroLength, timeSeries Path (PathSeries with -dt, PathTimeSeries with -time / files), Trig,
// Rectangular, Pulse, inline pattern series and UniformExcitation -vel0 -- against OpenSees 3.8's formulas
// (SRC/material/uniaxial/ElasticMaterial.cpp, ViscousMaterial.cpp, SRC/element/zeroLength/ZeroLength.cpp,
// SRC/domain/pattern/PathSeries.cpp, PathTimeSeries.cpp, TrigSeries.cpp, RectangularSeries.cpp,
// PulseSeries.cpp, UniformExcitation.cpp), and their bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "fem_tcl/materials/uniaxial_elastic.hpp"
#include "fem_tcl/materials/uniaxial_viscous.hpp"
#include "fem_tcl/tcl/interpreter.hpp"
#include "support/recorder_compare.hpp"
#include "support/scratch.hpp"
#include "support/tolerance.hpp"

namespace {

namespace fs = std::filesystem;
using fem::tcl::Interpreter;

std::string error_of(Interpreter& interp, const std::string& script) {
  std::string message;
  return interp.eval_script(script, "test", message) ? std::string() : message;
}

double series_at(Interpreter& interp, int tag, double t) { return interp.context().time_series.at(tag)->factor(t); }

constexpr const char* kModel = "model basic -ndm 2 -ndf 2\n";

// ---------------------------------------------------------------- time series
TEST(PathSeries, DtSeriesInterpolatesAndEndsOneSampleEarlyUnlessUseLast) {
  Interpreter interp;
  interp.eval(std::string(kModel) +
              "timeSeries Path 1 -dt 0.1 -values {0 1 2}\n"
              "timeSeries Path 2 -dt 0.1 -values {0 1 2} -useLast -factor 2\n"
              "timeSeries Path 3 -dt 0.1 -values {1 2} -prependZero -startTime 1.0\n"
              "timeSeries Path 4 -dt 0.1 -values 0 1 2\n");
  EXPECT_CLOSE(series_at(interp, 1, 0.0), 0.0, 1e-15, 0.0);
  EXPECT_CLOSE(series_at(interp, 1, 0.05), 0.5, 1e-12, 0.0);
  EXPECT_CLOSE(series_at(interp, 1, 0.15), 1.5, 1e-12, 0.0);
  EXPECT_CLOSE(series_at(interp, 4, 0.15), 1.5, 1e-12, 0.0);  // -values as separate words
  EXPECT_EQ(series_at(interp, 1, -0.1), 0.0);
  // OpenSees PathSeries::getFactor: the last sample's own time already counts as past the end
  testing::internal::CaptureStderr();
  EXPECT_EQ(series_at(interp, 1, 0.2), 0.0);
  EXPECT_EQ(series_at(interp, 1, 5.0), 0.0);
  const std::string warning = testing::internal::GetCapturedStderr();
  EXPECT_NE(warning.find("WARNING timeSeries Path 1: queried at t = 0.2, past its end"), std::string::npos) << warning;
  EXPECT_EQ(warning.find("WARNING", 10), std::string::npos) << "warned once: " << warning;
  // a record that ends at 0 gives the same 0 either way: no warning
  interp.eval("timeSeries Path 9 -dt 0.1 -values {0 1 0}");
  testing::internal::CaptureStderr();
  EXPECT_EQ(series_at(interp, 9, 3.0), 0.0);
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  EXPECT_CLOSE(series_at(interp, 2, 0.2), 4.0, 1e-15, 0.0);
  EXPECT_CLOSE(series_at(interp, 2, 9.0), 4.0, 1e-15, 0.0);
  EXPECT_CLOSE(series_at(interp, 2, 0.05), 1.0, 1e-12, 0.0);
  // -prependZero: {0 1 2} from t = 1.0
  EXPECT_EQ(series_at(interp, 3, 0.99), 0.0);
  EXPECT_CLOSE(series_at(interp, 3, 1.05), 0.5, 1e-9, 0.0);
  EXPECT_CLOSE(series_at(interp, 3, 1.15), 1.5, 1e-9, 0.0);
}

TEST(PathSeries, TimeSeriesWalksIntervalsAsOpenSees) {
  Interpreter interp;
  testing::internal::CaptureStderr();
  interp.eval(std::string(kModel) + "timeSeries Path 1 -time {0 1 1 2} -values {0 1 3 3} -factor 2 -useLast\n");
  const std::string warning = testing::internal::GetCapturedStderr();
  EXPECT_NE(warning.find("-useLast is ignored"), std::string::npos) << warning;  // as OpenSees 3.8
  EXPECT_EQ(series_at(interp, 1, -1.0), 0.0);
  EXPECT_CLOSE(series_at(interp, 1, 0.5), 1.0, 1e-15, 0.0);
  EXPECT_CLOSE(series_at(interp, 1, 1.0), 2.0, 1e-15, 0.0);  // the first value of a repeated time, walking forward
  EXPECT_CLOSE(series_at(interp, 1, 1.5), 6.0, 1e-15, 0.0);
  EXPECT_CLOSE(series_at(interp, 1, 2.0), 6.0, 1e-15, 0.0);  // the last time itself is inside
  testing::internal::CaptureStderr();
  EXPECT_EQ(series_at(interp, 1, 2.5), 0.0);
  testing::internal::GetCapturedStderr();
  EXPECT_CLOSE(series_at(interp, 1, 0.25), 0.5, 1e-15, 0.0);  // walking back
}

TEST(PathSeries, FilesWithDtTimesAndPairs) {
  const fs::path dir = test_support::fresh_scratch_folder("seismic_commands", "files");
  std::ofstream(dir / "v.txt") << "0.0 1.0\n2.0\n\n";
  std::ofstream(dir / "t.txt") << "0 0.5 1.5\n";
  std::ofstream(dir / "pairs.txt") << "0 0\n1 10\n";
  std::ofstream(dir / "bad.txt") << "0.0\n1.0\nabc 2.0\n";
  Interpreter interp;
  interp.eval(std::string(kModel) + "timeSeries Path 1 -dt 0.5 -filePath " + (dir / "v.txt").string() + "\n" +
              "timeSeries Path 2 -fileTime " + (dir / "t.txt").string() + " -filePath " + (dir / "v.txt").string() +
              "\n" + "timeSeries Path 3 -file " + (dir / "pairs.txt").string() + " -useLast\n");
  EXPECT_CLOSE(series_at(interp, 1, 0.75), 1.5, 1e-12, 0.0);
  EXPECT_CLOSE(series_at(interp, 2, 1.0), 1.5, 1e-12, 0.0);
  EXPECT_CLOSE(series_at(interp, 3, 0.5), 5.0, 1e-12, 0.0);
  EXPECT_CLOSE(series_at(interp, 3, 7.0), 10.0, 1e-12, 0.0);  // -useLast holds with -file
  const std::string bad = error_of(interp, "timeSeries Path 4 -dt 0.1 -filePath " + (dir / "bad.txt").string());
  EXPECT_NE(bad.find("timeSeries Path 4"), std::string::npos) << bad;
  EXPECT_NE(bad.find("bad.txt:3: expected a number, got 'abc'"), std::string::npos) << bad;
  EXPECT_NE(bad.find("usage: timeSeries"), std::string::npos) << bad;
  EXPECT_NE(error_of(interp, "timeSeries Path 5 -dt 0.1 -filePath " + (dir / "missing.txt").string()).find("cannot open"),
            std::string::npos);
}

TEST(PathSeries, BadOptionsAreErrorsWithTheUsageLine) {
  Interpreter interp;
  interp.eval(kModel);
  const std::string zero_dt = error_of(interp, "timeSeries Path 1 -dt 0 -values {1 2}");
  EXPECT_NE(zero_dt.find("timeSeries Path 1: -dt must be > 0"), std::string::npos) << zero_dt;
  EXPECT_NE(zero_dt.find("usage: timeSeries"), std::string::npos) << zero_dt;
  EXPECT_NE(error_of(interp, "timeSeries Path 2 -values {1 2}").find("expected -dt dt with -values"), std::string::npos);
  EXPECT_NE(error_of(interp, "timeSeries Path 3 -time {0 1} -values {1}").find("different lengths"), std::string::npos);
  EXPECT_NE(error_of(interp, "timeSeries Path 4 -time {0 2 1} -values {1 2 3}").find("must not decrease"),
            std::string::npos);
  EXPECT_NE(error_of(interp, "timeSeries Path 5 -dt 0.1 -values {1 x}").find("expected a list of numbers"),
            std::string::npos);
  EXPECT_NE(error_of(interp, "timeSeries Path 6 -dt 0.1 -values {1 2} -bogus").find("unknown option '-bogus'"),
            std::string::npos);
  EXPECT_NE(error_of(interp, "timeSeries Trig 7 0 1 0").find("non-zero period"), std::string::npos);
  EXPECT_NE(error_of(interp, "timeSeries Wave 8").find("unknown timeSeries type 'Wave'"), std::string::npos);
}

TEST(ClosedFormSeries, TrigRectangularAndPulse) {
  Interpreter interp;
  interp.eval(std::string(kModel) +
              "timeSeries Trig 1 0.0 10.0 2.0 -factor 3.0\n"
              "timeSeries Sine 2 1.0 10.0 2.0 -phaseShift 1.5707963267948966\n"
              "timeSeries Rectangular 3 1.0 2.0 -factor 4.0\n"
              "timeSeries Pulse 4 0.0 10.0 1.0 -width 0.25 -factor 2.0 -zeroShift 0.5\n");
  EXPECT_CLOSE(series_at(interp, 1, 0.5), 3.0, 1e-12, 0.0);  // 3 sin(2 pi 0.5 / 2)
  EXPECT_CLOSE(series_at(interp, 1, 1.5), -3.0, 1e-12, 0.0);
  EXPECT_EQ(series_at(interp, 1, 10.5), 0.0);
  EXPECT_CLOSE(series_at(interp, 2, 1.0), 1.0, 1e-12, 0.0);  // cos at tStart
  EXPECT_EQ(series_at(interp, 2, 0.5), 0.0);
  EXPECT_EQ(series_at(interp, 3, 1.5), 4.0);
  EXPECT_EQ(series_at(interp, 3, 2.0), 4.0);
  EXPECT_EQ(series_at(interp, 3, 2.1), 0.0);
  EXPECT_EQ(series_at(interp, 4, 1.1), 2.5);  // inside the pulse: factor + zeroShift
  EXPECT_EQ(series_at(interp, 4, 1.5), 0.5);  // between pulses: zeroShift
  EXPECT_EQ(series_at(interp, 4, 11.0), 0.0);
}

// ---------------------------------------------------------------- uniaxial materials
TEST(UniaxialMaterials, ElasticBilinearWithEtaAndViscousPowerLaw) {
  fem::materials::UniaxialElastic elastic(1, 100.0, 2.0, 50.0);
  elastic.set_trial_strain(0.1, 3.0);
  EXPECT_CLOSE(elastic.stress(), 100.0 * 0.1 + 2.0 * 3.0, 1e-12, 0.0);
  EXPECT_EQ(elastic.tangent(), 100.0);
  EXPECT_EQ(elastic.damp_tangent(), 2.0);
  elastic.set_trial_strain(-0.1, 0.0);
  EXPECT_CLOSE(elastic.stress(), -5.0, 1e-12, 0.0);
  EXPECT_EQ(elastic.tangent(), 50.0);
  EXPECT_EQ(elastic.initial_tangent(), 100.0);

  fem::materials::UniaxialViscous dashpot(2, 2.0, 0.5, 1e-4);
  dashpot.set_trial_strain(0.0, -4.0);
  EXPECT_CLOSE(dashpot.stress(), -2.0 * 2.0, 1e-12, 0.0);          // -C |v|^alpha
  EXPECT_CLOSE(dashpot.damp_tangent(), 0.5 * 2.0 / 2.0, 1e-12, 0.0);  // alpha C |v|^(alpha-1)
  EXPECT_EQ(dashpot.tangent(), 0.0);
  dashpot.set_trial_strain(0.0, 1e-6);  // below minVel: the stress is not bounded, the damping tangent is
  EXPECT_CLOSE(dashpot.stress(), 2.0 * 1e-3, 1e-15, 0.0);
  EXPECT_CLOSE(dashpot.damp_tangent(), 0.5 * 2.0 * std::pow(1e-4, -0.5), 1e-9, 0.0);
  dashpot.commit_state();
  dashpot.set_trial_strain(1.0, 9.0);
  dashpot.revert_to_last_commit();
  EXPECT_CLOSE(dashpot.strain_rate(), 1e-6, 1e-20, 0.0);
}

TEST(UniaxialMaterials, CommandErrorsAndOpenSeesWarnings) {
  Interpreter interp;
  interp.eval(kModel);
  EXPECT_NE(error_of(interp, "uniaxialMaterial Elastic 1").find("missing E"), std::string::npos);
  EXPECT_NE(error_of(interp, "uniaxialMaterial Steel01 1 1 2 3").find("unknown uniaxialMaterial type 'Steel01'"),
            std::string::npos);
  interp.eval("uniaxialMaterial Elastic 1 100.0");
  const std::string dup = error_of(interp, "uniaxialMaterial Viscous 1 1.0 1.0");
  EXPECT_NE(dup.find("uniaxialMaterial 1 already exists"), std::string::npos) << dup;
  EXPECT_NE(dup.find("usage: uniaxialMaterial Viscous tag C alpha <minVel>"), std::string::npos) << dup;
  testing::internal::CaptureStderr();
  interp.eval("uniaxialMaterial Viscous 2 1.0 -1.0 0.0");
  const std::string warnings = testing::internal::GetCapturedStderr();
  EXPECT_NE(warnings.find("alpha < 0, set to 1.0"), std::string::npos) << warnings;
  EXPECT_NE(warnings.find("minVel == 0, set to 1.0e-21"), std::string::npos) << warnings;
}

// ---------------------------------------------------------------- zeroLength
constexpr const char* kSpring = R"tcl(
model basic -ndm 2 -ndf 2
node 1 0 0
node 2 0 0
fix 1 1 1
uniaxialMaterial Elastic 1 100.0 0.0 50.0
uniaxialMaterial Elastic 2 400.0
)tcl";

TEST(ZeroLength, BilinearSpringStaticResponseForcesAndDeformations) {
  Interpreter interp;
  interp.eval(std::string(kSpring) + R"tcl(
element zeroLength 1 1 2 -mat 1 2 -dir 1 2
timeSeries Linear 1
pattern Plain 1 1 { load 2 10.0 -8.0 }
constraints Plain; numberer Plain; system FullGeneral; test NormDispIncr 1e-12 10; algorithm Newton
integrator LoadControl 1.0; analysis Static
analyze 1
)tcl");
  EXPECT_CLOSE(std::stod(interp.eval("nodeDisp 2 1")), 0.1, 1e-12, 0.0);
  EXPECT_CLOSE(std::stod(interp.eval("nodeDisp 2 2")), -0.02, 1e-12, 0.0);
  const auto& e = *interp.context().domain.find_element(1);
  const auto force = *const_cast<fem::domain::Element&>(e).response({"force"});
  ASSERT_EQ(force.size(), 4u);  // P1_1 P1_2 P2_1 P2_2
  EXPECT_CLOSE(force[0], -10.0, 1e-9, 0.0);
  EXPECT_CLOSE(force[1], 8.0, 1e-9, 0.0);
  EXPECT_CLOSE(force[2], 10.0, 1e-9, 0.0);
  EXPECT_CLOSE(force[3], -8.0, 1e-9, 0.0);
  const auto defo = *const_cast<fem::domain::Element&>(e).response({"deformation"});
  ASSERT_EQ(defo.size(), 2u);
  EXPECT_CLOSE(defo[0], 0.1, 1e-12, 0.0);
  EXPECT_CLOSE(defo[1], -0.02, 1e-12, 0.0);
  // eleResponse in OpenSees' %35.20f format, and the material response
  EXPECT_CLOSE(std::stod(interp.eval("lindex [eleResponse 1 basicForce] 0")), 10.0, 1e-9, 0.0);
  EXPECT_CLOSE(std::stod(interp.eval("eleResponse 1 material 2 strain")), -0.02, 1e-12, 0.0);
  EXPECT_EQ(interp.eval("eleNodes 1"), "1 2");
  // Eneg on the compression side (Linear series at t = 2: load -20)
  interp.eval("remove loadPattern 1\npattern Plain 2 1 { load 2 -10.0 0.0 }\nanalyze 1");
  EXPECT_CLOSE(std::stod(interp.eval("nodeDisp 2 1")), -20.0 / 50.0, 1e-12, 0.0);
}

TEST(ZeroLength, OrientationRotatesTheSpringAxes) {
  Interpreter interp;
  interp.eval(std::string(kSpring) + "element zeroLength 1 1 2 -mat 1 2 -dir 1 2 -orient 1 1 0 -1 1 0\n");
  auto& e = dynamic_cast<fem::domain::SolidElement&>(*interp.context().domain.find_element(1));
  const auto& K = e.tangent_stiffness();
  // x' = (1, 1)/sqrt2 with E = 100, y' = (-1, 1)/sqrt2 with E = 400: K_jj = R^T diag(100, 400) R
  EXPECT_CLOSE(K(2, 2), 250.0, 1e-9, 0.0);
  EXPECT_CLOSE(K(2, 3), -150.0, 1e-9, 0.0);
  EXPECT_CLOSE(K(3, 3), 250.0, 1e-9, 0.0);
  EXPECT_CLOSE(K(0, 2), -250.0, 1e-9, 0.0);
  EXPECT_EQ(K(4, 4), 0.0);  // the unused node slots stay empty
  const auto y = *e.response({"yaxis"});
  EXPECT_CLOSE(y[0], -std::sqrt(0.5), 1e-15, 0.0);
  EXPECT_CLOSE(y[1], std::sqrt(0.5), 1e-15, 0.0);
}

TEST(ZeroLength, BadInputNamesTheProblemWithTheUsageLine) {
  Interpreter interp;
  interp.eval(kSpring);
  const std::string dir = error_of(interp, "element zeroLength 1 1 2 -mat 1 -dir 3");
  EXPECT_NE(dir.find("element zeroLength 1: -dir 3 is outside 1..ndf"), std::string::npos) << dir;
  EXPECT_NE(dir.find("usage: element zeroLength tag iNode jNode -mat"), std::string::npos) << dir;
  EXPECT_NE(error_of(interp, "element zeroLength 1 1 2 -mat 1 -dir 0").find("outside 1..ndf"), std::string::npos);
  const std::string orient = error_of(interp, "element zeroLength 1 1 2 -mat 1 -dir 1 -orient 0 0 1");
  EXPECT_NE(orient.find("element zeroLength 1"), std::string::npos) << orient;
  EXPECT_NE(orient.find("singular"), std::string::npos) << orient;
  EXPECT_NE(orient.find("usage:"), std::string::npos) << orient;
  EXPECT_NE(error_of(interp, "element zeroLength 1 1 2 -mat 1 -dir 1 -orient 0 0 0").find("singular"), std::string::npos);
  EXPECT_NE(error_of(interp, "element zeroLength 1 1 2 -mat 9 -dir 1").find("uniaxialMaterial 9 does not exist"),
            std::string::npos);
  EXPECT_NE(error_of(interp, "element zeroLength 1 1 2 -mat 1 -dir 1 2").find("more directions than materials"),
            std::string::npos);
  EXPECT_NE(error_of(interp, "element zeroLength 1 1 2 -mat 1 2 -dir 1").find("missing direction (one per material)"), std::string::npos);
  EXPECT_NE(error_of(interp, "element zeroLength 1 1 3 -mat 1 -dir 1").find("node 3 does not exist"), std::string::npos);
  EXPECT_NE(error_of(interp, "element zeroLength 1 1 2 -dir 1").find("expected -mat"), std::string::npos);
  EXPECT_EQ(interp.eval("getEleTags"), "");  // nothing half-built
  // non-coincident nodes: OpenSees' warning, and the element works as if they were coincident
  interp.eval("node 3 1.0 0.0");
  testing::internal::CaptureStderr();
  interp.eval("element zeroLength 2 1 3 -mat 1 -dir 1");
  EXPECT_NE(testing::internal::GetCapturedStderr().find("not coincident"), std::string::npos);
}

TEST(ZeroLength, ViscousDashpotDampsAMassExactlyAsTheTrapezoidalRule) {
  // m v' + c v = 0 with v(0) = v0 (UniformExcitation -vel0 with a zero ground motion); Newmark average
  // acceleration gives v_{n+1} = v_n (1 - q) / (1 + q), q = c dt / 2m, with the damping tangent in the matrix,
  // after a first step v_1 = v0 / (1 + q) that starts, as in OpenSees, from a zero initial acceleration.
  Interpreter interp;
  interp.eval(R"tcl(
model basic -ndm 2 -ndf 2
node 1 0 0
node 2 0 0 -mass 2.0 2.0
fix 1 1 1
fix 2 0 1
uniaxialMaterial Viscous 1 3.0 1.0
element zeroLength 1 1 2 -mat 1 -dir 1
pattern UniformExcitation 1 1 -accel {Constant -factor 0.0} -vel0 1.5
constraints Plain; numberer Plain; system FullGeneral; test NormDispIncr 1e-14 10; algorithm Linear
integrator Newmark 0.5 0.25; analysis Transient
)tcl");
  EXPECT_EQ(std::stod(interp.eval("nodeVel 2 1")), 1.5);  // -vel0 on the free dof
  EXPECT_EQ(std::stod(interp.eval("nodeVel 1 1")), 0.0);  // not on the fixed one
  const double q = 3.0 * 0.1 / (2.0 * 2.0), ratio = (1.0 - q) / (1.0 + q);
  interp.eval("analyze 10 0.1");
  const double v10 = 1.5 / (1.0 + q) * std::pow(ratio, 9);
  EXPECT_CLOSE(std::stod(interp.eval("nodeVel 2 1")), v10, 1e-12, 1e-10);
  EXPECT_CLOSE(std::stod(interp.eval("lindex [eleResponse 1 force] 2")), 3.0 * v10, 1e-11, 1e-10);
}

TEST(ZeroLength, DoRayleighSemantics) {
  Interpreter interp;
  interp.eval(std::string(kSpring) + R"tcl(
uniaxialMaterial Viscous 3 5.0 1.0
element zeroLength 1 1 2 -mat 1 3 -dir 1 2
element zeroLength 2 1 2 -mat 1 3 -dir 1 2 -doRayleigh
element zeroLength 3 1 2 -mat 1 3 -dir 1 2 -doRayleigh 0
rayleigh 0.0 0.1 0.0 0.0
)tcl");
  auto& domain = interp.context().domain;
  const auto solid = [&](int tag) { return dynamic_cast<fem::domain::SolidElement*>(domain.find_element(tag)); };
  // default 0: no Rayleigh factors, the Viscous damping tangent in C
  EXPECT_FALSE(domain.find_element(1)->rayleigh().any());
  ASSERT_NE(solid(1)->damping_tangent(), nullptr);
  EXPECT_CLOSE((*solid(1)->damping_tangent())(3, 3), 5.0, 1e-12, 0.0);
  EXPECT_FALSE(domain.find_element(3)->rayleigh().any());
  // -doRayleigh (1): Rayleigh factors, and (as OpenSees' getDamp) no material damping tangent
  EXPECT_EQ(domain.find_element(2)->rayleigh().beta_k, 0.1);
  EXPECT_EQ(solid(2)->damping_tangent(), nullptr);
  EXPECT_NE(error_of(interp, "element zeroLength 4 1 2 -mat 1 -dir 1 -doRayleigh 2").find("expected 0 or 1"),
            std::string::npos);
}

TEST(ZeroLength, PrintJsonAndElementRecorderColumns) {
  const fs::path dir = test_support::fresh_scratch_folder("seismic_commands", "json");
  Interpreter interp;
  interp.eval(std::string(kSpring) + "uniaxialMaterial Viscous 3 5.0 0.5\n" +
              "element zeroLength 7 1 2 -mat 1 2 -dir 2 1 -doRayleigh 1\n"
              "print -JSON -file " + (dir / "model.json").string() + "\n" +
              "recorder Element -file " + (dir / "force.out").string() + " -ele 7 force\n" +
              "recorder Element -file " + (dir / "defo.out").string() + " -time -ele 7 deformations\n" +
              "timeSeries Constant 1\npattern Plain 1 1 { load 2 0.0 5.0 }\n"
              "constraints Plain; numberer Plain; system FullGeneral; test NormDispIncr 1e-12 10; algorithm Newton\n"
              "integrator LoadControl 1.0; analysis Static\nanalyze 1\nremove recorders\n");
  std::ifstream in(dir / "model.json");
  const auto j = nlohmann::json::parse(in);
  const auto& model = j.at("StructuralAnalysisModel");
  const auto& mats = model.at("properties").at("uniaxialMaterials");
  ASSERT_EQ(mats.size(), 3u);
  EXPECT_EQ(mats[0].at("type"), "ElasticMaterial");
  EXPECT_EQ(mats[0].at("Eneg"), 50.0);
  EXPECT_EQ(mats[2].at("type"), "Viscous");
  EXPECT_EQ(mats[2].at("Alpha"), 0.5);
  const auto& e = model.at("geometry").at("elements").at(0);
  EXPECT_EQ(e.at("type"), "ZeroLength");
  EXPECT_EQ(e.at("nodes"), nlohmann::json({1, 2}));
  EXPECT_EQ(e.at("materials"), nlohmann::json({"1", "2"}));
  EXPECT_EQ(e.at("dof"), nlohmann::json({"Vy", "P"}));
  EXPECT_EQ(e.at("transMatrix").at(1), nlohmann::json({-0.0, 1.0, 0.0}));
  const auto force = test_support::read_numeric_table(dir / "force.out");
  ASSERT_EQ(force.size(), 1u);
  EXPECT_EQ(force[0], (std::vector<double>{0, -5, 0, 5}));
  const auto defo = test_support::read_numeric_table(dir / "defo.out");
  ASSERT_EQ(defo.size(), 1u);
  ASSERT_EQ(defo[0].size(), 3u);  // time e1 e2
  EXPECT_CLOSE(defo[0][1], 0.05, 1e-12, 0.0);  // material 1 along y: 5 / 100
  EXPECT_EQ(defo[0][2], 0.0);    // material 2 along x
}

// ---------------------------------------------------------------- patterns
TEST(Patterns, InlineSeriesAndUniformExcitationOptions) {
  Interpreter interp;
  interp.eval(R"tcl(
model basic -ndm 2 -ndf 2
node 1 0 0 -mass 1.0 1.0
pattern Plain 1 {Linear -factor 2.0} { load 1 1.0 0.0 }
pattern UniformExcitation 2 1 -accel {Path -dt 0.1 -values {1 1 1} -factor 9.81} -fact 0.5
pattern UniformExcitation 3 2 -accel {Path 7 -time {0 1} -values {0 1}}
)tcl");
  auto& domain = interp.context().domain;
  EXPECT_CLOSE(domain.find_pattern(1)->factor(1.5), 3.0, 1e-15, 0.0);
  EXPECT_CLOSE(domain.find_pattern(2)->factor(0.05), 0.5 * 9.81, 1e-12, 0.0);
  EXPECT_CLOSE(domain.find_pattern(3)->factor(0.5), 0.5, 1e-15, 0.0);
  const std::string missing = error_of(interp, "pattern UniformExcitation 4 1 -accel 99");
  EXPECT_NE(missing.find("timeSeries 99 does not exist"), std::string::npos) << missing;
  EXPECT_NE(error_of(interp, "pattern UniformExcitation 5 1 -fact 2.0").find("missing -accel"), std::string::npos);
  EXPECT_NE(error_of(interp, "pattern UniformExcitation 6 3 -accel 1").find("expected dir 1 or 2"), std::string::npos);
  EXPECT_NE(error_of(interp, "pattern Plain 7 {Path -dt 0 -values {1}} {}").find("-dt must be > 0"), std::string::npos);
  EXPECT_NE(error_of(interp, "pattern UniformExcitation 8 1 -vel {Linear}").find("-vel' is not supported"),
            std::string::npos);
}

}  // namespace

// ---------------------------------------------------------------- PressureIndependMultiYield
TEST(MultiYieldMaterial, OpenSeesSyntaxStagesAndTheFiveStressColumns) {
  Interpreter interp;
  interp.eval(std::string(kModel) +
              "nDMaterial PressureIndependMultiYield 1 2 1.8 6.0e4 3.0e5 30 0.1\n"
              "nDMaterial PressureIndependMultiYield 2 2 1.8 6.0e4 3.0e5 30 0.1 0 100 0 10\n"
              "nDMaterial PressureIndependMultiYield 3 2 1.8 6.0e4 3.0e5 30 0.1 0 100 0 -3 1e-4 0.9 1e-3 0.6 1e-2 0.2\n"
              "nDMaterial PressureIndependMultiYield 4 2 2.0 6.0e4 3.0e5 5 0.1 30 80 0.5\n"
              "node 1 0 0; node 2 1 0; node 3 1 1; node 4 0 1\n"
              "element SSPquad 1 1 2 3 4 1 PlaneStrain 1.0\n");
  const auto& m = interp.context().materials;
  ASSERT_EQ(m.size(), 4u);
  EXPECT_EQ(m.at(3)->type_name(), "PressureIndependMultiYield");
  // OpenSees' getCommittedStress in 2D: sxx syy szz sxy and the stress ratio (0 while elastic).
  const std::string response = interp.eval("eleResponse 1 stress");
  std::istringstream words(response);
  std::vector<double> values{std::istream_iterator<double>(words), std::istream_iterator<double>()};
  EXPECT_EQ(values.size(), 5u) << response;
  interp.eval("updateMaterialStage -material 1 -stage 1");
  const std::string bad_stage = error_of(interp, "updateMaterialStage -material 1 -stage 2");
  EXPECT_NE(bad_stage.find("stages are 0 (elastic) and 1 (plastic)"), std::string::npos) << bad_stage;
}

TEST(MultiYieldMaterial, BadInputNamesTheParameterWithTheUsageLine) {
  Interpreter interp;
  interp.eval(kModel);
  const std::string nd = error_of(interp, "nDMaterial PressureIndependMultiYield 1 3 1.8 6.0e4 3.0e5 30 0.1");
  EXPECT_NE(nd.find("expected nd = 2"), std::string::npos) << nd;
  EXPECT_NE(nd.find("usage: nDMaterial PressureIndependMultiYield tag nd rho"), std::string::npos) << nd;
  EXPECT_NE(error_of(interp, "nDMaterial PressureIndependMultiYield 1 2 1.8 6.0e4 3.0e5 30").find("missing peakShearStra"),
            std::string::npos);
  EXPECT_NE(error_of(interp, "nDMaterial PressureIndependMultiYield 1 2 1.8 6.0e4 3.0e5 30 0.1 0 100 0 -2 1e-4 0.9")
                .find("missing"),
            std::string::npos);
  EXPECT_NE(error_of(interp, "nDMaterial PressureIndependMultiYield 1 2 1.8 -6.0e4 3.0e5 30 0.1").find("refShearModul > 0"),
            std::string::npos);
  EXPECT_NE(error_of(interp, "nDMaterial PressureIndependMultiYield 1 2 1.8 6.0e4 3.0e5 0 0.1").find("cohesi > 0"),
            std::string::npos);
}
