// fem2mpm --loads (bridge/nodal_loads.hpp): a FEM nodal force spread over the particles of the elements
// that share the node, with node a's shape function at each particle as the weight. The forces sum to the
// nodal force exactly, and around an interior node of a regular mesh they are centred on the node (the
// four elements' weights are mirror images); the particles of elements without the node carry nothing.
#include <gtest/gtest.h>

#include "bridge/nodal_loads.hpp"
#include "bridge/particle_mapping.hpp"
#include "support/bridge_states.hpp"
#include "support/tolerance.hpp"

namespace {

using bridge::Vec2;

/// 3 x 2 unit squares: nodes (i, j) = i + 4 j, elements row by row.
bridge::TransferState three_by_two() {
  std::vector<Vec2> nodes;
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 3; ++i) nodes.emplace_back(i, j);
  std::vector<std::array<int, 4>> quads;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) quads.push_back({i + 4 * j, i + 1 + 4 * j, i + 5 + 4 * j, i + 4 + 4 * j});
  return test_support::resting_state(nodes, quads, 2000, 1e7, 0.3);
}

TEST(NodalLoads, SumToTheNodalForceCentredOnTheNode) {
  bridge::TransferState st = three_by_two();
  st.load.assign(st.reference.size(), Vec2::Zero());
  const Vec2 F(3.0, -40.0);
  st.load[5] = F;  // interior node (1, 1): elements 0, 1, 3, 4
  const int n = 3;
  const auto loads = bridge::particle_loads(st, n);
  ASSERT_EQ(loads.size(), 4u * n * n);
  const bridge::MappingOptions mo{n};
  const auto particles = bridge::generate_particles(st, std::vector<bridge::Stress6>(st.reference.size()), mo);
  Vec2 total = Vec2::Zero(), moment = Vec2::Zero();
  for (const auto& l : loads) {
    total += l.force;
    const auto& p = particles[static_cast<std::size_t>(l.id)];
    moment += l.force.y() * Vec2(p.coord_x, p.coord_y);
    const long element = l.id / (n * n);
    EXPECT_TRUE(element == 0 || element == 1 || element == 3 || element == 4) << "particle " << l.id;
  }
  EXPECT_CLOSE(total.x(), F.x(), 1e-12, 0);
  EXPECT_CLOSE(total.y(), F.y(), 1e-12, 0);
  EXPECT_CLOSE(moment.x() / total.y(), 1.0, 1e-12, 0);  // the centroid of the forces is the node (1, 1)
  EXPECT_CLOSE(moment.y() / total.y(), 1.0, 1e-12, 0);
}

TEST(NodalLoads, NoneWithoutLoads) {
  bridge::TransferState st = three_by_two();
  EXPECT_TRUE(bridge::particle_loads(st, 2).empty());
  st.load.assign(st.reference.size(), Vec2::Zero());
  EXPECT_TRUE(bridge::particle_loads(st, 2).empty());
}

}  // namespace
