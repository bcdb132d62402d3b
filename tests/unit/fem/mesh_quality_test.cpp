// Unit tests: the mesh-distortion monitor (not in OpenSees): `minJacobian` (whole-mesh query), `meshQuality -warn`,
// `recorder MeshQuality` and the two one-time warnings of Domain::commit. A corner of element 2 is pushed, step by
// step, through the opposite node: its corner det J ratio (current / reference) is 1 - 0.4 k after step k, so the
// ratio warning (threshold 0.5) comes at step 2 (0.2) and the inversion warning at step 3 (-0.2).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "fem_tcl/tcl/interpreter.hpp"
#include "support/recorder_compare.hpp"
#include "support/tolerance.hpp"

namespace {

namespace fs = std::filesystem;
using fem::tcl::Interpreter;

constexpr const char* kModel = R"tcl(
model basic -ndm 2 -ndf 2
node 1 0 0
node 2 1 0
node 3 2 0
node 4 0 1
node 5 1 1
node 6 2 1
foreach n {1 2 4 5 6} { fix $n 1 1 }
fix 3 0 1
nDMaterial ElasticIsotropic 1 1000.0 0.25 2.0
element SSPquad 1 1 2 5 4 1 PlaneStrain 1.0
element SSPquad 2 2 3 6 5 1 PlaneStrain 1.0
timeSeries Linear 1
pattern Plain 1 1 { sp 3 1 -1.6 }
constraints Transformation
system UmfPack
test NormDispIncr 1e-10 5
algorithm Newton
integrator LoadControl 0.25
analysis Static
)tcl";

/// The Tcl result of `script` ("" after a failure, which is reported).
std::string eval(Interpreter& interp, const std::string& script) {
  try {
    return interp.eval(script);
  } catch (const std::exception& e) {
    ADD_FAILURE() << e.what();
    return {};
  }
}

TEST(MeshQuality, QueryRecorderAndOneTimeWarnings) {
  const fs::path file = fs::temp_directory_path() / ("geoflow_mesh_quality_" + std::to_string(::getpid()) + ".out");
  Interpreter interp;
  eval(interp, kModel);
  // undeformed unit squares: det J = 1/4 at every corner, ratio 1; the first element wins ties
  EXPECT_EQ(eval(interp, "minJacobian"), "0.25 1");
  EXPECT_EQ(eval(interp, "minJacobian -ratio"), "1 1");
  EXPECT_EQ(eval(interp, "meshQuality"), "0.5");  // the default threshold
  eval(interp, "recorder MeshQuality -file {" + file.string() + "} -time");

  testing::internal::CaptureStderr();
  eval(interp, "analyze 1");
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");  // ratio 0.6: no warning yet
  testing::internal::CaptureStderr();
  eval(interp, "analyze 1");
  const std::string second = testing::internal::GetCapturedStderr();
  EXPECT_NE(second.find("WARNING mesh quality: at t = 0.5 element 2"), std::string::npos) << second;
  EXPECT_EQ(second.find("inverted"), std::string::npos) << second;
  testing::internal::CaptureStderr();
  eval(interp, "analyze 1");
  const std::string third = testing::internal::GetCapturedStderr();
  EXPECT_NE(third.find("at t = 0.75 element 2 is inverted"), std::string::npos) << third;
  testing::internal::CaptureStderr();
  eval(interp, "analyze 1");
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");  // each warning once only

  // after step 4 node 3 is at x = 0.4: corner det J at node 2 = (0.4 - 1) / 4
  std::istringstream q(eval(interp, "minJacobian"));
  double value = 0.0;
  int element = 0;
  q >> value >> element;
  EXPECT_CLOSE(value, -0.15, 1e-12, 0.0);
  EXPECT_EQ(element, 2);
  eval(interp, "remove recorders");
  const auto rows = test_support::read_numeric_table(file);
  ASSERT_EQ(rows.size(), 4u);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    ASSERT_EQ(rows[k].size(), 5u);
    const double ratio = 1.0 - 0.4 * (k + 1);
    EXPECT_CLOSE(rows[k][0], 0.25 * (k + 1), 1e-12, 0.0) << "time";
    EXPECT_CLOSE(rows[k][1], 0.25 * ratio, 1e-6, 1e-5) << "min det J";
    EXPECT_EQ(rows[k][2], 2.0);
    EXPECT_CLOSE(rows[k][3], ratio, 1e-6, 1e-5) << "min ratio";
    EXPECT_EQ(rows[k][4], 2.0);
  }
  fs::remove(file);
}

TEST(MeshQuality, ThresholdIsSettableAndChecked) {
  Interpreter interp;
  eval(interp, kModel);
  EXPECT_EQ(eval(interp, "meshQuality -warn 0.1"), "0.10000000000000001");
  testing::internal::CaptureStderr();
  eval(interp, "analyze 2");  // ratio 0.2 > 0.1: no warning
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  std::string message;
  EXPECT_FALSE(interp.eval_script("meshQuality -warn 1.5", "test", message));
  EXPECT_NE(message.find("meshQuality"), std::string::npos) << message;
  EXPECT_FALSE(interp.eval_script("recorder MeshQuality -file /nonexistent/x.out -ele 1", "test", message));
  EXPECT_NE(message.find("recorder MeshQuality"), std::string::npos) << message;
}

TEST(MeshQuality, QueryOnAnEmptyModelIsAnError) {
  Interpreter interp;
  eval(interp, "model basic -ndm 2 -ndf 2");
  std::string message;
  EXPECT_FALSE(interp.eval_script("minJacobian", "test", message));
  EXPECT_NE(message.find("no elements"), std::string::npos) << message;
}

}  // namespace
