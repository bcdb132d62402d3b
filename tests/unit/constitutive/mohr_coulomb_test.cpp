// Unit tests of the plane-strain Mohr-Coulomb return mapping (constitutive/mohr_coulomb.hpp):
// every region (face, both edges, apex, tension cutoff and its corners), the flow rule, admissibility,
// bit-identical elastic states, c = 0 / tiny c, the consistent tangent against central differences, and
// the update with precomputed trigonometry (MohrCoulombSurface) and the return map (MohrCoulombReturnMap)
// equal bit for bit to the plain one.
#include "constitutive/mohr_coulomb.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "support/tolerance.hpp"

namespace {

using constitutive::IsotropicElasticity;
using constitutive::MohrCoulombStrength;
using constitutive::PlaneStrainStrain;
using constitutive::PlaneStrainStress;
using constitutive::ReturnRegion;

constexpr double kDeg = M_PI / 180.0;
const IsotropicElasticity kElastic = IsotropicElasticity::from_young_poisson(20e6, 0.3);
const double kInf = std::numeric_limits<double>::infinity();

MohrCoulombStrength strength(double phi_deg, double psi_deg, double c, double t = kInf) {
  return {phi_deg * kDeg, psi_deg * kDeg, c, t};
}

/// A plane-strain stress with in-plane principal values a, b (major axis at angle alpha to x) and szz.
PlaneStrainStress rotated(double a, double b, double szz, double alpha) {
  const double c = 0.5 * (a + b), r = 0.5 * (a - b);
  return {c + r * std::cos(2 * alpha), c - r * std::cos(2 * alpha), szz, r * std::sin(2 * alpha)};
}

/// Sorted principal values (s1 >= s2 >= s3) of a plane-strain stress.
Eigen::Vector3d principal(const PlaneStrainStress& s) {
  const double c = 0.5 * (s[0] + s[1]), r = std::hypot(0.5 * (s[0] - s[1]), s[3]);
  double v[3] = {c + r, c - r, s[2]};
  std::sort(v, v + 3, [](double x, double y) { return x > y; });
  return {v[0], v[1], v[2]};
}

double f_main(const Eigen::Vector3d& s, const MohrCoulombStrength& st) {
  return (s[0] - s[2]) + (s[0] + s[2]) * std::sin(st.friction) - 2 * st.cohesion * std::cos(st.friction);
}

/// Largest violation of any of the six Mohr-Coulomb planes (f evaluated on the sorted values is the max).
void expect_admissible(const PlaneStrainStress& s, const MohrCoulombStrength& st, double tol) {
  const Eigen::Vector3d p = principal(s);
  EXPECT_LE(f_main(p, st), tol);
  if (std::isfinite(st.tension_cutoff)) {
    EXPECT_LE(p[0], st.tension_cutoff + tol);
  }
}

/// Plastic strain increment in the trial's principal frame (sxy = 0 cases only): (e_xx, e_yy, e_zz).
Eigen::Vector3d plastic_principal(const constitutive::MohrCoulombUpdate& u) {
  return u.plastic_strain_increment.head<3>();
}

// ---------------------------------------------------------------------------------------------------------

TEST(MohrCoulombReturn, ElasticTrialIsReturnedBitForBit) {
  const auto st = strength(30, 10, 10e3);
  const PlaneStrainStress s0 = rotated(-100e3, -180e3, -150e3, 0.3);
  const PlaneStrainStrain de(1e-5, -2e-5, 3e-5);
  const auto u = constitutive::mohr_coulomb_update(s0, de, kElastic, st);
  const PlaneStrainStress trial = constitutive::elastic_trial(s0, de, kElastic);
  EXPECT_EQ(u.region, ReturnRegion::Elastic);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(u.stress[i], trial[i]);
  EXPECT_EQ(u.plastic_strain_increment.norm(), 0.0);
  // Zero stress, zero cohesion, zero increment: still elastic, no NaN.
  const auto z = constitutive::mohr_coulomb_update(PlaneStrainStress::Zero(), PlaneStrainStrain::Zero(), kElastic,
                                                   strength(30, 0, 0.0));
  EXPECT_EQ(z.region, ReturnRegion::Elastic);
  EXPECT_EQ(z.stress.norm(), 0.0);
}

TEST(MohrCoulombReturn, StateOnTheSurfaceStaysThere) {
  const auto st = strength(30, 5, 10e3);
  const auto first = constitutive::mohr_coulomb_return(rotated(-20e3, -400e3, -200e3, 0.4), kElastic, st);
  ASSERT_EQ(first.region, ReturnRegion::Face);
  const auto again = constitutive::mohr_coulomb_update(first.stress, PlaneStrainStrain::Zero(), kElastic, st);
  EXPECT_EQ(again.region, ReturnRegion::Elastic);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(again.stress[i], first.stress[i]);
}

TEST(MohrCoulombReturn, FaceReturnLiesOnThePlaneAndFollowsTheFlowRule) {
  const auto st = strength(30, 10, 10e3);
  const PlaneStrainStress trial(-20e3, -400e3, -200e3, 0.0);  // s1 = sxx, s2 = szz, s3 = syy
  const auto u = constitutive::mohr_coulomb_return(trial, kElastic, st);
  ASSERT_EQ(u.region, ReturnRegion::Face);
  EXPECT_CLOSE(f_main(principal(u.stress), st), 0.0, 1e-6, 0.0);
  expect_admissible(u.stress, st, 1e-6);
  // Flow rule (de Souza Neto et al. 2008, sec. 8.2): plastic strain ~ (1 + sin psi, 0, -(1 - sin psi)) on (s1, s2, s3).
  const Eigen::Vector3d ep = plastic_principal(u);
  const double sd = std::sin(st.dilation);
  EXPECT_GT(ep[0], 0.0);
  EXPECT_CLOSE(ep[2], 0.0, 1e-14, 0.0);  // s2 = szz carries no plastic strain
  EXPECT_CLOSE(ep[0] / ep[1], -(1 + sd) / (1 - sd), 0.0, 1e-10);
  EXPECT_EQ(u.stress[3], 0.0);
}

TEST(MohrCoulombReturn, TriaxialCompressionEdge) {
  const auto st = strength(30, 10, 10e3);
  const PlaneStrainStress trial(-20e3, -400e3, -25e3, 0.0);  // s1 = sxx ~ s2 = szz > s3 = syy
  const auto u = constitutive::mohr_coulomb_return(trial, kElastic, st);
  ASSERT_EQ(u.region, ReturnRegion::EdgeTriaxialCompression);
  const Eigen::Vector3d p = principal(u.stress);
  EXPECT_CLOSE(p[0], p[1], 1e-6, 1e-12);
  EXPECT_CLOSE(f_main(p, st), 0.0, 1e-6, 0.0);
  expect_admissible(u.stress, st, 1e-6);
  // Flow: a non-negative combination of the two planes' directions: both e1, e2 >= 0, e3 < 0, and
  // the volumetric part = 2 sin psi (g1 + g2) while (e1 + e2) - e3 = ... => e_v / (e1 + e2 - e3) = sin psi.
  const Eigen::Vector3d ep = plastic_principal(u);
  EXPECT_GT(ep[0], 0.0);
  EXPECT_GT(ep[2], 0.0);
  EXPECT_LT(ep[1], 0.0);
  EXPECT_CLOSE(ep.sum() / (ep[0] + ep[2] - ep[1]), std::sin(st.dilation), 0.0, 1e-9);
}

TEST(MohrCoulombReturn, TriaxialExtensionEdge) {
  const auto st = strength(30, 10, 10e3);
  const PlaneStrainStress trial(-20e3, -400e3, -395e3, 0.0);  // s1 = sxx > s2 = szz ~ s3 = syy
  const auto u = constitutive::mohr_coulomb_return(trial, kElastic, st);
  ASSERT_EQ(u.region, ReturnRegion::EdgeTriaxialExtension);
  const Eigen::Vector3d p = principal(u.stress);
  EXPECT_CLOSE(p[1], p[2], 1e-6, 1e-12);
  EXPECT_CLOSE(f_main(p, st), 0.0, 1e-6, 0.0);
  const Eigen::Vector3d ep = plastic_principal(u);
  EXPECT_GT(ep[0], 0.0);
  EXPECT_LT(ep[1], 0.0);
  EXPECT_LT(ep[2], 0.0);
  EXPECT_CLOSE(ep.sum() / (ep[0] - ep[1] - ep[2]), std::sin(st.dilation), 0.0, 1e-9);
}

TEST(MohrCoulombReturn, ApexForTensileTrials) {
  for (double c : {10e3, 1e-3, 0.0}) {
    const auto st = strength(30, 10, c);
    const double apex = c / std::tan(st.friction);
    const auto u = constitutive::mohr_coulomb_return(rotated(60e3, 40e3, 30e3, 0.2), kElastic, st);
    ASSERT_EQ(u.region, ReturnRegion::Apex) << "c = " << c;
    EXPECT_CLOSE(u.stress[0], apex, 1e-9, 1e-12);
    EXPECT_CLOSE(u.stress[1], apex, 1e-9, 1e-12);
    EXPECT_CLOSE(u.stress[2], apex, 1e-9, 1e-12);
    EXPECT_CLOSE(u.stress[3], 0.0, 1e-9, 0.0);
    EXPECT_TRUE(u.plastic_strain_increment.allFinite());
  }
}

TEST(MohrCoulombReturn, ZeroAndTinyCohesionGiveFiniteAdmissibleStates) {
  for (double c : {0.0, 1e-12, 1e-3}) {
    const auto st = strength(22.2, 0, c);
    for (double alpha : {0.0, 0.3, M_PI / 4}) {
      for (const auto& tr : {rotated(-1e3, -300e3, -100e3, alpha), rotated(-250e3, -300e3, -10e3, alpha),
                             rotated(1e3, -2e3, -1e3, alpha), rotated(-5e3, -5e3, -5e3, alpha)}) {
        const auto u = constitutive::mohr_coulomb_return(tr, kElastic, st);
        ASSERT_TRUE(u.stress.allFinite());
        ASSERT_TRUE(u.plastic_strain_increment.allFinite());
        expect_admissible(u.stress, st, 1e-6);
        const Eigen::Matrix3d t = constitutive::mohr_coulomb_tangent(tr, kElastic, st);
        EXPECT_TRUE(t.allFinite());
      }
    }
  }
}

TEST(MohrCoulombReturn, TrescaLimitHasNoApex) {
  const auto st = strength(0, 0, 50e3);
  const auto u = constitutive::mohr_coulomb_return(rotated(200e3, -100e3, 50e3, 0.7), kElastic, st);
  EXPECT_NE(u.region, ReturnRegion::Elastic);
  const Eigen::Vector3d p = principal(u.stress);
  EXPECT_CLOSE(p[0] - p[2], 100e3, 1e-6, 1e-12);  // Tresca: s1 - s3 = 2 c
  // phi = psi = 0: isochoric plastic flow.
  EXPECT_CLOSE(u.plastic_strain_increment.head<3>().sum(), 0.0, 1e-15, 0.0);
}

TEST(MohrCoulombReturn, TrescaWithAFarTensionCutoffStillYields) {
  // fem2mpm writes T = 1e30 for a frictionless material without -tension ("no cutoff"; the apex c cot(phi)
  // is at infinity). The elastic test used to take T into its round-off scale, 1e-12 x 1e30: every state
  // passed as elastic, and a Tresca slope or column in MPM did not fail at all.
  for (const double t : {1e30, 1e12, kInf}) {
    SCOPED_TRACE(t);
    const auto st = strength(0, 0, 50e3, t);
    const auto u = constitutive::mohr_coulomb_return(rotated(200e3, -100e3, 50e3, 0.7), kElastic, st);
    EXPECT_NE(u.region, ReturnRegion::Elastic);
    const Eigen::Vector3d p = principal(u.stress);
    EXPECT_CLOSE(p[0] - p[2], 100e3, 1e-6, 1e-12);
  }
}

TEST(MohrCoulombReturn, TensionCutoffRegions) {
  const double t = 5e3;
  const auto st = strength(30, 10, 10e3, t);  // apex 17.3 kPa > T
  {
    const auto u = constitutive::mohr_coulomb_return({8e3, 0.0, 0.0, 0.0}, kElastic, st);
    ASSERT_EQ(u.region, ReturnRegion::TensionCutoff);
    EXPECT_CLOSE(principal(u.stress)[0], t, 1e-6, 0.0);
    // Associated Rankine flow: plastic strain only along s1.
    EXPECT_GT(u.plastic_strain_increment[0], 0.0);
    EXPECT_CLOSE(u.plastic_strain_increment[1], 0.0, 1e-16, 0.0);
    EXPECT_CLOSE(u.plastic_strain_increment[2], 0.0, 1e-16, 0.0);
  }
  {
    const auto u = constitutive::mohr_coulomb_return({9e3, 8e3, -2e3, 0.0}, kElastic, st);
    ASSERT_EQ(u.region, ReturnRegion::TensionCutoffEdge);
    const Eigen::Vector3d p = principal(u.stress);
    EXPECT_CLOSE(p[0], t, 1e-6, 0.0);
    EXPECT_CLOSE(p[1], t, 1e-6, 0.0);
  }
  {
    const auto u = constitutive::mohr_coulomb_return({50e3, 40e3, 30e3, 0.0}, kElastic, st);
    ASSERT_EQ(u.region, ReturnRegion::TensionCorner);
    const Eigen::Vector3d p = principal(u.stress);
    for (int i = 0; i < 3; ++i) EXPECT_CLOSE(p[i], t, 1e-6, 0.0);
  }
  {
    const auto u = constitutive::mohr_coulomb_return({-16e3, -24e3, 20e3, 0.0}, kElastic, st);
    ASSERT_EQ(u.region, ReturnRegion::TensionShearEdge) << constitutive::to_string(u.region);
    const Eigen::Vector3d p = principal(u.stress);
    EXPECT_CLOSE(p[0], t, 1e-6, 0.0);
    EXPECT_CLOSE(f_main(p, st), 0.0, 1e-6, 0.0);
  }
  {
    // The corner where the cutoff meets the triaxial-extension edge: s1 = T, s2 = s3 on the main plane.
    const auto u = constitutive::mohr_coulomb_return({-20e3, -24e3, 28e3, 0.0}, kElastic, st);
    ASSERT_EQ(u.region, ReturnRegion::TensionCorner) << constitutive::to_string(u.region);
    const Eigen::Vector3d p = principal(u.stress);
    EXPECT_CLOSE(p[0], t, 1e-6, 0.0);
    EXPECT_CLOSE(p[1], p[2], 1e-6, 0.0);
    EXPECT_CLOSE(f_main(p, st), 0.0, 1e-6, 0.0);
  }
  // A cutoff at or above the apex is clamped there: the same as none.
  const auto above = strength(30, 10, 10e3, 1e9);
  const auto u = constitutive::mohr_coulomb_return({50e3, 40e3, 30e3, 0.0}, kElastic, above);
  EXPECT_EQ(u.region, ReturnRegion::Apex);
}

// --- consistent tangent vs central differences --------------------------------------------------------------

struct TangentCase {
  const char* name;
  PlaneStrainStress trial;
  MohrCoulombStrength st;
  ReturnRegion region;
};

class MohrCoulombTangent : public ::testing::TestWithParam<TangentCase> {};

TEST_P(MohrCoulombTangent, MatchesCentralDifferences) {
  const TangentCase& tc = GetParam();
  const auto u = constitutive::mohr_coulomb_return(tc.trial, kElastic, tc.st);
  ASSERT_EQ(u.region, tc.region) << constitutive::to_string(u.region);
  const Eigen::Matrix<double, 4, 3> t = constitutive::mohr_coulomb_tangent_4x3(tc.trial, kElastic, tc.st);
  Eigen::Matrix<double, 4, 3> fd;
  const double h = 1e-9;
  for (int j = 0; j < 3; ++j) {
    PlaneStrainStrain d = PlaneStrainStrain::Zero();
    d[j] = h;
    const auto up = constitutive::mohr_coulomb_update(tc.trial, d, kElastic, tc.st);
    const auto um = constitutive::mohr_coulomb_update(tc.trial, -d, kElastic, tc.st);
    ASSERT_EQ(up.region, tc.region);
    ASSERT_EQ(um.region, tc.region);
    fd.col(j) = (up.stress - um.stress) / (2 * h);
  }
  const double ref = kElastic.bulk_modulus + 4.0 / 3.0 * kElastic.shear_modulus;
  const double err = (t - fd).norm() / std::max(t.norm(), ref);
  EXPECT_LT(err, 1e-6) << tc.name << "\nanalytic\n" << t << "\nfd\n" << fd;
  // The 3x3 is the (sxx, syy, sxy) rows of the 4x3.
  const Eigen::Matrix3d t3 = constitutive::mohr_coulomb_tangent(tc.trial, kElastic, tc.st);
  EXPECT_EQ(t3(2, 2), t(3, 2));
  EXPECT_EQ(t3(1, 0), t(1, 0));
}

// A precomputed MohrCoulombSurface only saves the sin / cos evaluations: the update must be bit for bit
// the one from the strength, in every region.
TEST_P(MohrCoulombTangent, PrecomputedSurfaceGivesTheSameUpdateBitForBit) {
  const TangentCase& tc = GetParam();
  const constitutive::MohrCoulombSurface surface(tc.st);
  const PlaneStrainStrain de(1e-5, -2e-5, 3e-5);
  const auto a = constitutive::mohr_coulomb_update(tc.trial, de, kElastic, tc.st);
  const auto b = constitutive::mohr_coulomb_update(tc.trial, de, kElastic, surface);
  EXPECT_EQ(a.region, b.region);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(a.stress[i], b.stress[i]) << i;
    EXPECT_EQ(a.plastic_strain_increment[i], b.plastic_strain_increment[i]) << i;
  }
  const auto r = constitutive::mohr_coulomb_return(tc.trial, kElastic, surface);
  EXPECT_EQ(r.region, tc.region);
}

// The return map (planes and active-set matrices formed once per surface) must return the same stress,
// plastic strain and region as the plain return, bit for bit, in every region, and on a sweep of trials
// around each case (which visits the neighbouring regions and the corners of the tension cutoff); its
// elastic test (admits) must say elastic exactly where the return does.
TEST_P(MohrCoulombTangent, ReturnMapGivesTheSameReturnBitForBit) {
  const TangentCase& tc = GetParam();
  const constitutive::MohrCoulombSurface surface(tc.st);
  const constitutive::MohrCoulombReturnMap map(kElastic, surface);
  const auto same = [&](const PlaneStrainStress& trial) {
    const auto a = constitutive::mohr_coulomb_return(trial, kElastic, surface);
    const auto b = map.apply(trial);
    EXPECT_EQ(a.region, b.region);
    // The elastic fast test agrees with the return, and the plastic entry with apply.
    EXPECT_EQ(map.admits(trial), a.region == ReturnRegion::Elastic);
    if (!map.admits(trial)) {
      const auto c = map.apply_plastic(trial);
      EXPECT_EQ(c.region, b.region);
      for (int i = 0; i < 4; ++i) EXPECT_EQ(c.stress[i], b.stress[i]) << i;
    }
    for (int i = 0; i < 4; ++i) {
      EXPECT_EQ(a.stress[i], b.stress[i]) << i;
      EXPECT_EQ(a.plastic_strain_increment[i], b.plastic_strain_increment[i]) << i;
    }
  };
  same(tc.trial);
  EXPECT_EQ(map.apply(tc.trial).region, tc.region);
  const double scale = tc.trial.cwiseAbs().maxCoeff();
  for (int k = 0; k < 200; ++k) {
    const double u = 0.37 * k, w = 0.61 * k, z = 0.83 * k;
    same(tc.trial + 0.5 * scale * PlaneStrainStress(std::sin(u), std::cos(w), std::sin(z), std::cos(u + z)));
  }
}

INSTANTIATE_TEST_SUITE_P(
    AllRegions, MohrCoulombTangent,
    ::testing::Values(
        TangentCase{"elastic", rotated(-100e3, -180e3, -150e3, 0.3), strength(30, 10, 10e3), ReturnRegion::Elastic},
        TangentCase{"face", rotated(-20e3, -400e3, -200e3, 0.35), strength(30, 10, 10e3), ReturnRegion::Face},
        TangentCase{"face szz major", rotated(-100e3, -400e3, -10e3, 1.1), strength(30, 10, 10e3),
                    ReturnRegion::Face},
        TangentCase{"face szz minor", rotated(-20e3, -200e3, -400e3, -0.5), strength(30, 10, 10e3),
                    ReturnRegion::Face},
        TangentCase{"face associated", rotated(-20e3, -400e3, -200e3, 0.35), strength(30, 30, 10e3),
                    ReturnRegion::Face},
        TangentCase{"face c = 0", rotated(-20e3, -400e3, -200e3, 0.35), strength(22.2, 0, 0.0), ReturnRegion::Face},
        TangentCase{"edge TC (in plane)", rotated(-20e3, -400e3, -25e3, 0.6), strength(30, 10, 10e3),
                    ReturnRegion::EdgeTriaxialCompression},
        TangentCase{"edge TE (in plane)", rotated(-20e3, -400e3, -395e3, 0.6), strength(30, 10, 10e3),
                    ReturnRegion::EdgeTriaxialExtension},
        TangentCase{"edge TC (in-plane pair)", rotated(-30e3, -32e3, -400e3, 0.2), strength(30, 10, 10e3),
                    ReturnRegion::EdgeTriaxialCompression},
        TangentCase{"edge TC (szz major)", rotated(-30e3, -380e3, -20e3, 0.2), strength(30, 10, 10e3),
                    ReturnRegion::EdgeTriaxialCompression},
        TangentCase{"edge TE (in-plane pair)", rotated(-390e3, -400e3, -20e3, 0.2), strength(30, 10, 10e3),
                    ReturnRegion::EdgeTriaxialExtension},
        TangentCase{"edge TE (equal in-plane pair)", rotated(-400e3, -400e3, -20e3, 0.0), strength(30, 10, 10e3),
                    ReturnRegion::EdgeTriaxialExtension},
        TangentCase{"apex", rotated(60e3, 40e3, 30e3, 0.2), strength(30, 10, 10e3), ReturnRegion::Apex},
        TangentCase{"tension", rotated(8e3, 0.0, 0.0, 0.4), strength(30, 10, 10e3, 5e3), ReturnRegion::TensionCutoff},
        TangentCase{"tension edge", rotated(9e3, 8e3, -2e3, 0.4), strength(30, 10, 10e3, 5e3),
                    ReturnRegion::TensionCutoffEdge},
        TangentCase{"tension + shear", rotated(-16e3, -24e3, 20e3, 0.4), strength(30, 10, 10e3, 5e3),
                    ReturnRegion::TensionShearEdge},
        TangentCase{"tension corner", rotated(-20e3, -24e3, 28e3, 0.4), strength(30, 10, 10e3, 5e3),
                    ReturnRegion::TensionCorner},
        TangentCase{"tresca face", rotated(200e3, -100e3, 50e3, 0.7), strength(0, 0, 50e3), ReturnRegion::Face}),
    [](const ::testing::TestParamInfo<TangentCase>& info) {
      std::string n = info.param.name;
      for (char& ch : n) {
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
      }
      return n;
    });

}  // namespace
