// Unit tests of PM4Sand (fem_tcl/materials/pm4sand.hpp): parameters, stages, commands, responses, copies.
// References: OpenSees 3.8's PM4Sand.cpp (commit 2890cb36): OPS_PM4SandMaterial (the Tcl defaults: P_atm 101.3,
// emax 0.8, emin 0.5, nb 0.5, nd 0.1, cz 250, phicv 33, nu 0.3, Cgd 2, Q 10, R 1.5, m 0.01, IntScheme 5, TanType 0,
// TolF = TolR = 1e-8), the constructor (the Dr-derived defaults, lines "m_h0 = ..." to "m_p_sedo = ..."),
// initialize(Vector) (Ado, z_max), GetElasticModuli (the stage-0 and stage-1 moduli), setResponse / getState;
// and Boulanger & Ziotopoulou (2017), PM4Sand v3.1 manual (Report UCD/CGM-17/01), table 3.1 and section 4.1
// (default secondary parameters).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "common/command_args.hpp"
#include "common/input_error.hpp"
#include "fem_tcl/materials/pm4sand.hpp"
#include "support/input_error_message.hpp"
#include "support/pm4_paths.hpp"
#include "support/tolerance.hpp"

namespace {

using fem::materials::Matrix3;
using fem::materials::PlaneType;
using fem::materials::PM4Sand;
using fem::materials::PM4SandParameters;
using fem::materials::Vector3;
using test_support::input_error_message;

constexpr double kPatm = 101.3;
constexpr double kPi = 3.14159265359;

PM4SandParameters sand(double Dr) {
  PM4SandParameters p;
  p.Dr = Dr;
  p.G0 = 476.0;
  p.hpo = 0.53;
  p.density = 1.7;
  return p;
}

std::unique_ptr<fem::materials::NDMaterial> parse(const std::vector<std::string>& words) {
  common::CommandArgs args("nDMaterial PM4Sand", "usage", words);
  return fem::materials::parse_pm4sand(args);
}

/// Stage 0 (linear, G = G0 P_atm, K from nu): the strain that gives sxx = syy = -p (compression p > 0).
Vector3 isotropic_strain(const PM4SandParameters& p, double pressure) {
  const double G = p.G0 * kPatm;
  const double K = 2.0 / 3.0 * (1.0 + p.nu) / (1.0 - 2.0 * p.nu) * G;
  // sxx = (K + 4G/3) exx + (K - 2G/3) eyy with exx = eyy = e: (2K + 2G/3) e
  return Vector3(-pressure / (2.0 * K + 2.0 * G / 3.0), -pressure / (2.0 * K + 2.0 * G / 3.0), 0.0);
}

/// A material consolidated isotropically to p (stage 0), then stage 1 and FirstCall, as scripts do.
PM4Sand consolidated(const PM4SandParameters& p, double pressure) {
  return test_support::consolidated(PM4Sand(1, p), isotropic_strain(p, pressure));
}

// OpenSees' constructor: h0 = max(0.3, (0.25 + Dr) / 2); ce = 0.5 (Dr < 0.55), 0.5 - 1.5 (Dr - 0.55)
// (0.55..0.75), 0.2 (Dr > 0.75); Cdr = min(5 + 25 (Dr - 0.35), 10); Ckaf = clamp(5 + 220 (Dr - 0.26)^3, 4, 35);
// Fsed_min = min(0.03 exp(2.6 Dr), 0.99); p_sedo = P_atm / 5; Mc = 2 sin(phicv); e0 = emax - (emax - emin) Dr.
TEST(PM4SandParameters, DerivedDefaultsFollowOpenSeesFormulas) {
  for (double Dr : {0.35, 0.55, 0.75}) {
    SCOPED_TRACE("Dr " + std::to_string(Dr));
    const PM4Sand m(1, sand(Dr));
    const PM4SandParameters& p = m.parameters();
    const double ce = Dr > 0.75 ? 0.2 : (Dr < 0.55 ? 0.5 : 0.5 - (Dr - 0.55) * 1.5);
    EXPECT_CLOSE(p.h0, std::max(0.3, (0.25 + Dr) / 2.0), 0.0, 1e-14);
    EXPECT_CLOSE(p.ce, ce, 0.0, 1e-14);
    EXPECT_CLOSE(p.Cdr, std::min(5.0 + 25.0 * (Dr - 0.35), 10.0), 0.0, 1e-14);
    EXPECT_CLOSE(p.Ckaf, std::clamp(5.0 + 220.0 * std::pow(Dr - 0.26, 3), 4.0, 35.0), 0.0, 1e-14);
    EXPECT_CLOSE(p.Fsed_min, std::min(0.03 * std::exp(2.6 * Dr), 0.99), 0.0, 1e-14);
    EXPECT_CLOSE(p.p_sedo, kPatm / 5.0, 0.0, 1e-14);
    EXPECT_CLOSE(m.critical_stress_ratio(), 2.0 * std::sin(33.0 / 180.0 * kPi), 0.0, 1e-14);
    EXPECT_CLOSE(m.initial_void_ratio(), 0.8 - 0.3 * Dr, 0.0, 1e-14);
    // Ado and z_max wait for the first initialisation (OpenSees keeps -1 until initialize(stress)).
    EXPECT_EQ(p.Ado, -1.0);
    EXPECT_EQ(p.z_max, -1.0);
    // The Tcl defaults (OPS_PM4SandMaterial).
    EXPECT_EQ(p.P_atm, 101.3);
    EXPECT_EQ(p.emax, 0.8);
    EXPECT_EQ(p.emin, 0.5);
    EXPECT_EQ(p.nb, 0.5);
    EXPECT_EQ(p.nd, 0.1);
    EXPECT_EQ(p.cz, 250.0);
    EXPECT_EQ(p.phi_cv, 33.0);
    EXPECT_EQ(p.nu, 0.3);
    EXPECT_EQ(p.Cgd, 2.0);
    EXPECT_EQ(p.Q, 10.0);
    EXPECT_EQ(p.R, 1.5);
    EXPECT_EQ(p.m, 0.01);
    EXPECT_EQ(p.scheme, 5);
    EXPECT_EQ(p.tangent_type, 0);
    EXPECT_EQ(p.tol_f, 1e-8);
    EXPECT_EQ(p.tol_r, 1e-8);
  }
  // The three densities by hand: 5 + 220 x 0.09^3, 5 + 220 x 0.29^3, 5 + 220 x 0.49^3.
  EXPECT_NEAR(PM4Sand(1, sand(0.35)).parameters().Ckaf, 5.160, 5e-4);
  EXPECT_NEAR(PM4Sand(1, sand(0.55)).parameters().Ckaf, 10.366, 5e-4);
  EXPECT_NEAR(PM4Sand(1, sand(0.75)).parameters().Ckaf, 30.883, 5e-4);
  EXPECT_NEAR(PM4Sand(1, sand(0.75)).parameters().Cdr, 10.0, 0.0);  // 5 + 25 x 0.4 = 15, capped
}

// OpenSees initialize(stress): xi = R / (Q - ln(100 p0 / P_atm)) - Dr; z_max = min(0.7 exp(-6.1 xi), 20);
// dense of critical (xi < 0): Mb = Mc exp(-nb xi), Md = Mc exp(nd xi), Ado = 2.5 (asin(Mb/2) - asin(Mc/2)) /
// (Mb - Md); loose: Ado = 1.24.
TEST(PM4SandParameters, AdoAndZmaxFromTheStressAtFirstCall) {
  const double Mc = 2.0 * std::sin(33.0 / 180.0 * kPi);
  for (double Dr : {0.35, 0.55, 0.75}) {
    for (double pressure : {50.0, 100.0, 400.0}) {
      SCOPED_TRACE("Dr " + std::to_string(Dr) + ", p " + std::to_string(pressure));
      const PM4Sand m = consolidated(sand(Dr), pressure);
      const double p0 = -0.5 * (m.stress()[0] + m.stress()[1]);
      EXPECT_CLOSE(p0, pressure, 1e-9, 1e-12);
      const double xi = 1.5 / (10.0 - std::log(100.0 * p0 / kPatm)) - Dr;
      EXPECT_CLOSE(m.parameters().z_max, std::min(0.7 * std::exp(-6.1 * xi), 20.0), 0.0, 1e-12);
      if (xi < 0.0) {
        const double Mb = Mc * std::exp(-0.5 * xi), Md = Mc * std::exp(0.1 * xi);
        EXPECT_CLOSE(m.parameters().Ado, 2.5 * (std::asin(Mb / 2.0) - std::asin(Mc / 2.0)) / (Mb - Md), 0.0, 1e-12);
      } else {
        EXPECT_EQ(m.parameters().Ado, 1.24);
      }
    }
  }
  // Both branches are exercised: Dr 0.35 at 400 kPa is loose of critical, Dr 0.75 at 50 kPa dense.
  EXPECT_EQ(consolidated(sand(0.35), 400.0).parameters().Ado, 1.24);
  EXPECT_GT(consolidated(sand(0.75), 50.0).parameters().Ado, 0.0);
  EXPECT_NE(consolidated(sand(0.75), 50.0).parameters().Ado, 1.24);
  // Values given on the command line are kept.
  PM4SandParameters given = sand(0.55);
  given.Ado = 0.8;
  given.z_max = 12.0;
  const PM4Sand m = consolidated(given, 100.0);
  EXPECT_EQ(m.parameters().Ado, 0.8);
  EXPECT_EQ(m.parameters().z_max, 12.0);
}

TEST(PM4SandParameters, NegativeMeansDefaultGivenValuesAreKept) {
  // Every optional argument -1 (the documented "use the default"), through the Tcl parser.
  std::vector<std::string> words{"3", "0.55", "476", "0.53", "1.7"};
  for (int i = 0; i < 24; ++i) words.push_back("-1");
  const auto parsed = parse(words);
  const auto& all_default = dynamic_cast<const PM4Sand&>(*parsed).parameters();
  const PM4Sand reference(3, sand(0.55));
  const PM4SandParameters& d = reference.parameters();
  for (auto [a, b] : std::vector<std::pair<double, double>>{
           {all_default.P_atm, d.P_atm}, {all_default.h0, d.h0}, {all_default.emax, d.emax}, {all_default.emin, d.emin},
           {all_default.nb, d.nb}, {all_default.nd, d.nd}, {all_default.Ado, d.Ado}, {all_default.z_max, d.z_max},
           {all_default.cz, d.cz}, {all_default.ce, d.ce}, {all_default.phi_cv, d.phi_cv}, {all_default.nu, d.nu},
           {all_default.Cgd, d.Cgd}, {all_default.Cdr, d.Cdr}, {all_default.Ckaf, d.Ckaf}, {all_default.Q, d.Q},
           {all_default.R, d.R}, {all_default.m, d.m}, {all_default.Fsed_min, d.Fsed_min},
           {all_default.p_sedo, d.p_sedo}, {all_default.tol_f, d.tol_f}, {all_default.tol_r, d.tol_r}}) {
    EXPECT_EQ(a, b);
  }
  EXPECT_EQ(all_default.scheme, 5);
  EXPECT_EQ(all_default.tangent_type, 0);
  // Given values win, except OpenSees' caps: Cdr <= 10, 4 <= Ckaf <= 35, Fsed_min <= 0.99; p_sedo follows P_atm.
  const auto given = parse({"4", "0.55", "476", "0.53", "1.7", "100.0", "0.7", "0.9", "0.6", "0.4", "0.2", "0.9",
                            "8.0", "300", "0.3", "31.0", "0.25", "1.5", "20.0", "50.0", "9.0", "1.2", "0.02", "2.0"});
  const PM4SandParameters& g = dynamic_cast<const PM4Sand&>(*given).parameters();
  EXPECT_EQ(g.P_atm, 100.0);
  EXPECT_EQ(g.h0, 0.7);
  EXPECT_EQ(g.emax, 0.9);
  EXPECT_EQ(g.emin, 0.6);
  EXPECT_EQ(g.nb, 0.4);
  EXPECT_EQ(g.nd, 0.2);
  EXPECT_EQ(g.Ado, 0.9);
  EXPECT_EQ(g.z_max, 8.0);
  EXPECT_EQ(g.cz, 300.0);
  EXPECT_EQ(g.ce, 0.3);
  EXPECT_EQ(g.phi_cv, 31.0);
  EXPECT_EQ(g.nu, 0.25);
  EXPECT_EQ(g.Cgd, 1.5);
  EXPECT_EQ(g.Cdr, 10.0);
  EXPECT_EQ(g.Ckaf, 35.0);
  EXPECT_EQ(g.Q, 9.0);
  EXPECT_EQ(g.R, 1.2);
  EXPECT_EQ(g.m, 0.02);
  EXPECT_EQ(g.Fsed_min, 0.99);
  EXPECT_EQ(g.p_sedo, 20.0);  // P_atm / 5 of the given P_atm
  // ce = 0 also means the default (OpenSees tests ce > 0).
  PM4SandParameters zero_ce = sand(0.75);
  zero_ce.ce = 0.0;
  EXPECT_CLOSE(PM4Sand(1, zero_ce).parameters().ce, 0.5 - 0.2 * 1.5, 0.0, 1e-14);
}

TEST(PM4SandParameters, BadInputNamesTheArgument) {
  const auto message = [](PM4SandParameters p) { return input_error_message([&] { PM4Sand m(7, p); }); };
  PM4SandParameters p = sand(1.5);
  EXPECT_NE(message(p).find("Dr"), std::string::npos) << message(p);
  EXPECT_NE(message(p).find("nDMaterial PM4Sand 7"), std::string::npos) << message(p);
  p = sand(-0.1);
  EXPECT_NE(message(p).find("Dr"), std::string::npos);
  p = sand(0.5);
  p.G0 = 0.0;
  EXPECT_NE(message(p).find("G0"), std::string::npos) << message(p);
  p.G0 = -10.0;
  EXPECT_NE(message(p).find("G0"), std::string::npos);
  p = sand(0.5);
  p.hpo = 0.0;
  EXPECT_NE(message(p).find("hpo"), std::string::npos);
  p = sand(0.5);
  p.density = -1.0;
  EXPECT_NE(message(p).find("Den"), std::string::npos);
  p = sand(0.5);
  p.scheme = 7;
  EXPECT_NE(message(p).find("IntScheme"), std::string::npos);
  p = sand(0.5);
  p.emax = 0.4;
  EXPECT_NE(message(p).find("emax"), std::string::npos);
  // The parser: a word that is not a number, too many words, an integer argument given as 1.5.
  EXPECT_NE(input_error_message([] { parse({"1", "0.5", "abc", "0.5", "1.7"}); }).find("G0"), std::string::npos);
  std::vector<std::string> long_line{"1", "0.5", "476", "0.5", "1.7"};
  for (int i = 0; i < 25; ++i) long_line.push_back("-1");
  EXPECT_NE(input_error_message([&] { parse(long_line); }).find("unexpected argument"), std::string::npos);
  std::vector<std::string> half_scheme{"1", "0.5", "476", "0.5", "1.7"};
  for (int i = 0; i < 20; ++i) half_scheme.push_back("-1");
  half_scheme.push_back("1.5");
  EXPECT_NE(input_error_message([&] { parse(half_scheme); }).find("IntScheme"), std::string::npos);
  EXPECT_NE(input_error_message([] { parse({"1", "0.5", "476", "0.5"}); }).find("Den"), std::string::npos);
}

TEST(PM4SandStages, UnknownStageAndPlaneStressAreInputErrors) {
  PM4Sand m(5, sand(0.5));
  const std::string stage = input_error_message([&] { m.update_stage(2); });
  EXPECT_NE(stage.find("stage 2"), std::string::npos) << stage;
  EXPECT_NE(input_error_message([&] { m.set_parameter("updateMaterialStage", 3.0); }).find("stage 3"), std::string::npos);
  EXPECT_EQ(m.stage(), 0);
  const std::string plane = input_error_message([&] { (void)m.copy_for(PlaneType::PlaneStress); });
  EXPECT_NE(plane.find("plane-stress"), std::string::npos) << plane;
  EXPECT_NE(plane.find("PM4Sand 5"), std::string::npos) << plane;
  EXPECT_NE(input_error_message([&] { m.set_parameter("IntegrationScheme", 9.0); }).find("IntegrationScheme"),
            std::string::npos);
  EXPECT_NE(input_error_message([&] { m.set_parameter("refShearModulus", -3.0); }).find("G0"), std::string::npos);
  EXPECT_TRUE(m.copy_for(PlaneType::PlaneStrain) != nullptr);
}

// GetElasticModuli: stage 0 G = G0 P_atm whatever p; stage 1 G = G0 P_atm sqrt(p / P_atm) C_SR with C_SR = 1 at
// an isotropic stress; K = 2 (1 + nu) / (3 (1 - 2 nu)) G in both. The tangent is the elastic matrix (TanType 0).
TEST(PM4SandStages, ElasticStageModuliIgnorePressurePlasticStageFollowsSqrtP) {
  const PM4SandParameters p = sand(0.55);
  const double G_elastic = p.G0 * kPatm;
  const auto K_of = [&](double G) { return 2.0 / 3.0 * 1.3 / 0.4 * G; };
  for (double pressure : {10.0, 100.0, 400.0}) {
    PM4Sand m(1, p);
    m.set_trial_strain(isotropic_strain(p, pressure));
    m.commit_state();
    EXPECT_CLOSE(m.tangent()(2, 2), G_elastic, 0.0, 1e-12);
    EXPECT_CLOSE(m.tangent()(0, 1), K_of(G_elastic) - 2.0 / 3.0 * G_elastic, 0.0, 1e-12);
    EXPECT_CLOSE(m.stress()[0], -pressure, 1e-9, 1e-12);
    m.update_stage(1);
    m.set_parameter("FirstCall", 0.0);
    const double G = G_elastic * std::sqrt(pressure / kPatm);
    EXPECT_CLOSE(m.initial_tangent()(2, 2), G, 0.0, 1e-12);
    EXPECT_CLOSE(m.tangent()(0, 0), K_of(G) + 4.0 / 3.0 * G, 0.0, 1e-12);
    // FirstCall keeps the stress (inside the bounding surface, no offset) and sets alpha = s / p = 0.
    EXPECT_CLOSE(m.stress()[1], -pressure, 1e-9, 1e-12);
    const std::vector<double> alpha = *m.response("alpha");
    for (double a : alpha) EXPECT_EQ(a, 0.0);
  }
}

/// Undrained simple shear (exx = eyy = 0) from K0 = 0.5 consolidation at 100 kPa, cycles of +-0.3 % shear strain
/// in steps of `step`.
std::vector<Vector3> cyclic_path(double step = 2e-5) {
  return test_support::undrained_cyclic_path(Vector3(0.0, -4.0e-4, 0.0), 3e-3, 3, step);
}

/// The stresses along the whole path, stage 1 and FirstCall before row 20.
std::vector<Vector3> run_path(PM4Sand m, const std::vector<Vector3>& path) {
  return test_support::drive(m, path, 0, path.size());
}

TEST(PM4SandState, CloneCarriesTheStateRevertRestoresTheCommit) {
  PM4Sand m(1, sand(0.45));
  const auto path = cyclic_path();
  test_support::drive(m, path, 0, 200);
  test_support::expect_clone_and_revert(m, path, 200, 260);
  // copy_for gives the start state (zero stress, Ado / z_max as computed), keeping the stage.
  const auto fresh = m.copy_for(PlaneType::PlaneStrain);
  EXPECT_EQ(fresh->stress(), Vector3::Zero());
  EXPECT_EQ(dynamic_cast<const PM4Sand&>(*fresh).stage(), 1);
  EXPECT_EQ(dynamic_cast<const PM4Sand&>(*fresh).parameters().z_max, m.parameters().z_max);
}

// The integration schemes (IntScheme 1..5) integrate the same equations: on an undrained cyclic path (3 cycles of
// +-0.3 %, p' falling from 67 to 5 kPa) they converge to the default (5: modified Euler on 1e-5 sub-increments)
// as the strain step shrinks. Measured: with 5e-6 steps (the golden DSS run's) every scheme is within 0.05 kPa
// of it (0.3 % of the shear stress amplitude); with 2e-5 steps modified Euler without sub-increments (1) is within
// 0.02 kPa, forward Euler (2) 0.16, Runge-Kutta 4 (3, two fixed halves) 1.4, forward Euler on sub-increments (4)
// 1.2 kPa (its first sub-increment evaluates n, D, h at the whole step's elastic trial, as OpenSees).
TEST(PM4SandState, IntegrationSchemesConvergeToTheDefault) {
  const auto worst_difference = [](int scheme, double step, double& tau_peak) {
    const auto path = cyclic_path(step);
    const auto reference = run_path(PM4Sand(1, sand(0.45)), path);
    PM4SandParameters p = sand(0.45);
    p.scheme = scheme;
    const auto result = run_path(PM4Sand(1, p), path);
    double worst = 0.0;
    tau_peak = 0.0;
    for (std::size_t i = 0; i < path.size(); ++i) {
      worst = std::max(worst, (result[i] - reference[i]).cwiseAbs().maxCoeff());
      tau_peak = std::max(tau_peak, std::abs(reference[i][2]));
    }
    return worst;
  };
  double tau_peak = 0.0;
  for (int scheme : {1, 2, 3, 4}) {
    SCOPED_TRACE("IntScheme " + std::to_string(scheme));
    const double fine = worst_difference(scheme, 5e-6, tau_peak);
    EXPECT_GT(tau_peak, 15.0);
    EXPECT_LT(fine, 0.01 * tau_peak);
    const double coarse = worst_difference(scheme, 2e-5, tau_peak);
    if (scheme == 1) EXPECT_LT(coarse, 0.002 * tau_peak);
    else EXPECT_LT(fine, coarse / 3.0);
  }
  // Pore pressure builds up: syy (negative) is much less compressive after the cycles.
  const auto path = cyclic_path();
  const auto reference = run_path(PM4Sand(1, sand(0.45)), path);
  EXPECT_GT(reference.back()[1], reference[19][1] + 40.0);
}

TEST(PM4SandCommands, ParametersResponsesAndJson) {
  PM4Sand m(2, sand(0.55));
  const auto path = cyclic_path();
  test_support::drive(m, path, 0, 100);  // updateMaterialStage 1, FirstCall before row 20
  EXPECT_EQ(m.stage(), 1);
  test_support::expect_pm4_response_lengths(m);
  const auto stress = *m.response("stress");
  EXPECT_EQ(stress[2], m.stress()[2]);
  EXPECT_EQ((*m.response("strain"))[1], path[99][1]);
  const auto s3 = *m.response("stress3D");
  EXPECT_CLOSE(s3[2], 0.5 * (stress[0] + stress[1]), 0.0, 1e-14);
  EXPECT_EQ(s3[3], stress[2]);
  // state: the elastic strain (model sign: compression positive), alpha, fabric, alpha_in, e, dgamma, G, Kp.
  const auto state = *m.response("state");
  EXPECT_EQ(state[3], (*m.response("alpha"))[0]);
  EXPECT_EQ(state[6], (*m.response("fabric"))[0]);
  EXPECT_EQ(state[9], (*m.response("alpha_in"))[0]);
  EXPECT_CLOSE(state[12], m.initial_void_ratio() - (1.0 + m.initial_void_ratio()) * -(path[99][0] + path[99][1]), 1e-12, 0.0);
  EXPECT_GT(state[14], 0.0);
  // Parameters: known names return true, others false.
  for (const char* name : {"poissonRatio", "refShearModulus", "ShearModulus", "IntegrationScheme", "materialState"}) {
    const double value = std::string(name) == "poissonRatio" ? 0.25 : (std::string(name) == "IntegrationScheme" ? 1.0 : (std::string(name) == "materialState" ? 1.0 : 500.0));
    EXPECT_TRUE(m.set_parameter(name, value)) << name;
  }
  EXPECT_EQ(m.parameters().nu, 0.25);
  EXPECT_EQ(m.parameters().G0, 500.0);
  EXPECT_EQ(m.parameters().scheme, 1);
  EXPECT_TRUE(m.set_parameter("voidRatio", 0.7));
  EXPECT_CLOSE(m.initial_void_ratio(), (0.7 + -(path[99][0] + path[99][1])) / (1.0 - -(path[99][0] + path[99][1])), 0.0, 1e-14);
  EXPECT_TRUE(m.set_parameter("PostShake", 1.0));
  EXPECT_FALSE(m.set_parameter("E", 1.0));
  EXPECT_FALSE(m.set_parameter("frictionAngle", 30.0));
  EXPECT_EQ(m.density(), 1.7);
  const nlohmann::json j = nlohmann::json::parse(m.to_json().dump());
  EXPECT_EQ(j["type"], "PM4Sand");
  EXPECT_EQ(j["name"], "2");
  EXPECT_EQ(j["Dr"], 0.55);
  EXPECT_EQ(j["Ado"], m.parameters().Ado);
  EXPECT_EQ(j["IntScheme"], 1);
  EXPECT_EQ(m.type_name(), "PM4Sand");
}

// FirstCall beyond the bounding surface: OpenSees scales the stress ratio onto max(Mb, Md) and keeps the
// difference as an offset, so the reported stress (the element's equilibrium) does not jump.
TEST(PM4SandState, FirstCallOutsideTheBoundingSurfaceKeepsTheReportedStress) {
  const PM4SandParameters p = sand(0.35);
  PM4Sand m(1, p);
  const double G = p.G0 * kPatm;
  m.set_trial_strain(Vector3(0.0, 0.0, 80.0 / G) + isotropic_strain(p, 100.0));  // tau 80 kPa at p 100: q / p = 1.6
  m.commit_state();
  const Vector3 before = m.stress();
  m.update_stage(1);
  m.set_parameter("FirstCall", 0.0);
  EXPECT_CLOSE(m.stress()[2], before[2], 1e-9, 1e-12);
  EXPECT_CLOSE(m.stress()[0], before[0], 1e-9, 1e-12);
  // alpha sits inside: |alpha| sqrt(2) = (M_cut - m) < 1.6.
  const auto a = *m.response("alpha");
  EXPECT_LT(std::sqrt(2.0) * std::sqrt(a[0] * a[0] + a[1] * a[1] + 2.0 * a[2] * a[2]), 1.6);
  EXPECT_GT(std::abs(a[2]), 0.3);
}

}  // namespace
