// Unit tests of the `print -JSON` reader on OpenSees 3.8's own output (reference_runs case 1.1) and on
// the invalid JSON OpenSees writes for DruckerPrager.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "bridge/fem_model.hpp"
#include "common/input_error.hpp"
#include "support/tolerance.hpp"

namespace {

const std::filesystem::path kCase =
    std::filesystem::path(GEOFLOW_TEST_DATA_DIR) / "reference_runs/opensees/sspquad_block_surface_load/ref";

TEST(FemModel, ReadsOpenSeesPrintJson) {
  const auto model = bridge::read_fem_model(kCase / "model.json");
  ASSERT_EQ(model.nodes.size(), 35u);
  ASSERT_EQ(model.elements.size(), 24u);
  EXPECT_TRUE(model.materials_readable);
  EXPECT_EQ(model.nodes[34].tag, 35);
  EXPECT_CLOSE(model.nodes[34].crd.x(), 4.5, 0, 0);
  EXPECT_CLOSE(model.nodes[34].crd.y(), 2.0, 0, 0);
  const auto& e1 = model.elements[0];
  EXPECT_EQ(e1.kind, bridge::ElementKind::SSPquad);
  EXPECT_EQ(e1.node_tags, (std::array<long, 4>{1, 2, 9, 8}));
  EXPECT_EQ(e1.nodes, (std::array<int, 4>{0, 1, 8, 7}));
  EXPECT_EQ(e1.material, "3");
  EXPECT_CLOSE(e1.thickness, 1.0, 0, 0);
  const auto& m = model.materials.at("3");
  EXPECT_EQ(m.type, "ElasticIsotropicMaterial");
  EXPECT_CLOSE(*m.E, 50000.0, 0, 0);
  EXPECT_CLOSE(*m.nu, 0.3, 0, 0);
  EXPECT_CLOSE(*m.rho, 1.8, 0, 0);
  EXPECT_EQ(model.element_index(24), 23);
  EXPECT_EQ(model.node_index(99), -1);
}

// OpenSees 3.8 writes a bare word for DruckerPrager (FORMATS.md section 3): geometry is still read.
TEST(FemModel, ToleratesOpenSeesInvalidJsonForPlasticMaterials) {
  const std::string text = R"({
"StructuralAnalysisModel": {
	"properties": {
		"ndMaterials": [
			{"name": "1", "type": "DruckerPrager", "K": 53333.3, "mState": elastoplastic}
		]
	},
	"geometry": {
		"nodes": [
			{"name": 1, "ndf": 2, "crd": [0, 0]},
			{"name": 2, "ndf": 2, "crd": [1, 0]},
			{"name": 3, "ndf": 2, "crd": [1, 1]},
			{"name": 4, "ndf": 2, "crd": [0, 1]}
		],
		"elements": [
			{"name": 7, "type": "FourNodeQuad", "nodes": [1, 2, 3, 4], "thickness": 1, "surfacePressure": 0, "masspervolume": 2, "bodyForces": [0, -19.62], "material": "1"}
		]
	}
}
})";
  const auto model = bridge::parse_fem_model(text, "dp.json");
  EXPECT_FALSE(model.materials_readable);
  ASSERT_EQ(model.nodes.size(), 4u);
  ASSERT_EQ(model.elements.size(), 1u);
  EXPECT_EQ(model.elements[0].kind, bridge::ElementKind::Quad);
  EXPECT_CLOSE(model.elements[0].mass_per_volume, 2.0, 0, 0);
  EXPECT_CLOSE(model.elements[0].body_force.y(), -19.62, 0, 0);
  EXPECT_TRUE(model.materials.empty());
}

TEST(FemModel, RejectsUnsupportedElementAndUnknownNode) {
  const std::string bad_type = R"({"StructuralAnalysisModel": {"geometry": {
    "nodes": [{"name": 1, "crd": [0, 0]}],
    "elements": [{"name": 5, "type": "bbarQuad", "nodes": [1, 1, 1, 1], "material": "1"}]}}})";
  try {
    bridge::parse_fem_model(bad_type, "m.json");
    FAIL() << "expected an InputError";
  } catch (const common::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("m.json"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("'bbarQuad' (expected SSPquad, FourNodeQuad/quad, Tri31, SSPquadUP or FourNodeQuadUP)"), std::string::npos)
        << e.what();
  }
  // Tri31 takes three nodes, and only three.
  const std::string triangle = R"({"StructuralAnalysisModel": {"geometry": {
    "nodes": [{"name": 1, "crd": [0, 0]}, {"name": 2, "crd": [1, 0]}, {"name": 3, "crd": [0, 1]}],
    "elements": [{"name": 5, "type": "Tri31", "nodes": [1, 2, 3], "thickness": 1.0, "material": "1"}]}}})";
  const auto tri = bridge::parse_fem_model(triangle, "t.json");
  ASSERT_EQ(tri.elements.size(), 1u);
  EXPECT_EQ(tri.elements[0].kind, bridge::ElementKind::Tri31);
  EXPECT_EQ(tri.elements[0].nodes[2], 2);
  std::string four = triangle;
  four.replace(four.find("[1, 2, 3]"), 9, "[1, 2, 3, 1]");
  try {
    bridge::parse_fem_model(four, "t.json");
    FAIL() << "expected an InputError";
  } catch (const common::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("expected \"nodes\" with 3 node tags"), std::string::npos) << e.what();
  }
  const std::string bad_node = R"({"StructuralAnalysisModel": {"geometry": {
    "nodes": [{"name": 1, "crd": [0, 0]}],
    "elements": [{"name": 5, "type": "SSPquad", "nodes": [1, 2, 3, 4], "material": "1"}]}}})";
  try {
    bridge::parse_fem_model(bad_node, "m.json");
    FAIL() << "expected an InputError";
  } catch (const common::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("node 2"), std::string::npos) << e.what();
  }
  EXPECT_THROW(bridge::read_fem_model("/nonexistent/model.json"), common::InputError);
}

// The one-entry-per-line fast path and the full JSON parser give the same model: the reference file
// as OpenSees wrote it against the same JSON re-indented (entries over several lines, full parser).
TEST(FemModel, LineLayoutAndFullParserAgree) {
  std::ifstream in(kCase / "model.json");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto fast = bridge::parse_fem_model(text, "model.json");
  const auto full = bridge::parse_fem_model(nlohmann::json::parse(text).dump(2), "model.json");
  ASSERT_EQ(fast.nodes.size(), full.nodes.size());
  ASSERT_EQ(fast.elements.size(), full.elements.size());
  for (std::size_t i = 0; i < fast.nodes.size(); ++i) {
    EXPECT_EQ(fast.nodes[i].tag, full.nodes[i].tag);
    EXPECT_EQ(fast.nodes[i].crd, full.nodes[i].crd);
  }
  for (std::size_t i = 0; i < fast.elements.size(); ++i) {
    EXPECT_EQ(fast.elements[i].node_tags, full.elements[i].node_tags);
    EXPECT_EQ(fast.elements[i].material, full.elements[i].material);
    EXPECT_EQ(fast.elements[i].kind, full.elements[i].kind);
  }
  EXPECT_EQ(full.materials.at("3").E, fast.materials.at("3").E);
}

// fem_tcl's compact layout ({"name":1,"ndf":2,"crd":[0.0,0.0]}) and errors on single lines.
TEST(FemModel, CompactLayoutAndLineErrors) {
  const std::string compact = "{\n\"StructuralAnalysisModel\": {\n\t\"geometry\": {\n\t\t\"nodes\": [\n"
                              "\t\t\t{\"name\":1,\"ndf\":2,\"crd\":[0.0,0.0]},\n\t\t\t{\"name\":2,\"ndf\":2,\"crd\":[2.0,0.0]},\n"
                              "\t\t\t{\"name\":3,\"ndf\":2,\"crd\":[2.0,1.5]},\n\t\t\t{\"name\":4,\"ndf\":2,\"crd\":[0.0,1.5]}\n"
                              "\t\t],\n\t\t\"elements\": [\n"
                              "\t\t\t{\"name\":9,\"type\":\"SSPquad\",\"nodes\":[1,2,3,4],\"thickness\":1.0,\"bodyForces\":[0.0,-18.9],\"material\":\"1\"}\n"
                              "\t\t]\n\t}\n}\n}\n";
  const auto m = bridge::parse_fem_model(compact, "c.json");
  ASSERT_EQ(m.nodes.size(), 4u);
  EXPECT_EQ(m.nodes[2].crd, Eigen::Vector2d(2.0, 1.5));
  ASSERT_EQ(m.elements.size(), 1u);
  EXPECT_EQ(m.elements[0].tag, 9);
  EXPECT_EQ(m.elements[0].material, "1");
  EXPECT_EQ(m.elements[0].body_force, Eigen::Vector2d(0.0, -18.9));
  // A 3D node in the same layout: the line and what was expected.
  std::string bad = compact;
  bad.replace(bad.find("[2.0,1.5]"), 9, "[2.0,1.5,0]");
  try {
    bridge::parse_fem_model(bad, "c.json");
    FAIL() << "expected an InputError";
  } catch (const common::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("c.json:7"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("-ndm 2"), std::string::npos) << e.what();
  }
  // Duplicate tags are named.
  std::string dup = compact;
  dup.replace(dup.find("\"name\":2"), 8, "\"name\":1");
  EXPECT_THROW(bridge::parse_fem_model(dup, "c.json"), common::InputError);
}

}  // namespace
