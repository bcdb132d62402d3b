// mpm::io::read_deck on CB-Geo 3D decks (issue 37): MPMExplicit3D with Ascii3D meshes (ED3H8 and ED3H64G in
// CB-Geo's node orders, include/elements/3d/hexahedron_element.tcc and hexahedron_gimp_element.tcc), particle
// files and Gauss generators, 3D constraints, entity sets and resume from a 3D particle table; and each bad
// 3D input as one message naming the file, line or key. The decks are written by the tests
// (tests/support/mpm_deck_3d.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "common/input_error.hpp"
#include "mpm/io/cell_nodes.hpp"
#include "mpm/io/deck_reader.hpp"
#include "mpm/io/particle_table.hpp"
#include "support/mpm_deck_3d.hpp"
#include "support/scratch.hpp"
#include "support/tolerance.hpp"

namespace fs = std::filesystem;
using nlohmann::json;
using test_support::SmallDeck3d;

namespace {

/// A scratch copy of the small 3D deck; `deck` is written to mpm.json by read() and error().
class Deck3d {
 public:
  explicit Deck3d(const std::string& name)
      : dir(test_support::fresh_scratch_folder("geoflow_deck_reader_3d", name)), deck(SmallDeck3d::write(dir)) {}
  void write(const std::string& file, const std::string& text) const { std::ofstream(dir / file) << text; }
  mpm::Deck read() const {
    write("mpm.json", deck.dump(2));
    return mpm::io::read_deck(dir, "mpm.json");
  }
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

/// A GIMP mesh of `cells` x `cells` x `cells` cells of side 0.5 with its halo: (cells + 3)^3 nodes from
/// (-0.5, -0.5, -0.5), x fastest; each cell lists its 64 nodes in CB-Geo's ED3H64G order. Node ids outside
/// the lattice are clamped onto it (`clamp`), which makes the border cells lack their halo when the lattice
/// has none (`halo` false: (cells + 1)^3 nodes from 0).
void write_gimp_mesh(const fs::path& file, int cells, bool halo) {
  const int n = cells + 1 + (halo ? 2 : 0);
  const double h = 0.5, origin = halo ? -h : 0.0;
  std::ofstream out(file);
  out << n * n * n << " " << cells * cells * cells << "\n";
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) out << origin + i * h << " " << origin + j * h << " " << origin + k * h << "\n";
  const auto natural = mpm::io::cell_node_natural_coordinates(mpm::CellType::Gimp64, 3);
  const int shift = halo ? 1 : 0;
  for (int k = 0; k < cells; ++k)
    for (int j = 0; j < cells; ++j)
      for (int i = 0; i < cells; ++i) {
        for (std::size_t m = 0; m < natural.size(); ++m) {
          const int at[3] = {i + shift + (natural[m][0] + 1) / 2, j + shift + (natural[m][1] + 1) / 2,
                             k + shift + (natural[m][2] + 1) / 2};
          int id = 0;
          for (int d = 2; d >= 0; --d) id = id * n + std::clamp(at[d], 0, n - 1);
          out << id << (m + 1 < natural.size() ? " " : "\n");
        }
      }
}

}  // namespace

TEST(DeckReader3d, ReadsTheSmallDeckIntoALattice) {
  Deck3d d("ok");
  const auto deck = d.read();
  EXPECT_EQ(deck.grid.dim, 3);
  EXPECT_EQ(deck.grid.cell_type, mpm::CellType::Linear8);
  for (int a = 0; a < 3; ++a) {
    SCOPED_TRACE(a);
    EXPECT_EQ(deck.grid.nodes_per_axis[a], SmallDeck3d::kNodes[a]);
    EXPECT_CLOSE(deck.grid.spacing[a], SmallDeck3d::kSpacing[a], 1e-12, 0);
    EXPECT_CLOSE(deck.grid.origin[a], SmallDeck3d::kOrigin[a], 1e-12, 0);
    EXPECT_CLOSE(deck.grid.region_min[a], SmallDeck3d::kOrigin[a], 1e-12, 0);
    EXPECT_CLOSE(deck.grid.region_max[a], SmallDeck3d::kOrigin[a] + (SmallDeck3d::kNodes[a] - 1) * SmallDeck3d::kSpacing[a],
                 1e-12, 0);
  }
  EXPECT_EQ(deck.grid.node_count(), 36u);
  ASSERT_EQ(deck.particles.size(), 8u);
  EXPECT_EQ(deck.particles[7].coord_x, 2.75);
  EXPECT_EQ(deck.particles[7].coord_y, -0.125);
  EXPECT_EQ(deck.particles[7].coord_z, 1.5);
  EXPECT_EQ(deck.particles[0].volume, 0.0);  // the engine applies CB-Geo's defaults
  EXPECT_EQ(deck.materials[0].type, mpm::MaterialType::LinearElastic3D);
  EXPECT_EQ(deck.analysis.gravity.x(), 0.0);
  EXPECT_EQ(deck.analysis.gravity.y(), 0.0);
  EXPECT_EQ(deck.analysis.gravity_z, -9.81);
  // Node set 0 (the z = 0 face, file ids in reverse lattice order) becomes the lattice indices 0..11.
  ASSERT_EQ(deck.velocity_constraints.size(), 1u);
  EXPECT_EQ(deck.velocity_constraints[0].dir, 2);
  std::vector<int> bottom(deck.velocity_constraints[0].nodes);
  std::sort(bottom.begin(), bottom.end());
  EXPECT_EQ(bottom, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}));
  ASSERT_EQ(deck.friction_constraints.size(), 1u);
  EXPECT_EQ(deck.friction_constraints[0].dir, 0);
  std::set<int> left(deck.friction_constraints[0].nodes.begin(), deck.friction_constraints[0].nodes.end());
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j) EXPECT_EQ(left.count(SmallDeck3d::lattice_index(0, j, k)), 1u) << j << " " << k;
  EXPECT_EQ(left.size(), 9u);
}

TEST(DeckReader3d, GaussGeneratorFillsTheCellSetWithGaussPointsInXYZOrder) {
  Deck3d d("gauss");
  d.deck["particles"][0]["generator"] =
      json::parse(R"({"type": "gauss", "nparticles_per_dir": 2, "cset_id": 4, "material_id": 0, "pset_id": 1,
                      "particle_type": "P3D", "io_type": "Ascii3D"})");
  const auto deck = d.read();
  // Cell set 4 holds file cells 0 (lattice cell (0,0,0)) and 11 (the last, (2,1,1)): 8 points each.
  ASSERT_EQ(deck.particles.size(), 16u);
  const double g = 0.5 / std::sqrt(3.0);
  EXPECT_CLOSE(deck.particles[0].coord_x, 1.0 + 0.5 - g * 1.0, 1e-12, 0);
  EXPECT_CLOSE(deck.particles[0].coord_y, -1.0 + 0.25 - g * 0.5, 1e-12, 0);
  EXPECT_CLOSE(deck.particles[0].coord_z, 1.0 - g * 2.0, 1e-12, 0);
  EXPECT_CLOSE(deck.particles[1].coord_x, 1.0 + 0.5 + g * 1.0, 1e-12, 0);  // x fastest
  EXPECT_CLOSE(deck.particles[4].coord_z, 1.0 + g * 2.0, 1e-12, 0);        // z slowest
  EXPECT_CLOSE(deck.particles[15].coord_x, 3.5 + g, 1e-12, 0);
  EXPECT_CLOSE(deck.particles[15].coord_y, -0.25 + 0.5 * g, 1e-12, 0);
  EXPECT_CLOSE(deck.particles[15].coord_z, 3.0 + 2.0 * g, 1e-12, 0);
  d.deck["particles"][0]["generator"]["nparticles_per_dir"] = 5;
  EXPECT_MESSAGE_HAS(d.error(), "particles[0].generator.nparticles_per_dir: expected an integer in 1..4, got 5");
}

// CB-Geo's ED3H64G order (hexahedron_gimp_element.tcc natural_nodal_coordinates): the corners from
// (-1, 1, -1) with y = +1 first, then the halo by layers of y = 3, 1, -1, -3.
TEST(DeckReader3d, GimpHexahedronNodeOrderIsCbGeos) {
  const auto nodes = mpm::io::cell_node_natural_coordinates(mpm::CellType::Gimp64, 3);
  ASSERT_EQ(nodes.size(), 64u);
  EXPECT_EQ(nodes[0], (mpm::io::NaturalPoint{-1, 1, -1}));
  EXPECT_EQ(nodes[2], (mpm::io::NaturalPoint{1, 1, 1}));
  EXPECT_EQ(nodes[4], (mpm::io::NaturalPoint{-1, -1, -1}));
  EXPECT_EQ(nodes[7], (mpm::io::NaturalPoint{-1, -1, 1}));
  EXPECT_EQ(nodes[8], (mpm::io::NaturalPoint{-3, 3, -3}));
  EXPECT_EQ(nodes[23], (mpm::io::NaturalPoint{3, 3, 3}));
  EXPECT_EQ(nodes[28], (mpm::io::NaturalPoint{-3, 1, -1}));
  EXPECT_EQ(nodes[29], (mpm::io::NaturalPoint{3, 1, -1}));
  EXPECT_EQ(nodes[48], (mpm::io::NaturalPoint{-3, -3, -3}));
  EXPECT_EQ(nodes[63], (mpm::io::NaturalPoint{3, -3, 3}));
  EXPECT_EQ(std::set<mpm::io::NaturalPoint>(nodes.begin(), nodes.end()).size(), 64u);
  EXPECT_EQ(mpm::io::lowest_corner_position(mpm::CellType::Gimp64, 3), 4u);
  const auto hex = mpm::io::cell_node_natural_coordinates(mpm::CellType::Linear8, 3);
  ASSERT_EQ(hex.size(), 8u);
  EXPECT_EQ(hex[2], (mpm::io::NaturalPoint{1, 1, -1}));
  EXPECT_EQ(hex[4], (mpm::io::NaturalPoint{-1, -1, 1}));
}

TEST(DeckReader3d, ReadsAGimpMeshWithItsHalo) {
  Deck3d d("gimp");
  write_gimp_mesh(d.dir / "gimp.txt", 2, true);
  d.deck["mesh"]["mesh"] = "gimp.txt";
  d.deck["mesh"]["cell_type"] = "ED3H64G";
  d.deck["mesh"].erase("entity_sets");
  d.deck["mesh"].erase("boundary_conditions");
  d.write("particles.txt", "2\n0.25 0.25 0.25\n0.75 0.6 0.9\n");
  const auto deck = d.read();
  EXPECT_EQ(deck.grid.cell_type, mpm::CellType::Gimp64);
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(deck.grid.nodes_per_axis[a], 5);
    EXPECT_CLOSE(deck.grid.origin[a], -0.5, 1e-12, 0);
    EXPECT_CLOSE(deck.grid.spacing[a], 0.5, 1e-12, 0);
    EXPECT_CLOSE(deck.grid.region_min[a], 0.0, 1e-12, 0);
    EXPECT_CLOSE(deck.grid.region_max[a], 1.0, 1e-12, 0);
  }
  EXPECT_EQ(deck.particles.size(), 2u);

  // A GIMP mesh without its halo: the border cells' halo nodes are not in the file.
  write_gimp_mesh(d.dir / "gimp.txt", 2, false);
  EXPECT_MESSAGE_HAS(d.error(), "gimp.txt: cell 0: node 8 (id 6) is the GIMP halo node at natural coordinates (-3, 3, -3), "
                                "which lies outside the mesh's nodes (an ED3H64G mesh needs a halo of nodes");
  // ... or cells listing only their 8 corners.
  d.deck["mesh"]["mesh"] = "mesh.txt";
  EXPECT_MESSAGE_HAS(d.error(), "mesh.txt:39: cell 0: expected 64 node ids for this cell_type, got 8");
}

TEST(DeckReader3d, HexahedronCornersInAnyRotationButNotMirrored) {
  Deck3d d("rotation");
  d.deck["mesh"].erase("entity_sets");
  d.deck["mesh"].erase("boundary_conditions");
  d.write("particles.txt", "1\n0.5 0.5 0.5\n");
  // One unit cube, nodes x fastest: ids 0..7 at (i, j, k) = (id & 1, id >> 1 & 1, id >> 2).
  const std::string nodes = "8 1\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n";
  d.write("mesh.txt", nodes + "0 1 3 2 4 5 7 6\n");  // CB-Geo's order
  EXPECT_EQ(d.error(), "");
  d.write("mesh.txt", nodes + "1 3 2 0 5 7 6 4\n");  // turned a quarter about z
  EXPECT_EQ(d.error(), "");
  d.write("mesh.txt", nodes + "4 5 1 0 6 7 3 2\n");  // turned a quarter about x
  EXPECT_EQ(d.error(), "");
  d.write("mesh.txt", nodes + "0 2 3 1 4 6 7 5\n");  // mirrored (clockwise faces)
  EXPECT_MESSAGE_HAS(d.error(), "mesh.txt: cell 0: node 1 (id 2) is not where a box-shaped ED3H8 cell has it");
}

TEST(DeckReader3d, ResumeReadsA3dParticleTable) {
  Deck3d d("resume");
  std::vector<mpm::ParticleRecord> table;
  for (int k = 0; k < 2; ++k) {
    mpm::ParticleRecord r{};
    r.id = 10 - k;
    r.mass = 1.5;
    r.volume = 0.125;
    r.coord_x = 2.5;
    r.coord_y = -0.5 + 0.1 * k;
    r.coord_z = 3.0 + k;
    r.displacement_z = -0.01;
    r.velocity_z = -0.2;
    r.nsize_x = r.nsize_y = r.nsize_z = 1.0;
    r.stress_zz = -100.0;
    r.tau_yz = 3.0;
    r.tau_xz = 4.0;
    r.gamma_yz = 1e-4;
    r.gamma_xz = 2e-4;
    r.material_id = 0;
    table.push_back(r);
  }
  fs::create_directories(d.dir / "results/small3d");
  mpm::io::write_particle_table(d.dir / "results/small3d" / mpm::io::particle_file_name(5, 10), table);
  d.deck["analysis"]["resume"] = json::parse(R"({"resume": true, "uuid": "small3d", "step": 5})");
  const auto deck = d.read();
  EXPECT_TRUE(deck.resumed);
  EXPECT_EQ(deck.first_step, 6);
  ASSERT_EQ(deck.particles.size(), 2u);
  EXPECT_EQ(deck.particles[0].id, 9);  // sorted by id
  EXPECT_EQ(deck.particles[0].coord_z, 4.0);
  EXPECT_EQ(std::memcmp(&deck.particles[1], &table[0], sizeof(mpm::ParticleRecord)), 0);

  // A particle beyond the grid's z range, and a 2D table (no size in z) on the 3D deck.
  table[0].coord_z = 4.5;
  fs::remove(d.dir / "results/small3d/particles05.h5");
  mpm::io::write_particle_table(d.dir / "results/small3d/particles05.h5", table);
  EXPECT_MESSAGE_HAS(d.error(), "results/small3d/particles05.h5: particle 10 at (2.5, -0.5, 4.5) is outside the grid's cells");
  table[0].coord_z = 1.0;
  table[0].nsize_z = 0.0;
  fs::remove(d.dir / "results/small3d/particles05.h5");
  mpm::io::write_particle_table(d.dir / "results/small3d/particles05.h5", table);
  EXPECT_MESSAGE_HAS(d.error(), "particle 10 has a size in x and y but none in z (nsize_x 1, nsize_z 0): a 2D particle table on a 3D deck");
}

TEST(DeckReader3d, ParticleVolumesSizeAndCellsIn3d) {
  Deck3d d("volumes");
  d.write("volumes.txt", "0 0.03125\n7 0.03125\n");
  d.write("cells.txt", "0 4\n7 4\n");  // file cell 4 = lattice cell (1, 1, 0)
  d.deck["mesh"]["particles_volumes"] = "volumes.txt";
  d.deck["mesh"]["particle_cells"] = "cells.txt";
  const auto deck = d.read();
  EXPECT_EQ(deck.particles[7].volume, 0.03125);
  EXPECT_CLOSE(deck.particles[7].mass, 1800.0 * 0.03125, 1e-12, 0);
  // 8 particles in the cell: 2 per direction, natural size 2 / 2 on each axis.
  EXPECT_CLOSE(deck.particles[7].nsize_x, 1.0, 1e-15, 0);
  EXPECT_CLOSE(deck.particles[7].nsize_z, 1.0, 1e-15, 0);
  d.write("cells.txt", "0 10\n");  // lattice cell (1, 1, 1): the particle's z is below it
  EXPECT_MESSAGE_HAS(d.error(), "cells.txt: particle 0 at (2.25, -0.375, 0.5) is not inside cell 10");
}

TEST(DeckReader3d, ConstraintsAndLoadsTakeTheZAxis) {
  Deck3d d("axes");
  d.write("vc.txt", "0 2 -0.5\n");
  d.deck["mesh"]["boundary_conditions"]["velocity_constraints"].push_back(json::parse(R"({"file": "vc.txt"})"));
  d.deck["external_loading_conditions"]["concentrated_nodal_forces"] =
      json::parse(R"([{"nset_id": 0, "dir": 2, "force": -10.0}])");
  const auto deck = d.read();
  ASSERT_EQ(deck.velocity_constraints.size(), 2u);
  EXPECT_EQ(deck.velocity_constraints[1].dir, 2);
  EXPECT_EQ(deck.velocity_constraints[1].nodes, (std::vector<int>{35}));  // file id 0: the last lattice node
  ASSERT_EQ(deck.nodal_forces.size(), 1u);
  EXPECT_EQ(deck.nodal_forces[0].dir, 2);
  d.write("vc.txt", "0 3 -0.5\n");
  EXPECT_MESSAGE_HAS(d.error(), "vc.txt: entry 0: dir must be 0, 1 or 2");
  d.write("vc.txt", "0 2 -0.5\n");
  d.deck["mesh"]["boundary_conditions"]["friction_constraints"][0]["dir"] = 3;
  EXPECT_MESSAGE_HAS(d.error(), "friction_constraints[0].dir: expected 0 (x), 1 (y) or 2 (z), got 3");
}

// Each bad 3D input is one message naming the file (and line) or the key, never a 2D reading of a 3D deck
// or the reverse.
TEST(DeckReader3dErrors, DimensionMismatchesAreNamed) {
  const std::vector<std::pair<std::function<void(Deck3d&)>, std::string>> cases = {
      {[](Deck3d& d) { d.deck["mesh"]["cell_type"] = "ED2Q4"; },
       "mpm.json: mesh.cell_type: a 2D cell type (\"ED2Q4\") in a 3D analysis (expected ED3H8 or ED3H64G)"},
      {[](Deck3d& d) { d.deck["mesh"]["cell_type"] = "ED3H20"; }, "mesh.cell_type: unsupported cell type \"ED3H20\""},
      {[](Deck3d& d) { d.deck["mesh"]["io_type"] = "Ascii2D"; },
       "mesh.io_type: \"Ascii2D\" in a 3D analysis (expected \"Ascii3D\")"},
      {[](Deck3d& d) { d.deck["mesh"]["node_type"] = "N2D"; }, "mesh.node_type: \"N2D\" in a 3D analysis"},
      {[](Deck3d& d) { d.deck["particles"][0]["generator"]["particle_type"] = "P2D"; },
       "particles[0].generator.particle_type: \"P2D\" in a 3D analysis (expected \"P3D\")"},
      {[](Deck3d& d) { d.deck["materials"][0]["type"] = "LinearElastic2D"; },
       "materials[0].type: a 2D material (\"LinearElastic2D\") in a 3D analysis (expected LinearElastic3D or MohrCoulomb3D)"},
      {[](Deck3d& d) { d.deck["external_loading_conditions"]["gravity"] = json::parse("[0, -9.81]"); },
       "external_loading_conditions.gravity: expected [gx, gy, gz] (3 numbers, m/s^2)"},
      {[](Deck3d& d) { d.write("particles.txt", "2\n2.25 -0.375\n2.75 -0.375\n"); },
       "particles.txt:2: particle 0: expected \"x y z\", got 2 values (a 2D file in a 3D analysis?)"},
      {[](Deck3d& d) { d.write("particles.txt", "1\n2.25 -0.375 4.5\n"); },
       "particles.txt: particle 0 at (2.25, -0.375, 4.5) is outside the grid's cells [1, 4] x [-1, 0] x [0, 4]"},
      {[](Deck3d& d) { d.deck["analysis"]["type"] = "MPMExplicit1D"; },
       "analysis.type: unsupported analysis \"MPMExplicit1D\" (expected MPMExplicit2D or MPMExplicit3D)"},
  };
  for (std::size_t k = 0; k < cases.size(); ++k) {
    SCOPED_TRACE(cases[k].second);
    Deck3d d("mismatch_" + std::to_string(k));
    cases[k].first(d);
    EXPECT_MESSAGE_HAS(d.error(), cases[k].second);
  }
}

TEST(DeckReader3dErrors, NonLatticeMeshes) {
  Deck3d d("lattice");
  d.deck["mesh"].erase("entity_sets");
  d.deck["mesh"].erase("boundary_conditions");
  d.write("particles.txt", "1\n0.5 0.5 0.5\n");
  const std::string head = "8 1\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n";
  d.write("mesh.txt", head + "1 1.3 1\n0 1 3 2 4 5 7 6\n");
  EXPECT_MESSAGE_HAS(d.error(), "mesh.txt: nodes do not form a uniform box-shaped lattice");
  d.write("mesh.txt", head + "1 1\n0 1 3 2 4 5 7 6\n");
  EXPECT_MESSAGE_HAS(d.error(), "mesh.txt:9: node 7: expected \"x y z\", got 2 values");
  // An L of 3 cells on a 3 x 3 x 2 lattice: not a box.
  std::string mesh = "18 3\n";
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) mesh += std::to_string(i) + " " + std::to_string(j) + " " + std::to_string(k) + "\n";
  auto id = [](int i, int j, int k) { return std::to_string(i + 3 * j + 9 * k); };
  for (const auto& [i, j] : std::vector<std::pair<int, int>>{{0, 0}, {1, 0}, {0, 1}})
    mesh += id(i, j, 0) + " " + id(i + 1, j, 0) + " " + id(i + 1, j + 1, 0) + " " + id(i, j + 1, 0) + " " + id(i, j, 1) + " " +
            id(i + 1, j, 1) + " " + id(i + 1, j + 1, 1) + " " + id(i, j + 1, 1) + "\n";
  d.write("mesh.txt", mesh);
  EXPECT_MESSAGE_HAS(d.error(), "mesh.txt: cells do not form a box: they span 2 x 2 x 1 cells but the file has 3");
}

// The 2D reader's side of the same mismatches: a 3D particle file or io_type on a 2D deck.
TEST(DeckReader3dErrors, ThreeDimensionalInputOnATwoDimensionalDeck) {
  Deck3d d("on2d");
  d.deck["analysis"]["type"] = "MPMExplicit2D";
  EXPECT_MESSAGE_HAS(d.error(), "materials[0].type: a 3D material (\"LinearElastic3D\") in a 2D analysis");
  d.deck["materials"][0]["type"] = "LinearElastic2D";
  EXPECT_MESSAGE_HAS(d.error(), "mesh.io_type: \"Ascii3D\" in a 2D analysis (expected \"Ascii2D\")");
  d.deck["mesh"]["io_type"] = "Ascii2D";
  EXPECT_MESSAGE_HAS(d.error(), "mesh.node_type: \"N3D\" in a 2D analysis (expected \"N2D\")");
  d.deck["mesh"]["node_type"] = "N2D";
  EXPECT_MESSAGE_HAS(d.error(), "mesh.cell_type: a 3D cell type (\"ED3H8\") in a 2D analysis (expected ED2Q4 or ED2Q16G)");
  d.deck["mesh"]["cell_type"] = "ED2Q4";
  // The mesh file itself is 3D.
  EXPECT_MESSAGE_HAS(d.error(), "mesh.txt:3: node 0: a 2D mesh needs z = 0");
  // On a 2D mesh: the generator's 3D keys, then a 3D particle file.
  d.write("mesh.txt", "4 1\n0 0\n1 0\n1 1\n0 1\n0 1 2 3\n");
  d.deck["mesh"].erase("entity_sets");
  d.deck["mesh"].erase("boundary_conditions");
  d.deck["external_loading_conditions"]["gravity"] = json::parse("[0, -9.81]");
  EXPECT_MESSAGE_HAS(d.error(), "particles[0].generator.particle_type: \"P3D\" in a 2D analysis (expected \"P2D\")");
  d.deck["particles"][0]["generator"]["particle_type"] = "P2D";
  EXPECT_MESSAGE_HAS(d.error(), "particles[0].generator.io_type: \"Ascii3D\" in a 2D analysis (expected \"Ascii2D\")");
  d.deck["particles"][0]["generator"]["io_type"] = "Ascii2D";
  d.write("particles.txt", "1\n0.5 0.5 0.25\n");
  EXPECT_MESSAGE_HAS(d.error(), "particles.txt:2: particle 0: a 2D deck needs z = 0");
  d.write("particles.txt", "1\n0.5 0.5 0\n");
  EXPECT_EQ(d.error(), "");
}

// CB-Geo's benchmark 3d/uniaxial_stress (cb-geo/mpm-benchmarks): one unit ED3H8 cube, 8 particles, the base
// fixed in y and the top pulled at -0.01 m/s, LinearElastic3D with no gravity; written here in the current
// CB-Geo keys (pset_id inside the generator, mpm_scheme; the benchmark's older "set_id" and
// "stress_update" spellings: the first is not read, the second is).
TEST(DeckReader3d, ReadsCbGeosUniaxialStressBenchmark) {
  const auto dir = test_support::fresh_scratch_folder("geoflow_deck_reader_3d", "uniaxial_stress");
  std::ofstream(dir / "mesh.txt") << "#! elementShape hexahedron\n#! elementNumPoints 8\n8\t1\n"
                                     "     0         0         0\n1.0000         0         0\n1.0000    1.0000         0\n"
                                     "     0    1.0000         0\n     0         0    1.0000  \n1.0000         0    1.0000\n"
                                     "1.0000    1.0000    1.0000\n     0    1.0000    1.0000\n"
                                     "0         1         2        3        4         5         6        7\n";
  std::ofstream particles(dir / "particles.txt");
  particles << "8\n";
  for (const double z : {0.25, 0.75})
    for (const double y : {0.25, 0.75})
      for (const double x : {0.25, 0.75}) particles << x << " " << y << " " << z << "\n";
  particles.close();
  std::ofstream(dir / "entity_sets.json") << R"({"node_sets": [{"id": 0, "set": [0, 1, 4, 5]}, {"id": 1, "set": [2, 3, 6, 7]}]})";
  std::ofstream(dir / "mpm.json") << R"({
    "title": "Element test USF",
    "mesh": {"mesh": "mesh.txt", "entity_sets": "entity_sets.json", "cell_type": "ED3H8", "isoparametric": false,
             "io_type": "Ascii3D", "node_type": "N3D",
             "boundary_conditions": {"velocity_constraints": [{"nset_id": 0, "dir": 1, "velocity": 0.00},
                                                              {"nset_id": 1, "dir": 1, "velocity": -0.01}]}},
    "particles": [{"generator": {"check_duplicates": true, "location": "particles.txt", "io_type": "Ascii3D",
                                 "particle_type": "P3D", "material_id": 0, "type": "file", "pset_id": 0}}],
    "materials": [{"id": 0, "type": "LinearElastic3D", "density": 1, "youngs_modulus": 1000, "poisson_ratio": 0.0}],
    "external_loading_conditions": {"gravity": [0, 0, 0]},
    "analysis": {"type": "MPMExplicit3D", "stress_update": "usf", "dt": 0.01, "uuid": "uniaxial-stress-3d-usf",
                 "nsteps": 10, "resume": {"resume": false, "uuid": "uniaxial-stress-3d-usf", "step": 5}},
    "post_processing": {"path": "results/", "output_steps": 1}
  })";
  const auto deck = mpm::io::read_deck(dir, "mpm.json");
  EXPECT_EQ(deck.grid.dim, 3);
  for (int a = 0; a < 3; ++a) EXPECT_EQ(deck.grid.nodes_per_axis[a], 2);
  EXPECT_EQ(deck.particles.size(), 8u);
  ASSERT_EQ(deck.velocity_constraints.size(), 2u);
  EXPECT_EQ(deck.velocity_constraints[1].velocity, -0.01);
  EXPECT_EQ(deck.velocity_constraints[1].nodes, (std::vector<int>{3, 2, 7, 6}));  // lattice indices, x fastest
  EXPECT_EQ(deck.output.uuid, "uniaxial-stress-3d-usf");
}

// The mesh.generator extension in 3D: three entries per key, GIMP halo, named sets per axis.
TEST(DeckReader3d, GeneratedGimpGridWithNamedSetsPerAxis) {
  Deck3d d("generator");
  d.deck["mesh"].erase("mesh");
  d.deck["mesh"].erase("entity_sets");
  d.deck["mesh"]["cell_type"] = "ED3H64G";
  d.deck["mesh"]["generator"] = json::parse(R"({"origin": [0, 0, 0], "cell_size": [1, 0.5, 2], "cells": [3, 2, 2]})");
  d.deck["mesh"]["boundary_conditions"] =
      json::parse(R"({"velocity_constraints": [{"nset_id": "z_min", "dir": 2, "velocity": 0.0}]})");
  d.write("particles.txt", "1\n0.5 0.5 0.5\n");
  const auto deck = d.read();
  EXPECT_EQ(deck.grid.nodes_per_axis, (std::array<int, 3>{6, 5, 5}));
  EXPECT_CLOSE(deck.grid.origin[2], -2.0, 1e-12, 0);
  EXPECT_CLOSE(deck.grid.region_max[2], 4.0, 1e-12, 0);
  // z_min: the nodes at or below z = 0, the halo layer included: 2 layers of 6 x 5.
  ASSERT_EQ(deck.velocity_constraints.size(), 1u);
  EXPECT_EQ(deck.velocity_constraints[0].nodes.size(), 60u);
  d.deck["mesh"]["boundary_conditions"]["velocity_constraints"][0]["nset_id"] = "bottom";
  EXPECT_MESSAGE_HAS(d.error(), "nset_id: no node set named \"bottom\" (expected x_min, x_max, y_min, y_max, z_min, z_max or all)");
  d.deck["mesh"]["generator"]["cells"] = json::parse("[3, 2]");
  EXPECT_MESSAGE_HAS(d.error(), "mesh.generator.cells: expected [nx, ny, nz] (3 integers)");
}
