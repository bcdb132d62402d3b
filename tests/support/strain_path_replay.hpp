#pragma once
// One material point driven through the strain path of a golden OpenSees run, row by row, as the regression tests
// of the u-p direct simple shear runs do (tests/data/reference_runs/opensees/up_dss_*, README section 4: one
// SSPquadUP whose top is locked vertically after consolidation, so that its single material point sees exactly the
// strain path of ref/strain.out, time exx eyy gxy per committed step): the script's commands before their rows,
// set_trial_strain and commit_state per row, a response recorded after each commit; then each column's largest
// error against the recorded rows (ref/stress.out: time, then the values) and its peak |value|. The tests keep their
// own stages, tolerances and citations.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <vector>

#include "fem_tcl/materials/nd_material.hpp"

namespace test_support {

/// Rows of numbers, as read_numeric_table (recorder_compare.hpp) gives a recorder file.
using Rows = std::vector<std::vector<double>>;

/// A golden run's strain rows (time exx eyy gxy) against its recorded rows (time and `columns` values): as many
/// rows, the same times. Fatal failures; call with ASSERT_NO_FATAL_FAILURE.
inline void check_golden_rows(const Rows& strain, const Rows& recorded, std::size_t columns) {
  ASSERT_EQ(recorded.size(), strain.size());
  for (std::size_t i = 0; i < strain.size(); ++i) {
    ASSERT_EQ(strain[i].size(), 4u) << "strain row " << i + 1;
    ASSERT_EQ(recorded[i].size(), columns + 1) << "recorded row " << i + 1;
    ASSERT_EQ(strain[i][0], recorded[i][0]) << "row " << i + 1;
  }
}

/// The material's stress (sxx syy sxy) after a commit.
inline std::vector<double> stress_of(const fem::materials::NDMaterial& material) {
  const auto& s = material.stress();
  return {s[0], s[1], s[2]};
}

/// Drives `material` through `strain` (time exx eyy gxy) row by row: `before_row(row)` (1-based: the script's
/// commands before that row), set_trial_strain(exx, eyy, gxy), commit_state, `record(material)`. Returns the
/// recorded rows.
inline Rows replay_strain_path(fem::materials::NDMaterial& material, const Rows& strain,
                               const std::function<void(std::size_t row)>& before_row,
                               const std::function<std::vector<double>(const fem::materials::NDMaterial&)>& record =
                                   stress_of) {
  Rows recorded;
  recorded.reserve(strain.size());
  for (std::size_t i = 0; i < strain.size(); ++i) {
    before_row(i + 1);
    material.set_trial_strain(fem::materials::Vector3(strain[i][1], strain[i][2], strain[i][3]));
    material.commit_state();
    recorded.push_back(record(material));
  }
  return recorded;
}

struct ColumnError {
  double peak = 0.0;    ///< largest |reference value| of the column over the whole record
  double worst = 0.0;   ///< largest |fem - reference| over the rows compared
  std::size_t row = 0;  ///< where (1-based)
};

/// Column j of `fem` against column j + 1 of `ref` (after its time column): each column's peak |ref| over all rows,
/// its largest |fem - ref| over the rows [first, last) (0-based).
inline std::vector<ColumnError> column_errors(const Rows& ref, const Rows& fem, std::size_t first = 0,
                                              std::size_t last = std::numeric_limits<std::size_t>::max()) {
  const std::size_t columns = fem.empty() ? 0 : fem.front().size();
  std::vector<ColumnError> e(columns);
  for (std::size_t i = 0; i < ref.size(); ++i) {
    for (std::size_t j = 0; j < columns; ++j) {
      e[j].peak = std::max(e[j].peak, std::abs(ref[i][j + 1]));
      const double d = std::abs(fem[i][j] - ref[i][j + 1]);
      if (i >= first && i < last && d > e[j].worst) {
        e[j].worst = d;
        e[j].row = i + 1;
      }
    }
  }
  return e;
}

}  // namespace test_support
