// mpm::io::read_deck on small decks written by the test (one per error case: the message must name
// the file / key and what was expected), and on the CB-Geo reference decks in
// tests/data/reference_runs/cbgeo (written by make_decks.py; see that folder's README.md).
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "common/input_error.hpp"
#include "mpm/io/deck_reader.hpp"
#include "mpm/io/particle_table.hpp"
#include "support/scratch.hpp"
#include "support/tolerance.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

/// A scratch deck: a 4 m x 3 m grid of 1 m ED2Q4 cells (5 x 4 nodes), 4 particles in cell (1, 1),
/// base nodes in node set 0, one LinearElastic2D material.
class SmallDeck {
 public:
  explicit SmallDeck(const std::string& name) {
    dir = test_support::fresh_scratch_folder("geoflow_deck_reader", name);
    std::ofstream mesh(dir / "mesh.txt");
    mesh << "# nodes and cells\n20 12\n";
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 5; ++i) mesh << i << " " << j << "\n";
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 4; ++i) {
        const int n = i + 5 * j;
        mesh << n << " " << n + 1 << " " << n + 6 << " " << n + 5 << "\n";
      }
    write("particles.txt", "4\n1.25 1.25\n1.75 1.25\n1.25 1.75\n1.75 1.75\n");
    write("entity_sets.json", R"({"node_sets": [{"id": 0, "set": [0, 1, 2, 3, 4]}]})");
    deck = json::parse(R"({
      "title": "small",
      "mesh": {"mesh": "mesh.txt", "entity_sets": "entity_sets.json", "cell_type": "ED2Q4", "io_type": "Ascii2D",
               "node_type": "N2D", "isoparametric": false, "check_duplicates": true,
               "boundary_conditions": {"velocity_constraints": [{"nset_id": 0, "dir": 1, "velocity": 0.0}],
                                       "friction_constraints": [{"nset_id": 0, "dir": 1, "sign_n": -1, "friction": 0.3}]}},
      "particles": [{"generator": {"type": "file", "location": "particles.txt", "io_type": "Ascii2D", "pset_id": 0,
                                   "particle_type": "P2D", "material_id": 0, "check_duplicates": false}}],
      "materials": [{"id": 0, "type": "LinearElastic2D", "density": 1500.0, "youngs_modulus": 1e6, "poisson_ratio": 0.25}],
      "external_loading_conditions": {"gravity": [0.0, -9.81]},
      "analysis": {"type": "MPMExplicit2D", "mpm_scheme": "usl", "dt": 1e-3, "nsteps": 100, "uuid": "small",
                   "velocity_update": false, "locate_particles": true,
                   "damping": {"type": "Cundall", "damping_factor": 0.05},
                   "resume": {"resume": false, "uuid": "small", "step": 0}},
      "post_processing": {"path": "results/", "output_steps": 10}
    })");
  }
  SmallDeck(const SmallDeck&) = delete;
  SmallDeck& operator=(const SmallDeck&) = delete;
  ~SmallDeck() {
    std::error_code ec;
    fs::remove_all(dir, ec);
    fs::remove(dir.parent_path(), ec);  // the per-process folder, once empty
  }
  void write(const std::string& file, const std::string& text) const { std::ofstream(dir / file) << text; }
  mpm::Deck read() const {
    write("mpm.json", deck.dump(2));
    return mpm::io::read_deck(dir, "mpm.json");
  }
  /// The InputError message of reading the deck ("" if it reads fine).
  std::string error() const {
    try {
      read();
    } catch (const common::InputError& e) {
      return e.what();
    }
    return "";
  }
  fs::path dir;
  json deck;
};

#define EXPECT_MESSAGE_HAS(message, text) EXPECT_NE((message).find(text), std::string::npos) << "message: " << (message)

const fs::path kCbgeo = fs::path(GEOFLOW_TEST_DATA_DIR) / "reference_runs/cbgeo";

}  // namespace

TEST(DeckReader, ReadsTheSmallDeck) {
  SmallDeck d("ok");
  const auto deck = d.read();
  EXPECT_EQ(deck.grid.dim, 2);
  EXPECT_EQ(deck.grid.nodes_per_axis[0], 5);
  EXPECT_EQ(deck.grid.nodes_per_axis[1], 4);
  EXPECT_CLOSE(deck.grid.spacing[0], 1.0, 1e-12, 0);
  EXPECT_CLOSE(deck.grid.region_max[0], 4.0, 1e-12, 0);
  EXPECT_CLOSE(deck.grid.region_max[1], 3.0, 1e-12, 0);
  ASSERT_EQ(deck.particles.size(), 4u);
  EXPECT_EQ(deck.particles[3].id, 3);
  EXPECT_EQ(deck.particles[3].coord_y, 1.75);
  EXPECT_EQ(deck.particles[0].volume, 0.0);  // the engine applies CB-Geo's defaults
  EXPECT_EQ(deck.analysis.scheme, mpm::Scheme::USL);
  EXPECT_EQ(deck.analysis.cundall_damping, 0.05);
  EXPECT_EQ(deck.analysis.gravity.y(), -9.81);
  ASSERT_EQ(deck.velocity_constraints.size(), 1u);
  EXPECT_EQ(deck.velocity_constraints[0].nodes, (std::vector<int>{0, 1, 2, 3, 4}));
  ASSERT_EQ(deck.friction_constraints.size(), 1u);
  EXPECT_EQ(deck.friction_constraints[0].sign_n, -1);
  EXPECT_EQ(deck.friction_constraints[0].friction, 0.3);
  EXPECT_EQ(deck.output.uuid, "small");
  EXPECT_EQ(deck.output.output_steps, 10);
  EXPECT_FALSE(deck.resumed);
  EXPECT_EQ(deck.first_step, 0);
}

// CB-Geo's pressure_smoothing smooths the pressure of its fluid materials only (particle.tcc
// map_pressure_to_nodes needs a "pressure" state variable): true is read, with a warning naming the key.
TEST(DeckReader, PressureSmoothingIsAcceptedWithAWarning) {
  SmallDeck d("pressure_smoothing");
  EXPECT_TRUE(d.read().warnings.empty());
  d.deck["analysis"]["pressure_smoothing"] = false;
  EXPECT_TRUE(d.read().warnings.empty());
  d.deck["analysis"]["pressure_smoothing"] = true;
  const auto warnings = d.read().warnings;
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_MESSAGE_HAS(warnings[0], "analysis.pressure_smoothing");
  EXPECT_MESSAGE_HAS(warnings[0], "stress_smoothing");
  d.deck["analysis"]["pressure_smoothing"] = "yes";
  EXPECT_MESSAGE_HAS(d.error(), "analysis.pressure_smoothing");
}

// normal_lag (this code's key, not CB-Geo's) on a friction constraint: the regularised friction of
// mpm/core/lagged_friction.hpp; both numbers required, the slip distance > 0, the speed >= 0.
TEST(DeckReader, FrictionConstraintNormalLag) {
  SmallDeck d("normal_lag");
  EXPECT_EQ(d.read().friction_constraints[0].lag_slip_distance, 0.0);  // absent: instantaneous Coulomb
  auto& fc = d.deck["mesh"]["boundary_conditions"]["friction_constraints"][0];
  fc["normal_lag"] = json::parse(R"({"slip_distance": 0.1, "reference_velocity": 1.0})");
  const auto deck = d.read();
  EXPECT_EQ(deck.friction_constraints[0].lag_slip_distance, 0.1);
  EXPECT_EQ(deck.friction_constraints[0].lag_reference_velocity, 1.0);
  fc["normal_lag"]["slip_distance"] = 0.0;
  EXPECT_MESSAGE_HAS(d.error(), "normal_lag.slip_distance");
  fc["normal_lag"] = json::parse(R"({"slip_distance": 0.1})");
  EXPECT_MESSAGE_HAS(d.error(), "reference_velocity");
  fc["normal_lag"] = json::parse(R"({"slip_distance": 0.1, "reference_velocity": -1})");
  EXPECT_MESSAGE_HAS(d.error(), "normal_lag.reference_velocity");
  fc["normal_lag"] = json::parse(R"({"slip_distance": 0.1, "reference_velocity": 1, "lag": 2})");
  EXPECT_MESSAGE_HAS(d.error(), "normal_lag.lag");
}

TEST(DeckReader, MapsFileNodeIdsToLatticeIndices) {
  // The same mesh with the nodes listed in reverse order: file node n is lattice node 19 - n.
  SmallDeck d("reversed");
  std::ofstream mesh(d.dir / "mesh.txt");
  mesh << "20 12\n";
  for (int k = 19; k >= 0; --k) mesh << k % 5 << " " << k / 5 << "\n";
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i) {
      const int n = i + 5 * j;
      mesh << 19 - n << " " << 19 - (n + 1) << " " << 19 - (n + 6) << " " << 19 - (n + 5) << "\n";
    }
  mesh.close();
  d.write("entity_sets.json", R"({"node_sets": [{"id": 0, "set": [19, 18]}]})");
  const auto deck = d.read();
  EXPECT_EQ(deck.velocity_constraints[0].nodes, (std::vector<int>{0, 1}));
}

TEST(DeckReader, GaussGeneratorPlacesGaussPointsInTheCellSet) {
  SmallDeck d("gauss");
  d.write("entity_sets.json", R"({"node_sets": [{"id": 0, "set": [0]}], "cell_sets": [{"id": 3, "set": [5]}]})");
  d.deck["particles"][0]["generator"] = json::parse(
      R"({"type": "gauss", "nparticles_per_dir": 2, "cset_id": 3, "material_id": 0, "pset_id": 1, "particle_type": "P2D"})");
  const auto deck = d.read();
  ASSERT_EQ(deck.particles.size(), 4u);  // cell 5 is lattice cell (1, 1): x, y in [1, 2]
  const double a = 0.5 / std::sqrt(3.0);
  EXPECT_CLOSE(deck.particles[0].coord_x, 1.5 - a, 1e-12, 0);
  EXPECT_CLOSE(deck.particles[0].coord_y, 1.5 - a, 1e-12, 0);
  EXPECT_CLOSE(deck.particles[3].coord_x, 1.5 + a, 1e-12, 0);
  EXPECT_CLOSE(deck.particles[3].coord_y, 1.5 + a, 1e-12, 0);
}

TEST(DeckReader, ParticleStressesVolumesAndMaterialSets) {
  SmallDeck d("stresses");
  d.write("stresses.txt", "4\n-1 -2 -3 4 0 0\n-1 -2 -3 4 0 0\n-1 -2 -3 4 0 0\n-10 -20 -30 40 0 0\n");
  d.write("volumes.txt", "3 0.5\n");
  d.write("entity_sets.json", R"({"node_sets": [{"id": 0, "set": [0]}], "particle_sets": [{"id": 7, "set": [3]}]})");
  d.deck["mesh"]["particles_stresses"] = "stresses.txt";
  d.deck["mesh"]["particles_volumes"] = "volumes.txt";
  d.deck["mesh"]["update_materials"] = true;
  d.deck["materials"].push_back(json::parse(
      R"({"id": 2, "type": "MohrCoulomb2D", "density": 2000, "youngs_modulus": 1e7, "poisson_ratio": 0.3, "friction": 30,
          "dilation": 0, "cohesion": 10, "residual_friction": 30, "residual_dilation": 0, "residual_cohesion": 10,
          "peak_pdstrain": 0, "residual_pdstrain": 0, "tension_cutoff": 5, "softening": false})"));
  d.deck["material_sets"] = json::parse(R"([{"material_id": 2, "pset_id": 7}])");
  const auto deck = d.read();
  EXPECT_EQ(deck.particles[3].stress_xx, -10);
  EXPECT_EQ(deck.particles[3].stress_zz, -30);
  EXPECT_EQ(deck.particles[3].tau_xy, 40);
  EXPECT_EQ(deck.particles[3].volume, 0.5);
  EXPECT_EQ(deck.particles[3].material_id, 2u);
  EXPECT_EQ(deck.particles[3].mass, 2000 * 0.5);  // density of the material the set assigns
  EXPECT_CLOSE(deck.particles[3].nsize_x, 1.0, 1e-15, 0);  // 2 / sqrt(4 particles in the cell)
  EXPECT_EQ(deck.particles[0].material_id, 0u);
  ASSERT_EQ(deck.materials.size(), 2u);
  EXPECT_CLOSE(deck.materials[1].friction, M_PI / 6, 1e-15, 0);  // degrees -> radians
  EXPECT_EQ(deck.materials[1].separation_volume_ratio, mpm::kDefaultSeparationVolumeRatio);  // absent
}

TEST(DeckReader, ReadsTheCbGeoGimpColumnDeck) {
  const auto deck = mpm::io::read_deck(kCbgeo / "mc_column_gimp_short", "mpm.json");
  EXPECT_EQ(deck.grid.cell_type, mpm::CellType::Gimp16);
  EXPECT_EQ(deck.grid.nodes_per_axis[0], 63);  // 60 cells + the halo ring
  EXPECT_EQ(deck.grid.nodes_per_axis[1], 23);
  EXPECT_CLOSE(deck.grid.origin[0], -0.5, 1e-12, 0);
  EXPECT_CLOSE(deck.grid.region_min[0], 0.0, 1e-12, 0);
  EXPECT_CLOSE(deck.grid.region_max[0], 30.0, 1e-12, 0);
  EXPECT_CLOSE(deck.grid.region_max[1], 10.0, 1e-12, 0);
  EXPECT_EQ(deck.particles.size(), 1280u);
  EXPECT_CLOSE(deck.particles[0].stress_yy, -139056.75, 1e-9, 0);
  ASSERT_EQ(deck.materials.size(), 1u);
  EXPECT_EQ(deck.materials[0].type, mpm::MaterialType::MohrCoulomb2D);
  EXPECT_CLOSE(deck.materials[0].friction, M_PI / 6, 1e-15, 0);
  EXPECT_EQ(deck.materials[0].tension_cutoff, 300.0);
  EXPECT_EQ(deck.velocity_constraints.size(), 3u);
  ASSERT_EQ(deck.friction_constraints.size(), 1u);
  EXPECT_EQ(deck.friction_constraints[0].friction, 0.5);
  EXPECT_EQ(deck.output.uuid, "mc_column");
  EXPECT_EQ(deck.analysis.nsteps, 5001);
}

TEST(DeckReader, ResumeReadsTheHdf5StateAndStartsAfterItsStep) {
  const auto deck = mpm::io::read_deck(kCbgeo / "resume_from_h5", "mpm.json");
  EXPECT_TRUE(deck.resumed);
  EXPECT_EQ(deck.first_step, 1);
  EXPECT_EQ(deck.particles.size(), 288u);
  EXPECT_GT(deck.particles[0].volume, 0.0);
  EXPECT_EQ(deck.output.uuid, "bar_resume");
}

// A resumed deck whose friction has a normal_lag takes the lagged strengths from the particle file's
// /friction_memory; a file without it (CB-Geo's, fem2mpm's, a run without the lag) restarts them from the
// instantaneous normal forces, and the reader says so; a row for a node without the lag is an error.
TEST(DeckReader, ResumeWithALaggedFrictionReadsItsMemoryOrWarnsThatItRestarts) {
  const auto dir = test_support::fresh_scratch_folder("geoflow_deck_reader", "resume_lag");
  std::filesystem::copy(kCbgeo / "resume_from_h5", dir, std::filesystem::copy_options::recursive);
  auto deck_json = json::parse(std::ifstream(dir / "mpm.json"));
  EXPECT_TRUE(mpm::io::read_deck(dir, "mpm.json").warnings.empty());
  deck_json["mesh"]["boundary_conditions"]["friction_constraints"] = json::parse(
      R"([{"nset_id": -1, "dir": 1, "sign_n": -1, "friction": 0.3,
           "normal_lag": {"slip_distance": 0.1, "reference_velocity": 1.0}}])");
  std::ofstream(dir / "mpm.json") << deck_json.dump(1);
  const auto deck = mpm::io::read_deck(dir, "mpm.json");
  ASSERT_EQ(deck.warnings.size(), 1u);
  EXPECT_MESSAGE_HAS(deck.warnings[0], "normal_lag");
  EXPECT_MESSAGE_HAS(deck.warnings[0], "has no /friction_memory dataset");
  EXPECT_MESSAGE_HAS(deck.warnings[0], "restart from the instantaneous normal forces");
  EXPECT_TRUE(deck.friction_memory.empty());

  // The same file with the dataset: read, no warning.
  const auto file = dir / "results/bar_resume/particles000.h5";
  const auto table = mpm::io::read_particle_table(file);
  const auto rewrite = [&](const std::vector<mpm::FrictionMemoryRecord>& memory) {
    std::filesystem::remove(file);
    mpm::io::write_particle_table(file, table,
                                  [&](std::int64_t h5) { mpm::io::write_friction_memory_dataset(h5, memory, "test"); });
  };
  ASSERT_FALSE(deck.friction_constraints.empty());
  ASSERT_FALSE(deck.friction_constraints[0].nodes.empty());
  const std::vector<mpm::FrictionMemoryRecord> memory = {{deck.friction_constraints[0].nodes[0], 12.5, 0.75}};
  rewrite(memory);
  const auto with = mpm::io::read_deck(dir, "mpm.json");
  EXPECT_TRUE(with.warnings.empty());
  EXPECT_TRUE(with.friction_memory == memory);

  // A node the lag does not cover.
  deck_json["mesh"]["boundary_conditions"]["friction_constraints"][0]["nset_id"] = 0;
  std::ofstream(dir / "mpm.json") << deck_json.dump(1);
  const auto covered = mpm::io::read_deck(dir, "mpm.json").friction_constraints[0].nodes;
  int outside = 0;
  while (std::find(covered.begin(), covered.end(), outside) != covered.end()) ++outside;
  rewrite({{outside, 1.0, 1.0}});
  try {
    mpm::io::read_deck(dir, "mpm.json");
    ADD_FAILURE() << "node " << outside << " has no lagged friction";
  } catch (const common::InputError& e) {
    EXPECT_MESSAGE_HAS(std::string(e.what()), "particles000.h5");
    EXPECT_MESSAGE_HAS(std::string(e.what()), "row 0: node " + std::to_string(outside) + " has no friction constraint with a normal_lag");
  }
  std::filesystem::remove_all(dir);
}

// ---- every malformed input: one InputError naming the file / key -------------------------------

TEST(DeckReaderErrors, MissingInputFile) {
  SmallDeck d("missing");
  try {
    mpm::io::read_deck(d.dir, "nope.json");
    FAIL();
  } catch (const common::InputError& e) {
    EXPECT_MESSAGE_HAS(std::string(e.what()), "nope.json");
  }
}

TEST(DeckReaderErrors, TruncatedJson) {
  SmallDeck d("truncated");
  d.write("mpm.json", d.deck.dump(2).substr(0, 200));
  try {
    mpm::io::read_deck(d.dir, "mpm.json");
    FAIL();
  } catch (const common::InputError& e) {
    EXPECT_MESSAGE_HAS(std::string(e.what()), "mpm.json: invalid JSON");
  }
}

TEST(DeckReaderErrors, UnknownKeysAreNamedWithTheirPath) {
  SmallDeck d("unknown");
  d.deck["analysis"]["newmark"] = true;
  EXPECT_MESSAGE_HAS(d.error(), "mpm.json: analysis.newmark: unsupported key");
  SmallDeck t("unknown_top");
  t.deck["materiels"] = json::array();
  EXPECT_MESSAGE_HAS(t.error(), "mpm.json: materiels: unsupported key");
  SmallDeck m("unknown_material_key");
  m.deck["materials"][0]["porosity"] = 0.3;
  EXPECT_MESSAGE_HAS(m.error(), "materials[0].porosity: unsupported key");
}

TEST(DeckReaderErrors, DuplicateKey) {
  SmallDeck d("duplicate");
  std::string text = d.deck.dump(2);
  text.replace(text.find("\"dt\""), 0, "\"dt\": 0.5, ");
  d.write("mpm.json", text);
  try {
    mpm::io::read_deck(d.dir, "mpm.json");
    FAIL();
  } catch (const common::InputError& e) {
    EXPECT_MESSAGE_HAS(std::string(e.what()), "mpm.json: key \"dt\" appears twice");
  }
}

TEST(DeckReaderErrors, UnknownSchemeIsNotSilentlyUsf) {
  SmallDeck d("scheme");
  d.deck["analysis"]["mpm_scheme"] = "usx";
  EXPECT_MESSAGE_HAS(d.error(), "analysis.mpm_scheme: unknown scheme \"usx\"");
}

// Issue 37's bad input: a 2D deck's keys in a 3D analysis and 3D cells or particle tables in a 2D one are one
// line naming the key or the file, never read in the other dimension (deck_reader_3d_test.cpp: the 3D decks).
TEST(DeckReaderErrors, ThreeDimensionalDecksAndCellsAreNamed) {
  SmallDeck analysis("mpm3d");
  analysis.deck["analysis"]["type"] = "MPMExplicit3D";
  EXPECT_MESSAGE_HAS(analysis.error(), "materials[0].type: a 2D material (\"LinearElastic2D\") in a 3D analysis");
  for (const char* cell : {"ED3H8", "ED3H64G"}) {
    SmallDeck d(std::string("cell_") + cell);
    d.deck["mesh"]["cell_type"] = cell;
    EXPECT_MESSAGE_HAS(d.error(), std::string("mesh.cell_type: a 3D cell type (\"") + cell + "\") in a 2D analysis");
  }
}

TEST(DeckReaderErrors, AThreeDimensionalParticleTableOnATwoDimensionalDeck) {
  const auto dir = test_support::fresh_scratch_folder("geoflow_deck_reader", "resume_3d_table");
  std::filesystem::copy(kCbgeo / "resume_from_h5", dir, std::filesystem::copy_options::recursive);
  const auto file = dir / "results/bar_resume/particles000.h5";
  auto table = mpm::io::read_particle_table(file);
  ASSERT_NO_THROW(mpm::io::read_deck(dir, "mpm.json"));  // CB-Geo's 2D table: z = 0 throughout
  ASSERT_GE(table.size(), 2u);
  table[1].coord_z = 0.25;  // as CB-Geo's 3D tables hold them
  table[1].nsize_z = 0.5;
  std::filesystem::remove(file);
  mpm::io::write_particle_table(file, table);
  try {
    mpm::io::read_deck(dir, "mpm.json");
    ADD_FAILURE() << "a 3D table was read as 2D";
  } catch (const common::InputError& e) {
    EXPECT_MESSAGE_HAS(std::string(e.what()), "particles000.h5");
    EXPECT_MESSAGE_HAS(std::string(e.what()), "particle " + std::to_string(table[1].id) + " has a z coordinate");
    EXPECT_MESSAGE_HAS(std::string(e.what()), "a 3D particle table on a 2D deck");
  }
  std::filesystem::remove_all(dir);
}

TEST(DeckReaderErrors, UndefinedMaterialId) {
  SmallDeck d("material_id");
  d.deck["particles"][0]["generator"]["material_id"] = 3;
  EXPECT_MESSAGE_HAS(d.error(), "particles[0].generator.material_id: material 3 is not defined");
}

TEST(DeckReaderErrors, NegativeDensity) {
  SmallDeck d("density");
  d.deck["materials"][0]["density"] = -1500;
  EXPECT_MESSAGE_HAS(d.error(), "materials[0].density: expected a number > 0");
}

TEST(DeckReaderErrors, MissingMohrCoulombParameter) {
  SmallDeck d("mc_missing");
  d.deck["materials"][0] = json::parse(
      R"({"id": 0, "type": "MohrCoulomb2D", "density": 2000, "youngs_modulus": 1e7, "poisson_ratio": 0.3, "friction": 30,
          "dilation": 0, "cohesion": 10, "residual_friction": 30, "residual_dilation": 0, "residual_cohesion": 10,
          "peak_pdstrain": 0, "residual_pdstrain": 0, "softening": false})");
  EXPECT_MESSAGE_HAS(d.error(), "materials[0].tension_cutoff: missing");
}

TEST(DeckReaderErrors, SeparationVolumeRatio) {
  const json mc = json::parse(
      R"({"id": 0, "type": "MohrCoulomb2D", "density": 2000, "youngs_modulus": 1e7, "poisson_ratio": 0.3, "friction": 30,
          "dilation": 0, "cohesion": 10, "residual_friction": 30, "residual_dilation": 0, "residual_cohesion": 10,
          "peak_pdstrain": 0, "residual_pdstrain": 0, "tension_cutoff": 5, "softening": false})");
  for (const double ok : {0.0, 1.5, 10.0}) {
    SmallDeck d("separation_ok");
    d.deck["materials"][0] = mc;
    d.deck["materials"][0]["separation_volume_ratio"] = ok;
    EXPECT_EQ(d.read().materials[0].separation_volume_ratio, ok);
  }
  SmallDeck d("separation");
  d.deck["materials"][0] = mc;
  d.deck["materials"][0]["separation_volume_ratio"] = 0.9;
  EXPECT_MESSAGE_HAS(d.error(), "materials[0].separation_volume_ratio: expected 0 (never separate) or a volume ratio > 1, got 0.9");
  SmallDeck e("separation_elastic");
  e.deck["materials"][0]["separation_volume_ratio"] = 3;  // a LinearElastic2D material never separates
  EXPECT_MESSAGE_HAS(e.error(), "materials[0].separation_volume_ratio: unsupported key");
}

TEST(DeckReaderErrors, NonPositiveDtAndNsteps) {
  SmallDeck d("dt");
  d.deck["analysis"]["dt"] = 0.0;
  EXPECT_MESSAGE_HAS(d.error(), "analysis.dt: expected a number > 0");
  SmallDeck n("nsteps");
  n.deck["analysis"]["nsteps"] = -5;
  EXPECT_MESSAGE_HAS(n.error(), "analysis.nsteps: expected an integer > 0");
}

TEST(DeckReaderErrors, ParticleOutsideTheGrid) {
  SmallDeck d("outside");
  d.write("particles.txt", "2\n1.5 1.5\n4.5 1.0\n");
  EXPECT_MESSAGE_HAS(d.error(), "particles.txt: particle 1 at (4.5, 1) is outside the grid");
}

TEST(DeckReaderErrors, TruncatedParticleFile) {
  SmallDeck d("particles_truncated");
  d.write("particles.txt", "4\n1.5 1.5\n1.6 1.5\n");
  EXPECT_MESSAGE_HAS(d.error(), "particles.txt: header says 4 particles, found 2");
  SmallDeck w("particles_word");
  w.write("particles.txt", "2\n1.5 1.5\n1.6 abc\n");
  EXPECT_MESSAGE_HAS(w.error(), "particles.txt:3: \"abc\" is not a finite number");
}

TEST(DeckReaderErrors, MissingResumeFileIsNotZeroParticles) {
  SmallDeck d("resume");
  d.deck["analysis"]["resume"] = json::parse(R"({"resume": true, "uuid": "small", "step": 20})");
  EXPECT_MESSAGE_HAS(d.error(), "resume file results/small/particles020.h5 not found");
}

TEST(DeckReaderErrors, MissingMeshFile) {
  SmallDeck d("mesh_missing");
  d.deck["mesh"]["mesh"] = "other.txt";
  EXPECT_MESSAGE_HAS(d.error(), "other.txt: file not found");
}

TEST(DeckReaderErrors, NodesOffALatticeAndCellsNotARectangle) {
  SmallDeck d("lattice");
  {
    std::ofstream mesh(d.dir / "mesh.txt");
    mesh << "4 1\n0 0\n1 0\n1.3 1\n0 1\n0 1 2 3\n";
  }
  d.write("entity_sets.json", R"({"node_sets": [{"id": 0, "set": [0]}]})");
  d.write("particles.txt", "1\n0.5 0.5\n");
  EXPECT_MESSAGE_HAS(d.error(), "mesh.txt: nodes do not form a uniform rectangular lattice");
  SmallDeck r("rectangle");
  {
    std::ofstream mesh(r.dir / "mesh.txt");  // an L of 3 cells on a 3 x 3 lattice
    mesh << "9 3\n";
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) mesh << i << " " << j << "\n";
    mesh << "0 1 4 3\n1 2 5 4\n3 4 7 6\n";
  }
  r.write("entity_sets.json", R"({"node_sets": [{"id": 0, "set": [0]}]})");
  r.write("particles.txt", "1\n0.5 0.5\n");
  EXPECT_MESSAGE_HAS(r.error(), "mesh.txt: cells do not form a rectangle");
  SmallDeck c("clockwise");
  {
    std::ofstream mesh(c.dir / "mesh.txt");
    mesh << "4 1\n0 0\n1 0\n1 1\n0 1\n0 3 2 1\n";
  }
  c.write("entity_sets.json", R"({"node_sets": [{"id": 0, "set": [0]}]})");
  c.write("particles.txt", "1\n0.5 0.5\n");
  EXPECT_MESSAGE_HAS(c.error(), "mesh.txt: cell 0: node 1 (id 3) is not where");
  SmallDeck rot("rotated");  // counter-clockwise from the upper right: a valid ED2Q4 cell
  {
    std::ofstream mesh(rot.dir / "mesh.txt");
    mesh << "4 1\n0 0\n1 0\n1 1\n0 1\n2 3 0 1\n";
  }
  rot.write("entity_sets.json", R"({"node_sets": [{"id": 0, "set": [0]}]})");
  rot.write("particles.txt", "1\n0.5 0.5\n");
  EXPECT_EQ(rot.error(), "");
}

TEST(DeckReaderErrors, UndefinedNodeSetAndMathFunctionsAndVtk) {
  SmallDeck d("nset");
  d.deck["mesh"]["boundary_conditions"]["velocity_constraints"][0]["nset_id"] = 9;
  EXPECT_MESSAGE_HAS(d.error(), "velocity_constraints[0].nset_id: node set 9 is not defined");
  SmallDeck m("math");
  m.deck["math_functions"] = json::parse(R"([{"id": 0, "type": "Cosine", "xvalues": [0, 1], "fxvalues": [0, 1]}])");
  EXPECT_MESSAGE_HAS(m.error(), "mpm.json: math_functions[0].type: unsupported math function \"Cosine\" (expected Linear or Sin)");
  SmallDeck v("vtk");
  v.deck["post_processing"]["vtk"] = json::parse(R"(["stresses", "pressure"])");
  EXPECT_MESSAGE_HAS(v.error(), "post_processing.vtk: unknown attribute pressure (expected displacements, velocities");
  SmallDeck sv("vtk_statevars");
  sv.deck["post_processing"]["vtk_statevars"] = json::parse(R"([{"phase_id": 0, "statevars": ["pdstrain", "kappa"]}])");
  EXPECT_MESSAGE_HAS(sv.error(), "post_processing.vtk_statevars: expected state variable names among phi, psi");
  SmallDeck ph("vtk_phase");
  ph.deck["post_processing"]["vtk_statevars"] = json::parse(R"([{"phase_id": 1, "statevars": ["pdstrain"]}])");
  EXPECT_MESSAGE_HAS(ph.error(), "phase_id: expected 0 (single-phase MPM)");
  SmallDeck e("vtk_empty");
  e.deck["post_processing"]["vtk"] = json::array();
  EXPECT_EQ(e.error(), "");
}

TEST(DeckReader, VtkKeysTakeCbGeoNamesAndBothStateVariableForms) {
  SmallDeck d("vtk_ok");
  d.deck["post_processing"]["vtk"] = json::parse(R"(["stresses", "velocities", "pdstrain", "stresses"])");
  d.deck["post_processing"]["vtk_statevars"] = json::parse(R"(["pdstrain", {"phase_id": 0, "statevars": ["phi"]}])");
  const mpm::Deck deck = d.read();
  EXPECT_EQ(deck.output.vtk_fields, (std::vector<std::string>{"stress", "velocity", "pdstrain"}));
  EXPECT_EQ(deck.output.vtk_statevars, (std::vector<std::string>{"pdstrain", "phi"}));
}

// Extension: the output steps that write particle files (output_steps = 10, nsteps = 100 in SmallDeck).
TEST(DeckReader, ParticleOutputStepsAreOutputStepsBelowNsteps) {
  SmallDeck d("pos_ok");
  d.deck["post_processing"]["particle_output_steps"] = json::parse("[90, 0, 30]");
  const mpm::Deck deck = d.read();
  EXPECT_EQ(deck.output.particle_output_steps, (std::vector<long long>{0, 30, 90}));
  EXPECT_TRUE(deck.output.writes_particles(30));
  EXPECT_FALSE(deck.output.writes_particles(40));
  EXPECT_TRUE(SmallDeck("pos_absent").read().output.writes_particles(40));  // absent: every output step
  int case_number = 0;
  for (const char* bad : {"[15]", "[100]", "[-10]", "[10, 10]", "[]", "10", "[\"20\"]", "[2.5]"}) {
    SmallDeck e("pos_bad" + std::to_string(case_number++));
    e.deck["post_processing"]["particle_output_steps"] = json::parse(bad);
    EXPECT_MESSAGE_HAS(e.error(), "post_processing.particle_output_steps: expected an array of output steps "
                                  "(multiples of output_steps = 10 below nsteps = 100)") << bad;
  }
}

TEST(DeckReaderErrors, WrongTypesAreNamed) {
  SmallDeck d("types");
  d.deck["analysis"]["dt"] = "0.001";
  EXPECT_MESSAGE_HAS(d.error(), "analysis.dt: expected a number, got the string \"0.001\"");
  SmallDeck s("sets");
  s.deck["material_sets"] = json::parse(R"([{"material_id": 0, "pset_id": 0}])");
  EXPECT_MESSAGE_HAS(s.error(), "material_sets: given but mesh.update_materials is not true");
}

TEST(DeckReader, Extensions) {
  SmallDeck d("extensions");
  d.deck["analysis"].erase("dt");
  d.deck["analysis"]["cfl"] = 0.5;
  d.deck["analysis"]["pic_blend"] = 0.25;
  d.deck["analysis"]["stress_smoothing"] = "cell_volumetric";
  const auto deck = d.read();
  EXPECT_EQ(deck.analysis.cfl, 0.5);
  EXPECT_EQ(deck.analysis.dt, 0.0);  // no upper bound: the engine picks cfl h / c_p
  EXPECT_EQ(deck.analysis.pic_blend, 0.25);
  EXPECT_EQ(deck.analysis.stress_smoothing, "cell_volumetric");
  SmallDeck u("smoothing");
  u.deck["analysis"]["stress_smoothing"] = "magic";
  EXPECT_MESSAGE_HAS(u.error(), "analysis.stress_smoothing: unknown method \"magic\"");
  SmallDeck p("pic");
  p.deck["analysis"]["velocity_update"] = true;
  p.deck["analysis"]["pic_blend"] = 0.5;
  EXPECT_MESSAGE_HAS(p.error(), "analysis.pic_blend");
  SmallDeck n("nodt");
  n.deck["analysis"].erase("dt");
  EXPECT_MESSAGE_HAS(n.error(), "analysis.dt: missing");
}

TEST(DeckReader, VelocityTransferKeys) {
  // analysis.transfer ("flip", "pic", "apic") and CB-Geo's velocity_update (true = PIC) decide together.
  const std::vector<std::pair<json, mpm::Transfer>> accepted = {
      {json::object(), mpm::Transfer::FLIP},
      {{{"velocity_update", true}}, mpm::Transfer::PIC},
      {{{"transfer", "apic"}}, mpm::Transfer::APIC},
      {{{"transfer", "apic"}, {"velocity_update", false}}, mpm::Transfer::APIC},
      {{{"transfer", "pic"}, {"velocity_update", true}}, mpm::Transfer::PIC},
      {{{"transfer", "pic"}}, mpm::Transfer::PIC},
      {{{"transfer", "flip"}, {"pic_blend", 0.02}}, mpm::Transfer::FLIP},
  };
  for (const auto& [keys, transfer] : accepted) {
    SCOPED_TRACE(keys.dump());
    SmallDeck d("transfer");
    d.deck["analysis"].erase("velocity_update");
    for (const auto& [k, v] : keys.items()) d.deck["analysis"][k] = v;
    const auto deck = d.read();
    EXPECT_EQ(deck.analysis.transfer, transfer);
    EXPECT_EQ(deck.analysis.velocity_update, transfer == mpm::Transfer::PIC);
    EXPECT_EQ(deck.analysis.pic_blend, transfer == mpm::Transfer::PIC ? 1.0 : keys.value("pic_blend", 0.0));
  }
  const std::vector<std::pair<json, std::string>> refused = {
      {{{"transfer", "apic"}, {"velocity_update", true}}, "analysis.transfer: \"apic\" contradicts velocity_update true"},
      {{{"transfer", "pic"}, {"velocity_update", false}}, "analysis.transfer: \"pic\" contradicts velocity_update false"},
      {{{"transfer", "APIC"}}, "analysis.transfer: unknown transfer \"APIC\" (expected flip, pic or apic)"},
      {{{"transfer", "apic"}, {"pic_blend", 0.02}}, "analysis.pic_blend: blends FLIP with PIC and applies to the flip transfer only"},
      {{{"transfer", "pic"}, {"pic_blend", 1.0}}, "analysis.pic_blend: blends FLIP with PIC"},
      {{{"pic_blend", 1.5}}, "analysis.pic_blend: expected a number in [0, 1], got 1.5"},
  };
  for (const auto& [keys, message] : refused) {
    SmallDeck d("transfer_error");
    d.deck["analysis"].erase("velocity_update");
    for (const auto& [k, v] : keys.items()) d.deck["analysis"][k] = v;
    EXPECT_MESSAGE_HAS(d.error(), message);
  }
}

TEST(DeckReader, GeneratedGimpGridWithNamedBoundarySets) {
  SmallDeck d("generated");
  d.deck["mesh"] = json::parse(R"({
    "generator": {"origin": [0, 0], "cell_size": [0.5, 0.5], "cells": [8, 6]}, "cell_type": "ED2Q16G",
    "boundary_conditions": {"velocity_constraints": [{"nset_id": "left", "dir": 0, "velocity": 0}],
                            "friction_constraints": [{"nset_id": "bottom", "dir": 1, "sign_n": -1, "friction": 0.5}]}})");
  const auto deck = d.read();
  EXPECT_EQ(deck.grid.cell_type, mpm::CellType::Gimp16);
  EXPECT_EQ(deck.grid.nodes_per_axis[0], 8 + 3);  // 9 node columns + the GIMP halo on both sides
  EXPECT_EQ(deck.grid.nodes_per_axis[1], 6 + 3);
  EXPECT_EQ(deck.grid.origin[0], -0.5);
  EXPECT_EQ(deck.grid.region_min[0], 0.0);
  EXPECT_EQ(deck.grid.region_max[0], 4.0);
  EXPECT_EQ(deck.grid.region_max[1], 3.0);
  // "left": the node columns at x = -0.5 and x = 0 (halo included), 2 x 9 nodes.
  ASSERT_EQ(deck.velocity_constraints[0].nodes.size(), 18u);
  EXPECT_EQ(deck.velocity_constraints[0].nodes[0], 0);
  EXPECT_EQ(deck.velocity_constraints[0].nodes[1], 1);
  EXPECT_EQ(deck.friction_constraints[0].nodes.size(), 22u);  // "bottom": rows y = -0.5 and 0
  SmallDeck bad("generated_bad");
  bad.deck["mesh"] = json::parse(R"({"generator": {"origin": [0, 0], "cell_size": [0.5, 0.5], "cells": [8, 6]},
    "cell_type": "ED2Q4", "boundary_conditions": {"velocity_constraints": [{"nset_id": "floor", "dir": 1, "velocity": 0}]}})");
  EXPECT_MESSAGE_HAS(bad.error(), "velocity_constraints[0].nset_id: no node set named \"floor\"");
  SmallDeck named("named_on_file_mesh");
  named.deck["mesh"]["boundary_conditions"]["velocity_constraints"][0]["nset_id"] = "left";
  EXPECT_MESSAGE_HAS(named.error(), "named sets exist only on a generated grid");
}

TEST(DeckReader, ConstraintFilesAndParticleCells) {
  SmallDeck d("constraint_files");
  d.write("vc.txt", "# node dir velocity\n0 1 0.0\n4 0 -0.5\n");
  d.write("fc.txt", "1 1 -1 0.25\n");
  d.write("cells.txt", "0 5\n3 5\n");
  d.deck["mesh"]["boundary_conditions"] = json::parse(
      R"({"velocity_constraints": [{"file": "vc.txt"}], "friction_constraints": [{"file": "fc.txt"}]})");
  d.deck["mesh"]["particle_cells"] = "cells.txt";
  const auto deck = d.read();
  ASSERT_EQ(deck.velocity_constraints.size(), 2u);
  EXPECT_EQ(deck.velocity_constraints[1].nodes, (std::vector<int>{4}));
  EXPECT_EQ(deck.velocity_constraints[1].dir, 0);
  EXPECT_EQ(deck.velocity_constraints[1].velocity, -0.5);
  ASSERT_EQ(deck.friction_constraints.size(), 1u);
  EXPECT_EQ(deck.friction_constraints[0].friction, 0.25);
  SmallDeck bad("particle_cells_wrong");
  bad.write("cells.txt", "0 0\n");  // particle 0 is in cell 5, not 0
  bad.deck["mesh"]["particle_cells"] = "cells.txt";
  EXPECT_MESSAGE_HAS(bad.error(), "cells.txt: particle 0 at (1.25, 1.25) is not inside cell 0");
  SmallDeck node("constraint_file_node");
  node.write("vc.txt", "20 1 0.0\n");
  node.deck["mesh"]["boundary_conditions"] = json::parse(R"({"velocity_constraints": [{"file": "vc.txt"}]})");
  EXPECT_MESSAGE_HAS(node.error(), "vc.txt: entry 0: node id 20 is not a node of the mesh");
}

TEST(DeckReader, MathFunctionsAndBaseAcceleration) {
  SmallDeck d("base_acceleration");
  d.deck["math_functions"] = json::parse(
      R"([{"id": 3, "type": "Linear", "xvalues": [0, 1, 2], "fxvalues": [0, 2, -1]},
          {"id": 4, "type": "Linear", "xvalues": [0], "fxvalues": [7]}])");
  d.deck["external_loading_conditions"]["base_acceleration"] =
      json::parse(R"({"dir": 0, "acceleration": 9.81, "math_function_id": 3})");
  const auto deck = d.read();
  ASSERT_TRUE(deck.base_acceleration.has_value());
  const auto& b = *deck.base_acceleration;
  EXPECT_EQ(b.dir, 0);
  // CB-Geo's Linear function: linear between the points, held at the end values outside them.
  EXPECT_EQ(b.history.value(-1.0), 0.0);
  EXPECT_EQ(b.history.value(0.5), 1.0);
  EXPECT_EQ(b.history.value(1.0), 2.0);
  EXPECT_EQ(b.history.value(1.5), 0.5);
  EXPECT_EQ(b.history.value(5.0), -1.0);
  EXPECT_CLOSE(b.at(0.25), 9.81 * 0.5, 1e-15, 0);
}

TEST(DeckReaderErrors, MathFunctionsAndBaseAcceleration) {
  const auto with = [](const std::string& name, const char* functions, const char* base) {
    SmallDeck d(name);
    d.deck["math_functions"] = json::parse(functions);
    if (base != nullptr) d.deck["external_loading_conditions"]["base_acceleration"] = json::parse(base);
    return d.error();
  };
  const char* ok = R"([{"id": 0, "type": "Linear", "xvalues": [0, 1], "fxvalues": [0, 1]}])";
  EXPECT_MESSAGE_HAS(with("mf_sizes", R"([{"id": 0, "type": "Linear", "xvalues": [0, 1], "fxvalues": [0]}])", nullptr),
                     "math_functions[0].fxvalues: expected as many values as xvalues (2), got 1");
  EXPECT_MESSAGE_HAS(with("mf_order", R"([{"id": 0, "type": "Linear", "xvalues": [0, 1, 1], "fxvalues": [0, 1, 2]}])", nullptr),
                     "math_functions[0].xvalues: expected strictly increasing values, got 1 then 1 (entries 1 and 2)");
  EXPECT_MESSAGE_HAS(with("mf_text", R"([{"id": 0, "type": "Linear", "xvalues": [0, "a"], "fxvalues": [0, 1]}])", nullptr),
                     "math_functions[0].xvalues: entry 1: expected a finite number, got the string \"a\"");
  EXPECT_MESSAGE_HAS(with("mf_dup", R"([{"id": 0, "type": "Linear", "xvalues": [0], "fxvalues": [0]},
                                        {"id": 0, "type": "Linear", "xvalues": [0], "fxvalues": [1]}])", nullptr),
                     "math_functions[1].id: duplicate math function id 0");
  EXPECT_MESSAGE_HAS(with("mf_key", R"([{"id": 0, "type": "Linear", "xvalues": [0], "fxvalues": [0], "yvalues": [0]}])", nullptr),
                     "math_functions[0].yvalues: unsupported key");
  EXPECT_MESSAGE_HAS(with("ba_id", ok, R"({"dir": 0, "acceleration": 1, "math_function_id": 5})"),
                     "external_loading_conditions.base_acceleration.math_function_id: no math function with id 5 in math_functions");
  EXPECT_MESSAGE_HAS(with("ba_dir", ok, R"({"dir": 2, "acceleration": 1, "math_function_id": 0})"),
                     "external_loading_conditions.base_acceleration.dir: expected 0 (x) or 1 (y), got 2");
  EXPECT_MESSAGE_HAS(with("ba_missing", ok, R"({"dir": 0, "math_function_id": 0})"),
                     "external_loading_conditions.base_acceleration.acceleration: missing");
}

namespace {

TEST(DeckReader, SinFunctionAsCbGeo) {
  SmallDeck d("sin_function");
  d.deck["math_functions"] = json::parse(
      R"([{"id": 0, "type": "Sin", "a": 3.0, "x0": 0.25},
          {"id": 1, "type": "Sin", "a": 2.0, "x0": 0.0, "xrange": [-1.0, 1.0]}])");
  d.deck["external_loading_conditions"]["base_acceleration"] =
      json::parse(R"({"dir": 1, "acceleration": 2.0, "math_function_id": 0})");
  const auto b = *d.read().base_acceleration;
  // CB-Geo SinFunction: sin(a (x - x0)) inside xrange, 0 outside; the default range starts at the
  // smallest positive double, so f(0) = 0.
  EXPECT_EQ(b.history.value(0.0), 0.0);
  EXPECT_EQ(b.history.value(-1.0), 0.0);
  EXPECT_CLOSE(b.history.value(1.0), std::sin(3.0 * 0.75), 1e-15, 0);
  EXPECT_CLOSE(b.at(2.0), 2.0 * std::sin(3.0 * 1.75), 1e-15, 0);
  d.deck["external_loading_conditions"]["base_acceleration"]["math_function_id"] = 1;
  const auto r = *d.read().base_acceleration;
  EXPECT_CLOSE(r.history.value(-0.5), std::sin(-1.0), 1e-15, 0);
  EXPECT_EQ(r.history.value(1.5), 0.0);
}

TEST(DeckReader, ConcentratedNodalForcesAndParticleTractions) {
  SmallDeck d("external_loads");
  d.write("forces.txt", "7 0 5.5\n8 1 -2\n");
  d.write("entity_sets.json", R"({"node_sets": [{"id": 0, "set": [0, 1, 2, 3, 4]}, {"id": 2, "set": [6, 7]}],
                                  "particle_sets": [{"id": 5, "set": [2, 3]}]})");
  d.deck["math_functions"] = json::parse(R"([{"id": 1, "type": "Linear", "xvalues": [0, 1], "fxvalues": [0, 1]}])");
  d.deck["external_loading_conditions"]["concentrated_nodal_forces"] = json::parse(
      R"([{"nset_id": 2, "dir": 1, "force": -10.0, "math_function_id": 1}, {"file": "forces.txt"}])");
  d.deck["external_loading_conditions"]["particle_surface_traction"] = json::parse(
      R"([{"pset_id": 5, "dir": 1, "traction": -1000.0}, {"pset_id": 0, "dir": 0, "traction": 50.0, "math_function_id": 1},
          {"pset_id": -1, "dir": 0, "traction": 1.0}])");
  const auto deck = d.read();
  ASSERT_EQ(deck.nodal_forces.size(), 3u);
  EXPECT_EQ(deck.nodal_forces[0].nodes, (std::vector<int>{6, 7}));
  EXPECT_EQ(deck.nodal_forces[0].dir, 1);
  EXPECT_EQ(deck.nodal_forces[0].force, -10.0);
  EXPECT_EQ(deck.nodal_forces[0].function.value(0.5), 0.5);
  EXPECT_EQ(deck.nodal_forces[1].nodes, (std::vector<int>{7}));  // from the file: "node dir force"
  EXPECT_EQ(deck.nodal_forces[1].dir, 0);
  EXPECT_EQ(deck.nodal_forces[1].force, 5.5);
  EXPECT_EQ(deck.nodal_forces[1].function.value(0.5), 1.0);  // no function: scaled by 1
  EXPECT_EQ(deck.nodal_forces[2].force, -2.0);
  ASSERT_EQ(deck.particle_tractions.size(), 3u);
  EXPECT_EQ(deck.particle_tractions[0].particles, (std::vector<std::int64_t>{2, 3}));  // an entity set
  EXPECT_EQ(deck.particle_tractions[1].particles, (std::vector<std::int64_t>{0, 1, 2, 3}));  // the generator's pset_id
  EXPECT_EQ(deck.particle_tractions[1].dir, 0);
  EXPECT_EQ(deck.particle_tractions[1].function.value(0.25), 0.25);
  EXPECT_EQ(deck.particle_tractions[2].particles.size(), 4u);  // -1: every particle
}

TEST(DeckReaderErrors, ConcentratedNodalForcesAndParticleTractions) {
  const auto with = [](const std::string& name, const char* key, const char* list) {
    SmallDeck d(name);
    d.deck["math_functions"] = json::parse(R"([{"id": 0, "type": "Linear", "xvalues": [0], "fxvalues": [1]}])");
    d.deck["external_loading_conditions"][key] = json::parse(list);
    d.write("forces.txt", "3 2 1.0\n");
    return d.error();
  };
  const char* nodal = "concentrated_nodal_forces";
  const char* traction = "particle_surface_traction";
  EXPECT_MESSAGE_HAS(with("nf_set", nodal, R"([{"nset_id": 4, "dir": 0, "force": 1}])"),
                     "external_loading_conditions.concentrated_nodal_forces[0].nset_id: node set 4 is not defined");
  EXPECT_MESSAGE_HAS(with("nf_dir", nodal, R"([{"nset_id": 0, "dir": 2, "force": 1}])"),
                     "concentrated_nodal_forces[0].dir: expected 0 (x) or 1 (y), got 2");
  EXPECT_MESSAGE_HAS(with("nf_force", nodal, R"([{"nset_id": 0, "dir": 0, "force": "1"}])"),
                     "concentrated_nodal_forces[0].force: expected a number");
  EXPECT_MESSAGE_HAS(with("nf_fn", nodal, R"([{"nset_id": 0, "dir": 0, "force": 1, "math_function_id": 3}])"),
                     "concentrated_nodal_forces[0].math_function_id: no math function with id 3 in math_functions");
  EXPECT_MESSAGE_HAS(with("nf_file", nodal, R"([{"file": "forces.txt"}])"), "forces.txt: entry 0: dir must be 0 or 1");
  EXPECT_MESSAGE_HAS(with("nf_key", nodal, R"([{"nset_id": 0, "dir": 0, "force": 1, "phase": 0}])"),
                     "concentrated_nodal_forces[0].phase: unsupported key");
  EXPECT_MESSAGE_HAS(with("pt_set", traction, R"([{"pset_id": 9, "dir": 1, "traction": 1}])"),
                     "external_loading_conditions.particle_surface_traction[0].pset_id: particle set 9 is not defined");
  EXPECT_MESSAGE_HAS(with("pt_missing", traction, R"([{"pset_id": 0, "dir": 1}])"),
                     "particle_surface_traction[0].traction: missing");
  EXPECT_MESSAGE_HAS(with("pt_list", traction, R"({"pset_id": 0})"), "external_loading_conditions.particle_surface_traction: expected an array");
  SmallDeck sin("sin_range");
  sin.deck["math_functions"] = json::parse(R"([{"id": 0, "type": "Sin", "a": 1, "x0": 0, "xrange": [1, 0]}])");
  EXPECT_MESSAGE_HAS(sin.error(), "math_functions[0].xrange: expected [min, max] with min <= max");
}

}  // namespace
