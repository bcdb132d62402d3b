// Verification: a laterally confined elastic column (vertical rollers on both sides, fixed base) under
// self-weight is a uniaxial-strain (oedometric) problem:
//   syy(depth z) = -rho g z,  sxx = K0 syy with K0 = nu / (1 - nu),  top settlement rho g H^2 / (2 M),
//   M = E (1 - nu) / ((1 + nu)(1 - 2 nu))   (Davis & Selvadurai 1996, Elasticity and Geomechanics, Cambridge,
//   ch. 4, the K0 state; the settlement integrates the strain rho g z / M over the height).
// With linear elements and equal nodal body-force weights the nodal values of this 1D problem are exact and
// each element's stress is the exact value at its centroid depth (e.g. Hughes 2000, The Finite Element
// Method, sec. 1.10, nodal exactness in 1D), so the comparison is to round-off.
// Its free axial vibration has the period T1 = 4 H / c, c = sqrt(M / rho) (quarter-wave resonator;
// Kramer 1996, Geotechnical Earthquake Engineering, sec. 7.2, for the analogous shear column).
#include <gtest/gtest.h>

#include <cmath>

#include "fem_script.hpp"
#include "support/tolerance.hpp"

namespace {

using fem_verification::run;

constexpr double kH = 10.0, kE = 100.0e3, kNu = 0.25, kRho = 2.0, kG = 9.81;
constexpr double kM = kE * (1.0 - kNu) / ((1.0 + kNu) * (1.0 - 2.0 * kNu));

/// 3 elements wide (1 m), ny high, nodes row by row.
std::string column_script(int ny, const std::string& element, double b2) {
  return "set ny " + std::to_string(ny) + "; set elementType " + element + "; set b2 " + std::to_string(b2) +
         "; set H " + std::to_string(kH) + R"tcl(
model basic -ndm 2 -ndf 2
set dy [expr {$H/$ny}]
for {set j 0} {$j <= $ny} {incr j} {
  for {set i 0} {$i <= 3} {incr i} { node [expr {4*$j + $i + 1}] [expr {$i/3.0}] [expr {$j*$dy}] }
}
fixY 0.0 1 1
fixX 0.0 1 0
fixX 1.0 1 0
nDMaterial ElasticIsotropic 1 100.0e3 0.25 2.0
set e 0
for {set j 0} {$j < $ny} {incr j} {
  for {set i 0} {$i < 3} {incr i} {
    incr e
    set n1 [expr {4*$j + $i + 1}]
    if {$elementType eq "SSPquad"} {
      element SSPquad $e $n1 [expr {$n1+1}] [expr {$n1+5}] [expr {$n1+4}] 1 PlaneStrain 1.0 0.0 $b2
    } else {
      element quad $e $n1 [expr {$n1+1}] [expr {$n1+5}] [expr {$n1+4}] 1.0 PlaneStrain 1 0.0 0.0 0.0 $b2
    }
  }
}
)tcl";
}

/// One static load step of the body forces.
const std::string kGravityAnalysis = R"tcl(
constraints Plain; numberer RCM; system BandSPD; test NormDispIncr 1e-12 5; algorithm Newton
integrator LoadControl 1.0; analysis Static
if {[analyze 1] != 0} { error "gravity failed" }
)tcl";

void check_self_weight(const std::string& element) {
  const int ny = 20;
  fem::tcl::Interpreter interp;
  run(interp, column_script(ny, element, -kRho * kG) + kGravityAnalysis);
  const double dy = kH / ny;
  for (int j = 0; j < ny; ++j) {
    const double depth = kH - (j + 0.5) * dy;
    const auto s = fem_verification::element_response(interp, 3 * j + 2, "stress");
    for (std::size_t k = 0; k < s.size(); k += 3) {
      EXPECT_CLOSE(s[k + 1], -kRho * kG * depth, 1e-9, 1e-10) << element << " row " << j;
      EXPECT_CLOSE(s[k], kNu / (1.0 - kNu) * s[k + 1], 1e-9, 1e-10) << element << " row " << j;
      EXPECT_CLOSE(s[k + 2], 0.0, 1e-9, 0.0);
    }
  }
  const double settlement = -fem_verification::node_disp(interp, 4 * ny + 2, 1);
  EXPECT_CLOSE(settlement, kRho * kG * kH * kH / (2.0 * kM), 1e-15, 1e-10) << element;
}

// The same column of Tri31 triangles: 2 cells wide, each cut along a diagonal, the two cells mirror images.
// A triangle mesh does not reproduce the 1D solution node by node (the constant-strain triangles of a layer
// carry different stresses, the top nodes settle by -0.06 %, +0.06 %, -0.06 %), but layer means are exact:
// the test function that is one hat in y and uniform in x lies in the FE space, and with it the discrete
// equilibrium of the layers is the 1D one (a layer's mean syy = -rho g times the depth of its mid-height,
// its mean sxx = K0 times that, the hat-weighted mean settlement of a node row the 1D one).
TEST(ElasticColumn, SelfWeightStressK0AndSettlementTri31) {
  const int ny = 20;
  fem::tcl::Interpreter interp;
  run(interp, "set ny " + std::to_string(ny) + "; set H " + std::to_string(kH) + "; set b2 " +
                  std::to_string(-kRho * kG) + R"tcl(
model basic -ndm 2 -ndf 2
set dy [expr {$H/$ny}]
for {set j 0} {$j <= $ny} {incr j} {
  for {set i 0} {$i <= 2} {incr i} { node [expr {3*$j + $i + 1}] [expr {$i*0.5}] [expr {$j*$dy}] }
}
fixY 0.0 1 1
fixX 0.0 1 0
fixX 1.0 1 0
nDMaterial ElasticIsotropic 1 100.0e3 0.25 2.0
set e 0
for {set j 0} {$j < $ny} {incr j} {
  set a [expr {3*$j + 1}]
  # cell 0: nodes a, a+1, a+4, a+3, cut from a to a+4
  element tri31 [incr e] $a [expr {$a+1}] [expr {$a+4}] 1.0 PlaneStrain 1 0.0 0.0 0.0 $b2
  element tri31 [incr e] $a [expr {$a+4}] [expr {$a+3}] 1.0 PlaneStrain 1 0.0 0.0 0.0 $b2
  # cell 1: nodes a+1, a+2, a+5, a+4, cut from a+2 to a+4
  element tri31 [incr e] [expr {$a+1}] [expr {$a+2}] [expr {$a+4}] 1.0 PlaneStrain 1 0.0 0.0 0.0 $b2
  element tri31 [incr e] [expr {$a+2}] [expr {$a+5}] [expr {$a+4}] 1.0 PlaneStrain 1 0.0 0.0 0.0 $b2
}
)tcl" + kGravityAnalysis);
  const double dy = kH / ny;
  for (int j = 0; j < ny; ++j) {
    const double depth = kH - (j + 0.5) * dy;
    double syy = 0.0, sxx = 0.0;  // layer means (the four triangles have equal areas)
    for (int e = 4 * j + 1; e <= 4 * j + 4; ++e) {
      const auto s = fem_verification::element_response(interp, e, "stress");
      ASSERT_EQ(s.size(), 3u);
      syy += s[1] / 4.0;
      sxx += s[0] / 4.0;
    }
    EXPECT_CLOSE(syy, -kRho * kG * depth, 1e-9, 1e-10) << "layer " << j;
    EXPECT_CLOSE(sxx, kNu / (1.0 - kNu) * syy, 1e-9, 1e-10) << "layer " << j;
  }
  const double exact = kRho * kG * kH * kH / (2.0 * kM);
  double mean = 0.0;
  for (int i = 1; i <= 3; ++i) {
    const double settlement = -fem_verification::node_disp(interp, 3 * ny + i, 1);
    EXPECT_CLOSE(settlement, exact, 0.0, 1e-3) << "top node " << i;
    mean += (i == 2 ? 0.5 : 0.25) * settlement;
  }
  EXPECT_CLOSE(mean, exact, 1e-15, 1e-10);
  // A third of each triangle's mass at each of its nodes: the column's mass rho H (width 1 m) in all.
  double mass = 0.0;
  for (int e = 1; e <= 4 * ny; ++e) mass += dynamic_cast<fem::domain::SolidElement&>(*interp.context().domain.find_element(e)).lumped_mass().sum() / 2.0;
  EXPECT_CLOSE(mass, kRho * kH, 1e-12, 0.0);
}

TEST(ElasticColumn, SelfWeightStressK0AndSettlementSSPquad) { check_self_weight("SSPquad"); }
TEST(ElasticColumn, SelfWeightStressK0AndSettlementQuad) { check_self_weight("quad"); }

/// Releases a static top load and measures the period from successive downward zero crossings of the
/// top displacement.
double measured_period(const std::string& integrator, double dt, int steps) {
  const int ny = 40;
  fem::tcl::Interpreter interp;
  run(interp, column_script(ny, "SSPquad", 0.0) + "set top [expr {4*" + std::to_string(ny) + " + 1}]\n" + R"tcl(
timeSeries Constant 1
pattern Plain 1 1 { for {set i 0} {$i < 4} {incr i} { load [expr {$top + $i}] 0.0 -10.0 } }
constraints Plain; numberer RCM; system BandSPD; test NormDispIncr 1e-12 5; algorithm Linear
integrator LoadControl 1.0; analysis Static
if {[analyze 1] != 0} { error "preload failed" }
remove loadPattern 1
loadConst -time 0.0
wipeAnalysis
constraints Plain; numberer RCM; system BandSPD; algorithm Linear
)tcl" + "integrator " + integrator + "\nanalysis Transient\n");
  const int top = 4 * ny + 2;
  std::vector<double> crossings;
  double previous = fem_verification::node_disp(interp, top, 1);
  for (int s = 1; s <= steps; ++s) {
    run(interp, "analyze 1 " + std::to_string(dt));
    const double u = fem_verification::node_disp(interp, top, 1);
    if (previous > 0.0 && u <= 0.0) crossings.push_back((s - 1 + previous / (previous - u)) * dt);
    previous = u;
  }
  if (crossings.size() < 2) return 0.0;
  return (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

TEST(ElasticColumn, AxialFreeVibrationPeriodIsFourHOverC) {
  const double c = std::sqrt(kM / kRho);
  const double T = 4.0 * kH / c;
  const double dt = 2e-4;  // T / 816; the critical step of central differences is about h / c = 1e-3
  const int steps = static_cast<int>(3.2 * T / dt);
  const double newmark = measured_period("Newmark 0.5 0.25", dt, steps);
  EXPECT_CLOSE(newmark, T, 0.0, 0.01) << "Newmark";
  const double central = measured_period("CentralDifference", dt, steps);
  EXPECT_CLOSE(central, T, 0.0, 0.01) << "CentralDifference";
  const double hht = measured_period("HHT 0.9", dt, steps);
  EXPECT_CLOSE(hht, T, 0.0, 0.01) << "HHT";
}

}  // namespace
