// Unit tests of the state assembly on OpenSees 3.8 files (reference_runs case 1.1: 35 nodes, 24
// SSPquads, ElasticIsotropic E = 50e3 kPa, nu = 0.3, rho = 1.8 Mg/m3; kN-m-kPa units).
#include <gtest/gtest.h>

#include <fstream>

#include "bridge/fem_state_reader.hpp"
#include "bridge/recorder_file.hpp"
#include "common/input_error.hpp"
#include "support/input_error_message.hpp"
#include "support/tolerance.hpp"

namespace {

const std::filesystem::path kCase =
    std::filesystem::path(GEOFLOW_TEST_DATA_DIR) / "reference_runs/opensees/sspquad_block_surface_load/ref";

bridge::ReadOptions reference_options() {
  bridge::ReadOptions o;
  o.disp = kCase / "disp.out";
  o.stress = kCase / "stress.out";
  o.units = bridge::Units::kN;
  return o;
}

using test_support::input_error_message;

TEST(FemStateReader, AssemblesReferenceRunInSI) {
  const auto model = bridge::read_fem_model(kCase / "model.json");
  auto o = reference_options();
  o.time = 0.6;
  const auto a = bridge::read_fem_state(model, o);
  const auto& st = a.state;
  EXPECT_CLOSE(st.time, 0.6, 0, 1e-15);
  ASSERT_EQ(st.reference.size(), 35u);
  ASSERT_EQ(st.elements.size(), 24u);
  EXPECT_EQ(a.stress_components, 3);
  // disp.out row 3 (t = 0.6) read independently: node 32 (index 31) = values 62, 63.
  const bridge::RecorderFile disp(kCase / "disp.out");
  const auto u = disp.values(2);
  EXPECT_CLOSE(st.displacement[31].x(), u[62], 0, 0);
  EXPECT_CLOSE(st.displacement[31].y(), u[63], 0, 0);
  // Stress of element 1 at t = 0.6: kPa -> Pa, szz = nu (sxx + syy) (plane strain).
  const bridge::RecorderFile stress(kCase / "stress.out");
  const auto s = stress.values(2);
  EXPECT_CLOSE(st.gauss_stress[0][0], 1000 * s[0], 0, 1e-15);
  EXPECT_CLOSE(st.gauss_stress[0][1], 1000 * s[1], 0, 1e-15);
  EXPECT_CLOSE(st.gauss_stress[0][3], 1000 * s[2], 0, 1e-15);
  EXPECT_CLOSE(st.gauss_stress[0][2], 0.3 * 1000 * (s[0] + s[1]), 1e-9, 1e-14);
  ASSERT_EQ(st.materials.size(), 1u);
  EXPECT_CLOSE(st.materials[0].density, 1800, 0, 1e-15);
  EXPECT_CLOSE(st.materials[0].youngs_modulus, 50e6, 0, 1e-15);
  EXPECT_CLOSE(st.elements[0].density, 1800, 0, 1e-15);
  EXPECT_TRUE(a.warnings.empty());
  EXPECT_EQ(st.velocity[31], bridge::Vec2::Zero());  // no --vel: at rest, with a note
  bool noted = false;
  for (const auto& n : a.notes) noted = noted || n.find("zero velocity") != std::string::npos;
  EXPECT_TRUE(noted);
}

TEST(FemStateReader, WarnsWhenDensityLooksLikeMgPerM3InSI) {
  const auto model = bridge::read_fem_model(kCase / "model.json");
  auto o = reference_options();
  o.units = bridge::Units::SI;
  const auto a = bridge::read_fem_state(model, o);
  ASSERT_EQ(a.warnings.size(), 1u);
  EXPECT_NE(a.warnings[0].find("--units kN"), std::string::npos) << a.warnings[0];
}

TEST(FemStateReader, RowWidthDisagreeingWithLayoutNamesFileAndLine) {
  const auto model = bridge::read_fem_model(kCase / "model.json");
  auto o = reference_options();
  o.nodes = bridge::parse_tag_list("1-34", "--nodes");
  std::string msg = input_error_message([&] { bridge::read_fem_state(model, o); });
  EXPECT_NE(msg.find("disp.out:5"), std::string::npos) << msg;
  EXPECT_NE(msg.find("35 nodes x 2 dofs"), std::string::npos) << msg;
  EXPECT_NE(msg.find("34 nodes"), std::string::npos) << msg;
  o = reference_options();
  o.elements = bridge::parse_tag_list("1-23", "--elements");
  msg = input_error_message([&] { bridge::read_fem_state(model, o); });
  EXPECT_NE(msg.find("stress.out:5"), std::string::npos) << msg;
  EXPECT_NE(msg.find("23 elements"), std::string::npos) << msg;
}

TEST(FemStateReader, MaterialOverridesAndMohrCoulomb) {
  const auto model = bridge::read_fem_model(kCase / "model.json");
  auto o = reference_options();
  o.material.type = "mohr-coulomb";
  o.material.phi_deg = 30;
  o.material.cohesion = 5;  // kPa
  const auto a = bridge::read_fem_state(model, o);
  const auto& m = a.state.materials.at(0);
  EXPECT_EQ(m.type, bridge::MpmMaterial::Type::MohrCoulomb2D);
  EXPECT_CLOSE(m.cohesion, 5000, 0, 1e-15);
  EXPECT_CLOSE(m.friction, 30 * M_PI / 180, 0, 1e-15);
  EXPECT_CLOSE(m.tension_cutoff, 5000 / std::tan(30 * M_PI / 180), 0, 1e-12);  // apex
  o.material.cohesion.reset();
  const std::string msg = input_error_message([&] { bridge::read_fem_state(model, o); });
  EXPECT_NE(msg.find("--cohesion"), std::string::npos) << msg;
}

TEST(FemStateReader, TagListSyntax) {
  EXPECT_EQ(bridge::parse_tag_list("1-3,7 9", "--nodes"), (std::vector<long>{1, 2, 3, 7, 9}));
  EXPECT_THROW(bridge::parse_tag_list("1-x", "--nodes"), common::InputError);
  EXPECT_THROW(bridge::parse_tag_list("5-2", "--nodes"), common::InputError);
}

}  // namespace

namespace {

// Four-Gauss-point quads (reference_runs case 1.4, recorder_formats: two `quad` elements, OpenSees 3.8
// `stresses` = 4 Gauss points x (sxx syy sxy) per element; displacements at -precision 12). The model
// description is written here from model.tcl (that case has no print -JSON).
TEST(FemStateReader, ReadsQuadFourGaussPointStresses) {
  const std::filesystem::path dir =
      std::filesystem::path(GEOFLOW_TEST_DATA_DIR) / "reference_runs/opensees/recorder_formats/ref";
  const std::string json = R"({"StructuralAnalysisModel": {
    "properties": {"ndMaterials": [{"name": "7", "type": "ElasticIsotropicMaterial", "E": 2.5e7, "nu": 0.2, "rho": 2.4}]},
    "geometry": {
      "nodes": [{"name": 1, "crd": [0, 0]}, {"name": 2, "crd": [1, 0]}, {"name": 3, "crd": [2, 0]},
                {"name": 4, "crd": [0, 1]}, {"name": 5, "crd": [1, 1]}, {"name": 6, "crd": [2, 1]}],
      "elements": [
        {"name": 1, "type": "FourNodeQuad", "nodes": [1, 2, 5, 4], "thickness": 0.2, "surfacePressure": 0, "masspervolume": 0, "bodyForces": [0, 0], "material": "7"},
        {"name": 2, "type": "FourNodeQuad", "nodes": [2, 3, 6, 5], "thickness": 0.2, "surfacePressure": 0, "masspervolume": 0, "bodyForces": [0, 0], "material": "7"}]}}})";
  const auto model = bridge::parse_fem_model(json, "quads.json");
  bridge::ReadOptions o;
  o.disp = dir / "disp_all_p12.out";
  o.stress = dir / "stresses_range.out";
  o.units = bridge::Units::kN;
  o.time = 0.5;
  const auto a = bridge::read_fem_state(model, o);
  ASSERT_EQ(a.state.elements.size(), 2u);
  EXPECT_EQ(a.state.elements[1].gauss_points, 4);
  ASSERT_EQ(a.state.gauss_stress.size(), 8u);
  EXPECT_EQ(a.stress_components, 3);
  // t = 0.5 appears twice (end of stage 1, line 10; stage 2 after loadConst -time 0, line 60): the last
  // row is used, with a note naming both lines.
  bool noted = false;
  for (const auto& n : a.notes) noted = noted || n.find("lines 10, 60") != std::string::npos;
  EXPECT_TRUE(noted);
  const bridge::RecorderFile stress(dir / "stresses_range.out");
  const auto s = stress.values(stress.find_time(0.5));
  // Element 2, Gauss point 3 (+,+): values 12 + 6 .. 12 + 8.
  EXPECT_CLOSE(a.state.gauss_stress[6][0], 1000 * s[18], 0, 1e-15);
  EXPECT_CLOSE(a.state.gauss_stress[6][1], 1000 * s[19], 0, 1e-15);
  EXPECT_CLOSE(a.state.gauss_stress[6][3], 1000 * s[20], 0, 1e-15);
  const bridge::RecorderFile disp(dir / "disp_all_p12.out");
  const auto u = disp.values(disp.find_time(0.5));
  EXPECT_CLOSE(a.state.displacement[5].y(), u[11], 0, 0);  // node 6, 12 significant digits
  EXPECT_CLOSE(a.state.elements[0].density, 2400, 0, 1e-15);
  EXPECT_CLOSE(a.state.gauss_stress[6][2], 0.2 * 1000 * (s[18] + s[19]), 1e-9, 1e-14);  // plane-strain default
  // --row 10 is the stage-1 row at t = 0.5: the stresses come from the stage-1 row too (line 10),
  // not from the last row at that time.
  o.time.reset();
  o.row = 10;
  const auto stage1 = bridge::read_fem_state(model, o);
  const auto s1 = stress.values(9);
  EXPECT_CLOSE(stage1.state.gauss_stress[6][0], 1000 * s1[18], 0, 1e-15);
  EXPECT_NE(s1[18], s[18]);
  EXPECT_CLOSE(stage1.state.displacement[5].y(), disp.values(9)[11], 0, 0);
  o.row.reset();
  o.time = 0.5;
  // The case is PlaneStress: --plane-stress gives szz = 0.
  o.plane_stress = true;
  EXPECT_EQ(bridge::read_fem_state(model, o).state.gauss_stress[6][2], 0.0);
}

}  // namespace
