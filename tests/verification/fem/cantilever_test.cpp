// Verification: tip deflection of a cantilever (L = 10, h = 1, unit thickness, plane stress, E = 1000,
// nu = 0.3) under an end shear P = 1 converges, with mesh refinement, to Timoshenko beam theory
//   delta = P L^3 / (3 E I) + P L / (kappa G A),  I = h^3 / 12, A = h, kappa = 5/6
// (Timoshenko & Goodier 1970, Theory of Elasticity, 3rd ed., art. 21; Timoshenko 1921 shear correction).
// The clamped end (all nodes fixed) and the lumped end load differ from the beam model only locally, so
// the finest mesh is expected within 2 % and the error must decrease with each refinement.
#include <gtest/gtest.h>

#include <cmath>

#include "fem_script.hpp"
#include "support/tolerance.hpp"

namespace {

constexpr double kL = 10.0, kh = 1.0, kE = 1000.0, kNu = 0.3, kP = 1.0;

double tip_deflection(const std::string& element, int nx, int ny) {
  fem::tcl::Interpreter interp;
  fem_verification::run(interp, "set nx " + std::to_string(nx) + "; set ny " + std::to_string(ny) +
                                    "; set elementType " + element + R"tcl(
model basic -ndm 2 -ndf 2
set dx [expr {10.0/$nx}]; set dy [expr {1.0/$ny}]
for {set j 0} {$j <= $ny} {incr j} {
  for {set i 0} {$i <= $nx} {incr i} { node [expr {$j*($nx+1) + $i + 1}] [expr {$i*$dx}] [expr {$j*$dy - 0.5}] }
}
fixX 0.0 1 1
nDMaterial ElasticIsotropic 1 1000.0 0.3
set e 0
for {set j 0} {$j < $ny} {incr j} {
  for {set i 0} {$i < $nx} {incr i} {
    incr e
    set n1 [expr {$j*($nx+1) + $i + 1}]
    set n2 [expr {$n1 + 1}]; set n3 [expr {$n1 + $nx + 2}]; set n4 [expr {$n1 + $nx + 1}]
    if {$elementType eq "SSPquad"} {
      element SSPquad $e $n1 $n2 $n3 $n4 1 PlaneStress 1.0
    } else {
      element quad $e $n1 $n2 $n3 $n4 1.0 PlaneStress 1
    }
  }
}
timeSeries Linear 1
pattern Plain 1 1 {
  for {set j 0} {$j <= $ny} {incr j} {
    set w [expr {($j == 0 || $j == $ny) ? 0.5 : 1.0}]
    load [expr {$j*($nx+1) + $nx + 1}] 0.0 [expr {-$w/$ny}]
  }
}
constraints Plain; numberer RCM; system UmfPack; test NormDispIncr 1e-12 5; algorithm Linear
integrator LoadControl 1.0; analysis Static
if {[analyze 1] != 0} { error "cantilever failed" }
)tcl");
  const int mid = (ny / 2) * (nx + 1) + nx + 1;
  return -fem_verification::node_disp(interp, mid, 1);
}

void expect_convergence(const std::string& element) {
  const double I = kh * kh * kh / 12.0;
  const double G = kE / (2.0 * (1.0 + kNu));
  const double exact = kP * kL * kL * kL / (3.0 * kE * I) + kP * kL / (5.0 / 6.0 * G * kh);
  double previous_error = 1e300;
  for (int refine : {1, 2, 4, 8}) {
    const double delta = tip_deflection(element, 10 * refine, 2 * refine);
    const double error = std::abs(delta - exact) / exact;
    EXPECT_LT(error, previous_error) << element << " mesh " << 10 * refine << " x " << 2 * refine;
    previous_error = error;
  }
  EXPECT_LT(previous_error, 0.02) << element;
}

TEST(Cantilever, SSPquadTipDeflectionConvergesToBeamTheory) { expect_convergence("SSPquad"); }
TEST(Cantilever, QuadTipDeflectionConvergesToBeamTheory) { expect_convergence("quad"); }

}  // namespace
