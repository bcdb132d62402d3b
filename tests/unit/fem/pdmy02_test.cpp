// PressureDependMultiYield02 (fem_tcl/materials/pressure_depend_multi_yield02.hpp) as one class: OpenSees 3.8's
// Tcl syntax and defaults (SRC/material/nD/TclModelBuilderNDMaterialCommand.cpp, the PressureDependMultiYield02
// block, and the constructor's checks in SRC/material/nD/soil/PressureDependMultiYield02.cpp), its derived
// constants (setUpSurfaces), the stages (getTangent / getStress), the responses (getCommittedStress,
// getBackbone), and the trial / commit / revert / clone protocol.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "common/command_args.hpp"
#include "common/input_error.hpp"
#include "fem_tcl/materials/material_registry.hpp"
#include "fem_tcl/materials/pressure_depend_multi_yield02.hpp"
#include "support/tolerance.hpp"

namespace {

using fem::materials::PlaneType;
using fem::materials::PressureDependMultiYield02;
using fem::materials::PressureDependMultiYield02Parameters;
using fem::materials::Vector3;

constexpr double kPi = 3.14159265358979;  // OpenSees' value in this material

/// The command words after the type, as the up_dss_pdmy02 reference script writes them (e = 0.68).
std::vector<std::string> golden_words() {
  return {"1", "2", "1.8", "6.0e4", "1.6e5", "31.0", "0.1", "101.0", "0.5", "26.0", "0.067", "0.23", "0.06", "0.27",
          "20", "5.0", "3.0", "1.0", "0.0", "0.68", "0.9", "0.02", "0.7", "101.0"};
}

std::unique_ptr<fem::materials::NDMaterial> parse(std::vector<std::string> words) {
  const auto parser = fem::materials::find_nd_material_parser("PressureDependMultiYield02");
  if (!parser) throw std::runtime_error("PressureDependMultiYield02 is not registered");
  common::CommandArgs args("nDMaterial PressureDependMultiYield02", "", std::move(words));
  return parser(args);
}

const PressureDependMultiYield02& as_pdmy(const std::unique_ptr<fem::materials::NDMaterial>& m) {
  return dynamic_cast<const PressureDependMultiYield02&>(*m);
}

/// The message of the common::InputError that `f` throws ("" when it throws none).
template <class F>
std::string input_error(F&& f) {
  try {
    f();
  } catch (const common::InputError& e) {
    return e.what();
  }
  return "";
}

double compression_ratio(double phi_deg) {
  const double s = std::sin(phi_deg * kPi / 180.0);
  return 6.0 * s / (3.0 - s);
}

TEST(PressureDependMultiYield02, ParsesTheFullSyntaxInOpenSeesOrder) {
  const auto m = parse(golden_words());
  const auto& p = as_pdmy(m).parameters();
  EXPECT_EQ(m->tag(), 1);
  EXPECT_EQ(m->type_name(), "PressureDependMultiYield02");
  EXPECT_DOUBLE_EQ(m->density(), 1.8);
  EXPECT_DOUBLE_EQ(p.shear_modulus, 6.0e4);
  EXPECT_DOUBLE_EQ(p.bulk_modulus, 1.6e5);
  EXPECT_DOUBLE_EQ(p.friction_deg, 31.0);
  EXPECT_DOUBLE_EQ(p.peak_shear_strain, 0.1);
  EXPECT_DOUBLE_EQ(p.ref_pressure, 101.0);
  EXPECT_DOUBLE_EQ(p.pressure_exponent, 0.5);
  EXPECT_DOUBLE_EQ(p.pt_deg, 26.0);
  EXPECT_DOUBLE_EQ(p.contraction1, 0.067);
  EXPECT_DOUBLE_EQ(p.contraction3, 0.23);
  EXPECT_DOUBLE_EQ(p.dilation1, 0.06);
  EXPECT_DOUBLE_EQ(p.dilation3, 0.27);
  EXPECT_EQ(p.surfaces, 20);
  EXPECT_DOUBLE_EQ(p.contraction2, 5.0);
  EXPECT_DOUBLE_EQ(p.dilation2, 3.0);
  EXPECT_DOUBLE_EQ(p.liquefaction1, 1.0);
  EXPECT_DOUBLE_EQ(p.liquefaction2, 0.0);
  EXPECT_DOUBLE_EQ(p.void_ratio, 0.68);
  EXPECT_DOUBLE_EQ(p.cs1, 0.9);
  EXPECT_DOUBLE_EQ(p.cs2, 0.02);
  EXPECT_DOUBLE_EQ(p.cs3, 0.7);
  EXPECT_DOUBLE_EQ(p.atmospheric, 101.0);
  EXPECT_DOUBLE_EQ(p.cohesion, 0.1);  // not given: OpenSees' default c
  EXPECT_TRUE(p.backbone.empty());
}

TEST(PressureDependMultiYield02, DefaultsAreOpenSees) {
  // Only the 13 required values: noYieldSurf 20, contrac2 5, dilat2 3, liquefac1 1, liquefac2 0, e 0.6, cs1 0.9,
  // cs2 0.02, cs3 0.7, pa 101, c 0.1, Hv 0, Pv 1 (OPS_PressureDependMultiYield02's param[13..25]).
  auto words = golden_words();
  words.resize(14);
  const auto m = parse(words);
  const auto& p = as_pdmy(m).parameters();
  EXPECT_EQ(p.surfaces, 20);
  EXPECT_EQ(as_pdmy(m).surfaces().size(), 21u);
  EXPECT_DOUBLE_EQ(p.contraction2, 5.0);
  EXPECT_DOUBLE_EQ(p.dilation2, 3.0);
  EXPECT_DOUBLE_EQ(p.liquefaction1, 1.0);
  EXPECT_DOUBLE_EQ(p.liquefaction2, 0.0);
  EXPECT_DOUBLE_EQ(p.void_ratio, 0.6);
  EXPECT_DOUBLE_EQ(p.cs1, 0.9);
  EXPECT_DOUBLE_EQ(p.cs2, 0.02);
  EXPECT_DOUBLE_EQ(p.cs3, 0.7);
  EXPECT_DOUBLE_EQ(p.atmospheric, 101.0);
  EXPECT_DOUBLE_EQ(p.cohesion, 0.1);
  EXPECT_DOUBLE_EQ(p.hv, 0.0);
  EXPECT_DOUBLE_EQ(p.pv, 1.0);
  // The trailing c, Hv, Pv that OpenSees' parser also reads.
  auto more = golden_words();
  more.insert(more.end(), {"0.5", "2.0", "1.5"});
  const auto with_more = parse(more);
  const auto& q = as_pdmy(with_more).parameters();
  EXPECT_DOUBLE_EQ(q.cohesion, 0.5);
  EXPECT_DOUBLE_EQ(q.hv, 2.0);
  EXPECT_DOUBLE_EQ(q.pv, 1.5);
}

TEST(PressureDependMultiYield02, UserSurfacesComeBeforeTheOptionalParameters) {
  auto words = golden_words();
  words.resize(14);
  // noYieldSurf -4: four (shear strain, G/Gmax) points, then contrac2.
  words.insert(words.end(), {"-4", "1e-4", "0.9", "1e-3", "0.6", "1e-2", "0.1", "5e-2", "0.0233", "7.0"});
  const auto m = parse(words);
  const auto& pd = as_pdmy(m);
  const auto& p = pd.parameters();
  EXPECT_EQ(p.surfaces, 4);
  ASSERT_EQ(p.backbone.size(), 8u);
  EXPECT_DOUBLE_EQ(p.backbone[7], 0.0233);
  EXPECT_DOUBLE_EQ(p.contraction2, 7.0);
  // setUpSurfaces' user branch: tmax = G Gs_n r_n, M_f = (sqrt(3) tmax - 2 c) / p_ref, phi from M_f, and the
  // surfaces at sqrt(3) G Gs_i r_i / (p_ref + p_r).
  const double tmax = 6.0e4 * 0.0233 * 5e-2;
  const double m_f = (std::sqrt(3.0) * tmax - 2.0 * 0.1) / 101.0;
  EXPECT_CLOSE(p.friction_deg, std::asin(3.0 * m_f / (6.0 + m_f)) * 180.0 / kPi, 1e-12, 1e-12);
  const double pr = std::max(2.0 * 0.1 / m_f, 0.0001 * 101.0);
  EXPECT_CLOSE(pd.residual_pressure(), pr, 1e-15, 1e-12);
  EXPECT_CLOSE(pd.surfaces()[4].size, std::sqrt(3.0) * tmax / (101.0 + pr), 1e-15, 1e-12);
  EXPECT_CLOSE(pd.surfaces()[1].size, std::sqrt(3.0) * 6.0e4 * 0.9 * 1e-4 / (101.0 + pr), 1e-15, 1e-12);
}

TEST(PressureDependMultiYield02, DerivedConstantsAreOpenSeesSetUpSurfaces) {
  const auto m = parse(golden_words());
  const auto& pd = as_pdmy(m);
  const double m_f = compression_ratio(31.0);
  EXPECT_CLOSE(pd.residual_pressure(), 2.0 * 0.1 / m_f, 1e-15, 1e-12);  // p_r = 2 c / M_f
  EXPECT_CLOSE(pd.stress_ratio_pt(), compression_ratio(26.0), 1e-15, 1e-12);
  // The failure surface is the friction cone; the first one at 1/n of the strength; all centred at the origin.
  EXPECT_CLOSE(pd.surfaces()[20].size, m_f, 1e-15, 1e-12);
  EXPECT_CLOSE(pd.surfaces()[1].size, m_f / 20.0, 1e-15, 1e-12);
  EXPECT_EQ(pd.surfaces()[20].modulus, 0.0);
  for (int m2 = 1; m2 < 20; ++m2) {
    EXPECT_GT(pd.surfaces()[m2].modulus, pd.surfaces()[m2 + 1].modulus) << "surface " << m2;
    EXPECT_EQ(pd.surfaces()[m2].center.norm(), 0.0);
  }
}

TEST(PressureDependMultiYield02, BadInputNamesTheArgument) {
  auto with = [](std::size_t index, const std::string& value) {
    auto w = golden_words();
    w[index] = value;
    return w;
  };
  EXPECT_NE(input_error([&] { parse(with(1, "3")); }).find("2D"), std::string::npos);
  EXPECT_NE(input_error([&] { parse(with(1, "4")); }).find("nd"), std::string::npos);
  EXPECT_NE(input_error([&] { parse(with(3, "-6e4")); }).find("refShearModul"), std::string::npos);
  EXPECT_NE(input_error([&] { parse(with(4, "0")); }).find("refBulkModul"), std::string::npos);
  EXPECT_NE(input_error([&] { parse(with(5, "0")); }).find("frictionAng"), std::string::npos);
  EXPECT_NE(input_error([&] { parse(with(5, "90")); }).find("frictionAng"), std::string::npos);
  EXPECT_NE(input_error([&] { parse(with(6, "-0.1")); }).find("peakShearStra"), std::string::npos);
  EXPECT_NE(input_error([&] { parse(with(7, "0")); }).find("refPress"), std::string::npos);
  EXPECT_NE(input_error([&] { parse(with(9, "0")); }).find("PTAng"), std::string::npos);
  EXPECT_NE(input_error([&] { parse(with(2, "-1")); }).find("rho"), std::string::npos);
  EXPECT_NE(input_error([&] { parse(with(10, "abc")); }).find("contrac1"), std::string::npos);
  auto missing = golden_words();
  missing.resize(12);
  EXPECT_NE(input_error([&] { parse(missing); }).find("dilat1"), std::string::npos);
  auto extra = golden_words();
  extra.insert(extra.end(), {"0.1", "0", "1", "9"});
  EXPECT_NE(input_error([&] { parse(extra); }).find("'9'"), std::string::npos);
  // A peak strain too small for the strength: the hyperbola has no reference strain.
  EXPECT_NE(input_error([&] { parse(with(6, "1e-4")); }).find("peakShearStra"), std::string::npos);
}

TEST(PressureDependMultiYield02, OpenSeesCorrectionsOfDubiousValues) {
  auto w = golden_words();
  w[8] = "-1";   // pressDependCoe < 0 -> 0.5
  w[14] = "0";   // noYieldSurf <= 0 -> 10
  w[20] = "-1";  // cs1 < 0 -> 0.8
  w.push_back("-2");  // c < 0 -> 0.3
  const auto m = parse(w);
  const auto& p = as_pdmy(m).parameters();
  EXPECT_DOUBLE_EQ(p.pressure_exponent, 0.5);
  EXPECT_EQ(p.surfaces, 10);
  EXPECT_DOUBLE_EQ(p.cs1, 0.8);
  EXPECT_DOUBLE_EQ(p.cohesion, 0.3);
  w[14] = "150";  // > 100 -> 100
  EXPECT_EQ(as_pdmy(parse(w)).parameters().surfaces, 100);
}

TEST(PressureDependMultiYield02, StagesAndTheirErrors) {
  auto m = parse(golden_words());
  auto& pd = dynamic_cast<PressureDependMultiYield02&>(*m);
  EXPECT_EQ(pd.stage(), 0);
  const std::string message = input_error([&] { pd.update_stage(3); });
  EXPECT_NE(message.find("-stage 3"), std::string::npos) << message;
  EXPECT_NE(input_error([&] { pd.set_parameter("updateMaterialStage", -1); }).find("-stage -1"), std::string::npos);
  EXPECT_EQ(pd.stage(), 0);
  EXPECT_TRUE(pd.set_parameter("updateMaterialStage", 1));
  EXPECT_EQ(pd.stage(), 1);
  EXPECT_TRUE(pd.update_stage(2));
  EXPECT_EQ(pd.stage(), 2);
  EXPECT_FALSE(pd.set_parameter("materialState", 1));  // not in PressureDependMultiYield02::setParameter
  EXPECT_FALSE(pd.set_parameter("E", 1));
  EXPECT_NE(input_error([&] { pd.set_parameter("shearModulus", -5.0); }).find("shearModulus"), std::string::npos);
  EXPECT_TRUE(pd.set_parameter("shearModulus", 7.0e4));
  EXPECT_DOUBLE_EQ(pd.parameters().shear_modulus, 7.0e4);
  EXPECT_TRUE(pd.set_parameter("bulkModulus", 2.0e5));
  EXPECT_DOUBLE_EQ(pd.parameters().bulk_modulus, 2.0e5);
  EXPECT_TRUE(pd.set_parameter("frictionAngle", 35.0));
  EXPECT_CLOSE(pd.surfaces()[20].size, compression_ratio(35.0), 1e-15, 1e-12);
  EXPECT_TRUE(pd.set_parameter("cohesion", 1.0));
  EXPECT_CLOSE(pd.residual_pressure(), 2.0 / compression_ratio(35.0), 1e-15, 1e-12);
}

// Stage 0 is linear elastic with the reference moduli, whatever the confinement (getTangent, loadStage 0).
TEST(PressureDependMultiYield02, StageZeroIsElasticWithTheReferenceModuli) {
  auto m = parse(golden_words());
  const double G = 6.0e4, B = 1.6e5, lambda = B - 2.0 * G / 3.0;
  const Vector3 e(-1e-4, -3e-4, 2e-4);
  m->set_trial_strain(e);
  EXPECT_CLOSE(m->stress()[0], (lambda + 2.0 * G) * e[0] + lambda * e[1], 1e-12, 1e-12);
  EXPECT_CLOSE(m->stress()[1], lambda * e[0] + (lambda + 2.0 * G) * e[1], 1e-12, 1e-12);
  EXPECT_CLOSE(m->stress()[2], G * e[2], 1e-12, 1e-12);
  EXPECT_CLOSE(m->stress_3d()[2], lambda * (e[0] + e[1]), 1e-12, 1e-12);
  EXPECT_CLOSE(m->tangent()(0, 0), lambda + 2.0 * G, 1e-9, 1e-12);
  EXPECT_CLOSE(m->tangent()(2, 2), G, 1e-9, 1e-12);
  EXPECT_CLOSE(m->initial_tangent()(0, 1), lambda, 1e-9, 1e-12);
  // The committed response only changes at the commit; the ratio column is 0 outside stage 1.
  EXPECT_EQ((*m->response("stress"))[1], 0.0);
  m->commit_state();
  const auto s = *m->response("stress");
  ASSERT_EQ(s.size(), 5u);
  EXPECT_DOUBLE_EQ(s[1], m->stress()[1]);
  EXPECT_DOUBLE_EQ(s[3], m->stress()[2]);
  EXPECT_EQ(s[4], 0.0);
  const auto strain = *m->response("strain");
  ASSERT_EQ(strain.size(), 3u);
  EXPECT_DOUBLE_EQ(strain[2], e[2]);
}

// Stage 2: elastic with the moduli of the mean stress at which it was first used, G_r ((p - p_r) /
// (-p_ref - p_r))^d (getTangent, loadStage 2, initPress).
TEST(PressureDependMultiYield02, StageTwoScalesTheModuliToTheConfinement) {
  auto m = parse(golden_words());
  const auto& pd = as_pdmy(m);
  m->set_trial_strain(Vector3(-2e-4, -2e-4, 0.0));
  m->commit_state();
  const double p0 = m->stress_3d().head<3>().mean();
  m->update_stage(2);
  const double factor = std::pow((p0 - pd.residual_pressure()) / (-101.0 - pd.residual_pressure()), 0.5);
  m->set_trial_strain(Vector3(-2e-4, -2e-4, 1e-4));
  EXPECT_CLOSE(m->stress()[2], 6.0e4 * factor * 1e-4, 1e-12, 1e-12);
  EXPECT_CLOSE(m->tangent()(2, 2), 6.0e4 * factor, 1e-9, 1e-12);
  m->commit_state();
  m->set_trial_strain(Vector3(-4e-4, -4e-4, 1e-4));  // more confinement: the same moduli
  EXPECT_CLOSE(m->tangent()(2, 2), 6.0e4 * factor, 1e-9, 1e-12);
}

/// K0 consolidation in stage 0 as the reference script (syy about -80 kPa), then stage 1.
void consolidate(fem::materials::NDMaterial& m) {
  m.set_trial_strain(Vector3(0.0, -3.32673e-4, 0.0));
  m.commit_state();
  m.update_stage(1);
}

TEST(PressureDependMultiYield02, PlasticStageKeepsTheConsolidationStressAndReportsItsRatio) {
  auto m = parse(golden_words());
  const auto& pd = as_pdmy(m);
  consolidate(*m);
  m->set_trial_strain(Vector3(0.0, -3.32673e-4, 0.0));
  m->commit_state();
  const auto s = *m->response("stress");
  EXPECT_CLOSE(s[1], -79.8416, 1e-3, 0.0);  // ref/stress.out rows 126-150
  const double q = std::abs(s[1] - s[0]);       // sxx = szz: sqrt(3/2 s:s) = |syy - sxx|
  const double p = (s[0] + s[1] + s[2]) / 3.0;
  EXPECT_CLOSE(s[4], q / (std::abs(p) + pd.residual_pressure()) / compression_ratio(31.0), 1e-12, 1e-9);
  EXPECT_CLOSE(s[4], 0.601285, 1e-6, 0.0);  // ref/stress.out row 126
  EXPECT_GT(pd.active_surface(), 0);
}

TEST(PressureDependMultiYield02, RevertCloneAndCopy) {
  auto m = parse(golden_words());
  consolidate(*m);
  const double gamma[] = {1e-4, 3e-4, 6e-4, 2e-4, -3e-4};
  for (double g : gamma) {
    m->set_trial_strain(Vector3(0.0, -3.32673e-4, g));
    m->commit_state();
  }
  const Vector3 committed = m->stress();
  const auto clone = m->clone();
  // A trial, then a revert: the committed state again.
  m->set_trial_strain(Vector3(0.0, -3.32673e-4, 1e-3));
  EXPECT_GT((m->stress() - committed).norm(), 1.0);
  m->revert_to_last_commit();
  EXPECT_EQ((m->stress() - committed).norm(), 0.0);
  // The clone and the reverted original answer the same next step bit for bit.
  const Vector3 next(1e-5, -3.3e-4, 8e-4);
  m->set_trial_strain(next);
  clone->set_trial_strain(next);
  EXPECT_EQ((m->stress() - clone->stress()).norm(), 0.0);
  EXPECT_EQ((m->tangent() - clone->tangent()).norm(), 0.0);
  // copy_for: the start state (zero stress), plane strain only.
  const auto fresh = m->copy_for(PlaneType::PlaneStrain);
  EXPECT_EQ(fresh->stress().norm(), 0.0);
  EXPECT_EQ(fresh->strain().norm(), 0.0);
  EXPECT_THROW(m->copy_for(PlaneType::PlaneStress), common::InputError);
  // revert_to_start: zero stress, and a fresh plastic switch on the next consolidation.
  m->revert_to_start();
  EXPECT_EQ(m->stress().norm(), 0.0);
  EXPECT_EQ(as_pdmy(m).active_surface(), 0);
}

TEST(PressureDependMultiYield02, BackboneResponseFollowsTheSurfaces) {
  const auto m = parse(golden_words());
  const auto& pd = as_pdmy(m);
  const auto bb = pd.backbone({101.0, 50.0, -1.0});
  ASSERT_EQ(bb.rows(), 21);
  ASSERT_EQ(bb.cols(), 6);
  EXPECT_EQ(bb(0, 0), 101.0);
  EXPECT_EQ(bb(0, 2), 50.0);
  // At p = refPress: G_r, and the first surface at tau = M_1 (p + p_r) / sqrt(3).
  const double pr = pd.residual_pressure();
  const double tau1 = pd.surfaces()[1].size * (101.0 + pr) / std::sqrt(3.0);
  EXPECT_CLOSE(bb(1, 1), 6.0e4, 1e-9, 1e-12);
  EXPECT_CLOSE(bb(1, 0), tau1 / 6.0e4, 1e-15, 1e-12);
  // At 50 kPa G scales with ((50 + p_r) / (101 + p_r))^0.5; the secant modulus falls along the curve.
  EXPECT_CLOSE(bb(1, 3), 6.0e4 * std::sqrt((50.0 + pr) / (101.0 + pr)), 1e-9, 1e-12);
  for (int i = 2; i <= 20; ++i) EXPECT_LT(bb(i, 1), bb(i - 1, 1)) << "row " << i;
  // A confinement <= 0 leaves its columns empty, as OpenSees (it prints a warning).
  EXPECT_EQ(bb(5, 4), 0.0);
  EXPECT_EQ(bb(5, 5), 0.0);
}

TEST(PressureDependMultiYield02, JsonIsValidWithOpenSeesNames) {
  const auto m = parse(golden_words());
  const auto j = nlohmann::json::parse(m->to_json().dump());  // round trip: valid JSON
  EXPECT_EQ(j.at("type"), "PressureDependMultiYield02");
  EXPECT_EQ(j.at("name"), "1");
  EXPECT_DOUBLE_EQ(j.at("frictionAng").get<double>(), 31.0);
  EXPECT_DOUBLE_EQ(j.at("PTAng").get<double>(), 26.0);
  EXPECT_DOUBLE_EQ(j.at("e").get<double>(), 0.68);
  EXPECT_EQ(j.at("noYieldSurf").get<int>(), 20);
}

}  // namespace
