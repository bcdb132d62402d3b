#pragma once
// What the unit tests of the PM4 models (tests/unit/fem/pm4sand_test.cpp, pm4silt_test.cpp) share: the strain paths
// of undrained cyclic simple shear, driving a material through one as scripts do (stage 0, then stage 1 and
// FirstCall), and the checks of the protocol and the responses both models take from pm4::Material
// (fem_tcl/materials/pm4_material.hpp: OpenSees' PM4Sand.cpp and PM4Silt.cpp, commit 2890cb36).
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <vector>

#include "fem_tcl/materials/nd_material.hpp"

namespace test_support {

/// Undrained simple shear: `consolidation` reached in 20 equal steps, then `cycles` cycles 0 -> +amplitude ->
/// -amplitude -> 0 of shear strain gxy at that exx, eyy, in steps of `step`.
inline std::vector<fem::materials::Vector3> undrained_cyclic_path(const fem::materials::Vector3& consolidation,
                                                                  double amplitude, int cycles, double step) {
  using fem::materials::Vector3;
  std::vector<Vector3> path;
  for (int i = 1; i <= 20; ++i) path.push_back(consolidation * (i / 20.0));
  double g = 0.0;
  for (int cycle = 0; cycle < cycles; ++cycle) {
    for (double target : {amplitude, -amplitude, 0.0}) {
      const int n = static_cast<int>(std::round(std::abs(target - g) / step));
      const double start = g;
      for (int i = 1; i <= n; ++i) path.push_back(consolidation + Vector3(0.0, 0.0, start + (target - start) * i / n));
      g = target;
    }
  }
  return path;
}

/// `m` committed at `strain` in stage 0, then stage 1 and FirstCall, as scripts do after consolidation.
template <class Material>
Material consolidated(Material m, const fem::materials::Vector3& strain) {
  m.set_trial_strain(strain);
  m.commit_state();
  m.update_stage(1);
  m.set_parameter("FirstCall", 0.0);
  return m;
}

/// Drives `m` through path[begin, end) (set_trial_strain, commit_state), entering the plastic stage before row
/// `plastic_from` (0-based) as scripts do (`updateMaterialStage` 1, then `FirstCall`). Returns the stress after
/// each commit.
inline std::vector<fem::materials::Vector3> drive(fem::materials::NDMaterial& m,
                                                  const std::vector<fem::materials::Vector3>& path, std::size_t begin,
                                                  std::size_t end, std::size_t plastic_from = 20) {
  std::vector<fem::materials::Vector3> out;
  for (std::size_t i = begin; i < end; ++i) {
    if (i == plastic_from) {
      EXPECT_TRUE(m.set_parameter("updateMaterialStage", 1.0));
      EXPECT_TRUE(m.set_parameter("FirstCall", 0.0));
    }
    m.set_trial_strain(path[i]);
    m.commit_state();
    out.push_back(m.stress());
  }
  return out;
}

/// `m`, committed at path[at - 1]: a clone carries the committed stress and state; a trial at path[at] followed
/// by revert_to_last_commit restores them, and the same trial then gives the same stress; the clone is
/// independent of the original and follows it along path[at, end).
inline void expect_clone_and_revert(fem::materials::NDMaterial& m, const std::vector<fem::materials::Vector3>& path,
                                    std::size_t at, std::size_t end) {
  using fem::materials::Vector3;
  const Vector3 committed = m.stress();
  const auto state = *m.response("state");
  const auto copy = m.clone();
  EXPECT_EQ(copy->stress(), committed);
  EXPECT_EQ(*copy->response("state"), state);
  // A trial, then revert: the committed stress and state are back, and the same trial gives the same stress.
  m.set_trial_strain(path[at]);
  const Vector3 trial = m.stress();
  EXPECT_NE(trial, committed);
  m.revert_to_last_commit();
  EXPECT_EQ(m.stress(), committed);
  EXPECT_EQ(*m.response("state"), state);
  m.set_trial_strain(path[at]);
  EXPECT_EQ(m.stress(), trial);
  // (A second trial without a revert would start from the moduli this one left, as OpenSees.)
  m.revert_to_last_commit();
  // The clone is independent: driving the original on leaves it where it was, and it follows the same path.
  drive(m, path, at, end);
  EXPECT_EQ(copy->stress(), committed);
  drive(*copy, path, at, end);
  EXPECT_EQ(copy->stress(), m.stress());
}

/// OpenSees' response lengths: stress(es) / strain(s) 3, state 16, alpha / backstressratio, fabric, alpha_in /
/// alphain, tracker(s) 3; stress3D 6; none for an unknown name.
inline void expect_pm4_response_lengths(const fem::materials::NDMaterial& m) {
  for (const char* name : {"stress", "stresses", "strain", "strains"}) EXPECT_EQ(m.response(name)->size(), 3u) << name;
  EXPECT_EQ(m.response("state")->size(), 16u);
  for (const char* name : {"alpha", "backstressratio", "fabric", "alpha_in", "alphain", "tracker", "trackers"})
    EXPECT_EQ(m.response(name)->size(), 3u) << name;
  EXPECT_EQ(m.response("stress3D")->size(), 6u);
  EXPECT_FALSE(m.response("nonsense").has_value());
}

}  // namespace test_support
