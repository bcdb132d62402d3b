// Verification: the constant-strain patch test on a distorted mesh (MacNeal & Harder 1985, "A proposed
// standard set of problems to test finite element accuracy", Finite Elements in Analysis and Design 1:3-20,
// fig. 1 / table 1: 0.24 x 0.12 patch, interior nodes (0.04,0.02), (0.18,0.03), (0.16,0.08), (0.08,0.08);
// boundary displacements u = 1e-3 (x + y/2), v = 1e-3 (y + x/2), E = 1e6, nu = 0.25, plane stress).
// Exact: exx = eyy = gxy = 1e-3, sxx = syy = 1333.333..., sxy = 400, interior nodes on the linear field.
// Passing means the element represents constant strain exactly on distorted shapes (to round-off).
#include <gtest/gtest.h>

#include "fem_script.hpp"
#include "support/tolerance.hpp"

namespace {

using fem_verification::run;

std::string patch_script(const std::string& element_line) {
  return R"tcl(
model basic -ndm 2 -ndf 2
node 1 0.0 0.0
node 2 0.24 0.0
node 3 0.24 0.12
node 4 0.0 0.12
node 5 0.04 0.02
node 6 0.18 0.03
node 7 0.16 0.08
node 8 0.08 0.08
nDMaterial ElasticIsotropic 1 1.0e6 0.25
proc addElement {tag i j k l} { )tcl" + element_line + R"tcl( }
addElement 1 1 2 6 5
addElement 2 2 3 7 6
addElement 3 3 4 8 7
addElement 4 4 1 5 8
addElement 5 5 6 7 8
timeSeries Linear 1
pattern Plain 1 1 {
  foreach n {1 2 3 4} {
    set x [lindex [nodeCoord $n] 0]
    set y [lindex [nodeCoord $n] 1]
    sp $n 1 [expr {1.0e-3*($x + 0.5*$y)}]
    sp $n 2 [expr {1.0e-3*($y + 0.5*$x)}]
  }
}
constraints Transformation
numberer Plain
system UmfPack
test NormDispIncr 1.0e-14 5
algorithm Newton
integrator LoadControl 1.0
analysis Static
if {[analyze 1] != 0} { error "patch analysis failed" }
)tcl";
}

void expect_patch_passed(fem::tcl::Interpreter& interp, int values_per_element, int elements = 5) {
  auto& domain = interp.context().domain;
  for (int n = 5; n <= 8; ++n) {
    const auto& node = *domain.find_node(n);
    const double x = node.crd[0], y = node.crd[1];
    EXPECT_CLOSE(node.disp[0], 1e-3 * (x + 0.5 * y), 1e-16, 1e-10) << "node " << n;
    EXPECT_CLOSE(node.disp[1], 1e-3 * (y + 0.5 * x), 1e-16, 1e-10) << "node " << n;
  }
  const double c = 1e6 / (1.0 - 0.25 * 0.25);
  const double sxx = c * (1e-3 + 0.25 * 1e-3), sxy = 1e6 / (2.0 * 1.25) * 1e-3;
  for (int e = 1; e <= elements; ++e) {
    const auto s = fem_verification::element_response(interp, e, "stress");
    ASSERT_EQ(static_cast<int>(s.size()), values_per_element);
    for (int k = 0; k < values_per_element; k += 3) {
      EXPECT_CLOSE(s[k], sxx, 1e-9, 1e-10) << "element " << e;
      EXPECT_CLOSE(s[k + 1], sxx, 1e-9, 1e-10) << "element " << e;
      EXPECT_CLOSE(s[k + 2], sxy, 1e-9, 1e-10) << "element " << e;
    }
  }
}

TEST(PatchTest, SSPquadReproducesConstantStrainOnADistortedMesh) {
  fem::tcl::Interpreter interp;
  run(interp, patch_script("element SSPquad $tag $i $j $k $l 1 PlaneStress 0.001"));
  expect_patch_passed(interp, 3);
}

TEST(PatchTest, FourNodeQuadReproducesConstantStrainOnADistortedMesh) {
  fem::tcl::Interpreter interp;
  run(interp, patch_script("element quad $tag $i $j $k $l 0.001 PlaneStress 1"));
  expect_patch_passed(interp, 12);
}

// Each quad of the patch cut into two triangles (i j k) and (i k l): the constant-strain triangle is exact here.
TEST(PatchTest, Tri31ReproducesConstantStrainOnADistortedMesh) {
  fem::tcl::Interpreter interp;
  run(interp, patch_script("element tri31 [expr {2*$tag - 1}] $i $j $k 0.001 PlaneStress 1; "
                           "element tri31 [expr {2*$tag}] $i $k $l 0.001 PlaneStress 1"));
  expect_patch_passed(interp, 3, 10);
}

}  // namespace
