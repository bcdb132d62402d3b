// Unit tests: the u-p elements SSPquadUP and quadUP (fem_tcl/elements/up_quad.hpp, ssp_quad_up.hpp,
// four_node_quad_up.hpp) and the 3-dof nodes they need: the blocks of their system matrix, the two
// OpenSees 3.8 defects fem_tcl does not copy (PR #1811: the fluid storage of a weightless skeleton, the
// lower-side pressure), permeability parameters, mixed 2-dof / 3-dof models, recorders and print -JSON of
// 3-dof nodes, and the bad input the issue lists (one line naming the command and argument).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fem_tcl/elements/ssp_quad_up.hpp"
#include "fem_tcl/tcl/interpreter.hpp"
#include "support/recorder_compare.hpp"
#include "support/scratch.hpp"
#include "support/tolerance.hpp"

namespace {

using fem::tcl::Interpreter;

std::string error_of(Interpreter& interp, const std::string& script) {
  std::string message;
  return interp.eval_script(script, "test", message) ? std::string() : message;
}

void run(Interpreter& interp, const std::string& script) { ASSERT_EQ(error_of(interp, script), ""); }

// A unit square of u-p nodes and an elastic material (kPa, Mg/m3).
constexpr const char* kUnitSquare = R"tcl(
model basic -ndm 2 -ndf 3
node 1 0 0; node 2 1 0; node 3 1 1; node 4 0 1
nDMaterial ElasticIsotropic 1 2.0e4 0.25 2.0
nDMaterial ElasticIsotropic 2 2.0e4 0.25 0.0
)tcl";

// n = e / (1 + e) = 0.375 for e = 0.6; Kf = 2.2e6
std::string ssp_quad_up(int material, const std::string& extra = "") {
  return "element SSPquadUP 1 1 2 3 4 " + std::to_string(material) + " 1.0 2.2e6 1.0 1.0e-6 2.0e-6 0.6 1.0e-5" + extra +
         "\n";
}

fem::elements::SSPquadUP& ssp_element(Interpreter& interp) {
  return dynamic_cast<fem::elements::SSPquadUP&>(*interp.context().domain.find_element(1));
}

TEST(SSPquadUP, SystemMatrixIsSymmetricWithANegativeDefinitePressureBlock) {
  Interpreter interp;
  run(interp, std::string(kUnitSquare) + ssp_quad_up(1));
  auto& e = ssp_element(interp);
  fem::domain::ElementMatrix k;
  e.form_system_matrix({2.0, 3.0, 5.0}, k);
  ASSERT_EQ(k.rows(), 12);
  EXPECT_LT((k - k.transpose()).norm(), 1e-12 * k.norm());
  // the storage S (with the hourglass mode's, see ssp_quad_up.hpp) is positive definite, so the pressure
  // block -c2 H - c3 S is negative definite
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> s(e.storage());
  EXPECT_GT(s.eigenvalues().minCoeff(), 0.0);
  // coupling: a uniform expansion u = (x, y) (volumetric strain 2) gives Q^T u = 2 V / 4 at each node
  Eigen::Matrix<double, 8, 1> u;
  u << 0, 0, 1, 0, 1, 1, 0, 1;
  const Eigen::Vector4d qu = e.coupling().transpose() * u;
  for (int a = 0; a < 4; ++a) EXPECT_CLOSE(qu[a], 0.5, 1e-14, 0.0);
  // permeability: H = V dN diag(k1, k2) dN^T; H 1 = 0 (a uniform pressure does not flow)
  EXPECT_LT((e.permeability() * Eigen::Vector4d::Ones()).norm(), 1e-20);
  EXPECT_CLOSE(e.permeability()(0, 0), 0.25 * (1.0e-6 + 2.0e-6), 1e-20, 1e-12);  // dN_1 = (-1/2, -1/2)
}

// OpenSees 3.8's SSPquadUP::getMass returns zero for a material density of 0 and so drops the fluid storage
// (PR #1811): a weightless skeleton gets an incompressible pore fluid. fem_tcl keeps it. The undrained
// oedometric response of one element shows both numbers: p0 = q / (1 + n M / Kf) with the storage
// (Biot; Verruijt 2016, eq. 2.39), p0 = q without it.
TEST(SSPquadUP, KeepsTheFluidStorageOfAWeightlessSkeleton) {
  Interpreter with_mass, weightless;
  run(with_mass, std::string(kUnitSquare) + ssp_quad_up(1));
  run(weightless, std::string(kUnitSquare) + ssp_quad_up(2));
  EXPECT_EQ(ssp_element(weightless).storage(), ssp_element(with_mass).storage());
  {
    const int material = 2;
    Interpreter interp;
    run(interp, std::string(kUnitSquare) + ssp_quad_up(material) + R"tcl(
fix 1 1 1 0; fix 2 1 1 0; fix 3 1 0 0; fix 4 1 0 0
equalDOF 3 4 2
timeSeries Constant 1
pattern Plain 1 1 { load 3 0 -10.0 0; load 4 0 -10.0 0 }
constraints Transformation; numberer RCM; system UmfPack; test NormDispIncr 1e-12 10; algorithm Newton
integrator Newmark 0.5 0.25; analysis Transient
analyze 1 1.0e-6
)tcl");
    const double M = 2.0e4 * 0.75 / (1.25 * 0.5), n = 0.375, q = 20.0;
    const double with_storage = q / (1.0 + n * M / 2.2e6);
    const double p = interp.context().domain.find_node(3)->vel[2];
    EXPECT_CLOSE(p, with_storage, 0.0, 2e-3) << "material " << material;
    EXPECT_GT(q - p, 0.5 * (q - with_storage)) << "material " << material << ": OpenSees 3.8's p0 = q without the storage";
  }
}

// OpenSees 3.8's setPressureLoadAtNodes adds node 2's vertical share of the lower-side pressure into node 1's
// pore-pressure dof (pressureLoad(2) for (4), PR #1811). Here it is node 2's uy.
TEST(SSPquadUP, LowerSidePressureLoadsNodeTwoNotAPressureDof) {
  Interpreter interp;
  run(interp, std::string(kUnitSquare) + "element SSPquadUP 1 1 2 3 4 1 1.0 2.2e6 1.0 1e-6 1e-6 0.6 1e-5 0 0 0 8.0 0 0\n");
  const auto f = *interp.context().domain.find_element(1)->response({"forces"});
  ASSERT_EQ(f.size(), 12u);
  // the side 1-2 runs along +x: force P t/2 (dy, -dx) = (0, -4) at nodes 1 and 2, minus in the resisting force
  EXPECT_EQ(f[1], 4.0);   // node 1 uy
  EXPECT_EQ(f[4], 4.0);   // node 2 uy
  EXPECT_EQ(f[2], 0.0);   // node 1 p: OpenSees 3.8 writes 4 here
  for (int i : {0, 3, 5, 6, 7, 8, 9, 10, 11}) EXPECT_EQ(f[static_cast<std::size_t>(i)], 0.0) << i;
}

TEST(SSPquadUP, PermeabilityParametersRebuildTheFlowMatrixAndRefuseZero) {
  Interpreter interp;
  run(interp, std::string(kUnitSquare) + ssp_quad_up(1));
  auto& e = ssp_element(interp);
  const Eigen::Matrix4d H0 = e.permeability();
  run(interp, "setParameter -val 3.0e-6 -ele 1 hPerm\nsetParameter -val 6.0e-6 -ele 1 yPerm");
  EXPECT_LT((e.permeability() - 3.0 * H0).norm(), 1e-12 * H0.norm());
  EXPECT_EQ(e.fluid().hydraulic_x, 3.0e-6);
  EXPECT_EQ(e.fluid().hydraulic_y, 6.0e-6);
  const std::string zero = error_of(interp, "setParameter -val 0.0 -ele 1 vPerm");
  EXPECT_NE(zero.find("vPerm"), std::string::npos) << zero;
  EXPECT_NE(zero.find("expected a permeability > 0"), std::string::npos) << zero;
}

TEST(UpElements, BadInputNamesTheCommandAndArgument) {
  Interpreter interp;
  run(interp, std::string(kUnitSquare) + "model basic -ndm 2 -ndf 2\nnode 5 2 0; node 6 2 1\n");
  const auto expect = [&](const std::string& script, const std::string& part) {
    const std::string e = error_of(interp, script);
    EXPECT_NE(e.find(part), std::string::npos) << script << " -> " << e;
  };
  expect("element SSPquadUP 2 2 5 6 3 1 1.0 2.2e6 1.0 1e-6 1e-6 0.6 1e-5", "node 5 has 2 dofs (model -ndf 2), this element needs 3");
  expect("element SSPquad 3 1 2 3 4 1 PlaneStrain 1.0", "node 1 has 3 dofs (model -ndf 3)");
  expect("element SSPquadUP 4 1 2 3 4 1 1.0 2.2e6 1.0 0.0 1e-6 0.6 1e-5", "element SSPquadUP 4: expected k1 > 0");
  expect("element SSPquadUP 4 1 2 3 4 1 1.0 2.2e6 1.0 1e-6 nan 0.6 1e-5", "element SSPquadUP 4: expected k2");
  expect("element quadUP 4 1 2 3 4 1.0 1 2.2e6 1.0 1e-6 -1e-6", "element quadUP 4: expected vPerm > 0");
  expect("element SSPquadUP 4 1 2 3 4 1 1.0 2.2e6 1.0 1e-6 1e-6 0.6 1e-5 0.0", "expected 13 arguments, 15 with b1 b2");
  expect("recorder Node -file x.out -node 5 -dof 3 vel", "-dof 3: node 5 has 2 dofs");
  expect("equalDOF 3 6 1 2 3", "expected dof 1..2 (the dofs both nodes have), got 3");
  expect("fix 1 1 1", "node 1 has 3 dofs: expected 3 fix flags, got 2");
  expect("model basic -ndm 2 -ndf 4", "expected -ndf 2 (solids) or 3 (u-p");
  expect("sp 5 3 0.0", "");  // outside a pattern: refused before the dof is read
}

TEST(UpElements, StaticAnalysisOfFreePressuresNamesTheDof) {
  Interpreter interp;
  run(interp, std::string(kUnitSquare) + ssp_quad_up(1) +
                  "fix 1 1 1 0; fix 2 1 1 0; fix 3 1 0 1; fix 4 1 0 1\nanalysis Static\nintegrator LoadControl 1\n");
  EXPECT_EQ(interp.eval("analyze 1"), "-3");  // with a warning naming "node 1 dof 3 (pore pressure)"
}

// A u-p layer on a solid (2-dof) one, tied with equalDOF on dofs 1 2 as OpenSees users build them; the print
// -JSON of both kinds of nodes and the pore-pressure recorder. Consolidated under gravity, the pressure at the
// layer's base is hydrostatic: rho_f g times its depth below the drained top (1 m, 9.81 kPa; Newmark with
// gamma 0.6 damps the steps' oscillation by ~0.82 a step, so 60 steps leave < 1e-5 of it).
TEST(UpElements, MixedModelRecordsThePorePressureAndPrintsTheDofs) {
  test_support::ScratchDir scratch("up_mixed");
  const std::string dir = scratch.path().string();
  Interpreter interp;
  run(interp, R"tcl(
model basic -ndm 2 -ndf 2
node 1 0 0; node 2 1 0; node 3 1 1; node 4 0 1
fix 1 1 1; fix 2 1 1; fix 3 1 0; fix 4 1 0
nDMaterial ElasticIsotropic 1 2.0e4 0.25 2.0
element SSPquad 1 1 2 3 4 1 PlaneStrain 1.0 0.0 -19.62
model basic -ndm 2 -ndf 3
node 13 1 1; node 14 0 1; node 15 1 2; node 16 0 2
equalDOF 3 13 1 2; equalDOF 4 14 1 2
fix 15 1 0 1; fix 16 1 0 1
element SSPquadUP 2 14 13 15 16 1 1.0 2.2e6 1.0 1.0e-4 1.0e-4 0.6 1.0e-5 0.0 -9.81
)tcl");
  run(interp, "recorder Node -file " + dir + "/pp.out -time -node 14 13 -dof 3 vel\n" +
                  "print -JSON -file " + dir + "/model.json\n" + R"tcl(
constraints Transformation; numberer RCM; system UmfPack; test NormDispIncr 1e-10 20; algorithm Newton
integrator Newmark 0.6 0.3025; analysis Transient
analyze 60 100.0
)tcl");
  EXPECT_CLOSE(interp.context().domain.find_node(13)->vel[2], 9.81, 1e-6, 1e-6);
  interp.context().domain.flush_recorders();
  const auto rows = test_support::read_numeric_table(scratch.path() / "pp.out");
  ASSERT_EQ(rows.size(), 60u);
  ASSERT_EQ(rows.back().size(), 3u);
  EXPECT_CLOSE(rows.back()[1], 9.81, 1e-4, 1e-5);
  std::ifstream in(scratch.path() / "model.json");
  const auto model = nlohmann::json::parse(in)["StructuralAnalysisModel"];
  std::map<int, int> ndf;
  for (const auto& n : model["geometry"]["nodes"]) ndf[n["name"].get<int>()] = n["ndf"].get<int>();
  EXPECT_EQ(ndf[1], 2);
  EXPECT_EQ(ndf[13], 3);
  std::map<int, std::vector<int>> fix;
  for (const auto& f : model["constraints"]["fix"]) fix[f["node"].get<int>()] = f["fix"].get<std::vector<int>>();
  EXPECT_EQ(fix[3], (std::vector<int>{1, 0}));
  EXPECT_EQ(fix[15], (std::vector<int>{1, 0, 1}));
}

}  // namespace
