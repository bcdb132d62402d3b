// Unit tests of the per-material mapping (issue 9, item 2): each FEM material of a three-layer strip
// (elastic, MohrCoulomb, DruckerPrager; one SSPquad each) becomes its own MPM material with its own
// parameters, per-material options override one material only, and every particle carries its element's
// material id. The DruckerPrager match is checked against the forward plane-strain relations (Drucker &
// Prager 1952; de Souza Neto, Peric & Owen 2008, section 6.4.3): alpha = tan(phi) / sqrt(9 + 12 tan^2 phi),
// k = 3 c / sqrt(9 + 12 tan^2 phi), with OpenSees' alpha = rho / sqrt(2), k = sigma_y / sqrt(3).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "bridge/drucker_prager_match.hpp"
#include "bridge/fem_state_reader.hpp"
#include "bridge/mpm_deck.hpp"
#include "mpm/io/deck_reader.hpp"
#include "bridge/particle_mapping.hpp"
#include "bridge/stress_recovery.hpp"
#include "support/input_error_message.hpp"
#include "support/scratch.hpp"
#include "support/tolerance.hpp"

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Three 1 m elements side by side (nodes 1-4 at y = 0, 5-8 at y = 1), materials "1", "2", "3".
const char* kModel = R"({
"StructuralAnalysisModel": {
	"properties": {
		"ndMaterials": [
			{"name": "1", "type": "ElasticIsotropicMaterial", "E": 2e7, "nu": 0.25, "rho": 2000},
			{"name": "2", "type": "MohrCoulomb", "E": 3e7, "nu": 0.3, "rho": 1900, "phi": 25, "c": 4000, "psi": 0, "tension": null},
			{"name": "3", "type": "DruckerPrager", "K": 5e7, "G": 2e7, "sigma_y": 10000, "rho": 0.2, "rho_bar": 0.1, "Kinf": 0, "Ko": 0, "delta1": 0, "delta2": 0, "H": 0, "theta": 0, "density": 1800, "atm": 101}
		]
	},
	"geometry": {
		"nodes": [
			{"name": 1, "ndf": 2, "crd": [0, 0]},
			{"name": 2, "ndf": 2, "crd": [1, 0]},
			{"name": 3, "ndf": 2, "crd": [2, 0]},
			{"name": 4, "ndf": 2, "crd": [3, 0]},
			{"name": 5, "ndf": 2, "crd": [0, 1]},
			{"name": 6, "ndf": 2, "crd": [1, 1]},
			{"name": 7, "ndf": 2, "crd": [2, 1]},
			{"name": 8, "ndf": 2, "crd": [3, 1]}
		],
		"elements": [
			{"name": 1, "type": "SSPquad", "nodes": [1, 2, 6, 5], "thickness": 1, "material": "1"},
			{"name": 2, "type": "SSPquad", "nodes": [2, 3, 7, 6], "thickness": 1, "material": "2"},
			{"name": 3, "type": "SSPquad", "nodes": [3, 4, 8, 7], "thickness": 1, "material": "3"}
		]
	}
}
}
)";

class MaterialMapping : public ::testing::Test {
 protected:
  void SetUp() override {
    std::ofstream(dir_.path() / "disp.out") << "1.0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n";  // 8 nodes at rest
    std::ofstream(dir_.path() / "stress.out") << "1.0 -1 -2 0 -1 -2 0 -1 -2 0\n";
    options_.disp = dir_.path() / "disp.out";
    options_.stress = dir_.path() / "stress.out";
  }
  bridge::AssembledState read() { return bridge::read_fem_state(bridge::parse_fem_model(kModel, "model.json"), options_); }

  test_support::ScratchDir dir_{"material_mapping_test"};
  bridge::ReadOptions options_;
};

TEST_F(MaterialMapping, EachFemMaterialBecomesItsOwnMpmMaterial) {
  const auto a = read();
  const auto& mats = a.state.materials;
  ASSERT_EQ(mats.size(), 3u);
  EXPECT_EQ(mats[0].fem_name, "1");
  EXPECT_EQ(mats[0].type, bridge::MpmMaterial::Type::LinearElastic2D);
  EXPECT_CLOSE(mats[0].youngs_modulus, 2e7, 0, 0);
  EXPECT_CLOSE(mats[0].density, 2000, 0, 0);
  EXPECT_EQ(mats[1].type, bridge::MpmMaterial::Type::MohrCoulomb2D);
  EXPECT_CLOSE(mats[1].friction, 25 * kPi / 180, 0, 1e-15);
  EXPECT_CLOSE(mats[1].cohesion, 4000, 0, 0);
  EXPECT_CLOSE(mats[1].density, 1900, 0, 0);
  // DruckerPrager: E = 9KG / (3K + G), nu = (3K - 2G) / (2 (3K + G)), density from "density".
  EXPECT_EQ(mats[2].type, bridge::MpmMaterial::Type::MohrCoulomb2D);
  EXPECT_CLOSE(mats[2].youngs_modulus, 9 * 5e7 * 2e7 / (3 * 5e7 + 2e7), 0, 1e-14);
  EXPECT_CLOSE(mats[2].poisson_ratio, (3 * 5e7 - 2 * 2e7) / (2 * (3 * 5e7 + 2e7)), 0, 1e-14);
  EXPECT_CLOSE(mats[2].density, 1800, 0, 0);
  // Matched strength satisfies the forward plane-strain relations.
  const double t = std::tan(mats[2].friction), root = std::sqrt(9 + 12 * t * t);
  EXPECT_CLOSE(t / root, 0.2 / std::sqrt(2.0), 0, 1e-12);
  EXPECT_CLOSE(3 * mats[2].cohesion / root, 10000 / std::sqrt(3.0), 0, 1e-12);
  const double tp = std::tan(mats[2].dilation);
  EXPECT_CLOSE(tp / std::sqrt(9 + 12 * tp * tp), 0.1 / std::sqrt(2.0), 0, 1e-12);
  // Same apex: c cot(phi) = (1/3) sqrt(2/3) sigma_y / rho (OpenSees' T0 / 3, a mean stress).
  EXPECT_CLOSE(mats[2].cohesion / t, std::sqrt(2.0 / 3.0) * 10000 / 0.2 / 3, 0, 1e-12);
  // Every particle carries its own element's material.
  const auto particles = bridge::generate_particles(a.state, bridge::recover_nodal_stress(a.state, bridge::Recovery::InverseDistance), {});
  ASSERT_EQ(particles.size(), 48u);
  for (const auto& p : particles) EXPECT_EQ(p.material_id, static_cast<unsigned>(p.coord_x)) << "particle " << p.id;
}

TEST_F(MaterialMapping, AssociatedDruckerPragerWarnsOfItsDilation) {
  // rho_bar = rho: the match gives psi = phi = 25.9 deg (> 20): a warning naming the material and --psi;
  // the model's own rho_bar = 0.1 (psi 12.3 deg) and an associated one given --material 3:psi=0 give none.
  const auto warned = [](const bridge::AssembledState& a) {
    for (const auto& w : a.warnings)
      if (w.find("material '3': dilation angle") != std::string::npos && w.find("--psi") != std::string::npos) return true;
    return false;
  };
  EXPECT_FALSE(warned(read()));
  std::string model = kModel;
  const std::string from = R"("rho": 0.2, "rho_bar": 0.1)";
  model.replace(model.find(from), from.size(), R"("rho": 0.2, "rho_bar": 0.2)");
  const auto associated = bridge::read_fem_state(bridge::parse_fem_model(model, "model.json"), options_);
  EXPECT_CLOSE(associated.state.materials[2].dilation, associated.state.materials[2].friction, 0, 1e-12);
  EXPECT_TRUE(warned(associated));
  options_.per_material["3"].psi_deg = 0.0;
  EXPECT_FALSE(warned(bridge::read_fem_state(bridge::parse_fem_model(model, "model.json"), options_)));
}

TEST_F(MaterialMapping, AFreshStartGivesEachParticleItsOwnMaterial) {
  // Elements of materials 2, 1, 2 (interleaved): the particles are grouped by material, the deck has one
  // file generator per material, and a fresh (non-resumed) start of it reads every particle back with
  // the material and position the HDF5 file gives it (same ids).
  std::string model = kModel;
  const auto swap = [&](const std::string& from, const std::string& to) { model.replace(model.find(from), from.size(), to); };
  swap(R"("nodes": [1, 2, 6, 5], "thickness": 1, "material": "1")", R"("nodes": [1, 2, 6, 5], "thickness": 1, "material": "2")");
  swap(R"("nodes": [2, 3, 7, 6], "thickness": 1, "material": "2")", R"("nodes": [2, 3, 7, 6], "thickness": 1, "material": "1")");
  swap(R"("nodes": [3, 4, 8, 7], "thickness": 1, "material": "3")", R"("nodes": [3, 4, 8, 7], "thickness": 1, "material": "2")");
  swap(R"({"name": "3", "type": "DruckerPrager")", R"({"name": "9", "type": "DruckerPrager")");
  const auto a = bridge::read_fem_state(bridge::parse_fem_model(model, "model.json"), options_);
  const auto particles = bridge::generate_particles(a.state, bridge::recover_nodal_stress(a.state, bridge::Recovery::InverseDistance), {});
  ASSERT_EQ(particles.size(), 48u);
  const bridge::DeckText d = bridge::build_deck(a.state, particles, {});
  ASSERT_EQ(d.particle_files.size(), 2u);
  const auto deck_dir = dir_.path() / "deck";
  std::filesystem::create_directories(deck_dir);
  auto json = nlohmann::json::parse(d.mpm_json);
  ASSERT_EQ(json["particles"].size(), 2u);
  json["analysis"]["resume"]["resume"] = false;
  std::ofstream(deck_dir / "mpm.json") << json.dump(1);
  std::ofstream(deck_dir / "mesh.txt") << d.mesh_txt;
  std::ofstream(deck_dir / "entity_sets.json") << d.entity_sets_json;
  for (const auto& [name, body] : d.particle_files) std::ofstream(deck_dir / name) << body;
  const mpm::Deck fresh = mpm::io::read_deck(deck_dir, "mpm.json");
  ASSERT_EQ(fresh.particles.size(), particles.size());
  std::size_t of_material[2] = {0, 0};
  for (std::size_t k = 0; k < particles.size(); ++k) {
    EXPECT_EQ(fresh.particles[k].id, particles[k].id);
    EXPECT_EQ(fresh.particles[k].material_id, particles[k].material_id) << "particle " << k;
    EXPECT_CLOSE(fresh.particles[k].coord_x, particles[k].coord_x, 1e-12, 0);
    EXPECT_CLOSE(fresh.particles[k].coord_y, particles[k].coord_y, 1e-12, 0);
    ++of_material[std::min<std::size_t>(particles[k].material_id, 1)];
  }
  EXPECT_EQ(of_material[0], 16u);  // element 2 (material "1" -> the first id)
  EXPECT_EQ(of_material[1], 32u);  // elements 1 and 3
}

TEST_F(MaterialMapping, PerMaterialOptionsOverrideOneMaterial) {
  options_.material.cohesion = 1000;  // all at once: every Mohr-Coulomb material
  bridge::parse_material_override("2:phi=30,c=2000", "--material", options_.per_material);
  bridge::parse_material_override("1:type=mohr-coulomb,phi=35", "--material", options_.per_material);
  const auto mats = read().state.materials;
  EXPECT_EQ(mats[0].type, bridge::MpmMaterial::Type::MohrCoulomb2D);
  EXPECT_CLOSE(mats[0].friction, 35 * kPi / 180, 0, 1e-15);
  EXPECT_CLOSE(mats[0].cohesion, 1000, 0, 0);
  EXPECT_CLOSE(mats[1].friction, 30 * kPi / 180, 0, 1e-15);
  EXPECT_CLOSE(mats[1].cohesion, 2000, 0, 0);   // the per-material value wins over --cohesion
  EXPECT_CLOSE(mats[2].cohesion, 1000, 0, 0);   // --cohesion applies to the DruckerPrager match too
}

TEST_F(MaterialMapping, BadPerMaterialOptionsNameTheOption) {
  using test_support::input_error_message;
  std::map<std::string, bridge::MaterialOverrides> o;
  EXPECT_NE(input_error_message([&] { bridge::parse_material_override("phi=30", "--material", o); }).find("NAME:key=value"), std::string::npos);
  EXPECT_NE(input_error_message([&] { bridge::parse_material_override("2:phi=abc", "--material", o); }).find("phi: expected a number"), std::string::npos);
  EXPECT_NE(input_error_message([&] { bridge::parse_material_override("2:friction=30", "--material", o); }).find("unknown key 'friction'"), std::string::npos);
  bridge::parse_material_override("7:phi=30", "--material", options_.per_material);
  const std::string msg = input_error_message([&] { read(); });
  EXPECT_NE(msg.find("--material 7"), std::string::npos) << msg;
  EXPECT_NE(msg.find("1, 2, 3"), std::string::npos) << msg;
}

TEST_F(MaterialMapping, FrictionlessMultiYieldClayBecomesTrescaWithItsPlaneStrainStrength) {
  // fem_tcl's print -JSON entry of nDMaterial PressureIndependMultiYield (bridge/multi_yield_match.hpp):
  // E, nu from refShearModul and refBulkModul, phi = psi = 0, c = 2 cohesi / sqrt(3) (q_f = 2 cohesi,
  // tau_max = q_f / sqrt(3) in plane strain).
  std::string model = kModel;
  const std::string dp = model.substr(model.find(R"({"name": "3", "type": "DruckerPrager")"));
  const std::string line = dp.substr(0, dp.find('}') + 1);
  const std::string clay = R"({"name": "3", "type": "PressureIndependMultiYield", "rho": 1.8, "refShearModul": 60000, "refBulkModul": 300000, "cohesi": 30, "peakShearStra": 0.1, "frictionAng": 0, "refPress": 100, "pressDependCoe": 0, "noYieldSurf": 20})";
  model.replace(model.find(line), line.size(), clay);
  const auto a = bridge::read_fem_state(bridge::parse_fem_model(model, "model.json"), options_);
  const auto& m = a.state.materials[2];
  EXPECT_EQ(m.type, bridge::MpmMaterial::Type::MohrCoulomb2D);
  EXPECT_CLOSE(m.youngs_modulus, 9 * 3e5 * 6e4 / (3 * 3e5 + 6e4), 0, 1e-14);
  EXPECT_CLOSE(m.poisson_ratio, (3 * 3e5 - 2 * 6e4) / (2 * (3 * 3e5 + 6e4)), 0, 1e-14);
  EXPECT_CLOSE(m.density, 1.8, 0, 0);
  EXPECT_EQ(m.friction, 0.0);
  EXPECT_EQ(m.dilation, 0.0);
  EXPECT_CLOSE(m.cohesion, 2 * 30 / std::sqrt(3.0), 0, 1e-14);
  // With a friction angle its strength is frozen point by point at the switch: no one Mohr-Coulomb.
  model.replace(model.find(R"("frictionAng": 0)"), 16, R"("frictionAng": 30)");
  const std::string msg = test_support::input_error_message(
      [&] { bridge::read_fem_state(bridge::parse_fem_model(model, "model.json"), options_); });
  EXPECT_NE(msg.find("frictionAng 30"), std::string::npos) << msg;
  EXPECT_NE(msg.find("--material 3:type=mohr-coulomb"), std::string::npos) << msg;
}

TEST(DruckerPragerMatch, TooSteepConeHasNoMatch) {
  EXPECT_FALSE(bridge::plane_strain_mohr_coulomb(10, 0.5, 0));  // 12 alpha^2 = 1.5 >= 1
  const auto vm = bridge::plane_strain_mohr_coulomb(10, 0, 0);  // von Mises: c = k = sigma_y / sqrt(3)
  ASSERT_TRUE(vm);
  EXPECT_CLOSE(vm->phi_deg, 0, 0, 0);
  EXPECT_CLOSE(vm->cohesion, 10 / std::sqrt(3.0), 0, 1e-15);
}

}  // namespace
