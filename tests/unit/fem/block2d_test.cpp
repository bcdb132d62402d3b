// Unit tests: OpenSees' block2D mesh generator (fem_tcl/elements/block2d.hpp, fem_tcl/tcl/block2d_command.cpp).
// Reference: OpenSees 3.8, SRC/modelbuilder/tcl/Block2D.cpp (Ed Love; the 9-node Lagrange map, the default
// mid-side and centre points, getElementNodes) and TclCommand_doBlock2D in SRC/modelbuilder/tcl/
// TclModelBuilder.cpp (nodes created row by row, i fastest, from startNode; elements likewise from startEle,
// each as `element type tag n1 n2 n3 n4 eleArgs`). Expected coordinates below are computed by hand.
#include <gtest/gtest.h>

#include "fem_tcl/elements/block2d.hpp"
#include "fem_tcl/tcl/interpreter.hpp"
#include "support/tolerance.hpp"

namespace {

using fem::domain::Vector2;
using fem::elements::Block2dPoints;
using fem::tcl::Interpreter;

Block2dPoints corners(Vector2 a, Vector2 b, Vector2 c, Vector2 d) {
  Block2dPoints p;
  p[0] = a;
  p[1] = b;
  p[2] = c;
  p[3] = d;
  return p;
}

void expect_point(const Vector2& actual, double x, double y) {
  EXPECT_CLOSE(actual.x(), x, 1e-14, 1e-14);
  EXPECT_CLOSE(actual.y(), y, 1e-14, 1e-14);
}

std::string error_of(Interpreter& interp, const std::string& script) {
  std::string message;
  return interp.eval_script(script, "test", message) ? std::string() : message;
}

TEST(Block2dMap, ShapeFunctionsAreLagrangeAndSumToOne) {
  // N_k is 1 at its own point and 0 at the other eight (points in Block2D's order).
  const double nat[9][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {0, -1}, {1, 0}, {0, 1}, {-1, 0}, {0, 0}};
  for (int k = 0; k < 9; ++k) {
    const auto n = fem::elements::block2d_shape(nat[k][0], nat[k][1]);
    for (int m = 0; m < 9; ++m) EXPECT_CLOSE(n[m], m == k ? 1.0 : 0.0, 1e-15, 0.0) << k << " " << m;
  }
  const auto n = fem::elements::block2d_shape(0.3, -0.7);
  double sum = 0.0;
  for (double v : n) sum += v;
  EXPECT_CLOSE(sum, 1.0, 1e-15, 0.0);
}

TEST(Block2dMap, CornersOnlyIsTheBilinearMap) {
  // General quadrilateral 1 (0,0), 2 (4,0), 3 (3,3), 4 (0,1); numX = 4, numY = 2. With the default mid-side
  // points (edge midpoints) and centre (mean of the corners) the 9-node map is the bilinear one:
  // x(xi, eta) = sum N_k^bilinear x_k. Hand values: node (1,0): xi = -0.5 on edge 1-2 -> (1, 0);
  // node (0,1): midpoint of 1-4 -> (0, 0.5); node (2,1): centre = mean of corners -> (1.75, 1);
  // node (1,1): xi = -0.5, eta = 0 -> 0.75 * (0, 0.5) + 0.25 * (3.5, 1.5) = (0.875, 0.75);
  // node (3,2): on edge 4-3 at 3/4 -> (2.25, 2.5).
  const auto c = fem::elements::block2d_node_coords(4, 2, corners({0, 0}, {4, 0}, {3, 3}, {0, 1}));
  ASSERT_EQ(c.size(), 15u);
  const auto at = [&](int i, int j) { return c[static_cast<std::size_t>(i + j * 5)]; };
  expect_point(at(0, 0), 0, 0);
  expect_point(at(4, 0), 4, 0);
  expect_point(at(4, 2), 3, 3);
  expect_point(at(0, 2), 0, 1);
  expect_point(at(1, 0), 1, 0);
  expect_point(at(0, 1), 0, 0.5);
  expect_point(at(2, 1), 1.75, 1);
  expect_point(at(1, 1), 0.875, 0.75);
  expect_point(at(3, 2), 2.25, 2.5);
}

TEST(Block2dMap, MidSidePointBendsTheEdgeIntoAParabola) {
  // Square 2 x 2 with point 5 at (1, -0.5): edge 1-2 becomes y = -0.5 (1 - xi^2), x = 1 + xi.
  // numX = 4, numY = 2. Node (1,0): xi = -0.5: Nx = {0.375, 0.75, -0.125} -> 0.375 (0,0) + 0.75 (1,-0.5)
  // - 0.125 (2,0) = (0.5, -0.375). Node (2,0) is point 5 itself. Node (1,1): xi = -0.5, eta = 0, between the
  // default points 8 (0,1), 9 = corner mean (1,1) and 6 (2,1): (0.5, 1). Node (2,1) is the centre (1, 1).
  Block2dPoints p = corners({0, 0}, {2, 0}, {2, 2}, {0, 2});
  p[4] = Vector2(1, -0.5);
  const auto c = fem::elements::block2d_node_coords(4, 2, p);
  const auto at = [&](int i, int j) { return c[static_cast<std::size_t>(i + j * 5)]; };
  expect_point(at(1, 0), 0.5, -0.375);
  expect_point(at(2, 0), 1, -0.5);
  expect_point(at(3, 0), 1.5, -0.375);
  expect_point(at(1, 1), 0.5, 1);
  expect_point(at(2, 1), 1, 1);
  expect_point(at(2, 2), 1, 2);  // edge 3-4 stays straight
}

TEST(Block2dMap, CentrePointAndAllNinePoints) {
  // Point 9 given at (1.2, 1): the centre node (numX = numY = 2) is that point; node (1,0) stays the edge
  // midpoint. With points 5-8 given on the straight edges and 9 at the centre, the map is the bilinear one
  // again: numX = numY = 4, node (1,1) at (0.5, 0.5).
  Block2dPoints p = corners({0, 0}, {2, 0}, {2, 2}, {0, 2});
  p[8] = Vector2(1.2, 1);
  auto c = fem::elements::block2d_node_coords(2, 2, p);
  expect_point(c[4], 1.2, 1);
  expect_point(c[1], 1, 0);
  Block2dPoints all = corners({0, 0}, {2, 0}, {2, 2}, {0, 2});
  all[4] = Vector2(1, 0);
  all[5] = Vector2(2, 1);
  all[6] = Vector2(1, 2);
  all[7] = Vector2(0, 1);
  all[8] = Vector2(1, 1);
  c = fem::elements::block2d_node_coords(4, 4, all);
  expect_point(c[6], 0.5, 0.5);
}

TEST(Block2dMap, ElementNodesFollowOpenSees) {
  // Block2D::getElementNodes, 4-node: node1 = i + j (nx + 1), node2 = node1 + 1, node3 = node2 + nx + 1,
  // node4 = node1 + nx + 1.
  const auto n = fem::elements::block2d_element_nodes(3, 1, 1);
  EXPECT_EQ(n, (std::array<int, 4>{5, 6, 10, 9}));
}

TEST(Block2dMap, InvalidBlocksAreFound) {
  using fem::elements::block2d_invalid_corners;
  const auto contains = [](const std::optional<std::string>& e, const std::string& what) {
    return e && e->find(what) != std::string::npos;
  };
  EXPECT_FALSE(block2d_invalid_corners(corners({0, 0}, {1, 0}, {1, 1}, {0, 1})));
  EXPECT_TRUE(contains(block2d_invalid_corners(corners({0, 0}, {1, 0}, {0, 1}, {1, 1})), "crossed"));
  EXPECT_TRUE(contains(block2d_invalid_corners(corners({0, 0}, {1, 0}, {2, 0}, {3, 0})), "zero area"));
  EXPECT_TRUE(contains(block2d_invalid_corners(corners({0, 0}, {0, 1}, {1, 1}, {1, 0})), "clockwise"));
  EXPECT_TRUE(contains(block2d_invalid_corners(corners({0, 0}, {2, 0}, {0.5, 0.5}, {0, 2})), "concave"));
  // element level: a mid-side point pulled past the opposite edge folds the map
  const auto bad = [](Block2dPoints p) {
    return fem::elements::block2d_invalid_element(2, 2, fem::elements::block2d_node_coords(2, 2, p));
  };
  EXPECT_FALSE(bad(corners({0, 0}, {1, 0}, {1, 1}, {0, 1})));
  Block2dPoints folded = corners({0, 0}, {1, 0}, {1, 1}, {0, 1});
  folded[4] = Vector2(0.5, 1.6);
  EXPECT_FALSE(block2d_invalid_corners(folded));
  EXPECT_TRUE(contains(bad(folded), "folded"));
  EXPECT_TRUE(contains(fem::elements::block2d_invalid_element(1, 1, {{0, 0}, {1, 0}, {1, 0}, {1, 1}}), "zero area"));
}

TEST(Block2dCommand, NumberingAndElementArgumentsAsOpenSees) {
  Interpreter interp;
  ASSERT_EQ(error_of(interp, R"tcl(
model basic -ndm 2 -ndf 2
nDMaterial ElasticIsotropic 1 1000.0 0.25 2.0
block2D 3 2 101 11 quad "1.0 PlaneStrain 1" {1 0 0 2 3 0 3 3 2 4 0 2}
)tcl"), "");
  const auto& d = interp.context().domain;
  ASSERT_EQ(d.nodes().size(), 12u);
  ASSERT_EQ(d.elements().size(), 6u);
  // node 101 + i + 4 j at (i, j); element 11 + i + 3 j on nodes (i, j), (i+1, j), (i+1, j+1), (i, j+1)
  const auto* n106 = d.find_node(106);
  ASSERT_NE(n106, nullptr);
  expect_point(n106->crd, 1, 1);
  EXPECT_EQ(interp.eval("eleNodes 15"), "106 107 111 110");
  EXPECT_EQ(interp.eval("eleNodes 11"), "101 102 106 105");
  EXPECT_EQ(interp.eval("eleNodes 16"), "107 108 112 111");
  EXPECT_EQ(interp.context().domain.find_node(112)->crd, Vector2(3, 2));
  // SSPquad arguments (matTag type thick b1 b2) after the nodes; a variable in braced eleArgs is
  // substituted when each element command is evaluated, as in OpenSees
  ASSERT_EQ(error_of(interp, "set b -9.81\nblock2D 1 1 201 21 SSPquad {1 PlaneStrain 1.0 0.0 $b} {1 0 2 2 3 2 3 3 3 4 0 3}"), "");
  EXPECT_EQ(interp.eval("eleNodes 21"), "201 202 204 203");
}

TEST(Block2dCommand, ErrorsNameTheBlock) {
  Interpreter interp;
  ASSERT_EQ(error_of(interp, "model basic -ndm 2 -ndf 2\nnDMaterial ElasticIsotropic 1 1000.0 0.25 2.0"), "");
  const std::string square = " {1 0 0 2 1 0 3 1 1 4 0 1}";
  std::string e = error_of(interp, "block2D 2 2 1 1 quad \"1.0 PlaneStrain 1\" -numEleNodes 9" + square);
  EXPECT_NE(e.find("block2D 2 2 1 1"), std::string::npos) << e;
  EXPECT_NE(e.find("no 9-node element"), std::string::npos) << e;
  e = error_of(interp, "block2D 2 2 1 1 quad \"1.0 PlaneStrain 1\" {1 0 0 2 1 0 3 0 1 4 1 1}");
  EXPECT_NE(e.find("block2D 2 2 1 1"), std::string::npos) << e;
  EXPECT_NE(e.find("crossed"), std::string::npos) << e;
  e = error_of(interp, "block2D 2 2 1 1 quad \"1.0 PlaneStrain 1\" {1 0 0 2 1 0 3 2 0 4 3 0}");
  EXPECT_NE(e.find("zero area"), std::string::npos) << e;
  e = error_of(interp, "block2D 2 2 1 1 quad \"1.0 PlaneStrain 1\" {1 0 0 2 1 0 3 1 1}");
  EXPECT_NE(e.find("corner point 4 is missing"), std::string::npos) << e;
  e = error_of(interp, "block2D 2 2 1 1 quad \"1.0 PlaneStrain 1\" {1 0 0 2 1 0 3 1 1 4 0 1 10 0 0}");
  EXPECT_NE(e.find("point number 1-9"), std::string::npos) << e;
  e = error_of(interp, "block2D 2 2 1 1 tri31 \"1.0 PlaneStrain 1\"" + square);
  EXPECT_NE(e.find("element type 'tri31' has 3 nodes; block2D makes 4-node elements"), std::string::npos) << e;
  e = error_of(interp, "block2D 2 2 1 1 bbarQuad \"1.0 PlaneStrain 1\"" + square);
  EXPECT_NE(e.find("unknown element type 'bbarQuad' (4-node types: SSPquad, SSPquadUP, SSPQuadUP, quadUP, quad, FourNodeQuad)"), std::string::npos) << e;
  e = error_of(interp, "block2D 0 2 1 1 quad \"1.0 PlaneStrain 1\"" + square);
  EXPECT_NE(e.find("numX and numY >= 1"), std::string::npos) << e;
  // tags past the int range, and a block too large to build, fail before anything is allocated
  e = error_of(interp, "block2D 2 2 2147483640 2147483646 quad \"1.0 PlaneStrain 1\"" + square);
  EXPECT_NE(e.find("the block's tags would pass 2147483647 (nodes 2147483640-2147483648, elements 2147483646-2147483649)"),
            std::string::npos) << e;
  e = error_of(interp, "block2D 100000 100000 1 1 quad \"1.0 PlaneStrain 1\"" + square);
  EXPECT_NE(e.find("a block of 10000200001 nodes is beyond fem_tcl's limit of 20000000 per block"), std::string::npos) << e;
  EXPECT_TRUE(interp.context().domain.nodes().empty());  // nothing created by the failed blocks
  // an element error names the block, the element and the element's own complaint
  e = error_of(interp, "block2D 2 2 1 1 quad \"1.0 PlaneStrain 7\"" + square);
  EXPECT_NE(e.find("block2D 2 2 1 1: element 1"), std::string::npos) << e;
  EXPECT_NE(e.find("nDMaterial 7 does not exist"), std::string::npos) << e;
  // tags in use are found before anything is created
  ASSERT_EQ(error_of(interp, "wipe\nmodel basic -ndm 2 -ndf 2\nnDMaterial ElasticIsotropic 1 1000.0 0.25 2.0\nnode 5 9 9"), "");
  e = error_of(interp, "block2D 2 2 1 1 quad \"1.0 PlaneStrain 1\"" + square);
  EXPECT_NE(e.find("node 5 already exists"), std::string::npos) << e;
  EXPECT_EQ(interp.context().domain.nodes().size(), 1u);
}

}  // namespace
