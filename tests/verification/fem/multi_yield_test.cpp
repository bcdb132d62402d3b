// PressureIndependMultiYield (fem_tcl/materials/pressure_independ_multi_yield.hpp) driven point-wise in
// plane-strain pure shear (strain 0, 0, gamma), against the closed forms of its construction:
// - the backbone: OpenSees' surfaces sit at octahedral shear stresses tau_m = m tau_f / n on the hyperbola
//   tau = G g / (1 + g / g_r) (g octahedral shear strain, g_r = g_max tau_f / (G g_max - tau_f),
//   tau_f = 2 sqrt(2) c / 3 for frictionAng = 0), so under monotonic shear the response is elastic up to
//   tau_1 and then follows the hyperbola's secants: g(tau_m) = tau_1 / G + g_hyp(tau_m) - g_hyp(tau_1).
//   In pure shear tau_oct = sqrt(2/3) tau_xy and g_oct = sqrt(2/3) gamma_xy.
// - Masing's rules (Masing 1926; Kramer 1996, sec. 6.4.3), which Mroz's nested surfaces obey: unloading from
//   (gamma_a, tau_a) follows the backbone scaled by two, tau_a - tau = 2 f((gamma_a - gamma) / 2), and a closed
//   cycle returns to the point it left.
// - the strength: beyond g_max the shear stress stays at the failure surface (tau_xy = tau_f / sqrt(2/3)).
// - the user-defined backbone (noYieldSurf < 0): surfaces at tau_xy = G (G / Gmax)_i gamma_i in simple shear
//   (q = sqrt(3) tau_xy), reached at gamma_1 G_1 / Gmax + gamma_i - gamma_1 (elastic to the first, secants on).
// - with frictionAng > 0: a Drucker-Prager cone frozen at the confinement of the switch to plasticity.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common/input_error.hpp"
#include "fem_tcl/materials/pressure_independ_multi_yield.hpp"

namespace {

using fem::materials::PressureIndependMultiYield;
using fem::materials::PressureIndependMultiYieldParameters;
using fem::materials::Vector3;

// A clay in kN-m units (kPa): G = 60 MPa, B = 300 MPa, c = 30 kPa, peak octahedral shear strain 0.1.
PressureIndependMultiYieldParameters clay() {
  PressureIndependMultiYieldParameters p;
  p.density = 1.8;
  p.shear_modulus = 6.0e4;   // kPa
  p.bulk_modulus = 3.0e5;    // kPa
  p.cohesion = 30.0;         // kPa
  p.peak_shear_strain = 0.1;
  return p;
}

/// Drives one plane-strain point through the shear strains `path` (committing each) from zero stress, plastic.
struct ShearDriver {
  explicit ShearDriver(const PressureIndependMultiYieldParameters& p) : material(1, p) { material.update_stage(1); }
  double shear(double gamma) {
    material.set_trial_strain(Vector3(0.0, 0.0, gamma));
    material.commit_state();
    return material.stress()[2];
  }
  PressureIndependMultiYield material;
};

constexpr double kOct = 0.816496580927726;  // sqrt(2/3): tau_oct / tau_xy and g_oct / gamma_xy in pure shear

struct Backbone {  // OpenSees' automatic hyperbola, in octahedral measures
  double G, tau_f, g_r;
  explicit Backbone(const PressureIndependMultiYieldParameters& p)
      : G(p.shear_modulus), tau_f(2.0 * std::sqrt(2.0) * p.cohesion / 3.0),
        g_r(p.peak_shear_strain * tau_f / (G * p.peak_shear_strain - tau_f)) {}
  double hyperbola_strain(double tau) const { return tau * g_r / (G * g_r - tau); }
  /// The model's octahedral strain at octahedral stress tau (tau_1 <= tau <= tau_n-1), n surfaces.
  double model_strain(double tau, int n) const {
    const double t1 = tau_f / n;
    return t1 / G + hyperbola_strain(tau) - hyperbola_strain(t1);
  }
};

TEST(PressureIndependMultiYield, MonotonicShearFollowsTheSecantsOfItsHyperbola) {
  const auto p = clay();
  const Backbone b(p);
  const int n = p.surfaces;
  ShearDriver d(p);
  // Small strain steps, and at each surface stress tau_m compare the model's strain with the closed form.
  const double dg = 1e-7;  // the kinks fall inside a step: interpolation error < dg
  double gamma = 0.0, tau_prev = 0.0;
  int next = 1;
  for (int step = 0; step < 400000 && next < n; ++step) {
    gamma += dg;
    const double tau = d.shear(gamma) * kOct;
    const double t_m = next * b.tau_f / n;
    if (tau_prev < t_m && tau >= t_m) {  // crossed surface m in this step: interpolate its strain
      const double g_at = (gamma - dg + dg * (t_m - tau_prev) / (tau - tau_prev)) * kOct;
      SCOPED_TRACE(testing::Message() << "surface " << next);
      EXPECT_NEAR(g_at, b.model_strain(t_m, n), 1e-4 * b.model_strain(t_m, n) + 2e-7);
      ++next;
    }
    tau_prev = tau;
  }
  EXPECT_EQ(next, n) << "did not reach the last surface before the failure one";
  // Elastic below the first surface, exactly: G gamma.
  ShearDriver e(p);
  EXPECT_NEAR(e.shear(1e-5), p.shear_modulus * 1e-5, 1e-9);
}

TEST(PressureIndependMultiYield, HoldsTheStrengthBeyondThePeakStrain) {
  const auto p = clay();
  const Backbone b(p);
  ShearDriver d(p);
  double tau = 0.0;
  for (int i = 1; i <= 400; ++i) tau = d.shear(i * 1e-3);  // to gamma = 0.4 (g_oct 0.33 > peakShearStra 0.1)
  EXPECT_NEAR(tau, b.tau_f / kOct, 1e-9 * b.tau_f);         // 2 c / sqrt(3) in pure shear
  // The stress ratio response is 1 on the failure surface.
  const auto r = d.material.response("stress");
  ASSERT_TRUE(r.has_value());
  ASSERT_EQ(r->size(), 5u);
  EXPECT_NEAR((*r)[4], 1.0, 1e-9);
  EXPECT_NEAR((*r)[3], tau, 1e-12);
}

TEST(PressureIndependMultiYield, UnloadingFollowsMasingAndAClosedCycleReturnsToItsStart) {
  const auto p = clay();
  ShearDriver d(p);
  const double ga = 0.004, dg = 1e-5;
  double tau_a = 0.0;
  for (double g = dg; g <= ga + 1e-12; g += dg) tau_a = d.shear(g);
  // Backbone at half the unloading amplitude, from a fresh point.
  std::vector<double> backbone;
  {
    ShearDriver fresh(p);
    for (double g = dg; g <= ga + 1e-12; g += dg) backbone.push_back(fresh.shear(g));
  }
  // Unload to -ga: tau_a - tau(g) = 2 f((ga - g) / 2) at g = ga - 2 k dg.
  std::vector<double> down;
  for (double g = ga - dg; g >= -ga - 1e-12; g -= dg) down.push_back(d.shear(g));
  for (std::size_t k = 10; k < backbone.size(); k += 10) {
    const double unloaded = tau_a - down[2 * (k + 1) - 1];  // at g = ga - 2 (k + 1) dg
    SCOPED_TRACE(testing::Message() << "half amplitude " << (k + 1) * dg);
    EXPECT_NEAR(unloaded, 2.0 * backbone[k], 2e-3 * 2.0 * backbone[k] + 0.05);
  }
  // Reload to +ga: back at tau_a (the loop closes).
  double tau_back = 0.0;
  for (double g = -ga + dg; g <= ga + 1e-12; g += dg) tau_back = d.shear(g);
  EXPECT_NEAR(tau_back, tau_a, 1e-3 * tau_a);
  // Symmetric: the stress at -ga is -tau_a.
  EXPECT_NEAR(down.back(), -tau_a, 1e-3 * tau_a);
}

TEST(PressureIndependMultiYield, UserBackbonePointsAreReachedInSimpleShear) {
  // noYieldSurf = -4: (gamma, G / Gmax) points; tau_xy = G (G / Gmax) gamma at each (q = sqrt(3) tau_xy).
  auto p = clay();
  p.surfaces = 4;
  p.backbone = {1e-4, 0.9, 1e-3, 0.6, 1e-2, 0.2, 5e-2, 0.05};
  ShearDriver d(p);
  const std::vector<double> gammas{1e-4, 1e-3, 1e-2, 5e-2};
  // Elastic to tau_1 = G Gs_1 gamma_1 (at gamma = Gs_1 gamma_1), then the secants of the points.
  const double G = p.shear_modulus;
  const double tau1 = G * 0.9 * 1e-4, g1 = tau1 / G;
  double gamma = 0.0, tau = 0.0, prev = 0.0;
  const double dg = 1e-6;
  std::size_t next = 1;
  while (gamma < 0.08 && next < gammas.size()) {
    gamma += dg;
    tau = d.shear(gamma);
    const double t_i = G * p.backbone[2 * next + 1] * gammas[next];
    if (prev < t_i && tau >= t_i) {
      const double g_at = gamma - dg + dg * (t_i - prev) / (tau - prev);
      SCOPED_TRACE(testing::Message() << "point " << next);
      EXPECT_NEAR(g_at, g1 + gammas[next] - gammas[0], 1e-3 * gammas[next] + 2e-6);
      ++next;
    }
    prev = tau;
  }
  EXPECT_EQ(next, gammas.size());
  for (int i = 0; i < 20000; ++i) tau = d.shear(gamma += 1e-5);
  EXPECT_NEAR(tau, G * 0.05 * 5e-2, 1e-9 * tau);  // the last point is the strength
}

TEST(PressureIndependMultiYield, ElasticStageThenPlasticKeepsTheGravityStress) {
  // Stage 0 builds an elastic geostatic state (K0 from G and B); at the switch the surfaces are set around
  // it (OpenSees elast2Plast) and an added shear starts from it.
  const auto p = clay();
  PressureIndependMultiYield m(1, p);
  m.set_trial_strain(Vector3(0.0, -1.1e-4, 0.0));
  m.commit_state();
  const double K = p.bulk_modulus, G = p.shear_modulus;
  EXPECT_NEAR(m.stress()[1], -(K + 4.0 * G / 3.0) * 1.1e-4, 1e-9);
  EXPECT_NEAR(m.stress()[0], -(K - 2.0 * G / 3.0) * 1.1e-4, 1e-9);
  m.update_stage(1);
  m.set_trial_strain(Vector3(0.0, -1.1e-4, 0.0));  // no increment: the state is kept
  EXPECT_NEAR(m.stress()[1], -(K + 4.0 * G / 3.0) * 1.1e-4, 1e-9);
  EXPECT_GT(m.active_surface(), 0);  // the gravity deviator (sxx - syy = -2 G e) is beyond the first surfaces
}

TEST(PressureIndependMultiYield, FrictionScalesTheStrengthWithTheConfinementAtTheSwitch) {
  // frictionAng > 0: the surfaces are a Drucker-Prager cone frozen at the switch, q_f = M (p' + p_r) with
  // M = 6 sin(phi) / (3 - sin(phi)) and p_r = 3 c / (sqrt(2) M) (OpenSees setUpSurfaces / paramScaling).
  auto p = clay();
  p.friction_deg = 30.0;
  p.cohesion = 10.0;
  p.ref_pressure = 80.0;
  p.pressure_exponent = 0.5;
  PressureIndependMultiYield m(1, p);
  const double e = -2e-4;  // confined in stage 0: p' = -K (2 e) = 120 kPa
  m.set_trial_strain(Vector3(e, e, 0.0));
  m.commit_state();
  const double p_conf = -(m.stress_3d()[0] + m.stress_3d()[1] + m.stress_3d()[2]) / 3.0;
  EXPECT_NEAR(p_conf, -2.0 * p.bulk_modulus * e, 1e-9);
  m.update_stage(1);
  double gamma = 0.0;
  for (int i = 0; i < 2000; ++i) {
    m.set_trial_strain(Vector3(e, e, gamma += 2.5e-4));
    m.commit_state();
  }
  const auto s = m.stress_3d();
  const double mean = (s[0] + s[1] + s[2]) / 3.0;
  const double q = std::sqrt(1.5 * ((s[0] - mean) * (s[0] - mean) + (s[1] - mean) * (s[1] - mean) +
                                    (s[2] - mean) * (s[2] - mean) + 2.0 * s[3] * s[3]));
  const double M = 6.0 * 0.5 / (3.0 - 0.5), p_r = 3.0 * 10.0 / (std::sqrt(2.0) * M);
  EXPECT_NEAR(-mean, p_conf, 1e-9);             // shear does not change the pressure
  EXPECT_NEAR(q, M * (p_conf + p_r), 1e-6 * q);  // on the failure cone
  EXPECT_NEAR(m.initial_tangent()(2, 2), p.shear_modulus * std::sqrt((p_conf + p_r) / (80.0 + p_r)), 1e-6);
}

TEST(PressureIndependMultiYield, StrengthReductionDividesTheStrength) {
  // strengthReduction's factor F (reducible_strength.hpp): cohesi / F, so the pure-shear strength halves at
  // F = 2; from a plastic state the surfaces are set again around the committed stress.
  const auto p = clay();
  const Backbone b(p);
  ShearDriver d(p);
  d.shear(2e-4);
  ASSERT_NE(d.material.reducible_strength(), nullptr);
  d.material.set_strength_reduction(2.0);
  EXPECT_EQ(d.material.strength_reduction(), 2.0);
  double tau = 0.0;
  for (int i = 1; i <= 400; ++i) tau = d.shear(2e-4 + i * 1e-3);
  EXPECT_NEAR(tau, 0.5 * b.tau_f / kOct, 1e-9 * b.tau_f);
  EXPECT_THROW(d.material.set_strength_reduction(0.0), common::InputError);
}

TEST(PressureIndependMultiYield, RejectsBadParameters) {
  auto p = clay();
  p.shear_modulus = 0.0;
  EXPECT_THROW(PressureIndependMultiYield(1, p), common::InputError);
  p = clay();
  p.cohesion = 0.0;  // and frictionAng = 0: no strength
  EXPECT_THROW(PressureIndependMultiYield(1, p), common::InputError);
  p = clay();
  p.peak_shear_strain = 1e-6;  // G g_max below the strength: no hyperbola
  EXPECT_THROW(PressureIndependMultiYield(1, p), common::InputError);
  p = clay();
  p.surfaces = 3;
  p.backbone = {1e-4, 0.9, 1e-3, 0.6};  // 2 points for 3 surfaces
  EXPECT_THROW(PressureIndependMultiYield(1, p), common::InputError);
  p.surfaces = 2;
  p.backbone = {1e-3, 0.5, 1e-4, 0.9};  // the strain decreasing: the second surface inside the first
  EXPECT_THROW(PressureIndependMultiYield(1, p), common::InputError);
  p.backbone = {1e-4, 0.9, 1e-3, 0.05};  // the stress decreasing
  EXPECT_THROW(PressureIndependMultiYield(1, p), common::InputError);
  PressureIndependMultiYield ok(1, clay());
  EXPECT_THROW(ok.copy_for(fem::materials::PlaneType::PlaneStress), common::InputError);
  EXPECT_THROW(ok.update_stage(2), common::InputError);
}

}  // namespace
