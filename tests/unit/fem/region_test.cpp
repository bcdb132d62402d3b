// Unit tests: `region` (OpenSees 3.8 MeshRegion, SRC/domain/region/MeshRegion.cpp and OPS_MeshRegion):
// which nodes and elements a region holds, its Rayleigh factors replacing the global ones on its part of
// the model, `recorder ... -region`, and its bad input.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "fem_tcl/tcl/interpreter.hpp"
#include "support/scratch.hpp"

namespace {

using fem::tcl::Interpreter;

std::string error_of(Interpreter& interp, const std::string& script) {
  std::string message;
  return interp.eval_script(script, "test", message) ? std::string() : message;
}

// Three elements in a row on nodes 1-8 (1-4 bottom, 5-8 top), the left edge fixed.
constexpr const char* kRow = R"tcl(
model basic -ndm 2 -ndf 2
for {set i 0} {$i < 4} {incr i} { node [expr {$i + 1}] $i 0.0; node [expr {$i + 5}] $i 1.0 }
nDMaterial ElasticIsotropic 1 1000.0 0.25 2.0
element SSPquad 1 1 2 6 5 1 PlaneStrain 1.0
element SSPquad 2 2 3 7 6 1 PlaneStrain 1.0
element SSPquad 3 3 4 8 7 1 PlaneStrain 1.0
fix 1 1 1
fix 5 1 1
)tcl";

TEST(Region, ElementsBringTheirNodesAndNodesTheElementsTheyHoldWhole) {
  Interpreter interp;
  ASSERT_EQ(error_of(interp, std::string(kRow) + R"tcl(
region 1 -ele 3 2 99
region 2 -nodeRange 8 2
region 3 -eleOnly 1
region 4 -nodeOnly 1 2
)tcl"), "");
  const auto& d = interp.context().domain;
  // -ele: the elements that exist, in the order given, and every node they connect
  EXPECT_EQ(d.find_region(1)->elements, (std::vector<int>{3, 2}));
  EXPECT_EQ(d.find_region(1)->nodes, (std::vector<int>{3, 4, 8, 7, 2, 6}));
  // -nodeRange given high to low: nodes 2-8; the elements whose nodes all lie in it: 2 and 3
  EXPECT_EQ(d.find_region(2)->nodes, (std::vector<int>{2, 3, 4, 5, 6, 7, 8}));
  EXPECT_EQ(d.find_region(2)->elements, (std::vector<int>{2, 3}));
  EXPECT_EQ(d.find_region(3)->elements, (std::vector<int>{1}));
  EXPECT_TRUE(d.find_region(3)->nodes.empty());
  EXPECT_EQ(d.find_region(4)->nodes, (std::vector<int>{1, 2}));
  EXPECT_TRUE(d.find_region(4)->elements.empty());
}

/// The top-right node's displacement after a step load, 200 steps of Newmark, with `damping` (Tcl).
double damped_response(const std::string& damping) {
  Interpreter interp;
  const std::string err = error_of(interp, std::string(kRow) + "mass 4 0.5 0.5\nmass 8 0.5 0.5\n" + damping + R"tcl(
timeSeries Constant 1
pattern Plain 1 1 { load 8 0.0 -1.0 }
constraints Plain; numberer Plain; system BandGeneral; test NormDispIncr 1e-12 10; algorithm Newton
integrator Newmark 0.5 0.25; analysis Transient
analyze 200 0.01
)tcl");
  EXPECT_EQ(err, "") << damping;
  return std::stod(interp.eval("nodeDisp 8 2"));
}

TEST(Region, RayleighFactorsOnTheRegionOnly) {
  const double none = damped_response("");
  const double global = damped_response("rayleigh 2.0 0.002 0.0 0.0");
  // a region holding every element (and so every node) damps as the global command
  EXPECT_EQ(damped_response("region 1 -eleRange 1 3 -rayleigh 2.0 0.002 0.0 0.0"), global);
  // a region over part of the model damps less: its response lies apart from both
  const double part = damped_response("region 1 -ele 1 -rayleigh 2.0 0.002 0.0 0.0");
  EXPECT_NE(part, global);
  EXPECT_NE(part, none);
  // the nodal masses at 4 and 8 belong to element 3: a region of it takes their alphaM as well
  const double nodal = damped_response("region 1 -ele 3 -rayleigh 2.0 0.0 0.0 0.0");
  EXPECT_NE(nodal, damped_response("region 1 -eleOnly 3 -rayleigh 2.0 0.0 0.0 0.0"));
  // a region replaces the global factors on its part; all-zero factors change nothing (OpenSees)
  EXPECT_EQ(damped_response("rayleigh 2.0 0.002 0.0 0.0\nregion 1 -ele 1 2 3 -rayleigh 0.0 0.0 0.0 0.0"), global);
  EXPECT_EQ(damped_response("rayleigh 2.0 0.002 0.0 0.0\nregion 1 -ele 1 2 3 -rayleigh 1e-30 0.0 0.0 0.0"),
            damped_response("region 1 -ele 1 2 3 -rayleigh 1e-30 0.0 0.0 0.0"));
}

TEST(Region, RecordersOfARegion) {
  Interpreter interp;
  const auto dir = test_support::fresh_scratch_folder("unit_fem_region", "recorders");
  ASSERT_EQ(error_of(interp, std::string(kRow) + "region 7 -ele 3 2\n" + "recorder Node -file " +
                                 (dir / "n.out").string() + " -region 7 -dof 2 disp\nrecorder Element -file " +
                                 (dir / "e.out").string() + " -region 7 stress\n" + R"tcl(
timeSeries Linear 1
pattern Plain 1 1 { load 8 0.0 -1.0 }
constraints Plain; numberer Plain; system BandGeneral; test NormDispIncr 1e-12 10; algorithm Newton
integrator LoadControl 1.0; analysis Static
analyze 1
remove recorders
)tcl"), "");
  const auto count_columns = [](const std::filesystem::path& f) {
    std::ifstream in(f);
    std::string line;
    std::getline(in, line);
    std::istringstream words(line);
    int n = 0;
    for (std::string w; words >> w;) ++n;
    return n;
  };
  EXPECT_EQ(count_columns(dir / "n.out"), 6);  // the region's 6 nodes, dof 2
  EXPECT_EQ(count_columns(dir / "e.out"), 6);  // 2 SSPquads x (sxx syy sxy)
}

TEST(Region, BadInput) {
  Interpreter interp;
  ASSERT_EQ(error_of(interp, kRow), "");
  EXPECT_NE(error_of(interp, "region 1 -ele").find("missing tags after -ele"), std::string::npos);
  EXPECT_NE(error_of(interp, "region 1 -node all").find("missing tags after -node"), std::string::npos);
  EXPECT_NE(error_of(interp, "region 1 -ele 1 -damp 3").find("unknown option '-damp'"), std::string::npos);
  EXPECT_NE(error_of(interp, "region 1 -ele 1 -rayleigh 1 2").find("betaK0"), std::string::npos);
  EXPECT_NE(error_of(interp, "region 1 -ele 1 -rayleigh nan 0 0 0").find("alphaM"), std::string::npos);
  EXPECT_NE(error_of(interp, "region 1 -eleRange 50 2000000000").find("selects no node or element"), std::string::npos);
  EXPECT_NE(error_of(interp, "recorder Node -file x.out -region 9 -dof 1 disp").find("region 9 does not exist"),
            std::string::npos);
}

}  // namespace
