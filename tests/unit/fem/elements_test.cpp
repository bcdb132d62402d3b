// Unit tests: ElasticIsotropic, SSPquad, FourNodeQuad, Tri31 (one class each; properties any correct
// implementation must have: rigid-body modes, symmetry, mass and load totals, rejected geometry).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>

#include "fem_tcl/domain/domain.hpp"
#include "fem_tcl/elements/four_node_quad.hpp"
#include "fem_tcl/elements/ssp_quad.hpp"
#include "fem_tcl/elements/tri31.hpp"
#include "fem_tcl/materials/elastic_isotropic.hpp"
#include "support/tolerance.hpp"

namespace {

using fem::domain::Domain;
using fem::domain::Matrix8;
using fem::domain::Vector8;
using fem::materials::ElasticIsotropic;
using fem::materials::PlaneType;

TEST(ElasticIsotropic, PlaneStrainAndPlaneStressMatrices) {
  const double E = 200.0, nu = 0.25;
  ElasticIsotropic strain(1, E, nu, 2.0, PlaneType::PlaneStrain);
  const double c = E / ((1 + nu) * (1 - 2 * nu));
  EXPECT_CLOSE(strain.tangent()(0, 0), c * (1 - nu), 0.0, 1e-14);
  EXPECT_CLOSE(strain.tangent()(0, 1), c * nu, 0.0, 1e-14);
  EXPECT_CLOSE(strain.tangent()(2, 2), E / (2 * (1 + nu)), 0.0, 1e-14);
  ElasticIsotropic stress(1, E, nu, 2.0, PlaneType::PlaneStress);
  EXPECT_CLOSE(stress.tangent()(0, 0), E / (1 - nu * nu), 0.0, 1e-14);
  EXPECT_CLOSE(stress.tangent()(0, 1), E * nu / (1 - nu * nu), 0.0, 1e-14);
  strain.set_trial_strain(fem::materials::Vector3(1e-3, -2e-3, 5e-4));
  const auto s = strain.stress();
  EXPECT_CLOSE(s[0], c * ((1 - nu) * 1e-3 + nu * -2e-3), 1e-15, 1e-13);
  EXPECT_CLOSE(strain.stress_3d()[2], nu * (s[0] + s[1]), 1e-15, 1e-13);
  EXPECT_EQ(strain.density(), 2.0);
}

TEST(ElasticIsotropic, RejectsBadInputAndUpdatesParameters) {
  EXPECT_THROW(ElasticIsotropic(1, -1.0, 0.3, 0.0), common::InputError);
  EXPECT_THROW(ElasticIsotropic(1, 1.0, 0.5, 0.0), common::InputError);
  ElasticIsotropic m(3, 100.0, 0.2, 1.0);
  EXPECT_TRUE(m.set_parameter("E", 300.0));
  EXPECT_FALSE(m.set_parameter("cohesion", 1.0));
  EXPECT_EQ(m.youngs_modulus(), 300.0);
  const auto j = m.to_json();
  EXPECT_EQ(j["type"], "ElasticIsotropicMaterial");
  EXPECT_EQ(j["name"], "3");
  common::CommandArgs args("nDMaterial ElasticIsotropic", "usage", {"4", "1e3", "0.3"});
  auto parsed = fem::materials::parse_elastic_isotropic(args);
  EXPECT_EQ(parsed->tag(), 4);
  EXPECT_EQ(parsed->density(), 0.0);
  common::CommandArgs bad("nDMaterial ElasticIsotropic", "usage", {"4", "abc", "0.3"});
  EXPECT_THROW(fem::materials::parse_elastic_isotropic(bad), common::InputError);
}

struct QuadFixture {
  Domain domain;
  std::array<fem::domain::Node*, 4> nodes{};
  ElasticIsotropic material{1, 1000.0, 0.3, 2.0};
  // a distorted, counter-clockwise quadrilateral
  explicit QuadFixture(bool clockwise = false) {
    const double x[4] = {0.0, 2.0, 2.3, -0.2};
    const double y[4] = {0.0, 0.3, 1.7, 1.2};
    for (int i = 0; i < 4; ++i) {
      const int k = clockwise ? 3 - i : i;
      nodes[i] = &domain.add_node(i + 1, x[k], y[k], 2, "test");
    }
  }
  double area() const {
    double a = 0.0;
    for (int i = 0; i < 4; ++i) {
      const auto& p = nodes[i]->crd;
      const auto& q = nodes[(i + 1) % 4]->crd;
      a += 0.5 * (p[0] * q[1] - q[0] * p[1]);
    }
    return a;
  }
};

template <class E>
void expect_element_properties(E& e, double area, double thickness, double rho) {
  const Matrix8 K = e.tangent_stiffness();
  EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());
  Eigen::SelfAdjointEigenSolver<Matrix8> eig(K);
  const auto lambda = eig.eigenvalues();
  // three rigid-body modes, five deformation modes (SSPquad: hourglass stabilized, no spurious zero modes)
  for (int i = 0; i < 3; ++i) EXPECT_LT(std::abs(lambda[i]), 1e-10 * lambda[7]);
  EXPECT_GT(lambda[3], 1e-6 * lambda[7]);
  Vector8 rigid;
  const double theta = 1e-3;
  for (int a = 0; a < 4; ++a) {  // translation + infinitesimal rotation
    rigid[2 * a] = 0.1 - theta * e.nodes()[a]->crd[1];
    rigid[2 * a + 1] = -0.2 + theta * e.nodes()[a]->crd[0];
  }
  EXPECT_LT((K * rigid).norm(), 1e-10 * K.norm());
  const Vector8 m = e.lumped_mass();
  EXPECT_CLOSE(m.sum(), 2.0 * rho * area * thickness, 1e-12, 1e-12);
}

TEST(SSPquad, StiffnessMassAndBodyForce) {
  QuadFixture f;
  fem::elements::SSPquad e(1, f.nodes, f.material, PlaneType::PlaneStrain, 0.5, 0.0, -10.0);
  expect_element_properties(e, f.area(), 0.5, 2.0);
  e.update();
  const Vector8 r = e.resisting_force();  // zero displacement: minus the body force
  double fy = 0.0;
  for (int a = 0; a < 4; ++a) fy += r[2 * a + 1];
  EXPECT_CLOSE(fy, 10.0 * f.area() * 0.5, 1e-12, 1e-12);
  const auto stress = e.response({"stress"});
  ASSERT_TRUE(stress.has_value());
  EXPECT_EQ(stress->size(), 3u);
  EXPECT_FALSE(e.response({"bogus"}).has_value());
}

// The strain and internal force are computed from the factors of B0 and Kstab (not the dense matrices): on
// an elastic material the internal force must be K u exactly (to round-off) for any displacement, and the
// kept lumped mass must follow a density changed by setParameter rho.
TEST(SSPquad, InternalForceIsStiffnessTimesDisplacementAndMassFollowsRho) {
  QuadFixture f;
  fem::elements::SSPquad e(1, f.nodes, f.material, PlaneType::PlaneStrain, 0.5, 0.0, 0.0);
  const double u[8] = {1e-3, -2e-3, 3e-4, 5e-4, -7e-4, 1.1e-3, 2e-4, -9e-4};
  Vector8 uv;
  for (int a = 0; a < 4; ++a) {
    f.nodes[a]->disp.head<2>() = fem::domain::Vector2(u[2 * a], u[2 * a + 1]);
    uv[2 * a] = u[2 * a];
    uv[2 * a + 1] = u[2 * a + 1];
  }
  e.update();
  const Vector8 expected = e.tangent_stiffness() * uv;
  const Vector8 force = e.resisting_force();
  EXPECT_LT((force - expected).norm(), 1e-13 * expected.norm());
  const double mass0 = e.lumped_mass().sum();
  EXPECT_TRUE(e.set_parameter("rho", 6.0));
  EXPECT_CLOSE(e.lumped_mass().sum(), 3.0 * mass0, 0.0, 1e-13);
}

TEST(SSPquad, MinJacobianFollowsTheDeformedShape) {
  QuadFixture f;
  fem::elements::SSPquad e(1, f.nodes, f.material, PlaneType::PlaneStrain, 1.0, 0.0, 0.0);
  const double undeformed = e.response({"minJacobian"})->at(0);
  EXPECT_GT(undeformed, 0.0);
  f.nodes[2]->disp.head<2>() = fem::domain::Vector2(-3.0, -2.0);  // push node 3 past the diagonal 2-4: inverted corner
  EXPECT_LT(e.response({"minJacobian"})->at(0), 0.0);
  f.nodes[2]->disp.setZero();
  // a unit square has det J = 1/4 at every corner
  Domain d;
  std::array<fem::domain::Node*, 4> sq{&d.add_node(1, 0, 0, 2, "t"), &d.add_node(2, 1, 0, 2, "t"), &d.add_node(3, 1, 1, 2, "t"),
                                       &d.add_node(4, 0, 1, 2, "t")};
  fem::elements::SSPquad unit(2, sq, f.material, PlaneType::PlaneStrain, 1.0, 0.0, 0.0);
  EXPECT_CLOSE(unit.response({"minJacobian"})->at(0), 0.25, 0.0, 1e-15);
}

TEST(SSPquad, RejectsClockwiseNodes) {
  QuadFixture f(true);
  EXPECT_THROW(fem::elements::SSPquad(1, f.nodes, f.material, PlaneType::PlaneStrain, 1.0, 0.0, 0.0),
               common::InputError);
}

TEST(FourNodeQuad, StiffnessMassAndResponses) {
  QuadFixture f;
  fem::elements::FourNodeQuad e(1, f.nodes, f.material, PlaneType::PlaneStress, 0.2, 0.0, 0.0, 0.0, 0.0);
  expect_element_properties(e, f.area(), 0.2, 2.0);
  // the element density, when given, replaces the material's (OpenSees FourNodeQuad::getMass)
  fem::elements::FourNodeQuad heavy(2, f.nodes, f.material, PlaneType::PlaneStress, 0.2, 0.0, 5.0, 0.0, 0.0);
  EXPECT_CLOSE(heavy.lumped_mass().sum(), 2.0 * 5.0 * f.area() * 0.2, 1e-12, 1e-12);
  e.update();
  EXPECT_EQ(e.response({"stresses"})->size(), 12u);
  EXPECT_EQ(e.response({"strains"})->size(), 12u);
  EXPECT_EQ(e.response({"forces"})->size(), 8u);
  EXPECT_EQ(e.response({"stress3D"})->size(), 24u);
  EXPECT_EQ(e.response({"material", "3", "stress"})->size(), 3u);
  EXPECT_FALSE(e.response({"material", "5", "stress"}).has_value());
}

TEST(FourNodeQuad, RejectsClockwiseNodes) {
  QuadFixture f(true);
  EXPECT_THROW(fem::elements::FourNodeQuad(1, f.nodes, f.material, PlaneType::PlaneStrain, 1.0, 0, 0, 0, 0),
               common::InputError);
}

struct TriangleFixture {
  Domain domain;
  std::array<fem::domain::Node*, 3> nodes{};
  ElasticIsotropic material{1, 1000.0, 0.25, 2.0};
  explicit TriangleFixture(bool clockwise = false) {
    const double x[3] = {0.0, 2.0, 0.5}, y[3] = {0.0, 0.3, 1.5};
    for (int i = 0; i < 3; ++i) {
      const int k = clockwise ? 2 - i : i;
      nodes[i] = &domain.add_node(i + 1, x[k], y[k], 2, "test");
    }
  }
  double area() const { return 0.5 * (2.0 * 1.5 - 0.5 * 0.3); }
};

// The constant-strain triangle: 3 rigid-body modes and 3 deformation modes in its 6 dofs (the 2 padding dofs
// of the 8-dof storage stay zero), a third of the mass at each node, the body force a third at each node, and
// OpenSees' surface pressure (consistent nodal loads p/2 (dy, -dx) at both ends of each side, subtracted from
// the resisting force): on a free triangle it is an isotropic stress p in the plane.
TEST(Tri31, StiffnessMassBodyForceAndPressure) {
  TriangleFixture f;
  fem::elements::Tri31 e(1, f.nodes, f.material, PlaneType::PlaneStress, 0.5, 0.0, 0.0, 0.0, -10.0);
  const Matrix8 K = e.tangent_stiffness();
  EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());
  EXPECT_EQ(K.rightCols(2).norm(), 0.0);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eig(K.topLeftCorner(6, 6));
  for (int i = 0; i < 3; ++i) EXPECT_LT(std::abs(eig.eigenvalues()[i]), 1e-10 * eig.eigenvalues()[5]);
  EXPECT_GT(eig.eigenvalues()[3], 1e-6 * eig.eigenvalues()[5]);
  const Vector8 m = e.lumped_mass();
  for (int a = 0; a < 3; ++a) EXPECT_CLOSE(m[2 * a], 2.0 * f.area() * 0.5 / 3.0, 1e-12, 1e-12);
  e.update();
  const Vector8 r = e.resisting_force();  // zero displacement: minus the body force
  for (int a = 0; a < 3; ++a) EXPECT_CLOSE(r[2 * a + 1], 10.0 * f.area() * 0.5 / 3.0, 1e-12, 1e-12);
  EXPECT_EQ(e.response({"stresses"})->size(), 3u);
  EXPECT_EQ(e.response({"strains"})->size(), 3u);
  EXPECT_EQ(e.response({"forces"})->size(), 6u);
  EXPECT_EQ(e.response({"stressAtNodes"})->size(), 9u);
  EXPECT_EQ(e.response({"material", "1", "stress"})->size(), 3u);
  EXPECT_FALSE(e.response({"material", "2", "stress"}).has_value());
  EXPECT_EQ(e.to_json()["type"], "Tri31");
  EXPECT_EQ(e.to_json()["nodes"].size(), 3u);

  // The pressure: solve K u = -(resisting force at u = 0) on the free triangle, held statically determinate.
  fem::elements::Tri31 pressed(2, f.nodes, f.material, PlaneType::PlaneStress, 1.0, 10.0, 0.0, 0.0, 0.0);
  pressed.update();
  const Vector8 load = -pressed.resisting_force();
  EXPECT_GT(load.norm(), 0.0);
  EXPECT_LT(std::abs(load[0] + load[2] + load[4]) + std::abs(load[1] + load[3] + load[5]), 1e-12 * load.norm());
  const std::array<int, 3> fixed{0, 1, 3};  // node 1 x y, node 2 y
  std::vector<int> free;
  for (int i = 0; i < 6; ++i)
    if (std::find(fixed.begin(), fixed.end(), i) == fixed.end()) free.push_back(i);
  Eigen::Matrix3d Kf;
  Eigen::Vector3d lf;
  const Matrix8 Kp = pressed.tangent_stiffness();
  for (int i = 0; i < 3; ++i) {
    lf[i] = load[free[static_cast<std::size_t>(i)]];
    for (int j = 0; j < 3; ++j) Kf(i, j) = Kp(free[static_cast<std::size_t>(i)], free[static_cast<std::size_t>(j)]);
  }
  const Eigen::Vector3d uf = Kf.lu().solve(lf);
  for (int i = 0; i < 3; ++i) {
    const int dof = free[static_cast<std::size_t>(i)];
    f.nodes[static_cast<std::size_t>(dof / 2)]->disp[dof % 2] = uf[i];
  }
  pressed.update();
  const auto s = *pressed.response({"stress"});
  EXPECT_CLOSE(s[0], 10.0, 1e-12, 1e-12);
  EXPECT_CLOSE(s[1], 10.0, 1e-12, 1e-12);
  EXPECT_CLOSE(s[2], 0.0, 1e-12, 0.0);
}

TEST(Tri31, RejectsClockwiseOrCollapsedNodes) {
  TriangleFixture f(true);
  EXPECT_THROW(fem::elements::Tri31(1, f.nodes, f.material, PlaneType::PlaneStrain, 1.0, 0, 0, 0, 0),
               common::InputError);
  TriangleFixture g;
  g.nodes[2] = g.nodes[1];
  EXPECT_THROW(fem::elements::Tri31(1, g.nodes, g.material, PlaneType::PlaneStrain, 1.0, 0, 0, 0, 0),
               common::InputError);
  TriangleFixture h;
  EXPECT_THROW(fem::elements::Tri31(1, h.nodes, h.material, PlaneType::PlaneStrain, 0.0, 0, 0, 0, 0),
               common::InputError);
}

}  // namespace
