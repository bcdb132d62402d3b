// PressureDependMultiYield02 against the golden OpenSees 3.8.0 run tests/data/reference_runs/opensees/up_dss_pdmy02
// (tests/data/reference_runs/README.md, section 4: OpenSees built from commit 2890cb36): undrained cyclic direct
// simple shear of one SSPquadUP element whose top is locked vertically after consolidation, so that its single
// material point sees exactly the strain path of ref/strain.out (time, exx, eyy, gxy per committed step).
// The material is driven row by row (set_trial_strain, commit_state) with the script's stages: stage 0 for the
// 100 consolidation steps and the 25 undrained steps (`analyze 100`, `analyze 25`), `updateMaterialStage
// -material 1 -stage 1` before row 126 (the first row whose stress ratio, column 6 of ref/stress.out, is not 0),
// and compared with ref/stress.out (time, sxx syy szz sxy ratio: the element's `stress` response, which
// SSPquadUP forwards to the material): every column within 1 % of its peak |value| over the record.
#include <gtest/gtest.h>

#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "common/command_args.hpp"
#include "fem_tcl/materials/material_registry.hpp"
#include "support/recorder_compare.hpp"
#include "support/strain_path_replay.hpp"
#include "support/tolerance.hpp"

namespace {

const std::string kCase = std::string(GEOFLOW_TEST_DATA_DIR) + "/reference_runs/opensees/up_dss_pdmy02";

// The material line of model.tcl, with $e0 = 0.8 - 0.3 Dr = 0.68 (Dr = 0.4 from its lassign line).
const char* kMaterialLine =
    "nDMaterial PressureDependMultiYield02 1 2 1.8 6.0e4 1.6e5 31.0 0.1 101.0 0.5 26.0 0.067 0.23 0.06 0.27 20 "
    "5.0 3.0 1.0 0.0 $e0 0.9 0.02 0.7 101.0";

std::vector<std::string> material_words() {
  std::vector<std::string> words;
  std::istringstream in(kMaterialLine);
  std::string w;
  while (in >> w) words.push_back(w == "$e0" ? "0.68" : w);
  return {words.begin() + 2, words.end()};  // after "nDMaterial PressureDependMultiYield02"
}

TEST(PressureDependMultiYield02Golden, UndrainedCyclicSimpleShearMatchesOpenSees) {
  // The script still defines the material this test builds.
  std::ifstream script(kCase + "/model.tcl");
  ASSERT_TRUE(script.good()) << kCase << "/model.tcl";
  const std::string text((std::istreambuf_iterator<char>(script)), std::istreambuf_iterator<char>());
  ASSERT_NE(text.find(kMaterialLine), std::string::npos) << "model.tcl's material line changed";
  ASSERT_NE(text.find("set e0 [expr {0.8 - 0.3 * $Dr}]"), std::string::npos);
  ASSERT_NE(text.find("lassign {. pdmy02 0.4 "), std::string::npos);

  const auto strain = test_support::read_numeric_table(kCase + "/ref/strain.out");
  const auto stress = test_support::read_numeric_table(kCase + "/ref/stress.out");
  ASSERT_EQ(strain.size(), 22940u);
  ASSERT_NO_FATAL_FAILURE(test_support::check_golden_rows(strain, stress, 5));
  constexpr std::size_t kElasticRows = 125;  // analyze 100 (consolidation) + analyze 25 (undrained), stage 0
  ASSERT_EQ(stress[kElasticRows - 1][5], 0.0);
  ASSERT_NE(stress[kElasticRows][5], 0.0);

  common::CommandArgs args("nDMaterial PressureDependMultiYield02", "", material_words());
  auto material = fem::materials::find_nd_material_parser("PressureDependMultiYield02")(args)
                      ->copy_for(fem::materials::PlaneType::PlaneStrain);
  material->update_stage(0);  // updateMaterialStage -material 1 -stage 0
  const auto computed = test_support::replay_strain_path(
      *material, strain, [&](std::size_t row) {
        if (row == kElasticRows + 1) material->update_stage(1);
      },
      [](const fem::materials::NDMaterial& m) { return *m.response("stress"); });  // sxx syy szz sxy ratio
  ASSERT_EQ(computed.front().size(), 5u);
  const auto errors = test_support::column_errors(stress, computed);
  const char* names[] = {"sxx", "syy", "szz", "sxy", "ratio"};
  for (std::size_t j = 0; j < 5; ++j) {
    const auto& e = errors[j];
    std::cout << "up_dss_pdmy02 " << names[j] << ": peak |value| " << e.peak << ", largest error " << e.worst
              << " (" << 100.0 * e.worst / e.peak << " % of the peak) at row " << e.row << "\n";
    EXPECT_LE(e.worst, 0.01 * e.peak) << names[j] << " at row " << e.row;
  }
  // The record ends at 3 % shear strain with the stress ratio at the failure surface (summary.txt).
  EXPECT_CLOSE(stress.back()[5], 1.0, 1e-3, 0.0);
}

}  // namespace
