// Verification: PM4Silt (fem_tcl/materials/pm4silt.hpp) in monotonic direct simple shear, against the calibration
// targets of Boulanger & Ziotopoulou (2018), "PM4Silt (Version 1): a silt plasticity model for earthquake
// engineering applications", Report UCD/CGM-18/01, UC Davis (the manual):
//  - the primary input is the undrained shear strength S_u, or the ratio Su_Rat = S_u / sigma'vc; the
//    critical-state line e_cs = Gamma - lambda ln(101.3 p / P_atm) is placed through (p_cs = 2 S_u / M, eInit)
//    (manual section 2, critical state; M = 2 sin(phi_cv)), so that undrained (constant-volume) DSS loading ends
//    at critical state with a Mohr-circle radius, hence a horizontal shear stress, of S_u at e = eInit. The void
//    ratio of the shearing stage is eInit less the consolidation strain's change, so the critical state is
//    reached at p = p_cs exp((eInit - e) / lambda) and tau = S_u exp((eInit - e) / lambda) (1 to 2 % above S_u
//    here), with q / p = M;
//  - the state parameter xi = e - e_cs tells wet (loose, xi > 0: contractive, Mb < M) from dry (dense, xi < 0:
//    dilative, Mb > M) of critical (section 2, bounding and dilatancy surfaces); a normally consolidated silt
//    (Su_Rat near 0.25) is wet of critical: undrained its p falls, drained it contracts and hardens towards M;
//    a strongly overconsolidated one (Su_Rat 1.0) is dry: undrained its p rises, drained it dilates, peaks above M
//    and softens to M.
// Each point is consolidated one-dimensionally in the elastic stage (exx = 0, syy = -100 kPa, K0 = nu / (1 - nu)),
// switched to stage 1 with FirstCall (S_u = Su_Rat sigma'yy), then sheared: undrained with exx = eyy fixed,
// drained at constant syy with exx = 0, eyy found at each step by a bracketed secant iteration.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "fem_tcl/materials/pm4silt.hpp"
#include "support/tolerance.hpp"

namespace {

using fem::materials::PM4Silt;
using fem::materials::PM4SiltParameters;
using fem::materials::Vector3;

constexpr double kSigmaV = 100.0;  // kPa, vertical consolidation stress

struct Sample {
  double gamma = 0;  ///< engineering shear strain
  double eps_v = 0;  ///< volumetric strain of the shearing stage, compression positive
  double tau = 0;    ///< sxy (kPa)
  double p = 0;      ///< (sxx + syy) / 2, compression positive
  double ratio = 0;  ///< q / p, q = 2 sqrt(((sxx - syy) / 2)^2 + sxy^2)
  double xi = 0;     ///< state parameter at the current void ratio and p
  double e = 0;      ///< void ratio
};

/// A PM4Silt point consolidated in stage 0 to syy = -kSigmaV with exx = 0, then stage 1 and FirstCall.
class SimpleShear {
 public:
  explicit SimpleShear(double su_rat) : material_(1, parameters(su_rat)) {
    const PM4SiltParameters& p = material_.parameters();
    const double G = p.G0 * p.P_atm;  // stage 0: G = G_o P_atm, K from nu
    const double K = 2.0 / 3.0 * (1.0 + p.nu) / (1.0 - 2.0 * p.nu) * G;
    eyy0_ = eyy_ = -kSigmaV / (K + 4.0 / 3.0 * G);
    material_.set_trial_strain(Vector3(0.0, eyy_, 0.0));
    material_.commit_state();
    material_.update_stage(1);
    material_.set_parameter("FirstCall", 0.0);
  }

  /// Undrained (constant volume): exx = 0, eyy fixed, gamma in steps of 5e-6 to `gamma_end`.
  std::vector<Sample> undrained(double gamma_end, int every) {
    std::vector<Sample> out{sample(0.0)};
    const int steps = static_cast<int>(std::round(gamma_end / 5e-6));
    for (int i = 1; i <= steps; ++i) {
      material_.set_trial_strain(Vector3(0.0, eyy_, i * 5e-6));
      material_.commit_state();
      if (i % every == 0) out.push_back(sample(i * 5e-6));
    }
    return out;
  }

  /// Drained at constant syy = -kSigmaV: exx = 0, gamma in steps of 1e-5, eyy solved at each step.
  std::vector<Sample> drained(double gamma_end, int every) {
    std::vector<Sample> out{sample(0.0)};
    const int steps = static_cast<int>(std::round(gamma_end / 1e-5));
    for (int i = 1; i <= steps; ++i) {
      solve_eyy(i * 1e-5);
      material_.commit_state();
      if (i % every == 0) out.push_back(sample(i * 1e-5));
    }
    return out;
  }

  const PM4Silt& material() const { return material_; }

 private:
  static PM4SiltParameters parameters(double su_rat) {
    PM4SiltParameters p;  // the golden DSS run's silt (G_o 500, h_po 4) with OpenSees' defaults otherwise
    p.Su = 0.0;
    p.Su_Rat = su_rat;
    p.G0 = 500.0;
    p.hpo = 4.0;
    p.density = 1.7;
    return p;
  }

  double residual(double eyy, double gamma) {
    material_.set_trial_strain(Vector3(0.0, eyy, gamma));
    return material_.stress()[1] + kSigmaV;  // syy grows with eyy (tension positive)
  }

  /// syy(eyy) = -kSigmaV: a bracket from the last eyy with steps of the elastic compliance, then regula falsi
  /// with the Illinois weight, to |residual| < 1e-7 kSigmaV (or the bracket below 1e-15). Leaves the trial at eyy.
  void solve_eyy(double gamma) {
    const double direction = residual(eyy_, gamma) > 0.0 ? -1.0 : 1.0;  // r > 0: eyy too large
    double step = 1e-7;
    double a = eyy_, fa = residual(a, gamma);
    double b = eyy_ + direction * step, fb = residual(b, gamma);
    for (int k = 0; fa * fb > 0.0 && k < 60; ++k) {  // doubling steps away from the last eyy
      a = b;
      fa = fb;
      step *= 2.0;
      b = eyy_ + direction * step;
      fb = residual(b, gamma);
    }
    ASSERT_LE(fa * fb, 0.0) << "no bracket at gamma " << gamma;
    int side = 0;
    for (int it = 0; it < 200; ++it) {
      const double c = b - fb * (b - a) / (fb - fa);
      const double fc = residual(c, gamma);
      eyy_ = c;
      if (std::abs(fc) < 1e-7 * kSigmaV || std::abs(b - a) < 1e-15) return;
      if (fc * fb < 0.0) {
        a = b;
        fa = fb;
        if (side == -1) fa *= 0.5;
        side = -1;
      } else {
        if (side == 1) fa *= 0.5;
        side = 1;
      }
      b = c;
      fb = fc;
    }
    ADD_FAILURE() << "no convergence at gamma " << gamma;
  }

  Sample sample(double gamma) const {
    const Vector3 s = material_.stress();
    Sample r;
    r.gamma = gamma;
    r.eps_v = -(eyy_ - eyy0_);
    r.tau = s[2];
    r.p = -0.5 * (s[0] + s[1]);
    r.ratio = 2.0 * std::sqrt(0.25 * (s[0] - s[1]) * (s[0] - s[1]) + s[2] * s[2]) / r.p;
    r.e = (*material_.response("state"))[12];
    r.xi = material_.state_parameter(r.e, r.p);
    return r;
  }

  PM4Silt material_;
  double eyy_ = 0.0, eyy0_ = 0.0;
};

// Undrained DSS to 20 % shear strain: the shear stress approaches S_u = Su_Rat sigma'vc, exactly the critical
// state's S_u exp((eInit - e) / lambda), for S_u / sigma'vc from 0.15 to 1.0 (z_max and ce follow Su_Rat).
// Measured tau / (Su_Rat sigma'vc) at 20 %: 1.020, 1.018, 1.007, 1.008, 1.007; q / p within 0.8 % of M.
TEST(PM4SiltUndrainedSimpleShear, ShearStrengthApproachesSuRat) {
  for (double su_rat : {0.15, 0.25, 0.4, 0.6, 1.0}) {
    SCOPED_TRACE("Su_Rat " + std::to_string(su_rat));
    SimpleShear test(su_rat);
    const PM4Silt& m = test.material();
    const double Su = m.parameters().Su;
    EXPECT_CLOSE(Su, su_rat * kSigmaV, 1e-9, 1e-12);  // S_u = Su_Rat sigma'yy at FirstCall
    const auto path = test.undrained(0.2, 4000);      // every 2 %
    const Sample& end = path.back();
    const double lambda = m.parameters().lambda, e_init = m.parameters().e_init;
    const double shift = std::exp((e_init - end.e) / lambda);
    EXPECT_GT(shift, 1.0);  // the consolidation strain made the silt denser than eInit
    EXPECT_LT(shift, 1.03);
    EXPECT_CLOSE(end.tau, Su * shift, 0.0, 0.015);                      // critical-state strength
    EXPECT_CLOSE(end.tau, su_rat * kSigmaV, 0.0, 0.025);                // the calibration target Su_Rat sigma'vc
    EXPECT_CLOSE(end.p, m.critical_mean_stress() * shift, 0.0, 0.015);  // p_cs at the current void ratio
    EXPECT_CLOSE(end.ratio, m.critical_stress_ratio(), 0.0, 0.01);      // q / p = M
    EXPECT_CLOSE(end.xi, 0.0, 1e-3, 0.0);
    // Steady at large strain: the last 10 % change tau by less than 0.2 %.
    EXPECT_CLOSE(path[path.size() - 6].tau, end.tau, 0.0, 2e-3);
  }
}

// Wet of critical (Su_Rat 0.25: p0 = 71.4 kPa > p_cs = 47.2 kPa, xi0 = +0.024) the undrained p falls (positive
// excess pore pressure); dry of critical (Su_Rat 1.0: p_cs = 189 kPa, xi0 = -0.059) it rises.
TEST(PM4SiltUndrainedSimpleShear, WetOfCriticalContractsDryDilates) {
  SimpleShear wet(0.25);
  const auto w = wet.undrained(0.1, 2000);
  EXPECT_GT(w.front().xi, 0.01);
  EXPECT_LT(w.back().p, 0.75 * w.front().p);  // measured 48.1 of 71.4 kPa
  SimpleShear dry(1.0);
  const auto d = dry.undrained(0.1, 2000);
  EXPECT_LT(d.front().xi, -0.03);
  EXPECT_GT(d.back().p, 2.0 * d.front().p);  // measured 190.6 of 71.4 kPa
}

// Drained DSS at constant sigma'v: the normally consolidated silt (Su_Rat 0.25, xi0 = +0.024 at the shearing
// stage's void ratio) contracts throughout; after the first 5 %, where the rotation of the principal stresses
// from the K0 state (q / p 0.80) lowers the stress ratio and raises p (xi to +0.027), its state parameter falls
// towards 0 and its stress ratio rises towards M from below (measured at 40 %: eps_v 2.14 %, xi 0.0031,
// q / p 0.959 M).
TEST(PM4SiltDrainedSimpleShear, NormallyConsolidatedSiltContractsTowardsCriticalState) {
  SimpleShear test(0.25);
  const auto path = test.drained(0.4, 5000);  // every 5 %
  const double M = test.material().critical_stress_ratio();
  EXPECT_GT(path.front().xi, 0.02);
  for (std::size_t i = 1; i < path.size(); ++i) {
    SCOPED_TRACE("gamma " + std::to_string(path[i].gamma));
    EXPECT_GT(path[i].eps_v, path[i - 1].eps_v);  // contraction
    EXPECT_LT(path[i].ratio, M);                  // no peak above M
    if (i >= 2) {
      EXPECT_LT(path[i].xi, path[i - 1].xi);        // towards critical
      EXPECT_GT(path[i].ratio, path[i - 1].ratio);  // hardening
    }
  }
  EXPECT_GT(path.back().eps_v, 0.015);
  EXPECT_LT(path.back().xi, 0.006);
  EXPECT_GT(path.back().ratio, 0.93 * M);
}

// Drained DSS of the dry silt (Su_Rat 1.0, xi0 = -0.059): it dilates, its stress ratio peaks well above M and
// softens to M as xi reaches 0 (measured: peak q / p 1.32 = 1.25 M near 10 %; at 40 %: eps_v -2.06 %, q / p
// 1.0593, xi 0.0000).
TEST(PM4SiltDrainedSimpleShear, OverconsolidatedSiltDilatesPeaksAndSoftensToCriticalState) {
  SimpleShear test(1.0);
  const auto path = test.drained(0.4, 2500);  // every 2.5 %
  const double M = test.material().critical_stress_ratio();
  EXPECT_LT(path.front().xi, -0.03);
  double peak = 0.0;
  for (const Sample& s : path) peak = std::max(peak, s.ratio);
  EXPECT_GT(peak, 1.15 * M);
  EXPECT_LT(path.back().eps_v, -0.015);  // dilation
  EXPECT_LT(path[4].eps_v, 0.0);         // already at 10 %
  EXPECT_CLOSE(path.back().ratio, M, 0.0, 0.01);
  EXPECT_CLOSE(path.back().xi, 0.0, 1e-3, 0.0);
}

}  // namespace
