// Unit tests of the FEM support -> MPM boundary extraction (bridge/boundary_extraction) and of the deck's
// grid alignment to the support lines (bridge/deck_boundaries, mpm_deck choose_grid), on small hand-made
// meshes in fem_tcl's print -JSON layout: the expected lines, kinds, extents and named nodes follow from
// the meshes by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "bridge/boundary_extraction.hpp"
#include "bridge/deck_boundaries.hpp"
#include "bridge/fem_model.hpp"
#include "support/bridge_states.hpp"
#include "support/input_error_message.hpp"
#include "support/tolerance.hpp"

namespace {

/// A structured nx x ny mesh of dx x dy SSPquads from (x0, 0); node tags first_node + j (nx + 1) + i.
struct Mesh {
  std::vector<std::string> nodes, elements, fixes, ties;
  int next_element = 1;

  void block(int nx, int ny, double x0, double dx, double dy, int first_node) {
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        nodes.push_back("{\"name\": " + std::to_string(first_node + j * (nx + 1) + i) + ", \"ndf\": 2, \"crd\": [" +
                        std::to_string(x0 + i * dx) + ", " + std::to_string(j * dy) + "]}");
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int n1 = first_node + j * (nx + 1) + i;
        elements.push_back("{\"name\": " + std::to_string(next_element++) + ", \"type\": \"SSPquad\", \"nodes\": [" +
                           std::to_string(n1) + ", " + std::to_string(n1 + 1) + ", " + std::to_string(n1 + nx + 2) + ", " +
                           std::to_string(n1 + nx + 1) + "], \"thickness\": 1, \"material\": \"1\"}");
      }
  }
  void fix(int node, int fx, int fy) {
    fixes.push_back("{\"node\": " + std::to_string(node) + ", \"fix\": [" + std::to_string(fx) + ", " + std::to_string(fy) + "]}");
  }
  void tie(int retained, int constrained, const std::string& dofs) {
    ties.push_back("{\"retained\": " + std::to_string(retained) + ", \"constrained\": " + std::to_string(constrained) +
                   ", \"dofs\": [" + dofs + "]}");
  }
  std::string json(bool with_constraints = true) const {
    auto list = [](const std::vector<std::string>& items) {
      std::string s = "[\n";
      for (std::size_t i = 0; i < items.size(); ++i) s += "\t\t\t" + items[i] + (i + 1 < items.size() ? ",\n" : "\n");
      return s + "\t\t]";
    };
    std::string s = "{\n\"StructuralAnalysisModel\": {\n\t\"properties\": {\n\t\t\"ndMaterials\": " +
                    list({"{\"name\": \"1\", \"type\": \"ElasticIsotropicMaterial\", \"E\": 1e7, \"nu\": 0.3, \"rho\": 2000}"}) +
                    "\n\t},\n\t\"geometry\": {\n\t\t\"nodes\": " + list(nodes) + ",\n\t\t\"elements\": " + list(elements) + "\n\t}";
    if (with_constraints) s += ",\n\t\"constraints\": {\n\t\t\"fix\": " + list(fixes) + ",\n\t\t\"equalDOF\": " + list(ties) + "\n\t}";
    return s + "\n}\n}\n";
  }
};

/// The 4 x 3 mesh of 1 m cells (nodes 1..20, 5 per row): base fully fixed, left and right sides on rollers.
Mesh box_on_rollers() {
  Mesh m;
  m.block(4, 3, 0, 1, 1, 1);
  for (int i = 1; i <= 5; ++i) m.fix(i, 1, 1);
  for (int j = 1; j <= 3; ++j) {
    m.fix(1 + 5 * j, 1, 0);
    m.fix(5 + 5 * j, 1, 0);
  }
  return m;
}

bridge::ExtractedBoundaries extract(const Mesh& m, bool with_constraints = true) {
  return bridge::extract_boundaries(bridge::parse_fem_model(m.json(with_constraints), "model.json"));
}

std::string all(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines) s += l + "\n";
  return s;
}

TEST(BoundaryExtraction, RollerSidesAndFixedBase) {
  const auto b = extract(box_on_rollers());
  ASSERT_TRUE(b.from_model);
  EXPECT_TRUE(b.warnings.empty()) << all(b.warnings);
  ASSERT_EQ(b.lines.size(), 3u);
  const auto* left = b.line(bridge::GridEdge::Left);
  const auto* right = b.line(bridge::GridEdge::Right);
  const auto* base = b.line(bridge::GridEdge::Base);
  ASSERT_TRUE(left && right && base);
  EXPECT_EQ(left->kind, bridge::SupportKind::Roller);
  EXPECT_CLOSE(left->coordinate, 0, 0, 0);
  EXPECT_CLOSE(left->from, 0, 0, 0);
  EXPECT_CLOSE(left->to, 3, 0, 0);
  EXPECT_EQ(left->nodes, (std::vector<long>{1, 6, 11, 16}));
  EXPECT_EQ(right->kind, bridge::SupportKind::Roller);
  EXPECT_CLOSE(right->coordinate, 4, 0, 0);
  EXPECT_EQ(right->nodes, (std::vector<long>{5, 10, 15, 20}));
  EXPECT_EQ(base->kind, bridge::SupportKind::Fixed);
  EXPECT_CLOSE(base->coordinate, 0, 0, 0);
  EXPECT_EQ(base->nodes, (std::vector<long>{1, 2, 3, 4, 5}));
}

TEST(BoundaryExtraction, RollerFloorAndFreeSides) {
  Mesh m;
  m.block(4, 3, 0, 1, 1, 1);
  for (int i = 1; i <= 5; ++i) m.fix(i, 0, 1);
  const auto b = extract(m);
  EXPECT_TRUE(b.warnings.empty()) << all(b.warnings);
  ASSERT_EQ(b.lines.size(), 1u);
  EXPECT_EQ(b.lines[0].edge, bridge::GridEdge::Base);
  EXPECT_EQ(b.lines[0].kind, bridge::SupportKind::Roller);
}

TEST(BoundaryExtraction, WithoutConstraintsBlockTheOptionsDecide) {
  const auto b = extract(box_on_rollers(), false);
  EXPECT_FALSE(b.from_model);
  EXPECT_TRUE(b.lines.empty());
  ASSERT_EQ(b.notes.size(), 1u);
  EXPECT_NE(b.notes[0].find("no supports in the model file"), std::string::npos) << b.notes[0];
}

// Two blocks tied along x = 2 (nodes 3, 8, 13 of the left block to 16, 19, 22 of the right one): the base
// runs across both, the interface is no boundary, and the tie is a note, not a warning.
TEST(BoundaryExtraction, EqualDofTiesJoinCoincidentBlocks) {
  Mesh m;
  m.block(2, 2, 0, 1, 1, 1);    // nodes 1..9, x 0..2
  m.block(2, 2, 2, 1, 1, 16);   // nodes 16..24, x 2..4
  for (int n : {1, 2, 3, 16, 17, 18}) m.fix(n, 1, 1);
  for (int n : {4, 7}) m.fix(n, 1, 0);
  for (int n : {21, 24}) m.fix(n, 1, 0);
  for (int k = 0; k < 3; ++k) m.tie(3 + 3 * k, 16 + 3 * k, "1, 2");
  const auto b = extract(m);
  EXPECT_TRUE(b.warnings.empty()) << all(b.warnings);
  const auto* base = b.line(bridge::GridEdge::Base);
  ASSERT_TRUE(base);
  EXPECT_CLOSE(base->from, 0, 0, 0);
  EXPECT_CLOSE(base->to, 4, 0, 0);
  ASSERT_TRUE(b.line(bridge::GridEdge::Left) && b.line(bridge::GridEdge::Right));
  EXPECT_NE(all(b.notes).find("3 equalDOF ties join coincident nodes"), std::string::npos) << all(b.notes);
}

// Periodic sides (left node tied to the right node at the same height): no MPM counterpart, a warning naming them.
TEST(BoundaryExtraction, PeriodicTiesAreReportedNotRepresentable) {
  Mesh m;
  m.block(4, 3, 0, 1, 1, 1);
  for (int i = 1; i <= 5; ++i) m.fix(i, 1, 1);
  for (int j = 1; j <= 3; ++j) m.tie(1 + 5 * j, 5 + 5 * j, "1, 2");
  const auto b = extract(m);
  ASSERT_EQ(b.warnings.size(), 1u) << all(b.warnings);
  EXPECT_NE(b.warnings[0].find("periodic"), std::string::npos) << b.warnings[0];
  EXPECT_NE(b.warnings[0].find("6 10 11 15 16 20"), std::string::npos) << b.warnings[0];
  EXPECT_FALSE(b.line(bridge::GridEdge::Left));
  EXPECT_FALSE(b.line(bridge::GridEdge::Right));
}

// A single fixed point on the right side (node 15) and a support on the top (nodes 16, 17): named, not dropped.
TEST(BoundaryExtraction, SupportsThatCannotBeMappedAreNamed) {
  Mesh m = box_on_rollers();
  m.fixes.erase(m.fixes.begin() + 5, m.fixes.end());  // keep the base only
  m.fix(15, 1, 0);
  m.fix(16, 0, 1);
  m.fix(17, 0, 1);
  const auto b = extract(m);
  ASSERT_EQ(b.lines.size(), 1u);
  const std::string w = all(b.warnings);
  EXPECT_NE(w.find("nodes 15 cannot be represented"), std::string::npos) << w;
  EXPECT_NE(w.find("a single point"), std::string::npos) << w;
  EXPECT_NE(w.find("nodes 16 17 cannot be represented"), std::string::npos) << w;
}

// An inclined side: the one element (0,0) (2,0) (3,2) (0,2) with its inclined side's nodes 2 and 3 fixed in x.
TEST(BoundaryExtraction, InclinedSupportIsNamed) {
  Mesh m;
  m.nodes = {"{\"name\": 1, \"crd\": [0, 0]}", "{\"name\": 2, \"crd\": [2, 0]}", "{\"name\": 3, \"crd\": [3, 2]}",
             "{\"name\": 4, \"crd\": [0, 2]}"};
  m.elements = {"{\"name\": 1, \"type\": \"SSPquad\", \"nodes\": [1, 2, 3, 4], \"material\": \"1\"}"};
  m.fix(1, 1, 1);
  m.fix(2, 1, 1);
  m.fix(3, 1, 0);
  const auto b = extract(m);
  ASSERT_TRUE(b.line(bridge::GridEdge::Base));
  const std::string w = all(b.warnings);
  EXPECT_NE(w.find("nodes 3 cannot be represented"), std::string::npos) << w;
  EXPECT_NE(w.find("inclined"), std::string::npos) << w;
}

TEST(BoundaryExtraction, MalformedConstraintsNameFileLineAndKey) {
  Mesh m = box_on_rollers();
  m.fixes[2] = "{\"node\": 3, \"fix\": [1]}";
  const std::string text = m.json();
  const std::string line_msg = test_support::input_error_message([&] { bridge::parse_fem_model(text, "model.json"); });
  EXPECT_NE(line_msg.find("model.json:"), std::string::npos) << line_msg;
  EXPECT_NE(line_msg.find("constraints.fix"), std::string::npos) << line_msg;
  EXPECT_EQ(line_msg.find('\n'), std::string::npos) << line_msg;
  // The compact (one-line) layout goes through the full parser: the key path names the entry.
  std::string compact;
  for (char c : text) if (c != '\n') compact += c;
  const std::string full_msg = test_support::input_error_message([&] { bridge::parse_fem_model(compact, "model.json"); });
  EXPECT_NE(full_msg.find("model.json: constraints.fix[2]"), std::string::npos) << full_msg;
  m = box_on_rollers();
  m.tie(1, 99, "1");
  const std::string unknown = test_support::input_error_message([&] { bridge::parse_fem_model(m.json(), "model.json"); });
  EXPECT_NE(unknown.find("constraints.equalDOF"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("node 99"), std::string::npos) << unknown;
}

/// The transfer state of `m` at rest (1 m SSPquads, elastic).
bridge::TransferState state_of(const bridge::FemModel& model) {
  std::vector<bridge::Vec2> nodes;
  for (const auto& n : model.nodes) nodes.push_back(n.crd);
  std::vector<std::array<int, 4>> quads;
  for (const auto& fe : model.elements) quads.push_back(fe.nodes);
  return test_support::resting_state(nodes, quads, 2000, 1e7, 0.3);
}

// Walls 5.2 m apart and elements of 1.3 m2 (default cell sqrt(1.3) = 1.14 m, 4.56 cells): the cell size
// becomes 5.2 / 5 = 1.04 m so that both walls are grid edges; the base is a grid line one row above the grid's bottom; no
// runout area beyond the walls. An option still wins (--right-wall none: the runout area comes back).
TEST(DeckBoundaries, GridAlignedToSupportLines) {
  const Mesh m = box_on_rollers();
  const auto model = bridge::parse_fem_model(m.json(), "model.json");
  auto st = state_of(model);
  for (auto& p : st.reference) p.x() *= 1.3;  // 5.2 m x 3 m, elements 1.3 m x 1 m: default cell sqrt(1.3) m
  bridge::ExtractedBoundaries b = bridge::extract_boundaries(model);
  for (auto& l : b.lines) {
    if (l.edge == bridge::GridEdge::Base) { l.from *= 1.3; l.to *= 1.3; }
    else l.coordinate *= 1.3;
  }
  bridge::DeckOptions deck;
  const auto choices = bridge::apply_supports(b, {}, deck);
  EXPECT_EQ(deck.left, bridge::Wall::Roller);
  EXPECT_EQ(deck.right, bridge::Wall::Roller);
  EXPECT_EQ(deck.base, bridge::Base::Contact);
  const auto d = bridge::build_deck(st, {}, deck);
  EXPECT_CLOSE(d.grid.x0, 0, 0, 0);
  EXPECT_CLOSE(d.grid.x0 + d.grid.nx * d.grid.h, 5.2, 1e-12, 1e-12);
  EXPECT_EQ(d.grid.nx, 5);
  EXPECT_CLOSE(d.grid.h, 1.04, 1e-12, 1e-12);
  EXPECT_CLOSE(d.grid.y0, -d.grid.h, 1e-12, 0);
  EXPECT_CLOSE(d.base_y, 0, 0, 0);
  EXPECT_TRUE(d.warnings.empty());
  ASSERT_EQ(choices.size(), 3u);
  const std::string text = bridge::boundary_text(choices[1], d);
  EXPECT_NE(text.find("right wall at x = 5.2: roller"), std::string::npos) << text;
  EXPECT_NE(text.find("nodes 5 10 15 20"), std::string::npos) << text;

  bridge::DeckOptions user;
  user.right = bridge::Wall::None;
  bridge::BoundaryOptionsGiven given;
  given.right = true;
  bridge::apply_supports(b, given, user);
  const auto free_right = bridge::build_deck(st, {}, user);
  EXPECT_EQ(user.right, bridge::Wall::None);
  EXPECT_GT(free_right.grid.x0 + free_right.grid.nx * free_right.grid.h, 4 * 5.2 - 1e-9);  // 3 widths beyond

  bridge::DeckOptions odd;
  odd.cell_size = 1.5;  // 5.2 / 1.5 is no whole number: the right wall is put on the grid edge, with a warning
  bridge::apply_supports(b, {}, odd);
  const auto warned = bridge::build_deck(st, {}, odd);
  ASSERT_EQ(warned.warnings.size(), 1u);
  EXPECT_NE(warned.warnings[0].find("--cell-size"), std::string::npos) << warned.warnings[0];

  bridge::DeckOptions extent;  // --extent wins; a wall off its FEM line is said, the base still on its line
  extent.extent = std::array<double, 4>{-1.04, 5.2, -1.04, 5};
  extent.cell_size = 1.04;
  bridge::apply_supports(b, {}, extent);
  const auto with_extent = bridge::build_deck(st, {}, extent);
  EXPECT_CLOSE(with_extent.grid.x0, -1.04, 0, 0);
  EXPECT_CLOSE(with_extent.grid.x0 + with_extent.grid.nx * with_extent.grid.h, 5.2, 1e-12, 1e-12);
  EXPECT_CLOSE(with_extent.base_y, 0, 0, 0);
  ASSERT_EQ(with_extent.warnings.size(), 1u);
  EXPECT_NE(with_extent.warnings[0].find("--extent: the left wall lies on the grid's edge at x = -1.04"), std::string::npos) << with_extent.warnings[0];
}

}  // namespace

// A compliant base (a dummy node 100 under node 1, joined by a zeroLength dashpot, as in an OpenSees
// site-response model): the dashpot is a boundary device, not soil, so it is skipped with a warning naming it.
TEST(BoundaryExtraction, ZeroLengthDashpotsAreNamedNotTransferred) {
  Mesh m = box_on_rollers();
  m.nodes.push_back("{\"name\": 100, \"ndf\": 2, \"crd\": [0, 0]}");
  m.elements.push_back("{\"name\": 50, \"type\": \"ZeroLength\", \"nodes\": [100, 1], \"materials\": [\"7\"], \"dof\": [1]}");
  m.fix(100, 1, 1);
  const auto model = bridge::parse_fem_model(m.json(), "model.json");
  EXPECT_EQ(model.elements.size(), 12u);
  EXPECT_EQ(model.boundary_devices, std::vector<long>{50});
  const auto b = bridge::extract_boundaries(model);
  EXPECT_NE(all(b.warnings).find("zeroLength elements 50 (springs and dashpots of the FEM boundary)"), std::string::npos)
      << all(b.warnings);
  ASSERT_TRUE(b.line(bridge::GridEdge::Base));  // the soil's own supports still make the base
}
