// Verification: `eigen` (OpenSees' eigenvalue analysis, fem_tcl/analysis/eigen_analysis.cpp) against closed
// forms: a spring-mass oscillator (lambda = k / m, the shape mass-normalised), and a uniform elastic soil
// column on a rigid base with tied sides, whose shear modes are omega_k = (2k - 1) pi Vs / (2H) and first
// compression mode pi Vp / (2H) (Kramer 1996, Geotechnical Earthquake Engineering, sec. 7.2: the layer on
// rigid rock), 40 SSPquad elements over H; and its use for Rayleigh damping after a gravity analysis.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <vector>

#include "common/input_error.hpp"
#include "fem_script.hpp"
#include "support/tolerance.hpp"

namespace {

std::vector<double> doubles(const std::string& list) {
  std::istringstream in(list);
  std::vector<double> out;
  for (double v; in >> v;) out.push_back(v);
  return out;
}

TEST(Eigen, SpringMassOscillatorHasLambdaKOverM) {
  fem::tcl::Interpreter interp;
  fem_verification::run(interp, R"tcl(
model basic -ndm 2 -ndf 2
node 1 0 0; node 2 0 0
fix 1 1 1; fix 2 0 1
mass 2 2.0 2.0
uniaxialMaterial Elastic 1 800.0
element zeroLength 1 1 2 -mat 1 -dir 1
)tcl");
  const auto lambda = doubles(interp.eval("eigen -genBandArpack 1"));
  ASSERT_EQ(lambda.size(), 1u);
  EXPECT_CLOSE(lambda[0], 400.0, 1e-12, 0.0);
  EXPECT_CLOSE(std::abs(std::stod(interp.eval("nodeEigenvector 2 1 1"))), 1.0 / std::sqrt(2.0), 1e-12, 0.0);
  EXPECT_EQ(std::stod(interp.eval("nodeEigenvector 2 1 2")), 0.0);  // fixed dof
}

constexpr const char* kColumn = R"tcl(
model basic -ndm 2 -ndf 2
set H 20.0; set n 40; set rho 2.0; set G 20000.0; set nu 0.3
nDMaterial ElasticIsotropic 1 [expr {2*$G*(1+$nu)}] $nu $rho
for {set j 0} {$j <= $n} {incr j} {
  node [expr {2*$j+1}] 0 [expr {$j*$H/$n}]
  node [expr {2*$j+2}] 1 [expr {$j*$H/$n}]
}
fix 1 1 1; fix 2 1 1
for {set j 1} {$j <= $n} {incr j} { equalDOF [expr {2*$j+1}] [expr {2*$j+2}] 1 2 }
for {set j 0} {$j < $n} {incr j} {
  element SSPquad [expr {$j+1}] [expr {2*$j+1}] [expr {2*$j+2}] [expr {2*$j+4}] [expr {2*$j+3}] 1 PlaneStrain 1.0 0.0 -19.62
}
)tcl";

TEST(Eigen, SoilColumnModesMatchTheLayerOnRigidRock) {
  fem::tcl::Interpreter interp;
  fem_verification::run(interp, kColumn);
  const auto lambda = doubles(interp.eval("eigen 3"));
  ASSERT_EQ(lambda.size(), 3u);
  const double pi = std::acos(-1.0), H = 20.0, rho = 2.0, G = 20000.0, nu = 0.3;
  const double vs = std::sqrt(G / rho), vp = std::sqrt(2.0 * G * (1.0 - nu) / (1.0 - 2.0 * nu) / rho);
  // measured: 6.4e-5 (shear 1), 6.4e-5 (compression 1), 5.8e-4 (shear 2) relative in omega: the FE
  // discretisation, which falls as (h / wavelength)^2
  EXPECT_CLOSE(std::sqrt(lambda[0]), pi * vs / (2.0 * H), 0.0, 2e-4);
  EXPECT_CLOSE(std::sqrt(lambda[1]), pi * vp / (2.0 * H), 0.0, 2e-4);
  EXPECT_CLOSE(std::sqrt(lambda[2]), 3.0 * pi * vs / (2.0 * H), 0.0, 1e-3);
  // the first mode is horizontal shaking: tied sides move together, the top most
  const double top = std::stod(interp.eval("nodeEigenvector 81 1 1")), mid = std::stod(interp.eval("nodeEigenvector 41 1 1"));
  EXPECT_CLOSE(mid / top, std::sin(pi / 4.0), 1e-3, 0.0);
  EXPECT_EQ(std::stod(interp.eval("nodeEigenvector 82 1 1")), top);
  EXPECT_NEAR(std::stod(interp.eval("nodeEigenvector 81 1 2")), 0.0, 1e-9 * std::abs(top));
}

TEST(Eigen, GivesRayleighCoefficientsAfterAGravityAnalysis) {
  // The OpenSees idiom: gravity, then eigen for omega_1 and omega_2, then rayleigh a0 a1 0 0 with 5 %
  // damping at both; the damping ratio of mode 1 from the coefficients is 5 % again.
  fem::tcl::Interpreter interp;
  fem_verification::run(interp, std::string(kColumn) + R"tcl(
timeSeries Linear 1
pattern Plain 1 1 {}
constraints Transformation; numberer RCM; system BandSPD; test NormDispIncr 1e-10 10; algorithm Newton
integrator LoadControl 1.0; analysis Static
if {[analyze 1] != 0} { error "gravity failed" }
set lambda [eigen 2]
set w1 [expr {sqrt([lindex $lambda 0])}]; set w2 [expr {sqrt([lindex $lambda 1])}]
set a0 [expr {2*0.05*$w1*$w2/($w1+$w2)}]; set a1 [expr {2*0.05/($w1+$w2)}]
rayleigh $a0 0.0 0.0 $a1
)tcl");
  const double w1 = std::stod(interp.eval("set w1")), a0 = std::stod(interp.eval("set a0")),
               a1 = std::stod(interp.eval("set a1"));
  EXPECT_CLOSE(a0 / (2.0 * w1) + a1 * w1 / 2.0, 0.05, 1e-12, 0.0);
  EXPECT_GT(std::stod(interp.eval("nodeDisp 81 2")), -1.0);  // the gravity state is the model eigen saw
  EXPECT_LT(std::stod(interp.eval("nodeDisp 81 2")), 0.0);
}

TEST(Eigen, BadInputNamesTheProblem) {
  fem::tcl::Interpreter interp;
  fem_verification::run(interp, "model basic -ndm 2 -ndf 2\nnode 1 0 0\nnode 2 1 0\nfix 1 1 1\nmass 2 1.0 0.0\n"
                                "uniaxialMaterial Elastic 1 10.0\nelement zeroLength 1 1 2 -mat 1 -dir 1\nfix 2 0 1\n");
  EXPECT_THROW(interp.eval("eigen 0"), common::InputError);
  EXPECT_THROW(interp.eval("eigen 2"), common::InputError);  // one dof carries mass
  EXPECT_THROW(interp.eval("eigen -standard 1"), common::InputError);
  EXPECT_THROW(interp.eval("nodeEigenvector 2 1"), common::InputError);  // no eigen yet
  EXPECT_EQ(doubles(interp.eval("eigen 1")).size(), 1u);
  EXPECT_THROW(interp.eval("nodeEigenvector 2 2"), common::InputError);  // mode 2 not computed
}

}  // namespace
