// Unit tests: `algorithm ... -elasticTangent` (fem_tcl extension) iterates on the elastic effective stiffness,
// factored once while dt is unchanged, and converges to the same state as full Newton on the consistent tangent
// (both to NormDispIncr 1e-10 here); OpenSees' KrylovNewton `-iterate`/`-increment` tangent words are read.
#include <gtest/gtest.h>

#include <string>

#include "fem_tcl/tcl/interpreter.hpp"
#include "support/tolerance.hpp"

namespace {

using fem::tcl::Interpreter;

/// A 6 x 5 Mohr-Coulomb column (1 m SSPquads) after elastic gravity and the switch to stage 1, with the
/// transient analysis set up with `algorithm`, then 50 steps of 1e-3 s.
std::string column(const std::string& algorithm) {
  return R"tcl(
model basic -ndm 2 -ndf 2
set nx 6; set ny 5
for {set j 0} {$j <= $ny} {incr j} {
  for {set i 0} {$i <= $nx} {incr i} { node [expr {$j*($nx+1)+$i+1}] [expr {1.0*$i}] [expr {1.0*$j}] }
}
fixY 0.0 1 1
fixX 0.0 1 0
nDMaterial MohrCoulomb 1 172000.0 0.23 1.925 22.2 0.1 0.0
set e 0
for {set j 0} {$j < $ny} {incr j} {
  for {set i 0} {$i < $nx} {incr i} {
    incr e
    set n1 [expr {$j*($nx+1)+$i+1}]
    element SSPquad $e $n1 [expr {$n1+1}] [expr {$n1+$nx+2}] [expr {$n1+$nx+1}] 1 PlaneStrain 1.0 0.0 [expr {-1.925*9.81}]
  }
}
constraints Transformation
system UmfPack
test NormDispIncr 1e-10 10
algorithm Newton
integrator LoadControl 1.0
analysis Static
analyze 1
loadConst -time 0.0
wipeAnalysis
updateMaterialStage -material 1 -stage 1
constraints Transformation
system UmfPack
test NormDispIncr 1e-10 50
)tcl" + std::string("algorithm ") + algorithm + R"tcl(
integrator Newmark 0.5 0.25
analysis Transient
set ok [analyze 50 0.001]
)tcl";
}

double top_right_uy(Interpreter& interp) { return interp.context().domain.find_node(42)->disp[1]; }
double top_right_ux(Interpreter& interp) { return interp.context().domain.find_node(42)->disp[0]; }

TEST(ElasticTangent, SameStateAsFullNewtonWithOneFactorization) {
  Interpreter newton;
  newton.eval(column("Newton"));
  ASSERT_EQ(newton.eval("set ok"), "0");
  Interpreter krylov;
  krylov.eval(column("KrylovNewton -elasticTangent -maxDim 6"));
  ASSERT_EQ(krylov.eval("set ok"), "0");
  EXPECT_LT(top_right_uy(newton), -1e-3);  // the column has started to collapse
  EXPECT_CLOSE(top_right_uy(krylov), top_right_uy(newton), 1e-9, 0.0);
  EXPECT_CLOSE(top_right_ux(krylov), top_right_ux(newton), 1e-9, 0.0);
  const auto& stats = krylov.context().analysis->stats();
  EXPECT_EQ(stats.steps, 50);
  EXPECT_EQ(stats.factorizations, 1);  // the elastic effective stiffness, factored once for the 50 steps
  EXPECT_GT(newton.context().analysis->stats().factorizations, 50);  // one per Newton iteration
  Interpreter modified;
  modified.eval(column("ModifiedNewton -elasticTangent"));
  ASSERT_EQ(modified.eval("set ok"), "0");
  // modified Newton converges linearly: a last increment of 1e-10 leaves an error of about q / (1 - q) of it
  EXPECT_CLOSE(top_right_uy(modified), top_right_uy(newton), 1e-8, 0.0);
  EXPECT_EQ(modified.context().analysis->stats().factorizations, 1);
}

TEST(ElasticTangent, KrylovTangentWords) {
  Interpreter interp;
  interp.eval("model basic -ndm 2 -ndf 2");
  EXPECT_NO_THROW(interp.eval("algorithm KrylovNewton -iterate initial -increment initial -maxDim 4"));
  EXPECT_NO_THROW(interp.eval("algorithm KrylovNewton -iterate current -increment noTangent"));
  try {
    interp.eval("algorithm KrylovNewton -iterate secant");
    ADD_FAILURE() << "expected an error";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("unknown tangent type 'secant'"), std::string::npos) << e.what();
  }
}

}  // namespace
