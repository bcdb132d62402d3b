// Verification: material-point tests that drive the Mohr-Coulomb kernel and the DruckerPrager material to their
// analytical limit states, and the quadratic convergence of Newton's method with the consistent tangent.
//
// References
//   [CH]  Chen & Han (1988), Plasticity for Structural Engineers, Springer: ch. 2 (Mohr-Coulomb, Kp =
//         (1 + sin phi) / (1 - sin phi), compression limit s_1 = Kp s_3 + 2 c sqrt(Kp); Drucker-Prager and its
//         plane-strain match to Mohr-Coulomb).
//   [SPO] de Souza Neto, Peric & Owen (2008), Computational Methods for Plasticity: ch. 6 (the
//         plane-strain Drucker-Prager match: at collapse in plane strain with associated flow the DP cone gives
//         the Mohr-Coulomb in-plane limit), ch. 4 and 7 (quadratic convergence with the consistent tangent).
//   [D]   Davis (1968), Theories of plasticity and the failure of soil masses, in Soil Mechanics: Selected
//         Topics (Lee ed.): in plane-strain simple shear with non-dilatant flow the ultimate state has
//         sxx = syy and tau_xy = c cos(phi) - syy sin(phi).
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <cstdio>
#include <vector>

#include "constitutive/mohr_coulomb.hpp"
#include "fem_tcl/materials/drucker_prager.hpp"
#include "support/tolerance.hpp"

namespace {

using constitutive::IsotropicElasticity;
using constitutive::MohrCoulombStrength;
using constitutive::PlaneStrainStrain;
using constitutive::PlaneStrainStress;

constexpr double kDeg = M_PI / 180.0;
const double kInf = std::numeric_limits<double>::infinity();

/// Plane-strain biaxial compression under constant lateral stress sxx = -pc (mixed control: exx solved by
/// Newton with the consistent tangent), eyy compressed in steps, from a hydrostatic state -pc.
/// Returns the final syy; `residuals` gets the Newton history of the last plastic step.
double mc_biaxial(const IsotropicElasticity& el, const MohrCoulombStrength& st, double pc, int steps, double deyy,
                  std::vector<double>* residuals) {
  PlaneStrainStress s(-pc, -pc, -pc, 0.0);
  for (int k = 0; k < steps; ++k) {
    double dexx = 0.0;
    std::vector<double> history;
    constitutive::MohrCoulombUpdate up{};
    for (int it = 0; it < 30; ++it) {
      const PlaneStrainStrain de(dexx, deyy, 0.0);
      up = constitutive::mohr_coulomb_update(s, de, el, st);
      const double r = up.stress[0] + pc;  // want sxx = -pc
      history.push_back(std::abs(r) / pc);
      if (std::abs(r) <= 1e-13 * pc) break;
      const auto t = constitutive::mohr_coulomb_tangent_4x3(constitutive::elastic_trial(s, de, el), el, st);
      dexx -= r / t(0, 0);
    }
    s = up.stress;
    if (residuals != nullptr && up.region != constitutive::ReturnRegion::Elastic) *residuals = history;
  }
  return s[1];
}

TEST(MaterialPointLimits, MohrCoulombPlaneStrainCompressionReachesTheAnalyticalLimit) {
  // [CH] ch. 2: at failure s_major(compression) = Kp pc + 2 c sqrt(Kp) with the lateral stress pc.
  const IsotropicElasticity el = IsotropicElasticity::from_young_poisson(50e6, 0.3);
  for (double psi_deg : {0.0, 10.0, 30.0}) {
    for (double c : {0.0, 20e3}) {
      const MohrCoulombStrength st{30 * kDeg, psi_deg * kDeg, c, kInf};
      const double pc = 100e3;
      const double kp = (1 + std::sin(st.friction)) / (1 - std::sin(st.friction));
      std::vector<double> residuals;
      const double syy = mc_biaxial(el, st, pc, 200, -5e-5, &residuals);
      EXPECT_CLOSE(-syy, kp * pc + 2 * c * std::sqrt(kp), 1e-6, 1e-10) << "psi " << psi_deg << " c " << c;
      ASSERT_GE(residuals.size(), 2u);
    }
  }
}

TEST(MaterialPointLimits, NewtonWithTheConsistentTangentConvergesQuadratically) {
  // [SPO] ch. 4, 7: with the exact tangent the residual of a plastic step falls quadratically. Mixed control
  // with two unknowns (exx, gxy) and prescribed sxx = -pc, sxy = tau0 while eyy is compressed: the principal
  // axes rotate, so the plastic response is genuinely nonlinear (not piecewise linear) in the unknowns.
  const IsotropicElasticity el = IsotropicElasticity::from_young_poisson(50e6, 0.3);
  const MohrCoulombStrength st{30 * kDeg, 10 * kDeg, 5e3, kInf};
  const double pc = 100e3, tau0 = 20e3;
  PlaneStrainStress s(-pc, -pc, -pc, tau0);
  std::vector<double> residuals;
  for (int step = 0; step < 8; ++step) {
    Eigen::Vector2d x(0.0, 0.0);  // (dexx, dgxy)
    std::vector<double> history;
    constitutive::MohrCoulombUpdate up{};
    for (int it = 0; it < 30; ++it) {
      const PlaneStrainStrain de(x[0], -1e-3, x[1]);
      up = constitutive::mohr_coulomb_update(s, de, el, st);
      const Eigen::Vector2d r(up.stress[0] + pc, up.stress[3] - tau0);
      history.push_back(r.norm() / pc);
      if (r.norm() <= 1e-12 * pc) break;
      const auto t = constitutive::mohr_coulomb_tangent_4x3(constitutive::elastic_trial(s, de, el), el, st);
      Eigen::Matrix2d j;
      j << t(0, 0), t(0, 2), t(3, 0), t(3, 2);
      x -= j.inverse() * r;
    }
    s = up.stress;
    if (up.region != constitutive::ReturnRegion::Elastic) residuals = history;
  }
  std::printf("Newton residual history |r| / pc (last plastic step):");
  for (double r : residuals) std::printf(" %.3e", r);
  std::printf("\n");
  ASSERT_GE(residuals.size(), 3u);
  ASSERT_LE(residuals.size(), 8u);  // converged to 1e-12 within a few iterations
  EXPECT_LE(residuals.back(), 1e-12);
  // Quadratic: in the asymptotic range r_{k+1} <= C r_k^2.
  int checked = 0;
  for (std::size_t k = 1; k + 1 < residuals.size(); ++k) {
    if (residuals[k] < 1e-2 && residuals[k + 1] > 1e-14) {
      EXPECT_LE(residuals[k + 1], 10.0 * residuals[k] * residuals[k]);
      ++checked;
    }
  }
  EXPECT_GE(checked, 1);
}

TEST(MaterialPointLimits, MohrCoulombSimpleShearReachesDavisLimit) {
  // [D]: ultimate state of plane-strain simple shear (exx = eyy = 0, gxy increasing) with psi = 0:
  // sxx = syy and tau = c cos(phi) - syy sin(phi) (tension positive).
  const IsotropicElasticity el = IsotropicElasticity::from_young_poisson(20e6, 0.3);
  for (double c : {0.0, 10e3}) {
    const MohrCoulombStrength st{25 * kDeg, 0.0, c, kInf};
    PlaneStrainStress s(-80e3, -100e3, -60e3, 0.0);  // an anisotropic initial (K0-like) state
    for (int k = 0; k < 4000; ++k) s = constitutive::mohr_coulomb_update(s, {0.0, 0.0, 1e-4}, el, st).stress;
    EXPECT_CLOSE(s[0], s[1], 1e-3, 1e-8);
    EXPECT_CLOSE(s[3], c * std::cos(st.friction) - s[1] * std::sin(st.friction), 1e-3, 1e-8);
  }
}

// --- DruckerPrager (OpenSees) ---------------------------------------------------------------------------------

fem::materials::DruckerPragerParameters dp_matched(double phi, double c, double rho_bar_factor) {
  // [CH] ch. 2 / reference case 1.3: the plane-strain match of Mohr-Coulomb (phi, c).
  const double t = std::tan(phi), d = std::sqrt(9 + 12 * t * t);
  fem::materials::DruckerPragerParameters p{};
  p.bulk_modulus = 53333.33;
  p.shear_modulus = 32000;
  p.sigma_y = 3 * std::sqrt(3.0) * c / d;
  p.rho = std::sqrt(2.0) * t / d;
  p.rho_bar = rho_bar_factor * p.rho;
  p.theta = 1;
  return p;  // H = Kinf = Ko = delta = 0: perfect plasticity
}

TEST(MaterialPointLimits, DruckerPragerSimpleShearLimit) {
  // Non-dilatant (rho_bar = 0) DP in plane-strain simple shear: I1 stays at its initial value (no volume change,
  // elastic or plastic) and the ultimate deviator is pure shear, so sqrt(2) tau + rho I1 = sqrt(2/3) sigma_y.
  const auto p = dp_matched(30 * kDeg, 5.0, 0.0);
  fem::materials::DruckerPrager dp(1, p);
  auto m = dp.copy_for(fem::materials::PlaneType::PlaneStrain);
  const double e0 = -2e-4;  // initial isotropic in-plane compression
  for (int k = 0; k <= 3000; ++k) {
    m->set_trial_strain({e0, e0, 1e-5 * k});
    m->commit_state();
  }
  const double i1 = 3 * p.bulk_modulus * 2 * e0;
  const double tau = (std::sqrt(2.0 / 3.0) * p.sigma_y - p.rho * i1) / std::sqrt(2.0);
  EXPECT_CLOSE(m->stress()[2], tau, 1e-9, 1e-7);
  EXPECT_CLOSE(m->stress()[0], m->stress()[1], 1e-9, 1e-7);
}

TEST(MaterialPointLimits, AssociatedDruckerPragerMatchesMohrCoulombInPlaneStrainCompression) {
  // [SPO] ch. 6 / [CH] ch. 2: with the plane-strain match and associated flow, the DP collapse stress in
  // plane-strain biaxial compression equals the Mohr-Coulomb one, Kp pc + 2 c sqrt(Kp).
  const double phi = 30 * kDeg, c = 5.0, pc = 20.0;
  const auto p = dp_matched(phi, c, 1.0);
  fem::materials::DruckerPrager dp(1, p);
  auto m = dp.copy_for(fem::materials::PlaneType::PlaneStrain);
  // Start hydrostatic in plane: exx = eyy = e0 gives sxx = syy = -pc... then compress eyy with sxx held at
  // its value (mixed control, Newton on exx with the material's tangent).
  const double k = p.bulk_modulus, g = p.shear_modulus;
  const double e0 = -pc / (3 * k * 2.0 / 3.0 + 2 * g * (1 - 2.0 / 3.0));
  double exx = e0, eyy = e0;
  m->set_trial_strain({exx, eyy, 0.0});
  m->commit_state();
  const double sxx0 = m->stress()[0];
  for (int step = 0; step < 400; ++step) {
    eyy -= 2e-5;
    for (int it = 0; it < 100; ++it) {
      m->set_trial_strain({exx, eyy, 0.0});
      const double r = m->stress()[0] - sxx0;
      if (std::abs(r) < 1e-12 * pc) break;
      exx -= r / m->tangent()(0, 0);
    }
    m->commit_state();
  }
  const double kp = (1 + std::sin(phi)) / (1 - std::sin(phi));
  EXPECT_CLOSE(-m->stress()[1], kp * (-sxx0) + 2 * c * std::sqrt(kp), 1e-6, 1e-5);
}

}  // namespace
