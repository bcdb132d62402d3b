// Unit tests of the u-p transfer's parts (issue 36): the model reader on u-p nodes and elements, in fem_tcl's
// valid JSON and in OpenSees 3.8's text blocks (SRC/material/nD/UWmaterials/PM4Sand.cpp and
// SRC/element/UP-ucsd/FourNodeQuadUP.cpp Print, commit 2890cb36 = 3.8.0); the drained strength of PM4Sand and
// PDMY02; the reference row (the end of the gravity stage); the equivalent deviatoric strain; the strength
// table's line-by-line checks; Idriss & Boulanger's (2008) residual strength ratio; the liquefied materials and
// their grouping.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <numbers>

#include "bridge/drained_strength.hpp"
#include "bridge/fem_model.hpp"
#include "bridge/liquefied_strength.hpp"
#include "bridge/pore_pressure.hpp"
#include "bridge/recorder_rows.hpp"
#include "common/input_error.hpp"
#include "support/input_error_message.hpp"
#include "support/scratch.hpp"
#include "support/tolerance.hpp"

namespace {

using test_support::input_error_message;

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// fem_tcl's print -JSON of a u-p model: 3-dof nodes, SSPquadUP and FourNodeQuadUP entries, PM4Sand and PDMY02 as
// JSON, one flag per dof in constraints.fix, a pore-pressure equalDOF.
TEST(UpModel, ReadsFemTclsUpNodesElementsMaterialsAndConstraints) {
  const std::string text = R"({
"StructuralAnalysisModel": {
	"properties": {
		"ndMaterials": [
			{"G0":476.0,"Den":1.9,"P_atm":101.3,"name":"1","nu":0.3,"phicv":33.0,"type":"PM4Sand"},
			{"name":"2","type":"PressureDependMultiYield02","rho":2.0,"refShearModul":9.0e4,"refBulkModul":2.2e5,"frictionAng":36.0,"c":0.3}
		]
	},
	"geometry": {
		"nodes": [
			{"name":1,"ndf":3,"crd":[0.0,0.0]},
			{"name":2,"ndf":3,"crd":[1.0,0.0]},
			{"name":3,"ndf":3,"crd":[1.0,1.0]},
			{"name":4,"ndf":3,"crd":[0.0,1.0]},
			{"name":5,"ndf":3,"crd":[1.0,2.0]},
			{"name":6,"ndf":3,"crd":[0.0,2.0]},
			{"name":7,"ndf":2,"crd":[0.0,2.0]}
		],
		"elements": [
			{"name":1,"type":"SSPquadUP","nodes":[1,2,3,4],"thickness":1.0,"bodyForces":[0.0,-9.81],"material":"1","fluidBulkModulus":2200000.0,"fluidDensity":1.0,"permeability":[1e-05,1e-05],"porosity":0.4},
			{"name":2,"type":"FourNodeQuadUP","nodes":[4,3,5,6],"thickness":1.0,"surfacePressure":0.0,"bodyForces":[0.0,-9.81],"material":"2","combinedBulkModulus":5.5e6,"fluidDensity":1.0,"permeability":[1e-05,1e-05]}
		]
	},
	"constraints": {
		"fix": [
			{"node":1,"fix":[1,1,0]},
			{"node":6,"fix":[0,0,1]}
		],
		"equalDOF": [
			{"retained":1,"constrained":2,"dofs":[3]}
		]
	}
}
}
)";
  const auto model = bridge::parse_fem_model(text, "up.json");
  ASSERT_EQ(model.nodes.size(), 7u);
  EXPECT_EQ(model.nodes[0].ndf, 3);
  EXPECT_EQ(model.nodes[6].ndf, 2);
  ASSERT_EQ(model.elements.size(), 2u);
  EXPECT_EQ(model.elements[0].kind, bridge::ElementKind::SSPquad);
  EXPECT_TRUE(model.elements[0].pore_pressure);
  EXPECT_EQ(model.elements[1].kind, bridge::ElementKind::Quad);
  EXPECT_TRUE(model.elements[1].pore_pressure);
  ASSERT_EQ(model.fixes.size(), 2u);
  EXPECT_TRUE(model.fixes[0].x && model.fixes[0].y && !model.fixes[0].pore_pressure);
  EXPECT_TRUE(!model.fixes[1].x && model.fixes[1].pore_pressure);
  ASSERT_EQ(model.ties.size(), 1u);
  EXPECT_EQ(model.ties[0].dofs, std::vector<int>{3});
  EXPECT_TRUE(model.skipped.empty());

  // The drained strengths: PM4Sand phi_cv with the elastic stage's G = G0 P_atm; PDMY02 frictionAng and c, E and
  // nu from its reference moduli.
  const auto sand = bridge::drained_strength(model.materials.at("1"));
  ASSERT_TRUE(sand.has_value());
  EXPECT_CLOSE(sand->E, 2 * 476.0 * 101.3 * 1.3, 0, 1e-15);
  EXPECT_EQ(sand->nu, 0.3);
  EXPECT_EQ(*sand->rho, 1.9);
  EXPECT_EQ(sand->phi_deg, 33.0);
  EXPECT_EQ(sand->cohesion, 0.0);
  const auto pdmy = bridge::drained_strength(model.materials.at("2"));
  ASSERT_TRUE(pdmy.has_value());
  const double K = 2.2e5, G = 9.0e4;
  EXPECT_CLOSE(pdmy->E, 9 * K * G / (3 * K + G), 0, 1e-14);
  EXPECT_CLOSE(pdmy->nu, (3 * K - 2 * G) / (2 * (3 * K + G)), 0, 1e-14);
  EXPECT_EQ(pdmy->phi_deg, 36.0);
  EXPECT_EQ(pdmy->cohesion, 0.3);
  // A material without what it needs (OpenSees' text block): no drained strength, the options decide.
  bridge::FemMaterial bare;
  bare.type = "PM4Sand";
  EXPECT_FALSE(bridge::drained_strength(bare).has_value());
}

// OpenSees 3.8's own file for a u-p model: PM4Sand and PressureDependMultiYield02 print text blocks into the
// material list and FourNodeQuadUP a text block into the element list (their Print ignores the JSON flag). The
// nodes, the SSPquadUP entry and the FourNodeQuadUP blocks are read, each skipped block named.
TEST(UpModel, ReadsWhatOpenSees38sInvalidJsonHolds) {
  const std::string text =
      "{\n\"StructuralAnalysisModel\": {\n\t\"properties\": {\n\t\t\"uniaxialMaterials\": [\n\n\t\t],\n"
      "\t\t\"ndMaterials\": [\n"
      "PM4Sand Material, tag: 1\nType: PlaneStrain\n,\nPressureDependMultiYield02\n\n\t\t]\n\t},\n"
      "\t\"geometry\": {\n\t\t\"nodes\": [\n"
      "\t\t\t{\"name\": 1, \"ndf\": 3, \"crd\": [0, 0]},\n\t\t\t{\"name\": 2, \"ndf\": 3, \"crd\": [1, 0]},\n"
      "\t\t\t{\"name\": 3, \"ndf\": 3, \"crd\": [1, 1]},\n\t\t\t{\"name\": 4, \"ndf\": 3, \"crd\": [0, 1]},\n"
      "\t\t\t{\"name\": 5, \"ndf\": 3, \"crd\": [1, 2]},\n\t\t\t{\"name\": 6, \"ndf\": 3, \"crd\": [0, 2]},\n"
      "\t\t\t{\"name\": 7, \"ndf\": 3, \"crd\": [1, 3]},\n\t\t\t{\"name\": 8, \"ndf\": 3, \"crd\": [0, 3]}\n"
      "\t\t],\n\t\t\"elements\": [\n"
      "\t\t\t{\"name\": 1, \"type\": \"SSPquadUP\", \"nodes\": [1, 2, 3, 4], \"thickness\": 1, \"bodyForces\": [0, -9.81], "
      "\"material\": \"1\"},\n"
      "\nFourNodeQuadUP, element id:  2\n\tConnected external nodes:  4 3 5 6 \n\tthickness:  1\n\tmass density:  1\n"
      "\tsurface pressure:  0\n\tbody forces:  0 -9.81\nPM4Sand Material, tag: 1\nType: PlaneStrain\n"
      "\tStress (xx yy xy)\n\t\tGauss point 1: -1 -2 0\n\t\tGauss point 2: -1 -2 0\n\t\tGauss point 3: -1 -2 0\n"
      "\t\tGauss point 4: -1 -2 0\n,\n"
      "\nFourNodeQuadUP, element id:  3\n\tConnected external nodes:  6 5 7 8 \n\tthickness:  0.5\n\tmass density:  1\n"
      "\tsurface pressure:  0\n\tbody forces:  0 -9.81\nPressureDependMultiYield02\n\tStress (xx yy xy)\n"
      "\t\tGauss point 1: -1 -2 0\n\t\tGauss point 2: -1 -2 0\n\t\tGauss point 3: -1 -2 0\n\t\tGauss point 4: -1 -2 0\n\n"
      "\t\t]\n\t}\n}\n}\n";
  const auto model = bridge::parse_fem_model(text, "opensees.json");
  ASSERT_EQ(model.nodes.size(), 8u);
  EXPECT_EQ(model.nodes[7].ndf, 3);
  ASSERT_EQ(model.elements.size(), 3u);
  EXPECT_FALSE(model.materials_readable);
  const auto& quad = model.elements[1];
  EXPECT_EQ(quad.tag, 2);
  EXPECT_EQ(quad.kind, bridge::ElementKind::Quad);
  EXPECT_TRUE(quad.pore_pressure);
  EXPECT_EQ(quad.node_tags, (std::array<long, 4>{4, 3, 5, 6}));
  EXPECT_EQ(quad.material, "1");
  EXPECT_EQ(quad.body_force.y(), -9.81);
  EXPECT_EQ(model.elements[2].thickness, 0.5);
  EXPECT_EQ(model.elements[2].material, "");  // PDMY02 prints no tag
  std::string skipped;
  for (const auto& s : model.skipped) skipped += s + "\n";
  EXPECT_TRUE(has(skipped, "opensees.json:8: ndMaterials: OpenSees' text block 'PM4Sand Material, tag: 1' is not JSON"))
      << skipped;
  EXPECT_TRUE(has(skipped, "'PressureDependMultiYield02' is not JSON")) << skipped;
  EXPECT_TRUE(has(skipped, "FourNodeQuadUP element 3 (OpenSees' text block): its material prints no tag")) << skipped;
  EXPECT_TRUE(has(skipped, "2 FourNodeQuadUP elements read from OpenSees' text blocks")) << skipped;

  // A block without its node line is an error naming the block's line.
  std::string broken = text;
  broken.erase(broken.find("\tConnected external nodes:  4 3 5 6 \n"), std::string("\tConnected external nodes:  4 3 5 6 \n").size());
  EXPECT_TRUE(has(input_error_message([&] { bridge::parse_fem_model(broken, "broken.json"); }),
                  "broken.json:29: OpenSees' FourNodeQuadUP text block: expected"));
}

// The reference row: the last row before the time restarts lower (setTime 0.0 after the gravity stage), the last
// such restart before the transfer row; else a first row at t = 0; or the given time (at or before the transfer
// row).
TEST(UpReference, IsTheEndOfTheGravityStageOrTheGivenTime) {
  const test_support::ScratchDir dir("geoflow_up_reference");
  const auto file = dir.path() / "disp.out";
  std::ofstream(file) << "500 0 0\n1000 0 0\n1500 0 0\n0.01 0 0\n0.02 0 0\n0.03 0 0\n";
  const bridge::RecorderFile disp(file);
  std::vector<std::string> notes;
  const auto transfer = bridge::pick_transfer_row(disp, 0.02, std::nullopt, notes);
  std::string how;
  const auto reference = bridge::pick_reference_row(disp, transfer, std::nullopt, "--reference-time", how);
  EXPECT_EQ(reference.index, 2u);
  EXPECT_EQ(reference.time, 1500.0);
  EXPECT_TRUE(has(how, "line 3, t = 1500; line 4, t = 0.01")) << how;
  EXPECT_EQ(bridge::pick_reference_row(disp, transfer, 1000.0, "--reference-time", how).index, 1u);
  EXPECT_EQ(bridge::pick_reference_row(disp, transfer, 0.01, "--reference-time", how).index, 3u);
  EXPECT_TRUE(has(input_error_message([&] { bridge::pick_reference_row(disp, transfer, 0.03, "--reference-time", how); }),
                  "--reference-time 0.03: " + file.string() + ": time 0.03 is on line(s) 6, after the transfer row (line 5)"));
  EXPECT_TRUE(has(input_error_message([&] { bridge::pick_reference_row(disp, transfer, 700.0, "--reference-time", how); }),
                  "--reference-time 700: " + file.string() + ": no row at time 700"));
  // A transfer during the gravity stage, or files whose time never restarts: the time must be given.
  const auto early = bridge::pick_transfer_row(disp, 1000.0, std::nullopt, notes);
  EXPECT_TRUE(has(input_error_message([&] { bridge::pick_reference_row(disp, early, std::nullopt, "--reference-time", how); }),
                  "--reference-time: required: the time column of " + file.string() + " never decreases"));
  // Recorders made after the gravity stage, their first row recorded at t = 0 (`setTime 0.0`, `record`): that row.
  const auto after = dir.path() / "after_gravity.out";
  std::ofstream(after) << "0 0 0\n0.01 0 0\n0.02 0 0\n";
  const bridge::RecorderFile shaking(after);
  const auto t2 = bridge::pick_transfer_row(shaking, 0.02, std::nullopt, notes);
  EXPECT_EQ(bridge::pick_reference_row(shaking, t2, std::nullopt, "--reference-time", how).index, 0u);
  EXPECT_TRUE(has(how, "the first row, at t = 0")) << how;
}

// sqrt(2/3 e:e) of the strain increment's deviator: simple shear gamma gives gamma / sqrt(3); plane-strain
// biaxial compression exx = eyy = e (ezz = 0) gives 2 |e| / 3; a recorded ezz counts (6 components).
TEST(UpStrain, EquivalentDeviatoricStrainOfTheIncrement) {
  const std::vector<double> before = {0.001, 0.002, 0.0005, 0, 0, 0};
  const std::vector<double> shear = {0.001, 0.002, 0.0105, 0, 0, 0};
  EXPECT_CLOSE(bridge::equivalent_shear_strain(std::span(shear).first(3), std::span(before).first(3), 3)[0],
               0.01 / std::sqrt(3.0), 0, 1e-14);
  const std::vector<double> biaxial = {0.004, 0.005, 0.0005};
  EXPECT_CLOSE(bridge::equivalent_shear_strain(biaxial, std::span(before).first(3), 3)[0], 2 * 0.003 / 3, 0, 1e-14);
  const std::vector<double> iso6 = {0.004, 0.005, 0.003, 0, 0, 0}, before6 = {0.001, 0.002, 0.0, 0, 0, 0};
  EXPECT_CLOSE(bridge::equivalent_shear_strain(iso6, before6, 6)[0], 0.0, 1e-16, 0);  // exx = eyy = ezz: no deviator
}

TEST(StrengthTable, ParsesKpaOrPaAndRefusesEachBadLineByNumber) {
  const std::string header = "sigma_v0_upper_kPa, peak_cohesion_kPa, residual_cohesion_kPa, peak_pdstrain, residual_pdstrain\n";
  const auto bins = bridge::parse_strength_table("# Mochikoshi tailings\n\n" + header + "50,3,1.5,0,1\n100, 5.6, 2.8, 0, 1\ninf,12,6,0,1\n", "t.csv");
  ASSERT_EQ(bins.size(), 3u);
  EXPECT_EQ(bins[0].sigma_v0_upper, 50e3);
  EXPECT_EQ(bins[1].peak_cohesion, 5.6e3);
  EXPECT_EQ(bins[1].residual_cohesion, 2.8e3);
  EXPECT_EQ(bins[2].residual_pdstrain, 1.0);
  EXPECT_TRUE(std::isinf(bins[2].sigma_v0_upper));
  const auto pa = bridge::parse_strength_table(
      "sigma_v0_upper_Pa,peak_cohesion_Pa,residual_cohesion_Pa,peak_pdstrain,residual_pdstrain\n5e4,3000,3000,0,0\n", "p.csv");
  EXPECT_EQ(pa[0].sigma_v0_upper, 5e4);
  EXPECT_EQ(pa[0].peak_cohesion, 3000.0);
  const auto fails = [&](const std::string& body, const std::string& expected) {
    const std::string message = input_error_message([&] { bridge::parse_strength_table(body, "t.csv"); });
    EXPECT_TRUE(has(message, expected)) << message;
  };
  fails(header + "50,3,1.5,0,1\n# c\n40,5,2.5,0,1\n", "t.csv:4: unsorted bins: sigma_v0_upper 40 is not above the previous row's 50");
  fails(header + "50,3,1.5,0,1\n50,5,2.5,0,1\n", "t.csv:3: unsorted bins");
  fails("sigma,peak\n", "t.csv:1: expected the header");
  fails(header + "50,3,1.5,0\n", "t.csv:2: expected 5 comma-separated values");
  fails(header + "50,three,1.5,0,1\n", "t.csv:2: peak_cohesion: expected a number, got 'three'");
  fails(header + "50,3,-1,0,1\n", "t.csv:2: residual_cohesion: expected a finite number >= 0");
  fails(header + "50,3,4,0,1\n", "t.csv:2: residual_cohesion 4 is above peak_cohesion 3");
  fails(header + "50,3,1.5,1,1\n", "t.csv:2: residual_pdstrain 1 must be above peak_pdstrain 1");
  fails(header + "50,inf,1.5,0,1\n", "t.csv:2: peak_cohesion: expected a finite number >= 0");
  fails(header, "t.csv: the strength table has a header but no bins");
  fails("# nothing\n", "t.csv: empty strength table");
}

// Idriss & Boulanger (2008), EERI MNO-12, the residual strength ratio: at (N1)60cs-Sr = 0 both curves start at
// exp(-3 - (16/21.2)^3) = 0.0324; the "void redistribution could be significant" curve lies below the
// "negligible" one and rises slowly (about 0.09 at 10, 0.175 at 20); the "negligible" curve turns up steeply
// past about 15 (from below 0.3 at 15 to above tan 30 deg = 0.577 at 20: their figure's near-vertical branch).
TEST(ResidualStrength, IdrissBoulangerRatio) {
  using bridge::VoidRedistribution;
  const auto significant = [](double n) { return bridge::idriss_boulanger_residual_ratio(n, VoidRedistribution::Significant); };
  const auto negligible = [](double n) { return bridge::idriss_boulanger_residual_ratio(n, VoidRedistribution::Negligible); };
  EXPECT_CLOSE(significant(0), std::exp(-3.0 - std::pow(16.0 / 21.2, 3)), 0, 1e-15);
  EXPECT_CLOSE(significant(0), 0.0324, 0, 0.01);
  EXPECT_CLOSE(significant(10), 0.091, 0, 0.01);
  EXPECT_CLOSE(significant(20), 0.175, 0, 0.01);
  for (double n = 0; n <= 30; n += 1) EXPECT_LT(significant(n), negligible(n)) << n;
  EXPECT_LT(negligible(15), 0.3);
  EXPECT_GT(negligible(20), std::tan(30 * std::numbers::pi / 180));
}

/// A one-element state with two FEM materials for the liquefied-strength tests.
bridge::TransferState two_materials() {
  bridge::TransferState st;
  for (int k = 0; k < 2; ++k) {
    bridge::MpmMaterial m;
    m.id = static_cast<unsigned>(k);
    m.fem_name = std::to_string(k + 1);
    m.type = bridge::MpmMaterial::Type::MohrCoulomb2D;
    m.density = 1900;
    m.youngs_modulus = 1e8;
    m.poisson_ratio = 0.3;
    m.friction = 32 * std::numbers::pi / 180;
    st.materials.push_back(m);
  }
  return st;
}

// The ratio rule on particles of two FEM materials: liquefied ones (r_u > 0.7) get phi 0 and Sr = R sigma'v0 on
// the 5 % grid (one material per FEM material and grid value), softening and pdstrain as asked; the others keep
// theirs. With more distinct strengths than --max-liquefied-materials the grid widens until they fit.
TEST(LiquefiedStrength, RatioRuleGroupsStrengthsAndStartsTheSoftening) {
  bridge::TransferState st = two_materials();
  std::vector<mpm::ParticleRecord> particles(6);
  std::vector<mpm::PorePressureRecord> rows = {{50e3, 10e3, 0.9}, {50e3, 10.1e3, 0.8}, {50e3, 20e3, 0.75},
                                                   {50e3, 30e3, 0.5}, {50e3, 10e3, 0.95}, {50e3, 10e3, 0.7}};
  for (std::size_t k = 0; k < particles.size(); ++k) {
    particles[k].id = static_cast<std::int64_t>(k);
    particles[k].material_id = k < 4 ? 0 : 1;
    particles[k].stress_yy = -rows[k].sigma_v0;
  }
  const std::vector<double> strain = {0.05, 0.3, 0, 0, 0.1, 0};
  bridge::LiquefiedOptions o;
  o.rule = bridge::LiquefiedOptions::Rule::Ratio;
  o.ratio = 0.1;
  o.peak_factor = 2;
  o.pd_peak = 0;
  o.pd_residual = 0.2;
  const auto summary = bridge::assign_liquefied_strength(st, particles, rows, strain, o);
  EXPECT_EQ(summary.liquefied, 4u);  // r_u 0.9, 0.8, 0.75, 0.95; 0.7 is not above the threshold
  ASSERT_EQ(summary.materials, (std::vector<unsigned>{2, 3, 4}));  // (FEM 1, 1 kPa), (FEM 1, 2 kPa), (FEM 2, 1 kPa)
  EXPECT_EQ(particles[0].material_id, particles[1].material_id);     // 1000 and 1010 Pa: one grid value
  EXPECT_NE(particles[0].material_id, particles[4].material_id);     // equal strength, other FEM material
  EXPECT_EQ(particles[3].material_id, 0u);
  EXPECT_EQ(particles[5].material_id, 1u);
  const auto& m = st.materials[particles[0].material_id];
  EXPECT_EQ(m.friction, 0.0);
  EXPECT_CLOSE(m.softening->residual_cohesion, 1000.0, 0, 0.025);
  EXPECT_EQ(m.cohesion, 2 * m.softening->residual_cohesion);
  EXPECT_EQ(m.tension_cutoff, 0.0);
  EXPECT_EQ(particles[0].nstate_vars, 7u);
  EXPECT_EQ(particles[0].svars[6], 0.05);
  const double sr = m.softening->residual_cohesion;
  EXPECT_CLOSE(particles[0].svars[2], sr + sr * (0.05 - 0.2) / (0 - 0.2), 0, 1e-14);  // CB-Geo's linear softening
  EXPECT_EQ(particles[1].svars[2], sr);                                               // past the residual strain
  EXPECT_EQ(summary.softened_at_start, 3u);

  // Ten particles of strengths 1 to 512 kPa (ten grid values at 5 %) and at most 4 materials: the grid widens.
  bridge::TransferState wide = two_materials();
  std::vector<mpm::ParticleRecord> many(10);
  std::vector<mpm::PorePressureRecord> many_rows;
  for (int k = 0; k < 10; ++k) many_rows.push_back({0, 1e4 * std::pow(2.0, k), 0.9});
  o.max_materials = 4;
  const auto widened = bridge::assign_liquefied_strength(wide, many, many_rows, {}, o);
  EXPECT_LE(widened.materials.size(), 4u);
  EXPECT_GE(widened.materials.size(), 2u);
  EXPECT_TRUE(has(widened.rule, "widened from --strength-step 5 %")) << widened.rule;
}

// Regrouping by material keeps each material's particles in order, renumbers the ids and says where each came from.
// --effective-friction (Bishop & Morgenstern 1960: the strength on the effective stress, the pore pressure of the
// transfer held): a particle below the threshold with pore pressure p and total mean stress sigma_m gets
// tan(phi) = (1 - p / sigma_m) tan(phi'), on the 5 % grid; a liquefied one keeps its residual strength; one
// without pore pressure keeps phi'.
TEST(LiquefiedStrength, EffectiveFrictionHoldsThePorePressureOfTheTransfer) {
  bridge::TransferState st = two_materials();
  std::vector<mpm::ParticleRecord> particles(4);
  // p 50 kPa on a total mean stress of 100 kPa (tan phi halved), 25 of 100 (x 0.75), liquefied, no p
  const std::vector<mpm::PorePressureRecord> rows = {{50e3, 50e3, 0.3}, {25e3, 50e3, 0.1}, {80e3, 20e3, 0.9},
                                                         {0.0, 50e3, 0.0}};
  for (auto& r : particles) r.stress_xx = r.stress_yy = r.stress_zz = -100e3;
  bridge::LiquefiedOptions o;
  o.rule = bridge::LiquefiedOptions::Rule::Ratio;
  o.ratio = 0.1;
  o.effective_friction = true;
  const auto summary = bridge::assign_liquefied_strength(st, particles, rows, {}, o);
  const double tan_phi = std::tan(32 * std::numbers::pi / 180);
  ASSERT_EQ(summary.effective_materials.size(), 2u);
  EXPECT_CLOSE(std::tan(st.materials[particles[0].material_id].friction), 0.5 * tan_phi, 0, 0.025);
  EXPECT_CLOSE(std::tan(st.materials[particles[1].material_id].friction), 0.75 * tan_phi, 0, 0.025);
  EXPECT_EQ(st.materials[particles[2].material_id].friction, 0.0);        // liquefied: phi 0, Sr
  EXPECT_EQ(particles[3].material_id, 0u);                                // no pore pressure: phi'
  EXPECT_EQ(particles[0].nstate_vars, 7u);
  EXPECT_TRUE(has(summary.effective_friction, "tan(phi) = (1 - p / sigma_m) tan(phi')")) << summary.effective_friction;
  // Without the option the particles below the threshold keep phi' on the total stress.
  bridge::TransferState plain = two_materials();
  std::vector<mpm::ParticleRecord> same(4);
  for (auto& r : same) r.stress_xx = r.stress_yy = r.stress_zz = -100e3;
  o.effective_friction = false;
  EXPECT_TRUE(bridge::assign_liquefied_strength(plain, same, rows, {}, o).effective_materials.empty());
  EXPECT_EQ(same[0].material_id, 0u);
}

TEST(LiquefiedStrength, GroupByMaterialIsStableAndRenumbers) {
  bridge::ParticleList particles(5);
  const unsigned material[5] = {0, 2, 1, 2, 0};
  for (std::size_t k = 0; k < 5; ++k) {
    ::new (static_cast<void*>(&particles[k])) mpm::ParticleRecord{};
    particles[k].id = static_cast<std::int64_t>(k);
    particles[k].material_id = material[k];
    particles[k].mass = static_cast<double>(k);
  }
  const auto order = bridge::group_by_material(particles);
  EXPECT_EQ(order, (std::vector<std::size_t>{0, 4, 2, 1, 3}));
  for (std::size_t k = 0; k < 5; ++k) {
    EXPECT_EQ(particles[k].id, static_cast<std::int64_t>(k));
    EXPECT_EQ(particles[k].mass, static_cast<double>(order[k]));
  }
}

}  // namespace
