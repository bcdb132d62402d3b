// The checkerboard remedies of mpm/core/stress_remedy.hpp on hand-made strain increments: a uniform
// increment is kept, the cell mean is kept, and the within-cell modes are removed or scaled as each
// remedy promises.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "common/input_error.hpp"
#include "mpm/core/stress_remedy.hpp"
#include "support/tolerance.hpp"

namespace {

using mpm::core::StressSmoothing;

/// A cell of 4 x 4 particles with unequal volumes (as after some deformation).
struct Cell {
  std::vector<double> de;  // 3 per particle: dexx, deyy, dgxy
  std::vector<double> volume;
  std::size_t n() const { return volume.size(); }
  auto volume_of() const {
    return [this](std::size_t i) { return volume[i]; };
  }
};

/// de(x, y) = a + b x + c y per component at the 4 x 4 sub-cell centres of the unit cell, plus
/// `alt` times the alternating (checkerboard) sign (-1)^(i + j).
Cell make_cell(const std::array<double, 3>& a, const std::array<double, 3>& b, const std::array<double, 3>& c,
               const std::array<double, 3>& alt) {
  Cell cell;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const double x = (i + 0.5) / 4, y = (j + 0.5) / 4, s = (i + j) % 2 == 0 ? 1.0 : -1.0;
      for (int f = 0; f < 3; ++f) cell.de.push_back(a[f] + b[f] * x + c[f] * y + alt[f] * s);
      cell.volume.push_back(1.0 + 0.1 * ((3 * i + 5 * j) % 4));
    }
  return cell;
}

std::array<double, 3> weighted_mean(const Cell& cell) {
  double m[3];
  mpm::core::cell_mean_strain(cell.de.data(), cell.n(), cell.volume_of(), m);
  return {m[0], m[1], m[2]};
}

constexpr std::array<double, 3> kUniform = {1.5e-4, -2.5e-4, 3.0e-4};
constexpr std::array<double, 3> kZero = {0, 0, 0};

TEST(StressRemedy, CellRemediesKeepAUniformIncrement) {
  for (auto s : {StressSmoothing::CellVolumetric, StressSmoothing::CellStrain}) {
    Cell cell = make_cell(kUniform, kZero, kZero, kZero);
    mpm::core::apply_cell_remedy(s, cell.de.data(), cell.n(), cell.volume_of());
    for (std::size_t i = 0; i < cell.n(); ++i)
      for (int f = 0; f < 3; ++f) EXPECT_CLOSE(cell.de[3 * i + f], kUniform[f], 1e-19, 1e-14);
  }
}

TEST(StressRemedy, CellRemediesKeepTheCellMean) {
  const std::array<double, 3> b = {2e-4, 1e-4, -3e-4}, c = {-1e-4, 4e-4, 2e-4}, alt = {5e-5, -7e-5, 6e-5};
  for (auto s : {StressSmoothing::CellVolumetric, StressSmoothing::CellStrain}) {
    Cell cell = make_cell(kUniform, b, c, alt);
    const auto before = weighted_mean(cell);
    mpm::core::apply_cell_remedy(s, cell.de.data(), cell.n(), cell.volume_of());
    const auto after = weighted_mean(cell);
    // The volume-weighted mean of every component stays (so does the cell's work on the mean stress).
    for (int f = 0; f < 3; ++f) EXPECT_CLOSE(after[f], before[f], 1e-19, 1e-12);
  }
}

TEST(StressRemedy, CellVolumetricMakesTheDilatationUniformAndKeepsTheDeviator) {
  const std::array<double, 3> b = {2e-4, 1e-4, -3e-4}, alt = {5e-5, -7e-5, 6e-5};
  Cell cell = make_cell(kUniform, b, kZero, alt);
  const Cell original = cell;
  const auto mean = weighted_mean(cell);
  mpm::core::apply_cell_remedy(StressSmoothing::CellVolumetric, cell.de.data(), cell.n(), cell.volume_of());
  for (std::size_t i = 0; i < cell.n(); ++i) {
    const double* e = &cell.de[3 * i];
    const double* o = &original.de[3 * i];
    EXPECT_CLOSE(e[0] + e[1], mean[0] + mean[1], 1e-19, 1e-12);
    EXPECT_CLOSE(e[0] - e[1], o[0] - o[1], 1e-19, 1e-12);
    EXPECT_EQ(e[2], o[2]);
  }
}

TEST(StressRemedy, CellStrainRemovesTheAlternatingModeDownToItsStabilizingShare) {
  // Mean zero, every particle's increment +-alt: cell_strain keeps the share kCellStrainStabilization of
  // its deviatoric part and none of its volumetric part.
  const std::array<double, 3> alt = {5e-5, -7e-5, 6e-5};
  Cell cell = make_cell(kZero, kZero, kZero, alt);
  const Cell original = cell;
  const auto mean = weighted_mean(cell);
  mpm::core::apply_cell_remedy(StressSmoothing::CellStrain, cell.de.data(), cell.n(), cell.volume_of());
  const double keep = mpm::core::kCellStrainStabilization;
  ASSERT_GT(keep, 0.0);
  ASSERT_LT(keep, 0.5);
  for (std::size_t i = 0; i < cell.n(); ++i) {
    const double* e = &cell.de[3 * i];
    const double* o = &original.de[3 * i];
    const double dxx = o[0] - mean[0], dyy = o[1] - mean[1];
    EXPECT_CLOSE(e[0] + e[1], mean[0] + mean[1], 1e-19, 1e-12);                  // dilatation: the mean's
    EXPECT_CLOSE(e[0] - e[1], mean[0] - mean[1] + keep * (dxx - dyy), 1e-19, 1e-12);  // normal deviator
    EXPECT_CLOSE(e[2], mean[2] + keep * (o[2] - mean[2]), 1e-19, 1e-12);              // shear
  }
}

TEST(StressRemedy, NodalVolumetricReplacesOnlyTheDilatation) {
  const double de0[3] = {3e-4, -1e-4, 2e-4};
  double values[3] = {0, 0, 0};
  mpm::core::nodal_values(StressSmoothing::NodalVolumetric, de0, values);
  EXPECT_EQ(values[0], de0[0] + de0[1]);
  double de[3] = {de0[0], de0[1], de0[2]};
  const double smoothed[3] = {5e-4, 0, 0};
  mpm::core::apply_nodal_values(StressSmoothing::NodalVolumetric, smoothed, de);
  EXPECT_CLOSE(de[0] + de[1], 5e-4, 1e-19, 1e-13);
  EXPECT_CLOSE(de[0] - de[1], de0[0] - de0[1], 1e-19, 1e-13);
  EXPECT_EQ(de[2], de0[2]);
  EXPECT_EQ(mpm::core::nodal_projection(StressSmoothing::NodalVolumetric).values, 1);
  EXPECT_TRUE(mpm::core::nodal_projection(StressSmoothing::NodalVolumetric).volume_weighted);
}

TEST(StressRemedy, NodalStrainMapsAllThreeComponentsByMass) {
  const double de0[3] = {3e-4, -1e-4, 2e-4};
  double values[3] = {0, 0, 0};
  mpm::core::nodal_values(StressSmoothing::NodalStrain, de0, values);
  for (int f = 0; f < 3; ++f) EXPECT_EQ(values[f], de0[f]);
  double de[3] = {0, 0, 0};
  mpm::core::apply_nodal_values(StressSmoothing::NodalStrain, values, de);
  for (int f = 0; f < 3; ++f) EXPECT_EQ(de[f], de0[f]);
  EXPECT_EQ(mpm::core::nodal_projection(StressSmoothing::NodalStrain).values, 3);
  EXPECT_FALSE(mpm::core::nodal_projection(StressSmoothing::NodalStrain).volume_weighted);
  EXPECT_EQ(mpm::core::nodal_projection(StressSmoothing::CellStrain).values, 0);
}

TEST(StressRemedy, NamesAndBadNames) {
  using mpm::core::parse_stress_smoothing;
  EXPECT_EQ(parse_stress_smoothing("none"), StressSmoothing::None);
  EXPECT_EQ(parse_stress_smoothing("cell_volumetric"), StressSmoothing::CellVolumetric);
  EXPECT_EQ(parse_stress_smoothing("cell_strain"), StressSmoothing::CellStrain);
  EXPECT_EQ(parse_stress_smoothing("nodal_strain"), StressSmoothing::NodalStrain);
  EXPECT_EQ(parse_stress_smoothing("nodal_volumetric"), StressSmoothing::NodalVolumetric);
  EXPECT_TRUE(mpm::core::is_cell_remedy(StressSmoothing::CellStrain));
  EXPECT_FALSE(mpm::core::is_cell_remedy(StressSmoothing::NodalVolumetric));
  try {
    parse_stress_smoothing("bilateral");
    FAIL() << "no error for an unknown remedy";
  } catch (const common::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("analysis.stress_smoothing"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("cell_strain"), std::string::npos) << e.what();
  }
}

}  // namespace
