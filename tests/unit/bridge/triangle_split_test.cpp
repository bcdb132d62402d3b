// Unit tests of bridge::split_triangles: a unit square cut into two Tri31 triangles becomes six convex,
// counter-clockwise quads that tile it, sharing the midpoint of the shared side, with the triangles'
// linear displacement and velocity fields at the new nodes and each triangle's stress on its quads.
#include <gtest/gtest.h>

#include "bridge/quad_geometry.hpp"
#include "bridge/triangle_split.hpp"
#include "support/tolerance.hpp"

namespace {

bridge::TransferState two_triangles() {
  bridge::TransferState st;
  st.reference = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  // u = A x + b and v = B x + c: linear fields, which the triangles carry exactly.
  for (const auto& x : st.reference) {
    st.displacement.push_back(bridge::Vec2(0.01 * x.x() - 0.02 * x.y() + 0.003, 0.005 * x.x() + 0.04 * x.y()));
    st.velocity.push_back(bridge::Vec2(-0.3 * x.y(), 0.2 * x.x() + 0.1));
  }
  st.load = {bridge::Vec2(0, -5), bridge::Vec2::Zero(), bridge::Vec2::Zero(), bridge::Vec2::Zero()};
  bridge::TransferElement a, b, q;
  a.tag = 7;
  a.nodes = {0, 1, 2, 0};
  a.node_count = 3;
  b.tag = 8;
  b.nodes = {0, 2, 3, 0};
  b.node_count = 3;
  st.elements = {a, b};
  st.index_gauss_points();
  st.gauss_stress = {bridge::Stress6{-1, -2, -0.5, 0.3, 0, 0}, bridge::Stress6{-4, -5, -2, -0.1, 0, 0}};
  return st;
}

TEST(TriangleSplit, TwoTrianglesBecomeSixQuadsThatTileThem) {
  bridge::TransferState st = two_triangles();
  EXPECT_EQ(bridge::split_triangles(st), 2u);
  ASSERT_EQ(st.elements.size(), 6u);
  EXPECT_EQ(st.reference.size(), 4u + 5u + 2u);  // 5 side midpoints (one shared), 2 centroids
  ASSERT_EQ(st.gauss_stress.size(), 6u);
  ASSERT_EQ(st.gauss_offset.back(), 6u);
  ASSERT_EQ(st.load.size(), st.reference.size());
  double area = 0.0;
  for (std::size_t e = 0; e < st.elements.size(); ++e) {
    const auto& el = st.elements[e];
    EXPECT_EQ(el.node_count, 4);
    EXPECT_EQ(el.gauss_points, 1);
    EXPECT_GT(bridge::min_jacobian_determinant(st.reference_nodes(el)), 0.0) << "quad " << e;
    area += bridge::quad_area(st.reference_nodes(el));
    EXPECT_EQ(el.tag, e < 3 ? 7 : 8);
    EXPECT_EQ(st.gauss_stress[e][0], e < 3 ? -1.0 : -4.0);
  }
  EXPECT_CLOSE(area, 1.0, 1e-15, 1e-14);
  for (std::size_t i = 4; i < st.reference.size(); ++i) {
    const bridge::Vec2 x = st.reference[i];
    EXPECT_CLOSE(st.displacement[i].x(), 0.01 * x.x() - 0.02 * x.y() + 0.003, 1e-17, 1e-14) << "node " << i;
    EXPECT_CLOSE(st.displacement[i].y(), 0.005 * x.x() + 0.04 * x.y(), 1e-17, 1e-14) << "node " << i;
    EXPECT_CLOSE(st.velocity[i].x(), -0.3 * x.y(), 1e-16, 1e-14);
    EXPECT_CLOSE(st.velocity[i].y(), 0.2 * x.x() + 0.1, 1e-16, 1e-14);
    EXPECT_EQ(st.load[i], bridge::Vec2::Zero());
  }
  // The diagonal's midpoint (0.5, 0.5) is one node, used by a quad of each triangle.
  int at_diagonal = -1;
  for (std::size_t i = 4; i < st.reference.size(); ++i)
    if ((st.reference[i] - bridge::Vec2(0.5, 0.5)).norm() < 1e-15) at_diagonal = static_cast<int>(i);
  ASSERT_GE(at_diagonal, 0);
  int users = 0;
  for (const auto& el : st.elements)
    for (int a : el.nodes) users += a == at_diagonal;
  EXPECT_EQ(users, 4);  // two quads of each triangle touch the shared side's midpoint
}

TEST(TriangleSplit, QuadsAreLeftAlone) {
  bridge::TransferState st;
  st.reference = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  st.displacement.assign(4, bridge::Vec2::Zero());
  st.velocity.assign(4, bridge::Vec2::Zero());
  bridge::TransferElement q;
  q.nodes = {0, 1, 2, 3};
  st.elements = {q};
  st.index_gauss_points();
  st.gauss_stress = {bridge::Stress6{}};
  EXPECT_EQ(bridge::split_triangles(st), 0u);
  EXPECT_EQ(st.elements.size(), 1u);
  EXPECT_EQ(st.reference.size(), 4u);
}

}  // namespace
