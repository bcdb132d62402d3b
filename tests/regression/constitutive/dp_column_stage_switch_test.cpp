// Regression: the DruckerPrager column of tests/data/reference_runs/opensees/dp_column_stage_switch run through
// build/bin/fem_tcl must reproduce OpenSees 3.8's recorder files and printed numbers.
//
// Golden numbers: ref/disp.out, ref/stress.out, ref/state.out and ref/stdout.txt, written by OpenSees 3.8.0
// (Release, Linux x86-64) from the same model.tcl (reference_runs/README.md, section 1.3; nothing edited).
// Tolerances (README section 1, "Suggested comparison"): for each recorder file,
//   |ref - out| <= 1e-5 * max(|ref|, |out|) + 1e-7 * S,  S = the largest |value| of the reference file outside
// the time column (the 1e-5 covers the 6-significant-digit rounding of the recorder text);
// stdout.txt numbers token by token with a relative tolerance of 1e-9 plus an absolute 1e-12.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

using Table = std::vector<std::vector<double>>;

Table read_table(const fs::path& file) {
  std::ifstream in(file);
  Table rows;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::vector<double> row;
    double v;
    while (ls >> v) row.push_back(v);
    if (!row.empty()) rows.push_back(row);
  }
  return rows;
}

std::vector<std::string> tokens(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> out;
  std::string t;
  while (in >> t) out.push_back(t);
  return out;
}

class DpColumnStageSwitch : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    case_dir_ = fs::path(GEOFLOW_TEST_DATA_DIR) / "reference_runs/opensees/dp_column_stage_switch";
    // One scratch folder per process: ctest runs each case as its own process, possibly in parallel.
    run_dir_ = fs::temp_directory_path() / ("geoflow_dp_column_stage_switch_" + std::to_string(::getpid()));
    fs::remove_all(run_dir_);
    fs::create_directories(run_dir_);
    fs::copy_file(case_dir_ / "model.tcl", run_dir_ / "model.tcl");
    const fs::path exe = fs::path(GEOFLOW_BIN_DIR) / "fem_tcl";
    const std::string cmd = "cd \"" + run_dir_.string() + "\" && \"" + exe.string() +
                            "\" model.tcl > stdout.txt 2> stderr.txt";
    status_ = std::system(cmd.c_str());
  }
  static void TearDownTestSuite() {
    // Kept for inspection when a case failed; removed otherwise.
    if (::testing::UnitTest::GetInstance()->failed_test_count() == 0) fs::remove_all(run_dir_);
  }
  static fs::path case_dir_, run_dir_;
  static int status_;

  void compare_recorder(const std::string& name) {
    ASSERT_EQ(status_, 0) << "fem_tcl failed; see " << (run_dir_ / "stderr.txt");
    const Table ref = read_table(case_dir_ / "ref" / name);
    const Table out = read_table(run_dir_ / name);
    ASSERT_EQ(ref.size(), 10u) << name << ": the reference has 10 rows (t = 0.001 ... 0.181)";
    ASSERT_EQ(out.size(), ref.size()) << name << ": number of rows";
    double s = 0.0;
    for (const auto& row : ref)
      for (std::size_t j = 1; j < row.size(); ++j) s = std::max(s, std::abs(row[j]));
    double worst = 0.0;
    for (std::size_t i = 0; i < ref.size(); ++i) {
      ASSERT_EQ(out[i].size(), ref[i].size()) << name << ": row " << i + 1;
      for (std::size_t j = 0; j < ref[i].size(); ++j) {
        const double a = out[i][j], e = ref[i][j];
        const double allowed = 1e-5 * std::max(std::abs(a), std::abs(e)) + 1e-7 * s;
        worst = std::max(worst, std::abs(a - e) / allowed);
        EXPECT_LE(std::abs(a - e), allowed) << name << " row " << i + 1 << " column " << j + 1 << ": " << a
                                            << " vs OpenSees " << e;
      }
    }
    std::printf("%s: largest |diff| / allowed = %.3g\n", name.c_str(), worst);
  }
};

fs::path DpColumnStageSwitch::case_dir_;
fs::path DpColumnStageSwitch::run_dir_;
int DpColumnStageSwitch::status_ = -1;

TEST_F(DpColumnStageSwitch, DisplacementsMatchOpenSees) { compare_recorder("disp.out"); }
TEST_F(DpColumnStageSwitch, StressesMatchOpenSees) { compare_recorder("stress.out"); }
TEST_F(DpColumnStageSwitch, DruckerPragerStateMatchesOpenSees) { compare_recorder("state.out"); }

TEST_F(DpColumnStageSwitch, PrintedNumbersMatchOpenSees) {
  ASSERT_EQ(status_, 0);
  const auto ref = tokens(case_dir_ / "ref/stdout.txt");
  const auto out = tokens(run_dir_ / "stdout.txt");
  ASSERT_GT(ref.size(), 20u);
  ASSERT_EQ(out.size(), ref.size());
  for (std::size_t i = 0; i < ref.size(); ++i) {
    char* end_r = nullptr;
    char* end_o = nullptr;
    const double r = std::strtod(ref[i].c_str(), &end_r);
    const double o = std::strtod(out[i].c_str(), &end_o);
    if (end_r != ref[i].c_str() && *end_r == '\0' && end_o != out[i].c_str() && *end_o == '\0') {
      EXPECT_LE(std::abs(r - o), 1e-12 + 1e-9 * std::max(std::abs(r), std::abs(o))) << "token " << i << ": " << out[i]
                                                                                   << " vs OpenSees " << ref[i];
    } else {
      EXPECT_EQ(out[i], ref[i]) << "token " << i;
    }
  }
}

}  // namespace
