// Unit tests of mpm/core/materials.hpp: plane-strain linear elasticity (Hooke) and the Mohr-Coulomb
// wrapper (CB-Geo's state variables and linear softening, include/materials/mohr_coulomb.tcc).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>

#include "mpm/core/materials.hpp"
#include "support/mpm_softening_soil.hpp"
#include "support/tolerance.hpp"

namespace {

using mpm::core::LinearElastic;
using mpm::core::MohrCoulomb;

mpm::MaterialSpec mc_spec() { return mpm_test::softening_soil(mpm::MaterialType::MohrCoulomb2D); }

TEST(LinearElastic, PlaneStrainHooke) {
  mpm::MaterialSpec s;
  s.youngs_modulus = 2e7;
  s.poisson_ratio = 0.25;
  const LinearElastic m = LinearElastic::from(s);
  double stress[4] = {0, 0, 0, 0};
  const double de[3] = {1e-4, -2e-4, 3e-4};
  m.update(stress, de, nullptr);
  // sigma = lambda tr(e) I + 2 G e, lambda = E nu / ((1 + nu)(1 - 2 nu)), G = E / (2 (1 + nu)).
  const double E = 2e7, nu = 0.25, lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), G = E / (2 * (1 + nu));
  EXPECT_CLOSE(stress[0], lambda * (-1e-4) + 2 * G * 1e-4, 1e-6, 1e-12);
  EXPECT_CLOSE(stress[1], lambda * (-1e-4) + 2 * G * (-2e-4), 1e-6, 1e-12);
  EXPECT_CLOSE(stress[2], lambda * (-1e-4), 1e-6, 1e-12);
  EXPECT_CLOSE(stress[3], G * 3e-4, 1e-6, 1e-12);
}

TEST(MohrCoulombMaterial, InitialStateIsPeakStrength) {
  const MohrCoulomb m = MohrCoulomb::from(mc_spec());
  double sv[7];
  m.initial_state(sv);
  EXPECT_EQ(sv[0], m.phi_peak);
  EXPECT_EQ(sv[1], m.psi_peak);
  EXPECT_EQ(sv[2], 1000.0);
  for (int i = 3; i < 7; ++i) EXPECT_EQ(sv[i], 0.0);
}

TEST(MohrCoulombMaterial, ElasticStepKeepsPdstrainAndMatchesHooke) {
  const MohrCoulomb m = MohrCoulomb::from(mc_spec());
  double sv[7];
  m.initial_state(sv);
  double s[4] = {-1e4, -1e4, -1e4, 0};
  const double de[3] = {-1e-6, -1e-6, 0};
  m.update(s, de, sv);
  const double K = 1e7 / (3 * (1 - 0.6)), G = 1e7 / 2.6;
  EXPECT_CLOSE(s[0], -1e4 + (K + 4 * G / 3) * -1e-6 + (K - 2 * G / 3) * -1e-6, 1e-8, 1e-12);
  EXPECT_EQ(sv[6], 0.0);
}

TEST(MohrCoulombMaterial, ShearingToFailureAccumulatesPdstrainAndSoftens) {
  const MohrCoulomb m = MohrCoulomb::from(mc_spec());
  double sv[7];
  m.initial_state(sv);
  double s[4] = {-1e5, -1e5, -1e5, 0};
  const double de[3] = {0, 0, 2e-3};  // simple shear increments
  double last_pd = 0;
  for (int i = 0; i < 60; ++i) {
    m.update(s, de, sv);
    EXPECT_GE(sv[6], last_pd);
    last_pd = sv[6];
  }
  EXPECT_GT(sv[6], 0.05);  // past residual_pdstrain
  // Next update applies the residual values (CB-Geo: softening before the predictor).
  m.update(s, de, sv);
  EXPECT_CLOSE(sv[0], m.phi_residual, 1e-15, 0);
  EXPECT_CLOSE(sv[1], m.psi_residual, 1e-15, 0);
  EXPECT_CLOSE(sv[2], 100.0, 1e-12, 0);
  // The stress lies on the residual Mohr-Coulomb surface: (s1 - s3) + (s1 + s3) sin(phi) = 2 c cos(phi).
  const double c = 0.5 * (s[0] + s[1]), r = std::hypot(0.5 * (s[0] - s[1]), s[3]);
  const double s1 = std::max({c + r, s[2]}), s3 = std::min({c - r, s[2]});
  EXPECT_CLOSE((s1 - s3) + (s1 + s3) * std::sin(sv[0]), 2 * 100 * std::cos(sv[0]), 1e-6 * 1e5, 0);
}

TEST(MohrCoulombMaterial, SofteningIsLinearBetweenPeakAndResidual) {
  const MohrCoulomb m = MohrCoulomb::from(mc_spec());
  double sv[7];
  m.initial_state(sv);
  sv[6] = 0.03;  // half way between 0.01 and 0.05
  double s[4] = {-1e4, -1e4, -1e4, 0};
  const double de[3] = {0, 0, 0};
  m.update(s, de, sv);
  EXPECT_CLOSE(sv[0], 0.5 * (m.phi_peak + m.phi_residual), 1e-15, 1e-14);
  EXPECT_CLOSE(sv[2], 550.0, 1e-10, 0);
}

TEST(MohrCoulombMaterial, InvariantsInCbGeoConvention) {
  double sv[7] = {};
  const double s[4] = {-3e4, -1e4, -2e4, 0};
  MohrCoulomb::set_invariants(s, sv);
  EXPECT_CLOSE(sv[3], std::sqrt(3.0) * -2e4, 1e-8, 1e-12);  // epsilon = sqrt(3) p
  const double j2 = ((2e4 * 2e4) + (1e4 * 1e4) + (1e4 * 1e4)) / 6.0;
  EXPECT_CLOSE(sv[4], std::sqrt(2 * j2), 1e-8, 1e-12);  // rho = sqrt(2 J2)
  EXPECT_CLOSE(sv[5], std::acos(0.0) / 3.0, 1e-12, 0);  // pure shear deviator: J3 = 0 -> theta = pi/6
}

/// The bits of a double (NaN payloads and signed zeros compared too).
std::uint64_t bits(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

// update4 (the elastic test of four particles in the lanes of a Double4) against four update() calls:
// the same stress and state variables, bit for bit, on random groups that mix elastic trials, plastic
// returns, states on the surface within round-off, softened particles (which take update_general) and
// a non-finite increment.
TEST(MohrCoulombMaterial, UpdateOfFourParticlesIsFourUpdatesBitForBit) {
  const MohrCoulomb m = MohrCoulomb::from(mc_spec());
  constexpr std::size_t kSv = mpm::core::kStateVariables;
  std::mt19937_64 rng(20261204);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int elastic = 0, plastic = 0, softened = 0, on_surface = 0;
  for (int group = 0; group < 4000; ++group) {
    double s[16], de[12], sv[4 * kSv];
    for (int l = 0; l < 4; ++l) {
      double* sl = s + 4 * l;
      const double p = -2e4 * (1.0 + unit(rng)), q = 1e4 * unit(rng);
      sl[0] = p + q;
      sl[1] = p - q;
      sl[2] = p + 0.3 * q * unit(rng);
      sl[3] = 5e3 * unit(rng);
      const double scale = std::pow(10.0, -7.0 + 4.0 * (0.5 + 0.5 * unit(rng)));
      for (int c = 0; c < 3; ++c) de[3 * l + c] = scale * unit(rng);
      m.initial_state(sv + kSv * l);
      if (group % 7 == l) {  // softened: update_general
        sv[kSv * l + 6] = 0.02;
        ++softened;
      }
      if (group % 11 == l) {  // a returned state, loaded by nothing: on the surface within round-off
        double returned[4] = {-1e4, -1e4, -1e4, 0.0}, sv0[kSv];
        m.initial_state(sv0);
        const double shear[3] = {2e-3, -2e-3, 1e-3};
        m.update(returned, shear, sv0);
        std::memcpy(sl, returned, sizeof returned);
        for (int c = 0; c < 3; ++c) de[3 * l + c] = 0.0;
        ++on_surface;
      }
    }
    if (group == 3999) de[5] = std::numeric_limits<double>::quiet_NaN();
    double s4[16], sv4[4 * kSv];
    std::memcpy(s4, s, sizeof s);
    std::memcpy(sv4, sv, sizeof sv);
    m.update4(s4, de, sv4);
    for (int l = 0; l < 4; ++l) {
      const double pd_before = sv[kSv * l + 6];
      m.update(s + 4 * l, de + 3 * l, sv + kSv * l);
      (sv[kSv * l + 6] == pd_before ? elastic : plastic) += 1;
    }
    for (int i = 0; i < 16; ++i) ASSERT_EQ(bits(s4[i]), bits(s[i])) << "group " << group << " stress " << i;
    for (std::size_t i = 0; i < 4 * kSv; ++i) ASSERT_EQ(bits(sv4[i]), bits(sv[i])) << "group " << group << " svar " << i;
  }
  // Every path was taken (counted from the one-particle updates).
  EXPECT_GT(elastic, 1000);
  EXPECT_GT(plastic, 1000);
  EXPECT_GT(softened, 500);
  EXPECT_GT(on_surface, 300);
}

}  // namespace
