// Unit tests of bridge::exclude_materials (fem2mpm --exclude-material): a column of three unit quads, a
// foundation (material "1", two 4-point elements) under a soil (material "2", one 1-point element): the
// foundation's elements and every per-Gauss-point field of theirs go, the soil keeps its own values in
// order, its material becomes index 0 with id 0, and the report's mass and top are the foundation's
// (rho x area, the highest node); an unknown material and leaving nothing out are one error each.
#include <gtest/gtest.h>

#include "bridge/material_exclusion.hpp"
#include "common/input_error.hpp"
#include "support/tolerance.hpp"

namespace {

bridge::TransferState foundation_and_soil() {
  bridge::TransferState st;
  for (int j = 0; j <= 3; ++j)
    for (int i = 0; i <= 1; ++i) st.reference.push_back(bridge::Vec2(i, j));
  st.displacement.assign(st.reference.size(), bridge::Vec2::Zero());
  st.displacement[7] = bridge::Vec2(0.0, 0.01);  // the soil's top right node, a little up
  st.velocity.assign(st.reference.size(), bridge::Vec2::Zero());
  bridge::MpmMaterial foundation, soil;
  foundation.fem_name = "1";
  foundation.id = 0;
  soil.fem_name = "2";
  soil.id = 1;
  st.materials = {foundation, soil};
  for (int e = 0; e < 3; ++e) {
    bridge::TransferElement el;
    el.tag = 10 + e;
    el.nodes = {2 * e, 2 * e + 1, 2 * e + 3, 2 * e + 2};
    el.material = e < 2 ? 0u : 1u;
    el.gauss_points = e < 2 ? 4 : 1;
    el.density = e < 2 ? 2000.0 : 1800.0;
    st.elements.push_back(el);
  }
  st.index_gauss_points();  // 4 + 4 + 1 Gauss points
  for (std::size_t g = 0; g < st.gauss_offset.back(); ++g) {
    st.gauss_stress.push_back(bridge::Stress6{-double(g), 0, 0, 0, 0, 0});
    st.reference_gauss_stress.push_back(bridge::Stress6{0, -double(g), 0, 0, 0, 0});
    st.gauss_shear_strain.push_back(0.1 * double(g));
  }
  return st;
}

TEST(MaterialExclusion, TheFoundationGoesWithItsGaussPointsAndTheSoilIsRenumbered) {
  bridge::TransferState st = foundation_and_soil();
  const bridge::ExcludedMaterials out = bridge::exclude_materials(st, {"1"}, "--exclude-material");
  EXPECT_EQ(out.elements, 2u);
  EXPECT_CLOSE(out.mass, 2 * 2000.0, 1e-9, 0.0);
  EXPECT_CLOSE(out.top, 2.0, 1e-15, 0.0);
  ASSERT_EQ(st.elements.size(), 1u);
  EXPECT_EQ(st.elements[0].tag, 12);
  EXPECT_EQ(st.elements[0].material, 0u);
  ASSERT_EQ(st.materials.size(), 1u);
  EXPECT_EQ(st.materials[0].fem_name, "2");
  EXPECT_EQ(st.materials[0].id, 0u);
  ASSERT_EQ(st.gauss_offset.size(), 2u);
  EXPECT_EQ(st.gauss_offset[1], 1u);
  ASSERT_EQ(st.gauss_stress.size(), 1u);
  EXPECT_EQ(st.gauss_stress[0][0], -8.0);  // the soil's Gauss point was the ninth
  ASSERT_EQ(st.reference_gauss_stress.size(), 1u);
  EXPECT_EQ(st.reference_gauss_stress[0][1], -8.0);
  ASSERT_EQ(st.gauss_shear_strain.size(), 1u);
  EXPECT_CLOSE(st.gauss_shear_strain[0], 0.8, 1e-15, 0.0);
  EXPECT_EQ(st.reference.size(), 8u);  // the nodes stay (boundaries and extent are the model's)
}

TEST(MaterialExclusion, AnUnknownMaterialOrNothingLeftIsAnError) {
  bridge::TransferState st = foundation_and_soil();
  std::string message;
  try {
    bridge::exclude_materials(st, {"3"}, "--exclude-material");
  } catch (const common::InputError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("--exclude-material"), std::string::npos) << message;
  EXPECT_NE(message.find("they use: 1, 2"), std::string::npos) << message;
  EXPECT_EQ(st.elements.size(), 3u);  // untouched
  EXPECT_THROW(bridge::exclude_materials(st, {"1", "2"}, "--exclude-material"), common::InputError);
  EXPECT_EQ(st.elements.size(), 3u);
}

}  // namespace
