// Verification: PM4Sand (fem_tcl/materials/pm4sand.hpp) in drained monotonic direct simple shear, against the
// behaviour its critical-state framework prescribes (Boulanger & Ziotopoulou 2017, PM4Sand v3.1 manual, Report
// UCD/CGM-17/01: section 2, "Critical state and relative state parameter index" / "Bounding, dilatancy and
// critical state surfaces"; section 3, the drained monotonic simple-shear responses):
//  - the relative state parameter xi_R = R / (Q - ln(100 p / P_atm)) - Dr tells dense (xi_R < 0) from loose
//    (xi_R > 0) of critical; a dense sand dilates, reaches a peak stress ratio M_b = M exp(-nb xi_R) > M and
//    softens; a loose one contracts and hardens towards M from below;
//  - at large strain both reach critical state: xi_R -> 0, so M_b, M_d -> M and the stress ratio
//    q / p -> M = 2 sin(phi_cv), with the model's 2D measures p = (sxx + syy) / 2 and
//    q = 2 sqrt(((sxx - syy) / 2)^2 + sxy^2) (q / p = 2 sin(phi) of the Mohr circle).
// The point is consolidated one-dimensionally (K0 = nu / (1 - nu), stage 0), switched to stage 1 with FirstCall,
// then sheared at constant vertical stress with exx = 0 (simple shear): the free strain eyy is found at each
// step by Newton iterations on syy = -sigma_v with tangent() (the elastic matrix), then secant updates.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "fem_tcl/materials/pm4sand.hpp"
#include "support/tolerance.hpp"

namespace {

using fem::materials::PM4Sand;
using fem::materials::PM4SandParameters;
using fem::materials::Vector3;

constexpr double kPatm = 101.3;

struct Sample {
  double gamma;       ///< engineering shear strain
  double eps_v;       ///< volumetric strain, compression positive (= -eyy, exx = 0)
  double ratio;       ///< q / p
  double xi;          ///< relative state parameter at the current void ratio and p
};

/// Drained simple shear at constant vertical stress `sigma_v` (kPa, compression) to `gamma_end` in steps of 1e-5,
/// recording every `every` steps.
class DrainedSimpleShear {
 public:
  DrainedSimpleShear(double Dr, double sigma_v) : sigma_v_(sigma_v), material_(1, parameters(Dr)) {
    const PM4SandParameters& p = material_.parameters();
    const double G = p.G0 * kPatm;  // stage 0: G = G0 P_atm, K from nu (OpenSees GetElasticModuli, me2p = 0)
    const double K = 2.0 / 3.0 * (1.0 + p.nu) / (1.0 - 2.0 * p.nu) * G;
    eyy_ = -sigma_v / (K + 4.0 / 3.0 * G);
    material_.set_trial_strain(Vector3(0.0, eyy_, 0.0));
    material_.commit_state();
    eyy0_ = eyy_;
    material_.update_stage(1);
    material_.set_parameter("FirstCall", 0.0);
  }

  std::vector<Sample> run(double gamma_end, int every) {
    std::vector<Sample> out{sample(0.0)};
    const int steps = static_cast<int>(std::round(gamma_end / 1e-5));
    for (int i = 1; i <= steps; ++i) {
      const double gamma = i * 1e-5;
      solve(gamma);
      material_.commit_state();
      if (i % every == 0) out.push_back(sample(gamma));
    }
    return out;
  }
  const PM4Sand& material() const { return material_; }

 private:
  static PM4SandParameters parameters(double Dr) {
    PM4SandParameters p;
    p.Dr = Dr;
    p.G0 = 167.0 * std::sqrt(46.0 * Dr * Dr + 2.5);  // the manual's G0 from (N1)60 = 46 Dr^2 (section 4)
    p.hpo = 0.5;
    p.density = 1.7;
    p.nu = 1.0 / 3.0;  // K0 = 0.5 in the consolidation
    return p;
  }
  /// syy(eyy) = -sigma_v: Newton with tangent()(1, 1) first, then secant slopes (the elastic tangent converges
  /// slowly where the sand is soft), safeguarded by bisection inside the bracket of residuals of both signs. The
  /// response is smooth only to ~1e-4 kPa (sub-steps, stress correction, the moduli carried from trial to trial
  /// as in OpenSees), so the residual is asked to 1e-5 sigma_v, or the bracket to shrink below 1e-12.
  void solve(double gamma) {
    double previous_e = 0.0, previous_r = 0.0;
    double low = 0.0, high = 0.0;  // eyy with r < 0 (too compressive) and r > 0, once seen
    bool have_low = false, have_high = false;
    for (int it = 0; it < 60; ++it) {
      material_.set_trial_strain(Vector3(0.0, eyy_, gamma));
      const double r = material_.stress()[1] + sigma_v_;
      if (std::abs(r) < 1e-5 * sigma_v_ || (have_low && have_high && high - low < 1e-12)) {
        return;
      }
      // syy grows with eyy (d syy / d eyy > 0, tension positive): r > 0 means eyy is too large.
      if (r > 0.0) { high = eyy_; have_high = true; }
      else { low = eyy_; have_low = true; }
      const double slope = it == 0 ? material_.tangent()(1, 1) : (r - previous_r) / (eyy_ - previous_e);
      previous_e = eyy_;
      previous_r = r;
      double next = eyy_ - r / slope;
      if (!(slope > 0.0) || !std::isfinite(next) || (have_low && next <= low) || (have_high && next >= high)) {
        if (have_low && have_high) next = 0.5 * (low + high);
        else next = eyy_ - r / material_.tangent()(1, 1);
      }
      eyy_ = next;
    }
    ADD_FAILURE() << "no convergence at gamma " << gamma;
  }
  Sample sample(double gamma) const {
    const Vector3 s = material_.stress();
    const double p = -0.5 * (s[0] + s[1]);
    const double q = 2.0 * std::sqrt(0.25 * (s[0] - s[1]) * (s[0] - s[1]) + s[2] * s[2]);
    const PM4SandParameters& par = material_.parameters();
    const double e = (*material_.response("state"))[12];
    const double Dr = (par.emax - e) / (par.emax - par.emin);
    const double xi = par.R / (par.Q - std::log(100.0 * p / par.P_atm)) - Dr;
    return Sample{gamma, -(eyy_ - eyy0_), q / p, xi};
  }

  double sigma_v_;
  PM4Sand material_;
  double eyy_ = 0.0, eyy0_ = 0.0;
};

double peak_ratio(const std::vector<Sample>& path) {
  double peak = 0.0;
  for (const auto& s : path) peak = std::max(peak, s.ratio);
  return peak;
}

// Dense (Dr 0.75 at sigma_v 100 kPa: xi_R = -0.47): dilation from the start, a peak stress ratio well above M,
// softening towards M as xi_R rises towards 0.
TEST(PM4SandDrainedSimpleShear, DenseSandDilatesPeaksAndSoftensTowardsCriticalState) {
  DrainedSimpleShear test(0.75, 100.0);
  const auto path = test.run(1.0, 5000);  // every 5 % shear strain
  const double M = test.material().critical_stress_ratio();
  EXPECT_CLOSE(M, 2.0 * std::sin(33.0 / 180.0 * 3.14159265359), 0.0, 1e-12);
  EXPECT_LT(path[0].xi, -0.4);
  for (std::size_t i = 1; i < path.size(); ++i) {
    EXPECT_LT(path[i].eps_v, path[i - 1].eps_v) << "dilating at gamma " << path[i].gamma;
    EXPECT_GT(path[i].xi, path[i - 1].xi) << "towards critical at gamma " << path[i].gamma;
    if (i >= 2) {
      EXPECT_LT(path[i].ratio, path[i - 1].ratio) << "softening at gamma " << path[i].gamma;
    }
  }
  EXPECT_GT(peak_ratio(path), 1.2 * M);          // measured 1.378 = 1.27 M
  EXPECT_LT(path.back().eps_v, -0.07);           // measured -7.95 % at 100 % shear strain
  EXPECT_CLOSE(path.back().ratio, M, 0.0, 0.04); // measured 1.120 = 1.028 M, xi_R -0.056
}

// Loose of critical (Dr 0.35 at sigma_v 800 kPa: xi_R = +0.065 at the input Dr, +0.041 after the elastic
// consolidation strain): contraction throughout, the stress ratio rising to M from below, xi_R falling to 0 (after
// the first 10 %, where p still grows with sxx).
TEST(PM4SandDrainedSimpleShear, LooseSandContractsAndHardensToCriticalState) {
  DrainedSimpleShear test(0.35, 800.0);
  const auto path = test.run(1.0, 5000);
  const double M = test.material().critical_stress_ratio();
  EXPECT_GT(path[0].xi, 0.03);
  for (std::size_t i = 1; i < path.size(); ++i) {
    EXPECT_GT(path[i].eps_v, path[i - 1].eps_v) << "contracting at gamma " << path[i].gamma;
    if (i >= 3) {
      EXPECT_LT(path[i].xi, path[i - 1].xi) << "towards critical at gamma " << path[i].gamma;
    }
    EXPECT_GE(path[i].ratio, path[i - 1].ratio - 1e-4) << "hardening at gamma " << path[i].gamma;
  }
  EXPECT_LT(peak_ratio(path), M * 1.001);          // no peak above M
  EXPECT_GT(path.back().eps_v, 0.01);              // measured 1.36 %
  EXPECT_CLOSE(path.back().ratio, M, 0.0, 0.005);  // measured 1.0892 vs M = 1.0893
  EXPECT_CLOSE(path.back().xi, 0.0, 0.005, 0.0);   // measured 0.0007
}

// The golden DSS run's sand (Dr 0.35 at sigma_v 100 kPa) is slightly dense of critical with the default Q and R
// (xi_R = -0.09): it contracts first (stress ratios below the rotated dilatancy surface), then dilates mildly,
// and also ends at M.
TEST(PM4SandDrainedSimpleShear, MediumLooseSandContractsFirstThenReachesCriticalState) {
  DrainedSimpleShear test(0.35, 100.0);
  const auto path = test.run(1.0, 1000);  // every 1 %
  const double M = test.material().critical_stress_ratio();
  EXPECT_LT(path[0].xi, 0.0);
  EXPECT_GT(path[1].eps_v, 0.0);  // contraction at 1 % (measured +0.04 % near 2 %)
  EXPECT_LT(path.back().eps_v, 0.0);
  EXPECT_CLOSE(path.back().ratio, M, 0.0, 0.01);  // measured 1.095
  EXPECT_GT(path.back().xi, -0.02);               // measured -0.010
}

}  // namespace
