// Round trip of CB-Geo's particle table, and reading CB-Geo's own files (tests/data/reference_runs/cbgeo,
// written by CB-Geo MPM develop 53fcb76; see that folder's README.md).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include "common/input_error.hpp"
#include "mpm/io/particle_table.hpp"
#include "support/scratch.hpp"

namespace fs = std::filesystem;
using mpm::ParticleRecord;

TEST(ParticleTable, RoundTripKeepsEveryMember) {
  std::vector<ParticleRecord> in(3);
  for (std::size_t i = 0; i < in.size(); ++i) {
    auto& r = in[i];
    r.id = static_cast<std::int64_t>(i);
    r.mass = 1.5 + i; r.volume = 0.25; r.coord_x = 0.1 * i; r.coord_y = -2.0; r.nsize_x = r.nsize_y = 0.5;
    r.velocity_x = 3.0; r.stress_xx = -1e5; r.stress_zz = -4e4; r.tau_xy = 17.0; r.gamma_xy = 1e-3;
    r.cell_id = 42 + static_cast<std::int64_t>(i); r.status = 1; r.material_id = 7; r.nstate_vars = 7;
    for (int k = 0; k < 20; ++k) r.svars[k] = k * 0.5 + i;
  }
  const test_support::ScratchDir dir("geoflow_particle_table_roundtrip");
  const auto file = dir.path() / "roundtrip.h5";
  mpm::io::write_particle_table(file, in);
  EXPECT_FALSE(fs::exists(file.string() + ".tmp." + std::to_string(::getpid())));
  const auto out = mpm::io::read_particle_table(file);
  ASSERT_EQ(out.size(), in.size());
  for (std::size_t i = 0; i < in.size(); ++i) {
    EXPECT_EQ(out[i].id, in[i].id);
    EXPECT_EQ(out[i].mass, in[i].mass);
    EXPECT_EQ(out[i].coord_x, in[i].coord_x);
    EXPECT_EQ(out[i].stress_zz, in[i].stress_zz);
    EXPECT_EQ(out[i].gamma_xy, in[i].gamma_xy);
    EXPECT_EQ(out[i].cell_id, in[i].cell_id);
    EXPECT_EQ(out[i].status, in[i].status);
    EXPECT_EQ(out[i].material_id, in[i].material_id);
    EXPECT_EQ(out[i].nstate_vars, in[i].nstate_vars);
    EXPECT_EQ(out[i].svars[19], in[i].svars[19]);
  }
}

TEST(ParticleTable, AffineDatasetBesideTheTableRoundTripsExactly) {
  // APIC's B_p rows next to /table; /table keeps CB-Geo's 53 members (CB-Geo reads it alone).
  std::vector<ParticleRecord> in(2);
  in[1].id = 1;
  const std::vector<std::array<double, 4>> affine = {{{0.1, -2.5e-17, 3.0, 1.0 / 3.0}}, {{-1e300, 0.0, -0.0, 7.0}}};
  const test_support::ScratchDir dir("geoflow_particle_table_affine");
  const auto file = dir.path() / "affine.h5";
  mpm::io::write_particle_table(file, in, [&](std::int64_t h5) { mpm::io::write_affine_dataset(h5, affine, "affine.h5"); });
  EXPECT_EQ(mpm::io::read_particle_table(file).size(), 2u);
  const auto back = mpm::io::read_affine_dataset(file, 2);
  ASSERT_TRUE(back.has_value());
  ASSERT_EQ(back->size(), 2u);
  for (std::size_t k = 0; k < 2; ++k)
    EXPECT_EQ(std::memcmp((*back)[k].data(), affine[k].data(), sizeof affine[k]), 0) << "row " << k;
  try {
    mpm::io::read_affine_dataset(file, 3);
    ADD_FAILURE() << "a row count that differs from /table must be refused";
  } catch (const common::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("dataset \"/apic_affine\" must be 3 x 4 floats"), std::string::npos) << e.what();
  }
  const auto plain = dir.path() / "plain.h5";
  mpm::io::write_particle_table(plain, in);
  EXPECT_FALSE(mpm::io::read_affine_dataset(plain, 2).has_value());
}

TEST(ParticleTable, FrictionMemoryDatasetRoundTripsExactlyAndRefusesBadRows) {
  // The lagged friction strengths (node, N_s, node mass) beside /table; zero rows is a dataset too (a
  // lagged run with no node touched), told apart from none.
  const std::vector<ParticleRecord> in(1);
  const std::vector<mpm::FrictionMemoryRecord> memory = {{7, 1234.5, 0.0625}, {(1LL << 40) + 3, 0.0, 1e-300}};
  const test_support::ScratchDir dir("geoflow_particle_table_friction_memory");
  const auto write = [&](const char* name, std::span<const mpm::FrictionMemoryRecord> rows) {
    const auto file = dir.path() / name;
    mpm::io::write_particle_table(file, in, [&](std::int64_t h5) { mpm::io::write_friction_memory_dataset(h5, rows, name); });
    return file;
  };
  const auto back = mpm::io::read_friction_memory_dataset(write("memory.h5", memory));
  ASSERT_TRUE(back.has_value());
  EXPECT_TRUE(*back == memory);
  const auto empty = mpm::io::read_friction_memory_dataset(write("empty.h5", {}));
  ASSERT_TRUE(empty.has_value());
  EXPECT_TRUE(empty->empty());
  const auto plain = dir.path() / "plain.h5";
  mpm::io::write_particle_table(plain, in);
  EXPECT_FALSE(mpm::io::read_friction_memory_dataset(plain).has_value());
  for (const auto& bad : {mpm::FrictionMemoryRecord{-1, 1.0, 1.0}, mpm::FrictionMemoryRecord{2, -1.0, 1.0},
                          mpm::FrictionMemoryRecord{2, 1.0, 0.0},
                          mpm::FrictionMemoryRecord{2, std::numeric_limits<double>::infinity(), 1.0}}) {
    const std::vector<mpm::FrictionMemoryRecord> rows = {memory[0], bad};
    try {
      mpm::io::read_friction_memory_dataset(write("bad.h5", rows));
      ADD_FAILURE() << "row " << bad.node << " " << bad.force << " " << bad.mass << " must be refused";
    } catch (const common::InputError& e) {
      EXPECT_NE(std::string(e.what()).find("dataset \"/friction_memory\" row 1: expected a node index >= 0"),
                std::string::npos)
          << e.what();
    }
    fs::remove(dir.path() / "bad.h5");
  }
}

TEST(ParticleTable, ReadsTheResumeFileOfTheCbGeoReferenceDeck) {
  // particles000.h5 of resume_from_h5 was written by make_decks.py in CB-Geo's layout: 288 particles,
  // volume (0.25/3)^2, mass 1200*volume, cell_id -1, status 1.
  const fs::path file = fs::path(GEOFLOW_TEST_DATA_DIR) / "reference_runs/cbgeo/resume_from_h5/results/bar_resume/particles000.h5";
  const auto records = mpm::io::read_particle_table(file);
  ASSERT_EQ(records.size(), 288u);
  const double volume = (0.25 / 3) * (0.25 / 3);
  EXPECT_NEAR(records[0].volume, volume, 1e-15);
  EXPECT_NEAR(records[0].mass, 1200 * volume, 1e-12);
  EXPECT_EQ(records[0].cell_id, -1);
  EXPECT_EQ(records[0].status, 1);
  EXPECT_NEAR(records[0].nsize_x, 2.0 / 3.0, 1e-12);
}

TEST(ParticleTable, MissingFileIsAnInputErrorNamingTheFile) {
  try {
    mpm::io::read_particle_table("/nonexistent/particles000.h5");
    FAIL() << "expected an InputError";
  } catch (const common::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/particles000.h5"), std::string::npos);
  }
}

TEST(ParticleTable, GarbageFileIsAnInputError) {
  const test_support::ScratchDir dir("geoflow_particle_table_garbage");
  const auto file = dir.path() / "garbage.h5";
  std::ofstream(file) << "not hdf5";
  EXPECT_THROW(mpm::io::read_particle_table(file), common::InputError);
}

TEST(ParticleTable, FileNameIsZeroPaddedLikeCbGeo) {
  EXPECT_EQ(mpm::io::particle_file_name(250, 1001), "particles0250.h5");
  EXPECT_EQ(mpm::io::particle_file_name(0, 201), "particles000.h5");
  EXPECT_EQ(mpm::io::particle_file_name(5000, 5001), "particles5000.h5");
  EXPECT_EQ(mpm::io::particle_file_name(7, 9), "particles7.h5");
}
