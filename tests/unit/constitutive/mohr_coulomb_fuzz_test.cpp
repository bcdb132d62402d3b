// Randomised checks of the Mohr-Coulomb return (constitutive/mohr_coulomb.hpp) over many trial states and
// strengths (phi 0..45 deg, psi 0..phi, c = 0 / tiny / finite, with and without a tension cutoff):
// finiteness, admissibility, idempotence (a returned state reloaded with no increment is elastic), the
// projection property of associated returns, and the consistent tangent against central differences.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "constitutive/mohr_coulomb.hpp"
#include "support/tolerance.hpp"

namespace {

using namespace constitutive;

constexpr double kDeg = M_PI / 180.0;
const IsotropicElasticity kElastic = IsotropicElasticity::from_young_poisson(30e6, 0.28);

Eigen::Vector3d principal(const PlaneStrainStress& s) {
  const double c = 0.5 * (s[0] + s[1]), r = std::sqrt(0.25 * (s[0] - s[1]) * (s[0] - s[1]) + s[3] * s[3]);
  double v[3] = {c + r, c - r, s[2]};
  std::sort(v, v + 3, [](double x, double y) { return x > y; });
  return {v[0], v[1], v[2]};
}

/// Largest violation of the Mohr-Coulomb and Rankine conditions (Pa; <= 0 inside).
double violation(const PlaneStrainStress& s, const MohrCoulombStrength& st) {
  const Eigen::Vector3d p = principal(s);
  double v = (p[0] - p[2]) + (p[0] + p[2]) * std::sin(st.friction) - 2 * st.cohesion * std::cos(st.friction);
  if (std::isfinite(st.tension_cutoff)) v = std::max(v, p[0] - st.tension_cutoff);
  return v;
}

/// Complementary energy inner product (a, C b) with C the plane-strain compliance on (sxx, syy, szz, sxy).
double energy(const Eigen::Vector4d& a, const Eigen::Vector4d& b) {
  const double k = kElastic.bulk_modulus, g = kElastic.shear_modulus;
  const double pa = (a[0] + a[1] + a[2]) / 3, pb = (b[0] + b[1] + b[2]) / 3;
  double dev = 0.0;
  for (int i = 0; i < 3; ++i) dev += (a[i] - pa) * (b[i] - pb);
  return dev / (2 * g) + 3 * pa * pb / (3 * k) * 1.0 + a[3] * b[3] / g;
}

struct Sampler {
  std::mt19937_64 rng{20261122};
  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
  MohrCoulombStrength strength(bool associated) {
    const double phi = uniform(0.0, 1.0) < 0.1 ? 0.0 : uniform(0.0, 45.0) * kDeg;  // some exact Tresca
    const double psi = associated ? phi : uniform(0.0, 1.0) * phi;
    const double pick = uniform(0.0, 1.0);
    const double c = pick < 0.3 ? 0.0 : (pick < 0.4 ? 1e-9 : uniform(0.0, 50e3));
    const double t = uniform(0.0, 1.0) < 0.4 ? uniform(0.0, 30e3) : std::numeric_limits<double>::infinity();
    return {phi, psi, c, t};
  }
  PlaneStrainStress stress(double scale) {
    return {uniform(-scale, 0.3 * scale), uniform(-scale, 0.3 * scale), uniform(-scale, 0.3 * scale),
            uniform(-0.5 * scale, 0.5 * scale)};
  }
};

TEST(MohrCoulombFuzz, ReturnsAreFiniteAdmissibleAndIdempotent) {
  Sampler s;
  int plastic = 0;
  for (int n = 0; n < 20000; ++n) {
    const MohrCoulombStrength st = s.strength(false);
    const PlaneStrainStress trial = s.stress(300e3);
    const MohrCoulombUpdate u = mohr_coulomb_return(trial, kElastic, st);
    ASSERT_TRUE(u.stress.allFinite()) << n;
    ASSERT_TRUE(u.plastic_strain_increment.allFinite()) << n;
    const double scale = std::max(trial.cwiseAbs().maxCoeff(), st.cohesion);
    EXPECT_LE(violation(u.stress, st), 1e-8 * scale) << n << " region " << to_string(u.region);
    if (u.region == ReturnRegion::Elastic) {
      EXPECT_EQ(u.stress, trial);
      continue;
    }
    ++plastic;
    const MohrCoulombUpdate again = mohr_coulomb_update(u.stress, PlaneStrainStrain::Zero(), kElastic, st);
    // Reloading a returned state: elastic, or (within round-off of the surface) a return that moves it by
    // no more than round-off.
    EXPECT_LE((again.stress - u.stress).norm(), 1e-9 * scale) << n;
    EXPECT_TRUE(mohr_coulomb_tangent(trial, kElastic, st).allFinite()) << n;
  }
  EXPECT_GT(plastic, 5000);
}

TEST(MohrCoulombFuzz, AssociatedReturnIsTheClosestPointInTheEnergyNorm) {
  // For associated flow the return is the projection onto the convex admissible set in the complementary
  // energy norm (de Souza Neto, Peric & Owen 2008, ch. 7; Simo & Hughes 1998, ch. 3): (trial - s, C (tau - s)) <= 0 for every
  // admissible tau. Checked against random admissible states and against other returned states.
  Sampler s;
  for (int n = 0; n < 3000; ++n) {
    const MohrCoulombStrength st = s.strength(true);
    const PlaneStrainStress trial = s.stress(300e3);
    const MohrCoulombUpdate u = mohr_coulomb_return(trial, kElastic, st);
    if (u.region == ReturnRegion::Elastic) continue;
    const Eigen::Vector4d r = trial - u.stress;
    const double rn = std::sqrt(energy(r, r));
    for (int m = 0; m < 20; ++m) {
      const PlaneStrainStress tau = mohr_coulomb_return(s.stress(300e3), kElastic, st).stress;  // admissible
      const Eigen::Vector4d d = tau - u.stress;
      const double dn = std::sqrt(energy(d, d));
      EXPECT_LE(energy(r, d), 1e-8 * rn * dn + 1e-20) << n << " region " << to_string(u.region);
    }
  }
}

TEST(MohrCoulombFuzz, ConsistentTangentAwayFromRegionBoundaries) {
  Sampler s;
  int checked = 0;
  for (int n = 0; n < 4000 && checked < 800; ++n) {
    const MohrCoulombStrength st = s.strength(false);
    const PlaneStrainStress trial = s.stress(300e3);
    const MohrCoulombUpdate u = mohr_coulomb_return(trial, kElastic, st);
    const Eigen::Matrix<double, 4, 3> t = mohr_coulomb_tangent_4x3(trial, kElastic, st);
    Eigen::Matrix<double, 4, 3> fd;
    const double h = 1e-9;
    bool same_region = true;
    for (int j = 0; j < 3 && same_region; ++j) {
      PlaneStrainStrain d = PlaneStrainStrain::Zero();
      d[j] = h;
      const MohrCoulombUpdate up = mohr_coulomb_update(trial, d, kElastic, st);
      const MohrCoulombUpdate um = mohr_coulomb_update(trial, -d, kElastic, st);
      same_region = up.region == u.region && um.region == u.region;
      fd.col(j) = (up.stress - um.stress) / (2 * h);
    }
    if (!same_region) continue;  // a region boundary within h: the response is not differentiable there
    // Skip states within round-off of an edge (nearly equal principal values): the one-sided slopes differ.
    const Eigen::Vector3d p = principal(u.stress);
    if (u.region == ReturnRegion::Face && std::min(p[0] - p[1], p[1] - p[2]) < 1e-3 * (std::abs(p[0]) + std::abs(p[2])))
      continue;
    ++checked;
    const double ref = kElastic.bulk_modulus + 4.0 / 3.0 * kElastic.shear_modulus;
    EXPECT_LT((t - fd).norm() / std::max(t.norm(), ref), 1e-6) << n << " region " << to_string(u.region) << "\n"
                                                              << t << "\nfd\n" << fd;
  }
  EXPECT_GT(checked, 500);
}

}  // namespace
