// Unit tests: `strengthReduction` (fem_tcl/analysis/strength_reduction.*) and the reducible strength of
// MohrCoulomb (materials/reducible_strength.hpp): bad input names the command, option or material; the reduced
// strength is c / F (Griffiths & Lane 1999, Geotechnique 49(3), eq. 1); the model's state, its recorders and the
// materials' strength are as before the command once it returns.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "fem_tcl/materials/drucker_prager.hpp"
#include "fem_tcl/materials/mohr_coulomb.hpp"
#include "fem_tcl/tcl/interpreter.hpp"
#include "support/scratch.hpp"
#include "support/tolerance.hpp"

namespace {

using fem::tcl::Interpreter;

/// A 2 m high, 3 m wide soil block on a fixed base, roller on the left, free vertical face on the right
/// (a vertical cut), 6 x 4 SSPquads, gravity elastic then MohrCoulomb stage 1 (c = 10 kPa, phi = 20, gamma 20).
std::string cut_model(const std::string& material) {
  return "model basic -ndm 2 -ndf 2\n" + material + R"tcl(
nDMaterial ElasticIsotropic 9 1.0e5 0.3 0.0
set nx 6; set ny 4
for {set j 0} {$j <= $ny} {incr j} {
  for {set i 0} {$i <= $nx} {incr i} { node [expr {$j*($nx+1)+$i+1}] [expr {0.5*$i}] [expr {0.5*$j}] }
}
for {set j 0} {$j < $ny} {incr j} {
  for {set i 0} {$i < $nx} {incr i} {
    set n1 [expr {$j*($nx+1)+$i+1}]
    element SSPquad [expr {$j*$nx+$i+1}] $n1 [expr {$n1+1}] [expr {$n1+$nx+2}] [expr {$n1+$nx+1}] 1 PlaneStrain 1.0 0.0 -20.0
  }
}
for {set i 1} {$i <= $nx+1} {incr i} { fix $i 1 1 }
for {set j 1} {$j <= $ny} {incr j} { fix [expr {$j*($nx+1)+1}] 1 0 }
constraints Plain
numberer RCM
system UmfPack
test NormDispIncr 1.0e-8 50
algorithm NewtonLineSearch
integrator LoadControl 1.0
analysis Static
analyze 1
loadConst -time 0.0
)tcl";
}

const std::string kMohrCoulomb = "nDMaterial MohrCoulomb 1 1.0e5 0.3 0.0 20.0 10.0 0.0";

std::string error_of(Interpreter& interp, const std::string& script) {
  std::string message;
  return interp.eval_script(script, "test", message) ? std::string() : message;
}

TEST(StrengthReduction, BadInputNamesTheCommandOptionOrMaterial) {
  Interpreter interp;
  ASSERT_EQ(error_of(interp, cut_model(kMohrCoulomb)), "");
  const std::string elastic = error_of(interp, "strengthReduction -materials {9}");
  EXPECT_NE(elastic.find("strengthReduction"), std::string::npos) << elastic;
  EXPECT_NE(elastic.find("nDMaterial 9 (ElasticIsotropic) has no strength to reduce"), std::string::npos) << elastic;
  EXPECT_NE(error_of(interp, "strengthReduction -materials {1 7}").find("nDMaterial 7 does not exist"), std::string::npos);
  EXPECT_NE(error_of(interp, "strengthReduction").find("expected -materials {tags}"), std::string::npos);
  EXPECT_NE(error_of(interp, "strengthReduction -materials {a}").find("got 'a'"), std::string::npos);
  EXPECT_NE(error_of(interp, "strengthReduction -materials 1 -speed 2").find("unknown option '-speed'"), std::string::npos);
  EXPECT_NE(error_of(interp, "strengthReduction -materials 1 -criterion stiffness").find("-criterion convergence or displacement"),
            std::string::npos);
  EXPECT_NE(error_of(interp, "strengthReduction -materials 1 -bracket 2 1").find("Flo < Fhi"), std::string::npos);
  EXPECT_NE(error_of(interp, "strengthReduction -materials 1 -tol 0").find("-tol > 0"), std::string::npos);
  // an element that uses no listed material is not an error of the list, but no element at all is
  ASSERT_EQ(error_of(interp, "nDMaterial MohrCoulomb 5 1.0e5 0.3 0.0 20.0 10.0 0.0"), "");
  EXPECT_NE(error_of(interp, "strengthReduction -materials 5").find("no element uses the -materials given"),
            std::string::npos);
  Interpreter transient;
  ASSERT_EQ(error_of(transient, cut_model(kMohrCoulomb) + "integrator Newmark 0.5 0.25\nanalysis Transient\n"), "");
  EXPECT_NE(error_of(transient, "strengthReduction -materials 1").find("needs a static analysis"), std::string::npos);
}

TEST(StrengthReduction, MohrCoulombCohesionIsDividedByTheFactor) {
  // Tresca (phi = psi = 0), plane-strain simple shear far past yield: |sxy| = c_F = c / F.
  fem::materials::MohrCoulomb base(1, {1.0e5, 0.3, 0.0, 0.0, 10.0, 0.0, std::nullopt});
  auto m = base.copy_for(fem::materials::PlaneType::PlaneStrain);
  m->update_stage(1);
  ASSERT_NE(m->reducible_strength(), nullptr);
  m->reducible_strength()->set_strength_reduction(2.0);
  m->set_trial_strain({0.0, 0.0, 0.01});
  EXPECT_CLOSE(std::abs(m->stress()[2]), 5.0, 1e-9, 1e-9);
  // a clone keeps the factor; the defined strength (print -JSON) is unchanged
  EXPECT_CLOSE(m->clone()->reducible_strength()->strength_reduction(), 2.0, 0.0, 0.0);
  EXPECT_CLOSE(m->to_json()["c"].get<double>(), 10.0, 0.0, 0.0);
  m->reducible_strength()->set_strength_reduction(1.0);
  m->set_trial_strain({0.0, 0.0, 0.01});
  EXPECT_CLOSE(std::abs(m->stress()[2]), 10.0, 1e-9, 1e-9);
  EXPECT_THROW(m->reducible_strength()->set_strength_reduction(0.0), common::InputError);
}

TEST(StrengthReduction, DruckerPragerReducesThroughThePlaneStrainMatch) {
  // phi = 30 deg, c = 10 kPa, psi = 0 matched in plane strain (Drucker & Prager 1952): rho = sqrt(2) tan phi /
  // sqrt(9 + 12 tan^2 phi) = 0.22646, sigma_y = sqrt(3) 3 c / sqrt(9 + 12 tan^2 phi) = 14.4115. F = 2: tan phi / 2
  // and c / 2 give rho = sqrt(2) 0.288675 / sqrt(10) = 0.129099, sigma_y = sqrt(3) 15 / sqrt(10) = 8.21584.
  const double t = std::tan(30.0 * 3.14159265358979323846 / 180.0);
  const double rho = std::sqrt(2.0) * t / std::sqrt(9.0 + 12.0 * t * t);
  const double sigma_y = std::sqrt(3.0) * 30.0 / std::sqrt(9.0 + 12.0 * t * t);
  fem::materials::DruckerPrager dp(3, {1.0e4, 5.0e3, sigma_y, rho, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 101.0});
  ASSERT_NE(dp.reducible_strength(), nullptr);
  dp.set_strength_reduction(2.0);
  EXPECT_CLOSE(dp.to_json()["rho"].get<double>(), std::sqrt(2.0) * 0.5 * t / std::sqrt(9.0 + 3.0 * t * t), 1e-12, 1e-12);
  EXPECT_CLOSE(dp.to_json()["sigma_y"].get<double>(), std::sqrt(3.0) * 15.0 / std::sqrt(9.0 + 3.0 * t * t), 1e-12, 1e-12);
  EXPECT_CLOSE(dp.to_json()["rho_bar"].get<double>(), 0.0, 1e-15, 0.0);
  dp.set_strength_reduction(1.0);  // back to the defined strength
  EXPECT_CLOSE(dp.to_json()["rho"].get<double>(), rho, 1e-12, 1e-12);
  EXPECT_CLOSE(dp.to_json()["sigma_y"].get<double>(), sigma_y, 1e-12, 1e-12);
  fem::materials::DruckerPrager steep(4, {1.0e4, 5.0e3, 10.0, 0.5, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 101.0});
  EXPECT_THROW(steep.set_strength_reduction(1.5), common::InputError);
}

TEST(StrengthReduction, RestoresTheStateAndWritesNoRecorderLines) {
  const test_support::ScratchDir dir("geoflow_unit_strength_reduction");
  const std::string recorder = (dir.path() / "disp.out").string();
  Interpreter interp;
  ASSERT_EQ(error_of(interp, cut_model(kMohrCoulomb)), "");
  ASSERT_EQ(error_of(interp, "recorder Node -file " + recorder + " -closeOnWrite -time -node 35 -dof 1 2 disp\n"
                             "updateMaterialStage -material 1 -stage 1\nrecord"), "");
  const std::string before_disp = interp.eval("nodeDisp 35 1") + interp.eval("nodeDisp 35 2");
  const std::string before_stress = interp.eval("eleResponse 24 stress");
  const std::string factor = interp.eval("strengthReduction -materials {1} -tol 0.02");
  const double f = std::strtod(factor.c_str(), nullptr);
  EXPECT_GT(f, 0.3);
  EXPECT_LT(f, 3.0);
  EXPECT_EQ(interp.eval("nodeDisp 35 1") + interp.eval("nodeDisp 35 2"), before_disp);
  EXPECT_EQ(interp.eval("eleResponse 24 stress"), before_stress);
  EXPECT_EQ(interp.eval("getTime"), "0.000000");
  std::ifstream in(recorder);
  std::stringstream lines;
  lines << in.rdbuf();
  const std::string text = lines.str();
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;  // only the `record` line
  // the same search again gives the same factor (nothing left over from the first)
  EXPECT_EQ(interp.eval("strengthReduction -materials {1} -tol 0.02"), factor);
}

}  // namespace
