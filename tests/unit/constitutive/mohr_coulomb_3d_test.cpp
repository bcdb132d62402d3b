// Unit tests of the 3D Mohr-Coulomb return (constitutive/mohr_coulomb_3d.hpp): plane-strain states return
// as the plane-strain return does; the return is objective (a rotated trial returns the rotated stress); a
// general trial returns onto the surface (face, edges, apex, tension cutoff) with the flow rule's plastic
// strain, coaxial with the trial; elastic trials come back bit for bit; Hooke's law in the elastic trial.
// References: de Souza Neto, Peric & Owen (2008), Computational Methods for Plasticity, sec. 8.1 (isotropic
// returns are coaxial) and 8.2 (Mohr-Coulomb in principal stresses, its flow rule).
#include "constitutive/mohr_coulomb_3d.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <random>

#include "support/tolerance.hpp"

namespace {

using constitutive::IsotropicElasticity;
using constitutive::MohrCoulombStrength;
using constitutive::PlaneStrainStress;
using constitutive::ReturnRegion;
using constitutive::Strain6;
using constitutive::Stress6;

constexpr double kDeg = M_PI / 180.0;
const IsotropicElasticity kElastic = IsotropicElasticity::from_young_poisson(20e6, 0.3);
const double kInf = std::numeric_limits<double>::infinity();

MohrCoulombStrength strength(double phi_deg, double psi_deg, double c, double t = kInf) {
  return {phi_deg * kDeg, psi_deg * kDeg, c, t};
}

Stress6 voigt(const Eigen::Matrix3d& m) {
  Stress6 s;
  s << m(0, 0), m(1, 1), m(2, 2), m(0, 1), m(1, 2), m(0, 2);
  return s;
}

/// A proper rotation from three angles (z-x-z Euler).
Eigen::Matrix3d rotation(double a, double b, double c) {
  return (Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(b, Eigen::Vector3d::UnitX()) *
          Eigen::AngleAxisd(c, Eigen::Vector3d::UnitZ()))
      .toRotationMatrix();
}

/// A stress with principal values s1, s2, s3 on the axes of rotation r.
Stress6 with_principal(double s1, double s2, double s3, const Eigen::Matrix3d& r) {
  return voigt(r * Eigen::Vector3d(s1, s2, s3).asDiagonal() * r.transpose());
}

double f_main(const Eigen::Vector3d& s, const MohrCoulombStrength& st) {
  return (s[0] - s[2]) + (s[0] + s[2]) * std::sin(st.friction) - 2 * st.cohesion * std::cos(st.friction);
}

/// The plastic strain increment as a tensor (engineering shears halved).
Eigen::Matrix3d strain_tensor(const Strain6& e) {
  Eigen::Matrix3d m;
  m << e[0], 0.5 * e[3], 0.5 * e[5], 0.5 * e[3], e[1], 0.5 * e[4], 0.5 * e[5], 0.5 * e[4], e[2];
  return m;
}

// ---------------------------------------------------------------------------------------------------------

TEST(MohrCoulomb3D, ElasticTrialIsHookesLaw) {
  const double g = kElastic.shear_modulus, lambda = kElastic.bulk_modulus - 2.0 * g / 3.0;
  Strain6 de;
  de << 1e-4, -2e-4, 3e-4, 4e-4, -5e-4, 6e-4;
  const Stress6 t = constitutive::elastic_trial_3d(Stress6::Zero(), de, kElastic);
  const double vol = 2e-4;
  EXPECT_CLOSE(t[0], lambda * vol + 2 * g * 1e-4, 0.0, 1e-14);
  EXPECT_CLOSE(t[1], lambda * vol - 2 * g * 2e-4, 0.0, 1e-14);
  EXPECT_CLOSE(t[2], lambda * vol + 2 * g * 3e-4, 0.0, 1e-14);
  EXPECT_CLOSE(t[3], g * 4e-4, 0.0, 1e-14);
  EXPECT_CLOSE(t[4], -g * 5e-4, 0.0, 1e-14);
  EXPECT_CLOSE(t[5], g * 6e-4, 0.0, 1e-14);
  // The plane-strain trial is its restriction (ezz = gyz = gxz = 0).
  const PlaneStrainStress p = constitutive::elastic_trial(PlaneStrainStress::Zero(), {1e-4, -2e-4, 4e-4}, kElastic);
  Strain6 de2;
  de2 << 1e-4, -2e-4, 0, 4e-4, 0, 0;
  const Stress6 t2 = constitutive::elastic_trial_3d(Stress6::Zero(), de2, kElastic);
  for (int i = 0; i < 4; ++i) EXPECT_CLOSE(t2[i], p[i], 0.0, 1e-15);
}

TEST(MohrCoulomb3D, ElasticTrialIsReturnedBitForBit) {
  const auto st = strength(30, 10, 10e3);
  const Stress6 trial = with_principal(-100e3, -150e3, -180e3, rotation(0.3, 0.7, -0.2));
  const auto u = constitutive::mohr_coulomb_return_3d(trial, kElastic, st);
  EXPECT_EQ(u.region, ReturnRegion::Elastic);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(u.stress[i], trial[i]);
  EXPECT_EQ(u.plastic_strain_increment.norm(), 0.0);
  const auto z = constitutive::mohr_coulomb_return_3d(Stress6::Zero(), kElastic, strength(30, 0, 0.0));
  EXPECT_EQ(z.region, ReturnRegion::Elastic);
  EXPECT_EQ(z.stress.norm(), 0.0);
}

TEST(MohrCoulomb3D, PrincipalStressesAreSortedOrthonormalAndRebuildTheTensor) {
  const Stress6 s = with_principal(-10e3, -50e3, -200e3, rotation(1.1, 0.4, 2.0));
  const auto p = constitutive::principal_stresses(s);
  EXPECT_CLOSE(p.sorted[0], -10e3, 1e-8, 0.0);
  EXPECT_CLOSE(p.sorted[1], -50e3, 1e-8, 0.0);
  EXPECT_CLOSE(p.sorted[2], -200e3, 1e-8, 0.0);
  EXPECT_LT((p.axes.transpose() * p.axes - Eigen::Matrix3d::Identity()).norm(), 1e-14);
  EXPECT_LT((constitutive::on_principal_axes(p.axes, p.sorted) - s).norm(), 1e-9);
  // Repeated values (a triaxial state) still give an orthonormal basis.
  const auto q = constitutive::principal_stresses(with_principal(-20e3, -20e3, -90e3, rotation(0.5, 1.0, 0.1)));
  EXPECT_LT((q.axes.transpose() * q.axes - Eigen::Matrix3d::Identity()).norm(), 1e-14);
}

/// Plane-strain trials (syz = sxz = 0) in every region: the 3D return gives the plane-strain return's
/// stress and region; only the decomposition differs (round-off).
TEST(MohrCoulomb3D, PlaneStrainStatesReturnAsThePlaneStrainReturnDoes) {
  std::mt19937_64 rng(20261207);
  std::uniform_real_distribution<double> u(-400e3, 60e3);
  for (const auto& st : {strength(30, 10, 10e3), strength(35, 0, 0.0), strength(0, 0, 50e3),
                         strength(30, 10, 10e3, 5e3)}) {
    int plastic = 0;
    for (int n = 0; n < 400; ++n) {
      const PlaneStrainStress p2(u(rng), u(rng), u(rng), 0.5 * u(rng));
      const auto two = constitutive::mohr_coulomb_return(p2, kElastic, st);
      const auto three = constitutive::mohr_coulomb_return_3d(constitutive::to_stress6(p2), kElastic, st);
      ASSERT_EQ(three.region, two.region) << "trial " << p2.transpose();
      plastic += two.region != ReturnRegion::Elastic;
      const double scale = 1.0 + p2.cwiseAbs().maxCoeff();
      for (int i = 0; i < 4; ++i) EXPECT_CLOSE(three.stress[i], two.stress[i], 1e-9 * scale, 0.0);
      EXPECT_CLOSE(three.stress[4], 0.0, 1e-9 * scale, 0.0);
      EXPECT_CLOSE(three.stress[5], 0.0, 1e-9 * scale, 0.0);
      for (int i = 0; i < 3; ++i)
        EXPECT_CLOSE(three.plastic_strain_increment[i], two.plastic_strain_increment[i], 1e-15, 1e-8);
      EXPECT_CLOSE(three.plastic_strain_increment[3], two.plastic_strain_increment[3], 1e-15, 1e-8);
    }
    EXPECT_GT(plastic, 100);  // the sample reaches the plastic regions
  }
}

/// Objectivity: R sigma_trial R^T returns R sigma R^T (an isotropic return commutes with rotations).
TEST(MohrCoulomb3D, ARotatedTrialReturnsTheRotatedStress) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-400e3, 60e3), angle(-M_PI, M_PI);
  const auto st = strength(30, 10, 10e3, 8e3);
  for (int n = 0; n < 300; ++n) {
    const Stress6 trial = with_principal(u(rng), u(rng), u(rng), rotation(angle(rng), angle(rng), angle(rng)));
    const Eigen::Matrix3d r = rotation(angle(rng), angle(rng), angle(rng));
    const auto a = constitutive::mohr_coulomb_return_3d(trial, kElastic, st);
    const Stress6 rotated = voigt(r * constitutive::stress_tensor(trial) * r.transpose());
    const auto b = constitutive::mohr_coulomb_return_3d(rotated, kElastic, st);
    ASSERT_EQ(a.region, b.region);
    const double scale = 1.0 + trial.cwiseAbs().maxCoeff();
    const Stress6 a_rotated = voigt(r * constitutive::stress_tensor(a.stress) * r.transpose());
    EXPECT_LT((a_rotated - b.stress).cwiseAbs().maxCoeff(), 1e-9 * scale);
  }
}

/// General trials: the returned stress is admissible and on the surface, coaxial with the trial, and the
/// plastic strain increment is the flow rule's in the trial's principal frame.
TEST(MohrCoulomb3D, AGeneralTrialReturnsOntoTheSurfaceWithTheFlowRule) {
  const auto st = strength(30, 10, 10e3);
  const double sd = std::sin(st.dilation);
  const Eigen::Matrix3d r = rotation(0.4, 1.2, -0.8);
  struct Case {
    double s1, s2, s3;
    ReturnRegion region;
  };
  for (const Case& c : {Case{-20e3, -200e3, -400e3, ReturnRegion::Face},
                        Case{-20e3, -25e3, -400e3, ReturnRegion::EdgeTriaxialCompression},
                        Case{-20e3, -395e3, -400e3, ReturnRegion::EdgeTriaxialExtension},
                        Case{60e3, 40e3, 30e3, ReturnRegion::Apex}}) {
    SCOPED_TRACE(constitutive::to_string(c.region));
    const Stress6 trial = with_principal(c.s1, c.s2, c.s3, r);
    const auto up = constitutive::mohr_coulomb_return_3d(trial, kElastic, st);
    ASSERT_EQ(up.region, c.region);
    // On the surface.
    const Eigen::Vector3d p = constitutive::principal_stresses(up.stress).sorted;
    EXPECT_CLOSE(f_main(p, st), 0.0, 1e-6, 0.0);
    EXPECT_CLOSE(constitutive::mohr_coulomb_yield_3d(up.stress, st), 0.0, 1e-6, 0.0);
    // Coaxial: in the trial's principal frame the stress and the plastic strain are diagonal.
    const Eigen::Matrix3d s_local = r.transpose() * constitutive::stress_tensor(up.stress) * r;
    const Eigen::Matrix3d e_local = r.transpose() * strain_tensor(up.plastic_strain_increment) * r;
    EXPECT_LT(std::abs(s_local(0, 1)) + std::abs(s_local(1, 2)) + std::abs(s_local(0, 2)), 1e-6);
    const double e_scale = e_local.diagonal().cwiseAbs().maxCoeff();
    EXPECT_LT(std::abs(e_local(0, 1)) + std::abs(e_local(1, 2)) + std::abs(e_local(0, 2)), 1e-9 * e_scale);
    const Eigen::Vector3d ep = e_local.diagonal();
    if (c.region == ReturnRegion::Face) {  // along (1 + sin psi, 0, -(1 - sin psi))
      EXPECT_CLOSE(ep[1], 0.0, 1e-12 * e_scale, 0.0);
      EXPECT_CLOSE(ep[0] / ep[2], -(1 + sd) / (1 - sd), 0.0, 1e-9);
    } else if (c.region == ReturnRegion::EdgeTriaxialCompression) {
      EXPECT_CLOSE(p[0], p[1], 1e-6, 1e-12);
      EXPECT_CLOSE(ep.sum() / (ep[0] + ep[1] - ep[2]), sd, 0.0, 1e-9);
    } else if (c.region == ReturnRegion::EdgeTriaxialExtension) {
      EXPECT_CLOSE(p[1], p[2], 1e-6, 1e-12);
      EXPECT_CLOSE(ep.sum() / (ep[0] - ep[1] - ep[2]), sd, 0.0, 1e-9);
    } else {  // apex: c cot(phi) in every direction
      const double apex = st.cohesion / std::tan(st.friction);
      for (int i = 0; i < 3; ++i) EXPECT_CLOSE(up.stress[i], apex, 1e-6, 1e-12);
      for (int i = 3; i < 6; ++i) EXPECT_CLOSE(up.stress[i], 0.0, 1e-6, 0.0);
    }
    // Returned once, it stays (a state on the surface is elastic under a zero increment).
    const auto again = constitutive::mohr_coulomb_return_3d(up.stress, kElastic, st);
    EXPECT_EQ(again.region, ReturnRegion::Elastic);
  }
}

TEST(MohrCoulomb3D, TensionCutoffAndZeroCohesion) {
  const Eigen::Matrix3d r = rotation(-0.3, 0.9, 1.7);
  const auto cut = strength(30, 10, 10e3, 5e3);
  const auto u = constitutive::mohr_coulomb_return_3d(with_principal(8e3, -1e3, -2e3, r), kElastic, cut);
  ASSERT_EQ(u.region, ReturnRegion::TensionCutoff);
  EXPECT_CLOSE(constitutive::principal_stresses(u.stress).sorted[0], 5e3, 1e-6, 0.0);
  // c = 0: every trial, however tensile or sheared, returns finite and admissible.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> v(-300e3, 100e3), angle(-M_PI, M_PI);
  const auto sand = strength(35, 0, 0.0);
  for (int n = 0; n < 300; ++n) {
    const auto w = constitutive::mohr_coulomb_return_3d(
        with_principal(v(rng), v(rng), v(rng), rotation(angle(rng), angle(rng), angle(rng))), kElastic, sand);
    ASSERT_TRUE(w.stress.allFinite());
    ASSERT_TRUE(w.plastic_strain_increment.allFinite());
    EXPECT_LE(f_main(constitutive::principal_stresses(w.stress).sorted, sand), 1e-6);
  }
}

TEST(MohrCoulomb3D, TheUpdateIsTrialThenReturn) {
  const auto st = strength(30, 10, 10e3);
  const Stress6 s0 = with_principal(-50e3, -80e3, -100e3, rotation(0.1, 0.2, 0.3));
  Strain6 de;
  de << 2e-3, -1e-3, 0.0, 3e-3, -1e-3, 2e-3;
  const auto a = constitutive::mohr_coulomb_update_3d(s0, de, kElastic, st);
  const auto b = constitutive::mohr_coulomb_return_3d(constitutive::elastic_trial_3d(s0, de, kElastic), kElastic, st);
  EXPECT_NE(a.region, ReturnRegion::Elastic);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(a.stress[i], b.stress[i]);
}

}  // namespace
