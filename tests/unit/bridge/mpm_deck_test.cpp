// The deck writer against CB-Geo's own layout: the reference deck mc_column_gimp_short (reference_runs
// section 2.2, written by cbgeo/tools/make_decks.py and run by CB-Geo) has a 30 m x 10 m grid of 0.5 m
// ED2Q16G cells with a halo ring; the same grid from fem2mpm must give the same node count, cell
// connectivity and boundary node sets.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "bridge/mpm_deck.hpp"
#include "common/input_error.hpp"
#include "support/bridge_states.hpp"
#include "support/tolerance.hpp"

namespace {

const std::filesystem::path kDeck = std::filesystem::path(GEOFLOW_TEST_DATA_DIR) / "reference_runs/cbgeo/mc_column_gimp_short";

bridge::TransferState column_state() {
  bridge::TransferState st =
      test_support::resting_state({{0, 0}, {10, 0}, {10, 8}, {0, 8}}, {{0, 1, 2, 3}}, 1800, 50e6, 0.3);
  bridge::MpmMaterial& m = st.materials[0];
  m.type = bridge::MpmMaterial::Type::MohrCoulomb2D;
  m.friction = 30 * M_PI / 180;
  m.cohesion = 500;
  m.tension_cutoff = 300;
  return st;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

TEST(MpmDeck, GimpGridMatchesCbGeoReferenceDeck) {
  bridge::DeckOptions o;
  o.cell_size = 0.5;
  o.extent = std::array<double, 4>{0, 30, 0, 10};
  o.dt = 1e-4;
  o.nsteps = 5001;
  o.base_friction = 0.5;
  o.base = bridge::Base::Friction;  // CB-Geo's frictional base, as the reference deck
  const auto d = bridge::build_deck(column_state(), {}, o);
  EXPECT_EQ(d.grid.nx, 60);
  EXPECT_EQ(d.grid.ny, 20);
  std::ifstream ref_mesh(kDeck / "mesh.txt");
  std::string ref_text((std::istreambuf_iterator<char>(ref_mesh)), std::istreambuf_iterator<char>());
  const auto ours = lines_of(d.mesh_txt), ref = lines_of(ref_text);
  ASSERT_EQ(ours.size(), ref.size());
  EXPECT_EQ(ours[0], ref[0]);  // "1449\t1200"
  // Node coordinates equal as numbers; cells equal as text.
  for (std::size_t i = 1; i <= 1449; ++i) {
    double xa, ya, xb, yb;
    std::istringstream(ours[i]) >> xa >> ya;
    std::istringstream(ref[i]) >> xb >> yb;
    ASSERT_CLOSE(xa, xb, 1e-12, 0);
    ASSERT_CLOSE(ya, yb, 1e-12, 0);
  }
  for (std::size_t i = 1450; i < ref.size(); ++i) ASSERT_EQ(ours[i], ref[i]) << "mesh.txt line " << i + 1;
  // Node sets 0 (left, x <= 0), 1 (base, y <= 0), 2 (right, x >= 30): as the reference.
  const auto ours_sets = nlohmann::json::parse(d.entity_sets_json);
  std::ifstream ref_sets_in(kDeck / "entity_sets.json");
  const auto ref_sets = nlohmann::json::parse(ref_sets_in);
  EXPECT_EQ(ours_sets["node_sets"], ref_sets["node_sets"]);
  // mpm.json: the reference's boundary conditions and a resume block at step 0.
  const auto deck = nlohmann::json::parse(d.mpm_json);
  std::ifstream ref_json_in(kDeck / "mpm.json");
  const auto ref_json = nlohmann::json::parse(ref_json_in);
  EXPECT_EQ(deck["mesh"]["boundary_conditions"], ref_json["mesh"]["boundary_conditions"]);
  EXPECT_EQ(deck["mesh"]["cell_type"], "ED2Q16G");
  EXPECT_EQ(deck["analysis"]["resume"]["resume"], true);
  EXPECT_EQ(deck["analysis"]["resume"]["uuid"], "column");
  EXPECT_EQ(deck["analysis"]["resume"]["step"], 0);
  EXPECT_EQ(deck["analysis"]["nsteps"], 5001);
  EXPECT_EQ(d.particle_file, "results/column/particles0000.h5");  // 5001 steps -> 4 digits
  EXPECT_EQ(deck["materials"][0]["type"], "MohrCoulomb2D");
  EXPECT_CLOSE(deck["materials"][0]["friction"].get<double>(), 30.0, 1e-12, 0);
  // The velocity transfer: APIC by default (an extension key; CB-Geo reads velocity_update false = FLIP).
  EXPECT_EQ(deck["analysis"]["transfer"], "apic");
  EXPECT_EQ(deck["analysis"]["velocity_update"], false);
  // Every key of our deck exists in the CB-Geo reference deck (same schema), except analysis.transfer.
  for (const auto& [key, value] : deck.items()) EXPECT_TRUE(ref_json.contains(key)) << key;
  for (const auto& [key, value] : deck["analysis"].items())
    EXPECT_TRUE(ref_json["analysis"].contains(key) || key == "transfer") << key;
  for (const auto& [key, value] : deck["mesh"].items()) EXPECT_TRUE(ref_json["mesh"].contains(key)) << key;
}

// The default base, a one-sided frictional contact: the friction constraint on the base set without a
// normal velocity constraint (mpm reads that as a contact that stops the approach and never pulls).
TEST(MpmDeck, DefaultBaseIsAOneSidedFrictionalContact) {
  bridge::DeckOptions o;
  o.base_friction = 0.45;
  const auto deck = nlohmann::json::parse(bridge::build_deck(column_state(), {}, o).mpm_json);
  const auto& bc = deck["mesh"]["boundary_conditions"];
  for (const auto& v : bc["velocity_constraints"]) EXPECT_FALSE(v["nset_id"] == 1) << v;
  ASSERT_EQ(bc["friction_constraints"].size(), 1u);
  EXPECT_EQ(bc["friction_constraints"][0]["nset_id"], 1);
  EXPECT_EQ(bc["friction_constraints"][0]["dir"], 1);
  EXPECT_EQ(bc["friction_constraints"][0]["sign_n"], -1);
  EXPECT_EQ(bc["friction_constraints"][0]["friction"], 0.45);
}

// --base-lag L V*: the base friction's normal_lag (mpm/core/lagged_friction.hpp); none by default, an
// input error on a base without friction or with a slip distance <= 0.
TEST(MpmDeck, BaseLagWritesNormalLag) {
  bridge::DeckOptions o;
  EXPECT_FALSE(nlohmann::json::parse(bridge::build_deck(column_state(), {}, o).mpm_json)["mesh"]["boundary_conditions"]
                   ["friction_constraints"][0]
                       .contains("normal_lag"));
  o.base_lag = std::array<double, 2>{0.1, 1.0};
  const auto deck = nlohmann::json::parse(bridge::build_deck(column_state(), {}, o).mpm_json);
  const auto& lag = deck["mesh"]["boundary_conditions"]["friction_constraints"][0]["normal_lag"];
  EXPECT_EQ(lag["slip_distance"], 0.1);
  EXPECT_EQ(lag["reference_velocity"], 1.0);
  o.base_lag = std::array<double, 2>{0.0, 1.0};
  EXPECT_THROW(bridge::build_deck(column_state(), {}, o), common::InputError);
  o.base_lag = std::array<double, 2>{0.1, 1.0};
  o.base = bridge::Base::Roller;
  EXPECT_THROW(bridge::build_deck(column_state(), {}, o), common::InputError);
}

// --stress-smoothing: written as analysis.stress_smoothing (the checkerboard remedy of this project's mpm);
// the default "none" writes no key, so a default deck keeps CB-Geo's schema.
TEST(MpmDeck, StressSmoothingKey) {
  bridge::DeckOptions o;
  EXPECT_FALSE(nlohmann::json::parse(bridge::build_deck(column_state(), {}, o).mpm_json)["analysis"].contains(
      "stress_smoothing"));
  o.stress_smoothing = "cell_strain";
  const auto deck = nlohmann::json::parse(bridge::build_deck(column_state(), {}, o).mpm_json);
  EXPECT_EQ(deck["analysis"]["stress_smoothing"], "cell_strain");
}

// --base-y: the base node set is every node at or below the FEM base, so the grid may extend one cell
// row below it (a GIMP particle that dips a hair below the base then stays inside the grid).
TEST(MpmDeck, BaseBelowTheGridEdge) {
  bridge::DeckOptions o;
  o.cell_size = 1.0;
  o.extent = std::array<double, 4>{0, 40, -1, 10};
  o.base_y = 0.0;
  const auto d = bridge::build_deck(column_state(), {}, o);
  EXPECT_CLOSE(d.grid.y0, -1.0, 1e-12, 0);
  const auto sets = nlohmann::json::parse(d.entity_sets_json);
  const auto& base = sets["node_sets"][1]["set"];
  EXPECT_EQ(sets["node_sets"][1]["id"], 1);
  // lattice rows y = -2 (halo), -1, 0: 3 rows of 40 + 1 + 2 nodes
  ASSERT_EQ(base.size(), 3u * 43u);
  for (const auto& id : base) {
    const long k = id.get<long>();
    const int j = static_cast<int>(k / d.grid.nodes_x()) - d.grid.halo();
    EXPECT_LE(d.grid.y0 + j * d.grid.h, 1e-12) << "node " << k;
  }
  o.base_y = 20.0;  // above the grid
  EXPECT_THROW(bridge::build_deck(column_state(), {}, o), common::InputError);
}

TEST(MpmDeck, DefaultsAndErrors) {
  const auto st = column_state();
  bridge::DeckOptions o;
  const auto d = bridge::build_deck(st, {}, o);
  // Default extent: 10 m wide column + 3 widths, 8 m + 0.25 heights; cell = sqrt(area) = sqrt(80).
  EXPECT_CLOSE(d.grid.h, std::sqrt(80.0), 1e-12, 1e-12);
  EXPECT_GE(d.grid.x0 + d.grid.nx * d.grid.h, 40 - 1e-9);
  EXPECT_GE(d.grid.y0 + d.grid.ny * d.grid.h, 10 - 1e-9);
  // Default dt = 0.1 h / c_p.
  const double nu = 0.3, cp = std::sqrt(50e6 * (1 - nu) / ((1 + nu) * (1 - 2 * nu) * 1800));
  EXPECT_CLOSE(d.dt, 0.1 * d.grid.h / cp, 0, 1e-12);
  mpm::ParticleRecord outside{};
  outside.coord_x = 50;
  o.extent = std::array<double, 4>{0, 30, 0, 10};
  const std::vector<mpm::ParticleRecord> one{outside};
  EXPECT_THROW(bridge::build_deck(st, one, o), common::InputError);
  o = {};
  o.scheme = "leapfrog";
  EXPECT_THROW(bridge::build_deck(st, {}, o), common::InputError);
}

}  // namespace
