// The /pore_pressure dataset beside /table (mpm/io/particle_table.hpp; issue 36): written and read in one place,
// a malformed one refused with the file and row named, read on resume and sorted with the particles by id, and
// carried particle by particle into later states (resume_extras.hpp carried_pore_pressure) when particles leave.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "common/input_error.hpp"
#include "mpm/io/deck_reader.hpp"
#include "mpm/io/particle_table.hpp"
#include "mpm/io/resume_extras.hpp"
#include "support/input_error_message.hpp"
#include "support/scratch.hpp"

namespace {

namespace fs = std::filesystem;
using mpm::PorePressureRecord;

fs::path write(const fs::path& file, std::size_t particles, const std::vector<PorePressureRecord>* rows) {
  std::vector<mpm::ParticleRecord> table(particles);
  for (std::size_t k = 0; k < particles; ++k) table[k].id = static_cast<std::int64_t>(k);
  mpm::io::write_particle_table(file, table, [&](std::int64_t h5) {
    if (rows) mpm::io::write_pore_pressure_dataset(h5, *rows, file.string());
  });
  return file;
}

TEST(PorePressureDataset, RoundTripsExactlyAndRefusesBadShapesAndRows) {
  const test_support::ScratchDir dir("geoflow_pore_pressure_dataset");
  const std::vector<PorePressureRecord> rows = {{1.5e5, 8.0e4, 0.25}, {-3.0, 1e-300, 0.0}, {0.0, 2.0e4, 0.95}};
  const auto back = mpm::io::read_pore_pressure_dataset(write(dir.path() / "a.h5", 3, &rows), 3);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(*back, rows);
  // Zero rows is a dataset too; a file without it has none.
  const std::vector<PorePressureRecord> none;
  const auto empty = mpm::io::read_pore_pressure_dataset(write(dir.path() / "empty.h5", 0, &none), 0);
  ASSERT_TRUE(empty.has_value());
  EXPECT_TRUE(empty->empty());
  EXPECT_FALSE(mpm::io::read_pore_pressure_dataset(write(dir.path() / "plain.h5", 3, nullptr), 3).has_value());
  // One row per /table row.
  const auto shape = test_support::input_error_message(
      [&] { mpm::io::read_pore_pressure_dataset(write(dir.path() / "rows.h5", 4, &rows), 4); });
  EXPECT_NE(shape.find("rows.h5: dataset \"/pore_pressure\" must be 4 x 3 floats"), std::string::npos) << shape;
  // A value that is not finite: the file and the row.
  for (double bad : {std::nan(""), std::numeric_limits<double>::infinity()}) {
    auto odd = rows;
    odd[2].sigma_v0 = bad;
    const auto message = test_support::input_error_message(
        [&] { mpm::io::read_pore_pressure_dataset(write(dir.path() / "odd.h5", 3, &odd), 3); });
    EXPECT_NE(message.find("odd.h5: dataset \"/pore_pressure\" row 2: expected finite p, sigma'v0 and r_u"),
              std::string::npos) << message;
  }
}

// A resume file whose particles are stored out of id order: the rows are sorted with them; a later state that
// lost a particle gets the rows of the particles it still has.
TEST(PorePressureDataset, ResumeSortsTheRowsWithTheParticlesAndLaterStatesKeepTheirs) {
  const auto dir = test_support::fresh_scratch_folder("geoflow_pore_pressure_resume", "deck");
  fs::copy(fs::path(GEOFLOW_TEST_DATA_DIR) / "reference_runs/cbgeo/resume_from_h5", dir, fs::copy_options::recursive);
  const auto file = dir / "results/bar_resume/particles000.h5";
  auto table = mpm::io::read_particle_table(file);
  ASSERT_GT(table.size(), 3u);
  std::reverse(table.begin(), table.end());
  std::vector<PorePressureRecord> rows;
  for (const auto& p : table) rows.push_back({1000.0 * static_cast<double>(p.id), 5e4, 0.001 * static_cast<double>(p.id)});
  fs::remove(file);
  mpm::io::write_particle_table(file, table, [&](std::int64_t h5) { mpm::io::write_pore_pressure_dataset(h5, rows, "test"); });

  const auto deck = mpm::io::read_deck(dir, "mpm.json");
  ASSERT_TRUE(deck.particle_pore_pressure.has_value());
  ASSERT_EQ(deck.particle_pore_pressure->size(), deck.particles.size());
  for (std::size_t k = 0; k < deck.particles.size(); ++k) {
    EXPECT_EQ((*deck.particle_pore_pressure)[k].pressure, 1000.0 * static_cast<double>(deck.particles[k].id));
    if (k > 0) {
      EXPECT_LT(deck.particles[k - 1].id, deck.particles[k].id);
    }
  }
  // A later state without the second particle.
  std::vector<mpm::ParticleRecord> later = deck.particles;
  later.erase(later.begin() + 1);
  const auto carried = mpm::io::carried_pore_pressure(deck, later);
  ASSERT_EQ(carried.size(), later.size());
  for (std::size_t k = 0; k < later.size(); ++k) EXPECT_EQ(carried[k].ru, 0.001 * static_cast<double>(later[k].id));
  // A deck resumed from a file without the dataset carries none.
  mpm::Deck plain = deck;
  plain.particle_pore_pressure.reset();
  EXPECT_TRUE(mpm::io::carried_pore_pressure(plain, later).empty());
  fs::remove_all(dir);
}

}  // namespace
