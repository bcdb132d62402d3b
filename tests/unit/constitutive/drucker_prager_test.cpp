// Unit tests of fem::materials::DruckerPrager (OpenSees 3.8's DruckerPrager, plane strain): single-step returns
// against hand-computed values of the OpenSees equations (DruckerPrager.cpp, plastic_integrator), the
// materialState switch, the documented quirks, responses, parsing and JSON.
#include "fem_tcl/materials/drucker_prager.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <string>

#include "common/input_error.hpp"
#include "fem_tcl/materials/material_registry.hpp"
#include "support/tolerance.hpp"

namespace {

using fem::materials::DruckerPrager;
using fem::materials::DruckerPragerParameters;
using fem::materials::PlaneType;
using Vector6d = DruckerPrager::Vector6d;

// The parameters of reference case 1.3 (dp_column_stage_switch): E = 80e3, nu = 0.25, phi = 30 deg, c = 5.
DruckerPragerParameters column_parameters() {
  DruckerPragerParameters p{};
  p.bulk_modulus = 53333.33;
  p.shear_modulus = 32000;
  p.sigma_y = 7.20577;
  p.rho = 0.226455;
  p.rho_bar = 0.226455;
  p.k_inf = 0;
  p.k_o = 0;
  p.delta1 = 0;
  p.delta2 = 0;
  p.hardening = 10000;
  p.theta = 1;
  p.density = 1.8;
  return p;
}

std::unique_ptr<fem::materials::NDMaterial> make(const DruckerPragerParameters& p) {
  return DruckerPrager(1, p).copy_for(PlaneType::PlaneStrain);
}

/// Elastic plane-strain trial stress (6 components) for total strain (exx, eyy, gxy).
Vector6d elastic_stress(const DruckerPragerParameters& p, const fem::materials::Vector3& e) {
  const double k = p.bulk_modulus, g = p.shear_modulus, vol = e[0] + e[1];
  Vector6d s = Vector6d::Zero();
  s[0] = k * vol + 2 * g * (e[0] - vol / 3);
  s[1] = k * vol + 2 * g * (e[1] - vol / 3);
  s[2] = k * vol + 2 * g * (-vol / 3);
  s[3] = g * e[2];
  return s;
}

double norm_dev(const Vector6d& s, double* i1_out) {
  const double i1 = s[0] + s[1] + s[2];
  *i1_out = i1;
  Vector6d d = s;
  d.head<3>().array() -= i1 / 3;
  return std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2] + 2 * d[3] * d[3]);
}

TEST(DruckerPrager, StartsElastoplasticAndSwitchesWithMaterialState) {
  auto m = make(column_parameters());
  EXPECT_EQ(static_cast<DruckerPrager&>(*m).material_state(), 2);
  const fem::materials::Vector3 e(-1e-3, -4e-3, 3e-3);  // far outside the cone
  ASSERT_TRUE(m->set_parameter("materialState", 0));
  m->set_trial_strain(e);
  const Vector6d el = elastic_stress(column_parameters(), e);
  EXPECT_CLOSE(m->stress()[0], el[0], 1e-9, 1e-12);
  EXPECT_CLOSE(m->stress()[1], el[1], 1e-9, 1e-12);
  EXPECT_CLOSE(m->stress()[2], el[3], 1e-9, 1e-12);
  EXPECT_CLOSE(m->stress_3d()[2], el[2], 1e-9, 1e-12);
  EXPECT_CLOSE(m->tangent()(0, 0), 53333.33 + 4.0 / 3.0 * 32000, 1e-9, 1e-12);
  EXPECT_CLOSE(m->tangent()(2, 2), 32000, 1e-9, 1e-12);
  // Back to 2 with the same strain: now it returns to the cone.
  ASSERT_TRUE(m->set_parameter("materialState", 2));
  m->set_trial_strain(e);
  EXPECT_LT(std::abs(m->stress()[2]), std::abs(el[3]));
  // Unknown parameter names and updateMaterialStage have no effect.
  EXPECT_FALSE(m->set_parameter("noSuchParameter", 1.0));
  EXPECT_FALSE(m->update_stage(1));
}

TEST(DruckerPrager, ConeReturnMatchesHandComputation) {
  for (double rho_bar : {0.226455, 0.05})  // associated, then non-associated flow
  for (double theta : {1.0, 0.4}) {        // isotropic, then mixed isotropic / kinematic hardening
    DruckerPragerParameters p = column_parameters();
    p.rho_bar = rho_bar;
    p.theta = theta;
    auto m = make(p);
    const fem::materials::Vector3 e(-1e-3, -3e-3, 2e-3);
    m->set_trial_strain(e);
    // Hand computation: f1 = ||s|| + rho I1 - sqrt(2/3) sigma_y; with linear hardening the residual is linear:
    // gamma = f1 / (2G + 2/3 H' + 9 K rho rho_bar + 2/3 theta H)   (OpenSees R(0), g(0,0)).
    const Vector6d tr = elastic_stress(p, e);
    double i1;
    const double ns = norm_dev(tr, &i1);
    const double f1 = ns + p.rho * i1 - std::sqrt(2.0 / 3.0) * p.sigma_y;
    ASSERT_GT(f1, 0.0);
    const double hp = (1 - p.theta) * p.hardening;
    const double gamma = f1 / (2 * p.shear_modulus + 2.0 / 3.0 * hp + 9 * p.bulk_modulus * p.rho * p.rho_bar +
                               2.0 / 3.0 * p.theta * p.hardening);
    Vector6d s = tr;
    s.head<3>().array() -= i1 / 3;
    const Vector6d n = s / ns;
    Vector6d expected = tr - 2 * p.shear_modulus * gamma * n;
    expected.head<3>().array() -= 3 * p.bulk_modulus * p.rho_bar * gamma;
    EXPECT_CLOSE(m->stress()[0], expected[0], 1e-9, 1e-10);
    EXPECT_CLOSE(m->stress()[1], expected[1], 1e-9, 1e-10);
    EXPECT_CLOSE(m->stress()[2], expected[3], 1e-9, 1e-10);
    EXPECT_CLOSE(m->stress_3d()[2], expected[2], 1e-9, 1e-10);
    // state: I1, ||s - beta|| after the return, tr(eps_p) = 3 rho_bar gamma, ||dev eps_p|| = gamma ||n||_strain.
    const auto state = m->response("state");
    ASSERT_TRUE(state.has_value());
    ASSERT_EQ(state->size(), 5u);
    EXPECT_CLOSE((*state)[0], i1 - 9 * p.bulk_modulus * p.rho_bar * gamma, 1e-9, 1e-10);
    const double beta_norm = 2.0 / 3.0 * hp * gamma;  // back stress moves along -n
    EXPECT_CLOSE((*state)[1], ns - 2 * p.shear_modulus * gamma + beta_norm, 1e-9, 1e-10);
    EXPECT_CLOSE((*state)[2], 3 * p.rho_bar * gamma, 1e-15, 1e-10);
    // On the hardened cone up to OpenSees' back-stress sign: the residual assumes ||eta|| shrinks by
    // (2G + 2/3 H') gamma while beta_n+1 = beta_n - 2/3 H' gamma n makes it shrink by (2G - 2/3 H') gamma, so
    // f1 after the return is 4/3 H' gamma (zero for purely isotropic hardening, theta = 1, as in case 1.3).
    const double kiso = p.sigma_y + p.theta * p.hardening * std::sqrt(2.0 / 3.0) * gamma;
    EXPECT_CLOSE((*state)[1] + p.rho * (*state)[0] - std::sqrt(2.0 / 3.0) * kiso, 4.0 / 3.0 * hp * gamma, 1e-9, 1e-9);
  }
}

TEST(DruckerPrager, TwoSurfaceReturnReproducesTheOpenSeesResidual) {
  // Volumetric extension beyond the apex: both f1 and f2 > 0. OpenSees never assembles the cap residual
  // (README quirk 12): R = (R1, 0) with the coupled 2x2 Jacobian, so gamma = -g^-1 (f1, 0) for linear hardening.
  const DruckerPragerParameters p = column_parameters();
  auto m = make(p);
  const fem::materials::Vector3 e(2e-3, 1e-3, 0.0);
  m->set_trial_strain(e);
  const Vector6d tr = elastic_stress(p, e);
  double i1;
  const double ns = norm_dev(tr, &i1);
  const double f1 = ns + p.rho * i1 - std::sqrt(2.0 / 3.0) * p.sigma_y;
  const double t0 = std::sqrt(2.0 / 3.0) * p.sigma_y / p.rho;
  ASSERT_GT(f1, 0.0);
  ASSERT_GT(i1 - t0, 0.0);
  const double k = p.bulk_modulus, g = p.shear_modulus;
  Eigen::Matrix2d jac;
  jac << -2 * g - 2.0 / 3.0 * p.hardening - 9 * k * p.rho * p.rho_bar, -9 * k * p.rho,  //
      p.rho_bar * (-9 * k), 1.0;
  const Eigen::Vector2d gamma = -jac.inverse() * Eigen::Vector2d(f1, 0.0);
  ASSERT_GT(gamma[0], 0.0);
  ASSERT_GT(gamma[1], 0.0);
  Vector6d s = tr;
  s.head<3>().array() -= i1 / 3;
  Vector6d expected = tr - 2 * g * gamma[0] * s / ns;
  expected.head<3>().array() -= 3 * k * p.rho_bar * gamma[0] + 3 * k * gamma[1];
  EXPECT_CLOSE(m->stress()[0], expected[0], 1e-9, 1e-10);
  EXPECT_CLOSE(m->stress()[1], expected[1], 1e-9, 1e-10);
  EXPECT_CLOSE(m->stress()[2], expected[3], 1e-9, 1e-10);
  const auto state = m->response("state");
  EXPECT_CLOSE((*state)[2], 3 * (p.rho_bar * gamma[0] + gamma[1]), 1e-15, 1e-10);
}

TEST(DruckerPrager, CommitRevertAndHistory) {
  auto m = make(column_parameters());
  const fem::materials::Vector3 e(-1e-3, -3e-3, 2e-3);
  m->set_trial_strain(e);
  const auto s1 = m->stress();
  m->commit_state();
  // Unloading to zero strain from a plastic state leaves a residual stress (plastic strain was committed).
  m->set_trial_strain(fem::materials::Vector3::Zero());
  EXPECT_GT(m->stress().norm(), 1e-6);
  // Reloading to the same strain gives the same stress (now elastic from the committed plastic strain).
  m->set_trial_strain(e);
  EXPECT_CLOSE(m->stress()[2], s1[2], 1e-9, 1e-9);
  m->revert_to_start();
  m->set_trial_strain(fem::materials::Vector3::Zero());
  EXPECT_EQ(m->stress().norm(), 0.0);
}

TEST(DruckerPrager, ElasticTangentAndInitialTangentInElasticRange) {
  auto m = make(column_parameters());
  m->set_trial_strain({-1e-5, -1e-5, 0.0});
  const double k = 53333.33, g = 32000;
  EXPECT_CLOSE(m->tangent()(0, 1), k - 2.0 / 3.0 * g, 1e-9, 1e-12);
  EXPECT_CLOSE(m->initial_tangent()(0, 1), k - 2.0 / 3.0 * g, 1e-9, 1e-12);
}

TEST(DruckerPrager, ParseDefaultsResponsesAndJson) {
  const auto parse = fem::materials::find_nd_material_parser("DruckerPrager");
  ASSERT_NE(parse, nullptr);
  common::CommandArgs args("nDMaterial DruckerPrager", "usage",
                           {"7", "53333.33", "32000", "7.20577", "0.226455", "0.226455", "0", "0", "0", "0", "10000",
                            "1", "1.8"});
  const auto mat = parse(args);
  EXPECT_EQ(mat->tag(), 7);
  EXPECT_EQ(mat->type_name(), "DruckerPrager");
  EXPECT_EQ(mat->density(), 1.8);
  const nlohmann::json j = nlohmann::json::parse(mat->to_json().dump());
  EXPECT_EQ(j.at("name"), "7");
  EXPECT_EQ(j.at("type"), "DruckerPrager");
  EXPECT_EQ(j.at("atm"), 101.0);
  EXPECT_EQ(j.at("materialState"), 2);
  auto copy = mat->copy_for(PlaneType::PlaneStrain);
  copy->set_trial_strain({1e-6, 0, 0});
  EXPECT_EQ(copy->response("stress3D")->size(), 6u);
  EXPECT_EQ(copy->response("strain")->at(0), 1e-6);
  EXPECT_FALSE(copy->response("nonsense").has_value());
  EXPECT_THROW(mat->copy_for(PlaneType::PlaneStress), common::InputError);
  common::CommandArgs few("nDMaterial DruckerPrager", "usage", {"7", "1", "2"});
  EXPECT_THROW(parse(few), common::InputError);
  common::CommandArgs bad_k("nDMaterial DruckerPrager", "usage",
                            {"7", "-1", "32000", "7", "0.2", "0.2", "0", "0", "0", "0", "0", "1"});
  EXPECT_THROW(parse(bad_k), common::InputError);
}

TEST(DruckerPrager, ThetaOutsideZeroToOneIsAnInputError) {
  // OpenSees' manual: 0 <= theta <= 1. Found by fuzzing: theta 1e308 gave NaN stresses on the first step
  // (the kinematic modulus (1 - theta) H overflowed), written into the recorders by an analysis that "converged".
  for (double theta : {-0.1, 1.5, 1e308}) {
    DruckerPragerParameters p = column_parameters();
    p.theta = theta;
    try {
      DruckerPrager(1, p);
      ADD_FAILURE() << "theta " << theta << " accepted";
    } catch (const common::InputError& e) {
      EXPECT_NE(std::string(e.what()).find("expected 0 <= theta <= 1"), std::string::npos) << e.what();
    }
  }
  for (double theta : {0.0, 0.5, 1.0}) {
    DruckerPragerParameters p = column_parameters();
    p.theta = theta;
    EXPECT_NO_THROW(DruckerPrager(1, p));
  }
}

}  // namespace
