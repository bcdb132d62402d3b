// Verification at reduced size of scripts/column_collapse/column_collapse.tcl (the FEM-only reference scene):
// a 10 m x 8 m column (same aspect ratio 0.8 as the paper's 50 x 40 m; 1 m SSPquads), elastic gravity with
// MohrCoulomb in stage 0, the switch to Mohr-Coulomb (phi 22.2, c 0.1 kPa) and 1 s of Newmark collapse.
// Checks, with their references:
//  - the script's contract: files, rows every 0.05 s from t = 0, rows exactly at 0.5 and 1 s, node/element order;
//  - after the switch (t = 0 row) the stresses are the elastic geostatic ones: szz = nu (sxx + syy) (plane
//    strain) and syy = -rho g (H - y) within 3 % in the interior of the bottom row (1D column, self weight);
//  - the first plastic steps converge (the K0 = 0.30 state is outside the yield surface, which needs a ratio of
//    at least Ka = (1 - sin phi) / (1 + sin phi) = 0.45, so the first step returns the whole column);
//  - energy: with Newmark average acceleration (no numerical dissipation) and dissipative plasticity,
//    KE(t) <= PE(0) - PE(t) (+ the small elastic energy released, bounded by 2 % of the drop);
//  - the physics of the collapse at t = 1 s (t / tau_c = 1.1, tau_c = sqrt(H / g) = 0.90 s): the crest settles
//    (top-right node: uy < -0.4 m), the face moves right (the right-face node one metre above the fixed base:
//    ux > 0.05 m), potential energy has dropped by 1 % to 10 % (measured 5.1 %), no element has
//    inverted (min corner det J > 0), and no step needed cutting;
//  - step cutting: with -dt 0.05 the equilibrium iterations fail, the script halves the step (0.0125 s), still
//    lands on every record time, and the crest settlement at 1 s agrees with the dt = 1e-3 run within 2 %
//    (measured 0.2 %);
//  - a clean stop at the first inverted corner (a 25 m x 20 m column of 1 m cells inverts a free-face element at
//    t = 2.119 s): the message on stdout, the warning on stderr, every file complete up to that step.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/recorder_compare.hpp"
#include "support/tolerance.hpp"

namespace {

namespace fs = std::filesystem;
using Table = std::vector<std::vector<double>>;

Table read_table(const fs::path& file, char sep = ' ') {
  std::ifstream in(file);
  Table rows;
  std::string line;
  while (std::getline(in, line)) {
    if (sep != ' ') for (char& c : line) if (c == sep) c = ' ';
    std::istringstream ls(line);
    std::vector<double> row;
    double v;
    while (ls >> v) row.push_back(v);
    if (!row.empty()) rows.push_back(row);
  }
  return rows;
}

/// Runs scripts/column_collapse/column_collapse.tcl in `dir`, writing its outputs there too.
int run_collapse(const fs::path& dir, const std::string& options) {
  const fs::path script = fs::path(GEOFLOW_SOURCE_DIR) / "scripts/column_collapse/column_collapse.tcl";
  return test_support::run_fem_tcl(GEOFLOW_BIN_DIR, dir, script.string(), "'" + dir.string() + "' " + options);
}

constexpr int kNx = 10, kNy = 8;
constexpr double kRho = 1.925, kG = 9.81, kNu = 0.23;

class ColumnCollapse : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = test_support::fresh_scratch_folder("geoflow_column_collapse", "run");
    status_ = run_collapse(dir_, "-width 10 -height 8 -tend 1.0");
  }
  static void TearDownTestSuite() {
    if (::testing::UnitTest::GetInstance()->failed_test_count() == 0) fs::remove_all(dir_.parent_path());
  }
  static fs::path dir_;
  static int status_;

  /// Lumped nodal masses (element area x rho / 4 per corner) of the 1 m mesh.
  static std::vector<double> masses() {
    std::vector<double> m((kNx + 1) * (kNy + 1), 0.0);
    for (int j = 0; j < kNy; ++j)
      for (int i = 0; i < kNx; ++i) {
        const int n1 = j * (kNx + 1) + i;
        for (int n : {n1, n1 + 1, n1 + kNx + 1, n1 + kNx + 2}) m[n] += 0.25 * kRho;
      }
    return m;
  }
  static double potential(const std::vector<double>& disp_row) {
    const auto m = masses();
    double pe = 0.0;
    for (std::size_t n = 0; n < m.size(); ++n) pe += m[n] * kG * (static_cast<double>(n / (kNx + 1)) + disp_row[1 + 2 * n + 1]);
    return pe;
  }
  static double kinetic(const std::vector<double>& vel_row) {
    const auto m = masses();
    double ke = 0.0;
    for (std::size_t n = 0; n < m.size(); ++n) {
      const double vx = vel_row[1 + 2 * n], vy = vel_row[1 + 2 * n + 1];
      ke += 0.5 * m[n] * (vx * vx + vy * vy);
    }
    return ke;
  }
};

fs::path ColumnCollapse::dir_;
int ColumnCollapse::status_ = -1;

TEST_F(ColumnCollapse, WritesTheContractedFiles) {
  ASSERT_EQ(status_, 0);
  for (const char* f : {"model.json", "disp.out", "vel.out", "stress.out", "mesh_quality.out", "steps.csv"}) {
    EXPECT_TRUE(fs::exists(dir_ / f)) << f;
  }
  const Table disp = read_table(dir_ / "disp.out");
  const Table vel = read_table(dir_ / "vel.out");
  const Table stress = read_table(dir_ / "stress.out");
  ASSERT_EQ(disp.size(), 21u);  // t = 0, 0.05, ..., 1
  ASSERT_EQ(vel.size(), 21u);
  ASSERT_EQ(stress.size(), 21u);
  for (std::size_t k = 0; k < disp.size(); ++k) {
    EXPECT_CLOSE(disp[k][0], 0.05 * k, 1e-9, 0.0);
    EXPECT_EQ(disp[k].size(), 1u + 2u * (kNx + 1) * (kNy + 1));
    EXPECT_EQ(stress[k].size(), 1u + 6u * kNx * kNy);
  }
  EXPECT_EQ(disp[10][0], 0.5);
  EXPECT_EQ(disp[20][0], 1.0);
  const Table steps = read_table(dir_ / "steps.csv", ',');  // the header line has no numbers
  ASSERT_EQ(steps.size(), 1000u);
  EXPECT_EQ(steps.back()[0], 1.0);
  for (const auto& s : steps) EXPECT_EQ(s[3], 0.0) << "cut step at t = " << s[0];
  const Table mq = read_table(dir_ / "mesh_quality.out");
  ASSERT_EQ(mq.size(), 1001u);  // t = 0 and every step
  for (const auto& r : mq) {
    ASSERT_EQ(r.size(), 5u);
    EXPECT_GT(r[1], 0.0) << "inverted element " << r[2] << " at t = " << r[0];
  }
}

TEST_F(ColumnCollapse, StressesAfterTheSwitchAreElasticAndTheFirstPlasticStepsConverge) {
  ASSERT_EQ(status_, 0);
  const Table stress = read_table(dir_ / "stress.out");
  const auto& s0 = stress.at(0);
  ASSERT_EQ(s0[0], 0.0);
  for (int e = 0; e < kNx * kNy; ++e) {
    const double* s = &s0[1 + 6 * e];
    EXPECT_CLOSE(s[2], kNu * (s[0] + s[1]), 1e-3, 1e-4) << "element " << e + 1;
  }
  for (int i = 1; i < kNx - 2; ++i) {  // bottom row away from the free face
    EXPECT_CLOSE(s0[1 + 6 * i + 1], -kRho * kG * (kNy - 0.5), 0.0, 0.03) << "element " << i + 1;
  }
  const Table steps = read_table(dir_ / "steps.csv", ',');
  ASSERT_GE(steps.size(), 5u);
  for (int k = 0; k < 5; ++k) EXPECT_LE(steps[k][2], 8.0) << "iterations of plastic step " << k + 1;
}

TEST_F(ColumnCollapse, CollapsesDissipatingEnergy) {
  ASSERT_EQ(status_, 0);
  const Table disp = read_table(dir_ / "disp.out");
  const Table vel = read_table(dir_ / "vel.out");
  const double pe0 = potential(disp[0]);
  for (std::size_t k = 1; k < disp.size(); ++k) {
    const double drop = pe0 - potential(disp[k]);
    EXPECT_LE(kinetic(vel[k]), drop + 0.02 * std::abs(drop) + 1e-6 * pe0) << "t = " << disp[k][0];
  }
  const auto& last = disp.back();
  const int top_right = (kNy + 1) * (kNx + 1) - 1;  // 0-based node index
  const int face_row1 = 2 * (kNx + 1) - 1;
  const double crest_uy = last[1 + 2 * top_right + 1];
  const double face_ux = last[1 + 2 * face_row1];
  const double pe_ratio = potential(last) / pe0;
  std::printf("t = 1 s: crest uy %.4f m, face ux (y = 1 m) %.4f m, PE/PE0 %.4f, KE/PE0 %.4f\n", crest_uy, face_ux,
              pe_ratio, kinetic(vel.back()) / pe0);
  EXPECT_LT(crest_uy, -0.4);
  EXPECT_GT(face_ux, 0.05);
  EXPECT_LT(pe_ratio, 0.99);
  EXPECT_GT(pe_ratio, 0.90);
}

TEST_F(ColumnCollapse, CutsStepsThatFailAndLandsOnTheRecordTimes) {
  ASSERT_EQ(status_, 0);
  const fs::path cut = dir_ / "cut";
  fs::create_directories(cut);
  ASSERT_EQ(run_collapse(cut, "-width 10 -height 8 -tend 1.0 -dt 0.05"), 0);
  const std::string text = test_support::fem_tcl_output(cut);
  EXPECT_NE(text.find("reached t = 1.0 s"), std::string::npos) << text;
  const Table steps = read_table(cut / "steps.csv", ',');
  int cut_steps = 0;
  for (const auto& s : steps) cut_steps += s[3] > 0.0 ? 1 : 0;
  EXPECT_GT(cut_steps, 0);
  EXPECT_EQ(steps.back()[0], 1.0);
  const Table coarse = read_table(cut / "disp.out");
  const Table fine = read_table(dir_ / "disp.out");
  ASSERT_EQ(coarse.size(), fine.size());
  for (std::size_t k = 0; k < coarse.size(); ++k) EXPECT_CLOSE(coarse[k][0], fine[k][0], 1e-9, 0.0);
  const int top_right = (kNy + 1) * (kNx + 1) - 1;
  EXPECT_CLOSE(coarse.back()[1 + 2 * top_right + 1], fine.back()[1 + 2 * top_right + 1], 0.0, 0.02);
}

TEST_F(ColumnCollapse, StopsCleanlyWhenTheMeshInverts) {
  const fs::path run = dir_ / "inverting";
  fs::create_directories(run);
  ASSERT_EQ(run_collapse(run, "-width 25 -height 20 -tend 3.0"), 0);
  const std::string text = test_support::fem_tcl_output(run);
  EXPECT_NE(text.find("column_collapse: the mesh inverted at t = "), std::string::npos) << text;
  EXPECT_NE(text.find("WARNING mesh quality: at t = "), std::string::npos) << text;
  const Table steps = read_table(run / "steps.csv", ',');
  ASSERT_FALSE(steps.empty());
  const double t_stop = steps.back()[0];
  EXPECT_GT(t_stop, 1.5);
  EXPECT_LT(t_stop, 3.0);
  const Table mq = read_table(run / "mesh_quality.out");
  ASSERT_EQ(mq.size(), steps.size() + 1);  // t = 0 and every step
  EXPECT_EQ(mq.back()[0], t_stop);
  EXPECT_LE(mq.back()[1], 0.0);
  for (std::size_t k = 0; k + 1 < mq.size(); ++k) ASSERT_GT(mq[k][1], 0.0) << "t = " << mq[k][0];
  const Table disp = read_table(run / "disp.out");
  const Table stress = read_table(run / "stress.out");
  const std::size_t rows = static_cast<std::size_t>(std::floor(t_stop / 0.05 + 1e-9)) + 1;
  EXPECT_EQ(disp.size(), rows);
  EXPECT_EQ(stress.size(), rows);
  EXPECT_EQ(disp.back().size(), 1u + 2u * 26u * 21u);
}

}  // namespace
