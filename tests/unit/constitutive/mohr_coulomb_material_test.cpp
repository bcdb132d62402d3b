// Unit tests of fem::materials::MohrCoulomb (the FEM material around the constitutive Mohr-Coulomb kernel):
// parsing, JSON keys, stages, plane-strain szz, commit / revert, parameters.
#include "fem_tcl/materials/mohr_coulomb.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "common/input_error.hpp"
#include "fem_tcl/materials/material_registry.hpp"
#include "support/tolerance.hpp"

namespace {

using fem::materials::MohrCoulomb;
using fem::materials::PlaneType;
using fem::materials::Vector3;

std::unique_ptr<fem::materials::NDMaterial> parse(std::vector<std::string> words) {
  const auto parser = fem::materials::find_nd_material_parser("MohrCoulomb");
  EXPECT_NE(parser, nullptr);
  common::CommandArgs args("nDMaterial MohrCoulomb", "nDMaterial MohrCoulomb tag E nu rho phi c psi <-tension T>",
                           std::move(words));
  return parser(args);
}

// The paper's soil: E = 172 MPa, nu = 0.23, 1925 kg/m3, phi = 22.2 deg, minimal cohesion.
std::unique_ptr<fem::materials::NDMaterial> paper_soil() {
  return parse({"3", "172e6", "0.23", "1925", "22.2", "10", "0"})->copy_for(PlaneType::PlaneStrain);
}

TEST(MohrCoulombMaterial, ParsesAndWritesTheBridgeJson) {
  const auto m = parse({"3", "172e6", "0.23", "1925", "22.2", "10", "0"});
  const nlohmann::json j = nlohmann::json::parse(m->to_json().dump());
  EXPECT_EQ(j.at("name"), "3");
  EXPECT_EQ(j.at("type"), "MohrCoulomb");
  EXPECT_EQ(j.at("E"), 172e6);
  EXPECT_EQ(j.at("nu"), 0.23);
  EXPECT_EQ(j.at("rho"), 1925.0);
  EXPECT_EQ(j.at("phi"), 22.2);
  EXPECT_EQ(j.at("c"), 10.0);
  EXPECT_EQ(j.at("psi"), 0.0);
  EXPECT_TRUE(j.at("tension").is_null());
  EXPECT_EQ(j.size(), 9u);
  EXPECT_EQ(m->density(), 1925.0);
  const auto t = parse({"4", "1e7", "0.3", "0", "30", "0", "5", "-tension", "2.5"});
  EXPECT_EQ(t->to_json().at("tension"), 2.5);
}

TEST(MohrCoulombMaterial, RejectsBadInput) {
  EXPECT_THROW(parse({"3", "172e6", "0.23", "1925", "22.2", "10"}), common::InputError);          // missing psi
  EXPECT_THROW(parse({"3", "-1", "0.23", "1925", "22.2", "10", "0"}), common::InputError);        // E
  EXPECT_THROW(parse({"3", "1e6", "0.5", "1925", "22.2", "10", "0"}), common::InputError);        // nu
  EXPECT_THROW(parse({"3", "1e6", "0.2", "1925", "95", "10", "0"}), common::InputError);          // phi
  EXPECT_THROW(parse({"3", "1e6", "0.2", "1925", "30", "-1", "0"}), common::InputError);          // c
  EXPECT_THROW(parse({"3", "1e6", "0.2", "1925", "30", "1", "0", "-tension"}), common::InputError);
  EXPECT_THROW(parse({"3", "1e6", "0.2", "1925", "30", "1", "0", "extra"}), common::InputError);
  EXPECT_THROW(parse({"3", "1e6", "0.2", "1925", "30", "1", "0"})->copy_for(PlaneType::PlaneStress), common::InputError);
}

TEST(MohrCoulombMaterial, StageZeroIsLinearElasticWithPlaneStrainSzz) {
  auto m = paper_soil();
  EXPECT_EQ(static_cast<MohrCoulomb&>(*m).stage(), 0);
  const Vector3 e(2e-3, -5e-3, 4e-3);  // far beyond the strength: still elastic in stage 0
  m->set_trial_strain(e);
  const double E = 172e6, nu = 0.23, c = E / ((1 + nu) * (1 - 2 * nu));
  EXPECT_CLOSE(m->stress()[0], c * ((1 - nu) * e[0] + nu * e[1]), 1e-3, 1e-12);
  EXPECT_CLOSE(m->stress()[1], c * (nu * e[0] + (1 - nu) * e[1]), 1e-3, 1e-12);
  EXPECT_CLOSE(m->stress()[2], E / (2 * (1 + nu)) * e[2], 1e-3, 1e-12);
  EXPECT_CLOSE(m->stress_3d()[2], nu * (m->stress()[0] + m->stress()[1]), 1e-3, 1e-12);
  EXPECT_CLOSE(m->tangent()(0, 0), c * (1 - nu), 1e-3, 1e-12);
  EXPECT_EQ(m->response("yieldRegion")->at(0), 0.0);
}

TEST(MohrCoulombMaterial, StageSwitchKeepsTheStressAndYields) {
  auto m = paper_soil();
  // Gravity-like elastic state (stage 0), committed.
  m->set_trial_strain({-5e-4, -5e-4, 0.0});
  m->commit_state();
  const Vector3 s0 = m->stress();
  ASSERT_TRUE(m->update_stage(1));
  m->set_trial_strain({-5e-4, -5e-4, 0.0});  // same strain: same stress (it is inside the surface)
  EXPECT_EQ(m->stress(), s0);
  // Shear it far: plastic, admissible, with the out-of-plane elastic strain cancelling the plastic one.
  m->set_trial_strain({-5e-4, -5e-4, 5e-3});
  EXPECT_NE(m->response("yieldRegion")->at(0), 0.0);
  const constitutive::MohrCoulombStrength st{22.2 * M_PI / 180, 0.0, 10.0, INFINITY};
  const Eigen::Vector4d s4 = static_cast<MohrCoulomb&>(*m).stress_plane_strain();
  EXPECT_LE(constitutive::mohr_coulomb_yield(s4, st), 1e-6);
  const double E = 172e6, nu = 0.23;
  const double elastic_ezz = (s4[2] - nu * (s4[0] + s4[1])) / E;
  const auto ep = m->response("plasticStrain");
  ASSERT_TRUE(ep.has_value());
  EXPECT_CLOSE(elastic_ezz + (*ep)[2], 0.0, 1e-12, 0.0);  // total ezz = 0 (plane strain)
  // revert: back to the committed state.
  m->revert_to_last_commit();
  EXPECT_EQ(m->stress(), s0);
  EXPECT_THROW(m->update_stage(2), common::InputError);
  EXPECT_TRUE(m->set_parameter("updateMaterialStage", 0));
  EXPECT_EQ(static_cast<MohrCoulomb&>(*m).stage(), 0);
}

TEST(MohrCoulombMaterial, ParametersAndResponses) {
  auto m = paper_soil();
  EXPECT_TRUE(m->set_parameter("phi", 30.0));
  EXPECT_TRUE(m->set_parameter("c", 0.0));
  EXPECT_TRUE(m->set_parameter("E", 50e6));
  EXPECT_FALSE(m->set_parameter("noSuchThing", 1.0));
  EXPECT_THROW(m->set_parameter("phi", 120.0), common::InputError);
  EXPECT_EQ(m->to_json().at("phi"), 30.0);  // the failed update left the material as it was
  EXPECT_EQ(m->response("stress3D")->size(), 6u);
  EXPECT_EQ(m->response("stress")->size(), 3u);
  m->set_trial_strain({1e-4, 0.0, 0.0});
  m->revert_to_start();
  EXPECT_EQ(m->stress().norm(), 0.0);
}

}  // namespace
