// Regression: the OpenSees reference runs of tests/data/reference_runs/opensees (golden files written by
// OpenSees 3.8.0, Release, Linux x86-64; README.md section 1 "How they were run") are re-run with fem_tcl
// on a scratch copy of each case folder and compared:
//   *.out        same rows and columns; |ref - out| <= 1e-5 max(|ref|,|out|) + 1e-7 S (S = file's max |value|
//                outside the time column) -- README section 1 "Suggested comparison"
//   stdout.txt   token by token, numbers within 1e-9 relative + 1e-12 absolute
//   model.json   same structure and keys, numbers within 1e-12 relative + 1e-15 absolute
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/recorder_compare.hpp"

namespace {

namespace fs = std::filesystem;

struct RecorderFile {
  const char* name;
  bool time_column;
};

fs::path case_dir(const std::string& name) { return fs::path(GEOFLOW_TEST_DATA_DIR) / "reference_runs/opensees" / name; }

/// Copies the case (without ref/) to a scratch folder and runs it; returns the scratch folder.
void run_case(const std::string& name, const test_support::ScratchDir& scratch) {
  for (const auto& entry : fs::directory_iterator(case_dir(name))) {
    if (entry.path().filename() != "ref") fs::copy(entry.path(), scratch.path() / entry.path().filename());
  }
  const int status = test_support::run_fem_tcl(GEOFLOW_BIN_DIR, scratch.path(), "model.tcl");
  const std::string err = test_support::read_text(scratch.path() / "stderr.txt");
  ASSERT_EQ(status, 0) << err;
  EXPECT_EQ(err.find("WARNING"), std::string::npos) << err;  // the reference runs printed no warnings
}

void expect_recorders(const std::string& name, const fs::path& out, const std::vector<RecorderFile>& files) {
  for (const auto& f : files) {
    EXPECT_TRUE(test_support::compare_recorder_files(case_dir(name) / "ref" / f.name, out / f.name, f.time_column))
        << name << "/" << f.name;
  }
  EXPECT_TRUE(test_support::compare_tokens(test_support::read_text(case_dir(name) / "ref/stdout.txt"),
                                           test_support::read_text(out / "stdout.txt")))
      << name << "/stdout.txt";
}

::testing::AssertionResult same_json(const nlohmann::json& a, const nlohmann::json& b, const std::string& path) {
  if (a.is_number() && b.is_number()) {
    const double x = a.get<double>(), y = b.get<double>();
    if (std::abs(x - y) <= 1e-12 * std::max(std::abs(x), std::abs(y)) + 1e-15) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << path << ": " << y << " vs reference " << x;
  }
  if (a.type() != b.type()) return ::testing::AssertionFailure() << path << ": type differs";
  if (a.is_object()) {
    if (a.size() != b.size()) return ::testing::AssertionFailure() << path << ": key count differs";
    for (auto it = a.begin(); it != a.end(); ++it) {
      if (!b.contains(it.key())) return ::testing::AssertionFailure() << path << ": missing key " << it.key();
      auto r = same_json(it.value(), b[it.key()], path + "/" + it.key());
      if (!r) return r;
    }
    return ::testing::AssertionSuccess();
  }
  if (a.is_array()) {
    if (a.size() != b.size()) return ::testing::AssertionFailure() << path << ": array length differs";
    for (std::size_t i = 0; i < a.size(); ++i) {
      auto r = same_json(a[i], b[i], path + "/" + std::to_string(i));
      if (!r) return r;
    }
    return ::testing::AssertionSuccess();
  }
  if (a == b) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << path << ": value differs";
}

TEST(OpenSeesReferenceRuns, SSPquadBlockSurfaceLoad) {
  const std::string name = "sspquad_block_surface_load";
  test_support::ScratchDir scratch("fem_reg_" + name);
  run_case(name, scratch);
  expect_recorders(name, scratch.path(), {{"disp.out", true}, {"stress.out", true}, {"strain.out", true}});
  std::ifstream ref_in(case_dir(name) / "ref/model.json"), out_in(scratch.path() / "model.json");
  ASSERT_TRUE(out_in.good());
  const auto ref = nlohmann::json::parse(ref_in);
  auto out = nlohmann::json::parse(out_in);  // throws (fails the test) if not valid JSON
  // fem_tcl's one addition (fem_tcl/README.md): the supports, which OpenSees 3.8's JSON does not carry.
  ASSERT_TRUE(out["StructuralAnalysisModel"].contains("constraints"));
  EXPECT_FALSE(out["StructuralAnalysisModel"]["constraints"]["fix"].empty());
  out["StructuralAnalysisModel"].erase("constraints");
  EXPECT_TRUE(same_json(ref, out, ""));
}

TEST(OpenSeesReferenceRuns, QuadGravityThenDynamic) {
  const std::string name = "quad_gravity_then_dynamic";
  test_support::ScratchDir scratch("fem_reg_" + name);
  run_case(name, scratch);
  expect_recorders(name, scratch.path(),
                   {{"base_reaction.out", true}, {"ele_stresses.out", true}, {"crest_disp.out", true},
                    {"crest_vel.out", true}, {"crest_accel.out", true}});
}

TEST(OpenSeesReferenceRuns, RecorderFormats) {
  const std::string name = "recorder_formats";
  test_support::ScratchDir scratch("fem_reg_" + name);
  run_case(name, scratch);
  expect_recorders(name, scratch.path(),
                   {{"disp_all_p12.out", true}, {"disp_n6_plain.out", false}, {"uy_tip_dT.out", true},
                    {"forces_dT.out", true}, {"reaction_cow.out", true}, {"incr_disp.out", false},
                    {"vx_tip.out", true}, {"stresses_range.out", true}, {"strains_e2.out", true},
                    {"gp3_stress_e1.out", false}});
  // -precision 12 really gives 12 significant digits (README 1.4)
  const std::string text = test_support::read_text(scratch.path() / "disp_all_p12.out");
  EXPECT_NE(text.find("-0.000119242283962"), std::string::npos);
}

TEST(OpenSeesReferenceRuns, DruckerPragerColumnStageSwitch) {
  const std::string name = "dp_column_stage_switch";
  // Every recorder uses -time -dT 0.02: 10 rows at t = 0.001, 0.021, ..., 0.181 (reference_runs/README.md 1.3).
  ASSERT_EQ(test_support::read_numeric_table(case_dir(name) / "ref/disp.out").size(), 10u);
  test_support::ScratchDir scratch("fem_reg_" + name);
  run_case(name, scratch);
  expect_recorders(name, scratch.path(), {{"disp.out", true}, {"stress.out", true}, {"state.out", true}});
}

}  // namespace

namespace {

/// The elastoplastic stage of dp_column_stage_switch (first 60 steps) with another algorithm: every
/// algorithm converges to the same displacements as KrylovNewton (the reference run's) within the
/// test tolerance (NormDispIncr 1e-11, so 1e-7 relative on a 5 mm displacement is generous).
std::string top_right_displacement(const std::string& algorithm, const test_support::ScratchDir& scratch) {
  std::string script = test_support::read_text(case_dir("dp_column_stage_switch") / "model.tcl");
  const auto replace = [&](const std::string& from, const std::string& to) {
    const auto at = script.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) script.replace(at, from.size(), to);
  };
  replace("algorithm KrylovNewton", "algorithm " + algorithm);
  replace("analyze 200 0.001", "analyze 60 0.001");
  { std::ofstream(scratch.path() / "model.tcl") << script; }
  const int status = test_support::run_fem_tcl(GEOFLOW_BIN_DIR, scratch.path(), "model.tcl");
  EXPECT_EQ(status, 0) << test_support::read_text(scratch.path() / "stderr.txt");
  const std::string out = test_support::read_text(scratch.path() / "stdout.txt");
  const auto at = out.find("top-right node displacement ", out.find("elastoplastic stage"));
  return at == std::string::npos ? std::string() : out.substr(at, out.find('\n', at) - at);
}

TEST(OpenSeesReferenceRuns, AlgorithmsConvergeToTheSameElastoplasticState) {
  test_support::ScratchDir scratch("fem_reg_algorithms");
  const std::string reference = top_right_displacement("KrylovNewton", scratch);
  ASSERT_FALSE(reference.empty());
  for (const char* algorithm : {"Newton", "NewtonLineSearch", "ModifiedNewton", "KrylovNewton -maxDim 6"}) {
    EXPECT_TRUE(test_support::compare_tokens(reference, top_right_displacement(algorithm, scratch), 1e-7, 1e-12))
        << algorithm;
  }
}

}  // namespace

namespace {

// The README's main job (scripts/column_collapse/elastic_column.tcl) runs and reports the base stress of
// the 50 m x 40 m column within 3 % of -rho g (H - y_c); the free right face makes the column not exactly
// laterally confined, so the difference is physical (about 1.8 %), not round-off.
TEST(MainJob, ElasticColumnPrintsBaseStressNearTheAnalyticalValue) {
  test_support::ScratchDir scratch("fem_main_job");
  const fs::path script = fs::path(GEOFLOW_SOURCE_DIR) / "scripts/column_collapse/elastic_column.tcl";
  ASSERT_EQ(test_support::run_fem_tcl(GEOFLOW_BIN_DIR, scratch.path(), "'" + script.string() + "'"), 0)
      << test_support::read_text(scratch.path() / "stderr.txt");
  const std::string out = test_support::read_text(scratch.path() / "stdout.txt");
  const auto at = out.find("error ");
  ASSERT_NE(at, std::string::npos) << out;
  const double error_percent = std::strtod(out.c_str() + at + 6, nullptr);
  EXPECT_LT(std::abs(error_percent), 3.0) << out;
  EXPECT_NE(out.find("analytical -rho g (H - y) = -745.928 kPa"), std::string::npos) << out;
}

}  // namespace
