#include "fem_tcl/materials/pm4_integration.hpp"

#include <algorithm>
#include <cmath>

// Moved from pm4sand.cpp when PM4Silt came (the code PM4Sand.cpp and PM4Silt.cpp of OpenSees commit 2890cb36
// share); the operations and their order are unchanged, so that PM4Sand's results stay bit-identical. OpenSees'
// function names are given where the algorithm is OpenSees' own; the quirks kept are listed in pm4sand.cpp
// (6 to 8) and pm4silt.cpp.

namespace fem::materials::pm4 {

namespace {

constexpr double kMaxStrainIncrement = 1e-5;  // OpenSees' maxStrainInc (schemes 4 and 5)
constexpr double kOneThird = 1.0 / 3.0;
constexpr double kTwoThirds = 2.0 / 3.0;

/// A point of the explicit integration: the start of a (sub-)increment.
struct Point {
  Vector3 stress, strain, elastic_strain, alpha, fabric;
};

/// Where one scheme call writes G, K, the plastic multiplier and the void ratio: OpenSees' members for a single
/// step, locals for the sub-increments of the max-strain schemes.
struct Outputs {
  double& G;
  double& K;
  double& dgamma;
  double& void_ratio;
};

/// One rate evaluation (a Delta of the Euler schemes).
struct Increment {
  Vector3 dsigma = Vector3::Zero(), dalpha = Vector3::Zero(), dfabric = Vector3::Zero(), dplastic = Vector3::Zero();
  bool neutral = false;
};

/// One trial's integration: OpenSees' integrator member functions over the model's trial state.
class Integrator {
 public:
  Integrator(Model& model, const Settings& settings, State& trial, const History& committed)
      : model_(model), s_(settings), t_(trial.history), c_(trial.carried), n_(committed) {}

  void integrate(int stage);

 private:
  void record_reversal(const Vector3& n_trial);
  void elastic_update();
  void plastic_update();
  void run_scheme(const Point& start);
  void forward_euler(const Point& cur, const Vector3& next_strain, const Outputs& out);
  void modified_euler(const Point& cur, const Vector3& next_strain, const Outputs& out);
  void runge_kutta4(const Point& cur, const Vector3& next_strain, const Outputs& out);
  void correct_stress(const Vector3& fabric_at_start, double void_ratio);
  Increment rate(const Vector3& stress, const Vector3& alpha, const Vector3& fabric, double void_ratio,
                 const Vector3& ddev, double dvol, double G, double K, double& dgamma);
  double void_ratio_at(const Vector3& strain) const { return pm4::void_ratio_at(s_.e_init, strain); }

  Model& model_;
  const Settings& s_;
  History& t_;
  Carried& c_;
  const History& n_;
};

// OpenSees integrate(): a loading reversal (the back-stress ratio behind the trial loading direction) first
// updates the reversal memory, then the elastic (stage 0) or elasto-plastic (stage 1) update runs.
void Integrator::integrate(int stage) {
  const Vector3 n_trial = yield_normal(n_.stress + c_.ce * (t_.strain - n_.strain), t_.alpha);
  if (stage != 0 && contract(t_.alpha - t_.alpha_in_true, n_trial) < 0.0) record_reversal(n_trial);
  if (stage == 0) elastic_update();
  else plastic_update();
}

// Manual section 2, "Loading reversals" (both manuals): alpha_in_true = alpha; the apparent alpha_in moves to the
// previous extreme of the same sign (for a reversal of the same shear sense) or to alpha; p_zp and z_xp track the
// reversal with the largest |z| p (for C_pzp).
void Integrator::record_reversal(const Vector3& n_trial) {
  t_.alpha_in_p = t_.alpha_in;
  t_.alpha_in_true = t_.alpha;
  t_.fabric_in = t_.fabric;
  double p = mean_stress(n_.stress);
  if (p <= s_.p_min) p = s_.p_min;
  const double z_xp = norm(n_.fabric) * p;
  if ((z_xp > c_.z_xp && p > c_.p_zp) || c_.p_zp_unset) {
    c_.z_xp = z_xp;
    c_.p_zp = p;
    c_.p_zp_unset = false;
  }
  for (int i = 0; i < 3; ++i) {
    if (t_.alpha_in[i] > 0.0) t_.alpha_in_min[i] = std::min(t_.alpha_in_min[i], t_.alpha[i]);
    else t_.alpha_in_max[i] = std::max(t_.alpha_in_max[i], t_.alpha[i]);
  }
  if (t_.alpha[2] * t_.alpha_in_p[2] > 0.0) {
    for (int i = 0; i < 3; ++i) {
      t_.alpha_in[i] = n_trial[i] > 0.0 ? std::max(0.0, t_.alpha_in_min[i]) : std::min(0.0, t_.alpha_in_max[i]);
    }
  } else {
    t_.alpha_in = t_.alpha;
  }
}

// Stage 0 (OpenSees elastic_integrator): linear elastic from the committed stress; the back-stress ratio follows
// the stress ratio where p > p_min.
void Integrator::elastic_update() {
  const Vector3 dstrain = t_.strain - n_.strain;
  t_.void_ratio = void_ratio_at(t_.strain);
  t_.elastic_strain = n_.elastic_strain + dstrain;
  model_.elastic_stage_moduli(n_.stress, c_.K, c_.G);
  c_.ce = c_.cep = elastic_stiffness(c_.K, c_.G);
  t_.stress = n_.stress + c_.ce * dstrain;
  const double p = mean_stress(t_.stress);
  if (p > s_.p_min) t_.alpha = deviator(t_.stress) / p;
}

// Stage 1 (OpenSees explicit_integrator): an elastic predictor with the current moduli; inside the yield surface
// the step is elastic, otherwise the elastic part (Pegasus intersection, also after elastic unloading from the
// surface) is taken first and the rest integrated by the scheme.
void Integrator::plastic_update() {
  const double m = s_.m, tol = s_.tol_f;
  if (s_.variant.void_ratio_before_elastic_check) t_.void_ratio = void_ratio_at(t_.strain);
  const Vector3 dstrain = t_.strain - n_.strain;
  t_.elastic_strain = n_.elastic_strain + dstrain;
  const double dvol = trace(dstrain);
  const Vector3 ddev = dstrain - dvol / 3.0 * identity();
  c_.ce = elastic_stiffness(c_.K, c_.G);
  const Vector3 dsigma = 2.0 * c_.G * tensor_shear(ddev) + c_.K * dvol * identity();
  t_.stress = n_.stress + dsigma;
  const double f = yield_function(t_.stress, n_.alpha, m);
  const double f_start = yield_function(n_.stress, n_.alpha, m);
  Point start{n_.stress, n_.strain, n_.elastic_strain, n_.alpha, n_.fabric};
  const auto past_elastic_part = [&](double a) {
    const Vector3 de = a * dstrain;
    start.stress += c_.ce * de;
    start.strain += de;
    start.elastic_strain += de;
  };
  if (f <= tol) {  // elastic
    t_.alpha = n_.alpha;
    t_.fabric = n_.fabric;
    c_.dgamma = 0.0;
    c_.cep = c_.ce;
    return;
  }
  if (f_start < -tol) {  // from inside the surface to outside
    past_elastic_part(elastic_fraction(n_.stress, c_.ce * dstrain, n_.alpha, m, tol));
  } else if (std::abs(f_start) < tol) {  // from the surface: loading, or elastic unloading then loading
    const double length = norm(dsigma);
    const double loading = contract(yield_normal(n_.stress, n_.alpha), dsigma) / (length == 0.0 ? 1.0 : length);
    if (!(loading > -std::sqrt(tol))) {
      past_elastic_part(elastic_fraction_after_unloading(n_.stress, c_.ce * dstrain, n_.alpha, m, tol));
    }
  }  // else: already outside (OpenSees' "illegal stress state"), integrated as plastic from the start
  run_scheme(start);
}

// IntScheme: 1 modified Euler, 2 forward Euler, 3 Runge-Kutta 4 on the whole (plastic part of the) increment;
// 4 and 5 forward / modified Euler on equal sub-increments of at most 1e-5 strain (OpenSees MaxStrainInc), whose
// moduli and multiplier stay local (OpenSees passes locals), the stress, alpha, fabric flowing from one to the next.
void Integrator::run_scheme(const Point& start) {
  const Outputs members{c_.G, c_.K, c_.dgamma, t_.void_ratio};
  const Vector3 next_strain = t_.strain;
  switch (s_.scheme) {
    case Scheme::ModifiedEuler: modified_euler(start, next_strain, members); return;
    case Scheme::ForwardEuler: forward_euler(start, next_strain, members); return;
    case Scheme::RungeKutta4: runge_kutta4(start, next_strain, members); return;
    case Scheme::ForwardEulerMaxStrain:
    case Scheme::ModifiedEulerMaxStrain: break;
  }
  const bool forward = s_.scheme == Scheme::ForwardEulerMaxStrain;
  const int steps = strain_substeps(next_strain - start.strain, kMaxStrainIncrement);
  if (steps == 1) {
    if (forward) forward_euler(start, next_strain, members);
    else modified_euler(start, next_strain, members);
    return;
  }
  const Vector3 sub = (next_strain - start.strain) / static_cast<double>(steps);
  double G = 0.0, K = 0.0, dgamma = 0.0, void_ratio = 0.0;
  const Outputs locals{G, K, dgamma, void_ratio};
  Point cur = start;
  for (int i = 1; i <= steps; ++i) {
    const Vector3 sub_end = cur.strain + sub;
    if (forward) forward_euler(cur, sub_end, locals);
    else modified_euler(cur, sub_end, locals);
    cur = Point{t_.stress, sub_end, t_.elastic_strain, t_.alpha, t_.fabric};
  }
}

// One rate evaluation of the modified-Euler scheme at (stress, alpha, fabric): the plastic multiplier
// L = (2G n : de - n : r K dev) / (Kp + 2G - K D n : r), the stress increment 2G de + K dev I - <L> (2G n + K D I),
// the back-stress ratio increment 2/3 L h (alpha_b - alpha), the fabric increment of the manuals' section 2
// ("Fabric", dz = -cz / (1 + <z_cum / (2 z_max) - 1>) <-D> <L> (z_max n + z) while dilating past the dilatancy
// surface) and the plastic strain L R. A negative L gives an elastic increment; a vanishing denominator a neutral
// one.
Increment Integrator::rate(const Vector3& stress, const Vector3& alpha, const Vector3& fabric, double void_ratio,
                           const Vector3& ddev, double dvol, double G, double K, double& dgamma) {
  Increment inc;
  const double p = mean_stress(stress);
  const Hardening hd = model_.state_dependent(stress, alpha, fabric, G, void_ratio);
  c_.Kp = hd.Kp;
  const Vector3 r = deviator(stress) / p;
  const double n_r = contract(hd.n, r);
  const double denominator = c_.Kp + 2.0 * G - K * hd.D * n_r;
  if (std::abs(denominator) < kSmall) {
    inc.neutral = true;
    return inc;
  }
  const double L = (2.0 * G * contract_mixed(hd.n, ddev) - n_r * K * dvol) / denominator;
  dgamma = L;
  const Vector3 elastic = 2.0 * G * tensor_shear(ddev) + K * dvol * identity();
  if (L < 0.0) {
    inc.dsigma = elastic;
    return inc;
  }
  inc.dsigma = elastic - macaulay(L) * (2.0 * G * hd.n + K * hd.D * identity());
  if (contract(hd.alpha_d - alpha, hd.n) < 0.0) {
    inc.dfabric = -s_.cz / (1.0 + macaulay(t_.z_cum / 2.0 / s_.z_max - 1.0)) * macaulay(L) * step(-hd.D) *
                  (s_.z_max * hd.n + fabric);
  }
  inc.dplastic = L * engineering_shear(hd.R);
  inc.dalpha = kTwoThirds * L * hd.h * hd.b;
  return inc;
}

// OpenSees ModifiedEuler: Euler / Heun pairs with the relative error of the stress increments
// |dsigma2 - dsigma1| / (2 |sigma|) held below 1e-5 by an adaptive sub-step dT in [1e-4, 1] (of the increment),
// the moduli frozen at the start, each accepted sub-step corrected back onto the yield surface.
void Integrator::modified_euler(const Point& cur, const Vector3& next_strain, const Outputs& out) {
  constexpr double kStepMin = 1e-4, kTolerance = 1e-5;
  t_.elastic_strain = cur.elastic_strain + next_strain - cur.strain;
  t_.stress = cur.stress;
  t_.alpha = cur.alpha;
  t_.fabric = cur.fabric;
  model_.elastic_moduli(t_.stress, out.K, out.G);
  if (mean_stress(cur.stress) < s_.p_min / 5.0) t_.stress = deviator(t_.stress) + s_.p_min / 5.0 * identity();
  const Vector3 total = next_strain - cur.strain;
  const auto give_up = [&] {  // p < 0 at the smallest step: the increment is dropped
    t_.elastic_strain = cur.elastic_strain + (next_strain - cur.strain);
    t_.stress = cur.stress;
    t_.alpha = cur.alpha;
    t_.fabric = cur.fabric;
  };
  double T = 0.0, dT = 1.0;
  while (T < 1.0) {
    out.void_ratio = void_ratio_at(total * T + cur.strain);
    const double e = out.void_ratio;
    const double dvol = dT * trace(total);
    const Vector3 dstrain = total * dT;
    const Vector3 ddev = dstrain - dvol / 3.0 * identity();

    Increment d1 = rate(t_.stress, t_.alpha, t_.fabric, e, ddev, dvol, out.G, out.K, out.dgamma);
    if (d1.neutral) d1.dplastic = dstrain;
    const Vector3 stress1 = t_.stress + d1.dsigma;
    if (mean_stress(stress1) < 0.0) {
      if (dT == kStepMin) return give_up();
      dT = std::max(0.1 * dT, kStepMin);
      continue;
    }
    double L2 = c_.dgamma;
    Increment d2 = rate(stress1, t_.alpha + d1.dalpha, t_.fabric + d1.dfabric, e, ddev, dvol, out.G, out.K, L2);
    if (d2.neutral) {
      d2.dplastic = d1.dplastic;
    } else {
      out.dgamma = L2;
      c_.dgamma = L2;
    }
    const Vector3 stress2 = (d1.dsigma + d2.dsigma) * 0.5 + t_.stress;
    const Vector3 fabric2 = (d1.dfabric + d2.dfabric) * 0.5 + t_.fabric;
    const Vector3 alpha2 = (d1.dalpha + d2.dalpha) * 0.5 + t_.alpha;
    if (mean_stress(stress2) < 0.0) {
      if (dT == kStepMin) return give_up();
      dT = std::max(0.1 * dT, kStepMin);
      continue;
    }
    const double stress_norm = norm(t_.stress);
    double error = norm(d2.dsigma - d1.dsigma);
    if (!(stress_norm < 0.5)) error /= 2.0 * stress_norm;
    if (error > kTolerance) {
      const double q = std::max(0.8 * std::sqrt(kTolerance / error), 0.1);
      if (dT == kStepMin) {  // accepted at the smallest step; the fabric is not advanced (PM4Sand quirk 8)
        t_.elastic_strain -= (d1.dplastic + d2.dplastic) * 0.5;
        t_.stress = stress2;
        t_.alpha = alpha2;
        correct_stress(cur.fabric, out.void_ratio);
        T += dT;
      }
      dT = std::max(q * dT, kStepMin);
    } else {
      t_.elastic_strain -= (d1.dplastic + d2.dplastic) * 0.5;
      t_.stress = stress2;
      t_.alpha = alpha2;
      t_.fabric = fabric2;
      correct_stress(cur.fabric, out.void_ratio);
      T += dT;
      const double q = std::max(0.8 * std::sqrt(kTolerance / error), 0.5);
      dT = std::max(q * dT, kStepMin);
      dT = std::min(dT, 1.0 - T);
    }
  }
}

// OpenSees ForwardEuler: one explicit step; n, D, h, the moduli evaluated at the stress the trial holds when the
// scheme starts (the elastic trial of the whole increment, or the end of the previous sub-increment; PM4Sand
// quirk 7), r = s / p with p of the start.
void Integrator::forward_euler(const Point& cur, const Vector3& next_strain, const Outputs& out) {
  const Vector3 probe = t_.stress;
  model_.elastic_moduli(probe, out.K, out.G);
  const double e_start = void_ratio_at(cur.strain);
  double p = mean_stress(cur.stress);
  if (p < s_.p_min) p = s_.p_min;
  out.void_ratio = void_ratio_at(next_strain);
  const Vector3 dstrain = next_strain - cur.strain;
  t_.elastic_strain = cur.elastic_strain + dstrain;
  const Hardening hd = model_.state_dependent(probe, cur.alpha, cur.fabric, c_.G, e_start);
  c_.Kp = hd.Kp;
  const double dvol = trace(dstrain);
  const Vector3 ddev = dstrain - dvol / 3.0 * identity();
  const Vector3 r = deviator(probe) / p;
  const double n_r = contract(hd.n, r);
  const double denominator = c_.Kp + 2.0 * out.G - out.K * hd.D * n_r;
  Increment inc;
  if (std::abs(denominator) < kSmall) {
    inc.dplastic = dstrain;
  } else {
    const double L = (2.0 * out.G * contract_mixed(hd.n, ddev) - n_r * out.K * dvol) / denominator;
    out.dgamma = L;
    c_.dgamma = L;
    const Vector3 elastic = 2.0 * out.G * tensor_shear(ddev) + out.K * dvol * identity();
    if (L < 0.0) {
      inc.dsigma = elastic;
    } else {
      inc.dsigma = elastic - macaulay(L) * (2.0 * out.G * hd.n + out.K * hd.D * identity());
      if (contract(hd.alpha_d - cur.alpha, hd.n) < 0.0) {
        inc.dfabric = -s_.cz / (1.0 + macaulay(t_.z_cum / 2.0 / s_.z_max - 1.0)) * macaulay(L) * step(-hd.D) *
                      (s_.z_max * hd.n + cur.fabric);
      }
      inc.dplastic = L * engineering_shear(hd.R);
      inc.dalpha = kTwoThirds * L * hd.h * hd.b;
    }
  }
  t_.fabric = cur.fabric + inc.dfabric;
  t_.elastic_strain -= inc.dplastic;
  t_.stress = cur.stress + inc.dsigma;
  t_.alpha = cur.alpha + inc.dalpha;
  correct_stress(cur.fabric, out.void_ratio);
}

// OpenSees RungeKutta4: two halves (dT = 0.5) of classical fourth-order Runge-Kutta with the members' moduli, no
// error control; as OpenSees, the stages' back-stress ratios start from the increment's start and the fabric rule
// tests alpha_d - alpha at the start. PM4Silt floors a negative denominator of the first stage (Variant).
void Integrator::runge_kutta4(const Point& cur, const Vector3& next_strain, const Outputs& out) {
  t_.elastic_strain = cur.elastic_strain + (next_strain - cur.strain);
  t_.stress = cur.stress;
  t_.alpha = cur.alpha;
  t_.fabric = cur.fabric;
  if (mean_stress(cur.stress) < s_.p_min / 5.0) t_.stress = deviator(t_.stress) + s_.p_min / 5.0 * identity();
  const Vector3 total = next_strain - cur.strain;
  constexpr double dT = 0.5;
  double T = 0.0;
  while (T < 1.0) {
    out.void_ratio = void_ratio_at(cur.strain + T * total);
    const double e = out.void_ratio;
    const double dvol = dT * trace(total);
    const Vector3 ddev = dT * total - dvol / 3.0 * identity();
    const auto stage_rate = [&](const Vector3& stress, const Vector3& alpha, const Vector3& fabric,
                                const Vector3& fabric_in_rule, bool first) {
      Increment inc;
      const double p = mean_stress(stress);
      Hardening hd = model_.state_dependent(stress, alpha, fabric, c_.G, e);
      const Vector3 r = deviator(stress) / p;
      const double n_r = contract(hd.n, r);
      double denominator = hd.Kp + 2.0 * c_.G - c_.K * hd.D * n_r;
      if (first && s_.variant.rk4_floors_negative_denominator && denominator < 0.0) {
        c_.Kp = -0.5 * (2.0 * c_.G - c_.K * hd.D * n_r);
        denominator = c_.Kp + 2.0 * c_.G - c_.K * hd.D * n_r;
        hd.h = 1.5 * c_.Kp / (p * contract(hd.b, hd.n));
      }
      if (std::abs(denominator) < kSmall) {
        inc.dplastic = ddev + dvol * identity();
        return inc;
      }
      const double L = (2.0 * c_.G * contract_mixed(hd.n, ddev) - n_r * c_.K * dvol) / denominator;
      out.dgamma = L;
      const Vector3 elastic = 2.0 * c_.G * tensor_shear(ddev) + c_.K * dvol * identity();
      if (L < 0.0) {
        inc.dsigma = elastic;
        return inc;
      }
      inc.dsigma = elastic - macaulay(L) * (2.0 * c_.G * hd.n + c_.K * hd.D * identity());
      if (contract(hd.alpha_d - cur.alpha, hd.n) < 0.0) {
        inc.dfabric = -s_.cz / (1.0 + macaulay(t_.z_cum / 2.0 / s_.z_max - 1.0)) * macaulay(L) * step(-hd.D) *
                      (s_.z_max * hd.n + fabric_in_rule);
      }
      inc.dplastic = L * engineering_shear(hd.R);
      inc.dalpha = kTwoThirds * L * hd.h * hd.b;
      return inc;
    };
    const Increment k1 = stage_rate(t_.stress, t_.alpha, t_.fabric, cur.fabric, true);
    const Increment k2 = stage_rate(t_.stress + 0.5 * k1.dsigma, cur.alpha + 0.5 * k1.dalpha,
                                    t_.fabric + 0.5 * k1.dfabric, cur.fabric + 0.5 * k1.dfabric, false);
    const Increment k3 = stage_rate(t_.stress + 0.5 * k2.dsigma, cur.alpha + 0.5 * k2.dalpha,
                                    t_.fabric + 0.5 * k2.dfabric, cur.fabric + 0.5 * k2.dfabric, false);
    const Increment k4 = stage_rate(t_.stress + k3.dsigma, cur.alpha + k3.dalpha, t_.fabric + k3.dfabric,
                                    cur.fabric + k3.dfabric, false);
    t_.elastic_strain -= (k1.dplastic + k4.dplastic + 2.0 * (k2.dplastic + k3.dplastic)) / 6.0;
    t_.stress += (k1.dsigma + k4.dsigma + 2.0 * (k2.dsigma + k3.dsigma)) / 6.0;
    t_.alpha += (k1.dalpha + k4.dalpha + 2.0 * (k2.dalpha + k3.dalpha)) / 6.0;
    t_.fabric += (k1.dfabric + k4.dfabric + 2.0 * (k2.dfabric + k3.dfabric)) / 6.0;
    correct_stress(cur.fabric, out.void_ratio);
    T += dT;
  }
}

// OpenSees Stress_Correction: a state outside the yield surface is brought back by at most 25 iterations along
// the plastic corrector (-lambda Ce : L R for the stress, +lambda 2/3 h b for alpha, lambda from the linearised
// f), or along df/dsigma where that does not reduce |f|; a p below p_min / 5 is lifted to it (inside the surface)
// or replaced by a small simple-shear state on it. Not converged, the state stays uncorrected (OpenSees' fallback
// bisects between two aliases of the same vector, in PM4Sand.cpp and PM4Silt.cpp alike).
void Integrator::correct_stress(const Vector3& fabric_at_start, double void_ratio) {
  const double m = s_.m, tol = s_.tol_f;
  double p = mean_stress(t_.stress);
  if (p < s_.p_min / 5.0) {
    if (yield_function(t_.stress, t_.alpha, m) < tol) {
      t_.stress += (s_.p_min / 5.0 - p) * identity();
    } else {
      t_.stress = s_.p_min / 5.0 * identity();
      t_.stress[2] = 0.8 * s_.Mc * s_.p_min / 5.0;
      t_.alpha = Vector3(0.0, 0.0, 0.8 * s_.Mc);
    }
    return;
  }
  double f = yield_function(t_.stress, t_.alpha, m);
  if (f < tol) return;
  Vector3 stress = t_.stress, alpha = t_.alpha;
  for (int i = 1; i <= 25; ++i) {
    const Vector3 r = deviator(stress) / p;
    const Hardening hd = model_.state_dependent(stress, alpha, fabric_at_start, c_.G, void_ratio);
    const Vector3 dsigma_p = elastic_stiffness(c_.K, c_.G) * (c_.dgamma * engineering_shear(hd.R));
    const Vector3 a_bar = kTwoThirds * hd.h * hd.b;
    const Vector3 df_dsigma = hd.n - 0.5 * contract(hd.n, r) * identity();
    const Vector3 df_dalpha = -p * hd.n;
    double lambda = f / (contract(df_dsigma, dsigma_p) - contract(df_dalpha, a_bar));
    if (std::abs(yield_function(stress - lambda * dsigma_p, alpha + lambda * a_bar, m)) < std::abs(f)) {
      stress -= lambda * dsigma_p;
      alpha += lambda * a_bar;
    } else {
      lambda = f / contract(df_dsigma, df_dsigma);
      stress -= lambda * df_dsigma;
    }
    f = yield_function(stress, alpha, m);
    if (std::abs(f) < tol) {
      t_.stress = stress;
      t_.alpha = alpha;
      return;
    }
    p = std::max(mean_stress(stress), s_.p_min);
  }
}

}  // namespace

void integrate(Model& model, const Settings& settings, int stage, State& trial, const History& committed) {
  Integrator(model, settings, trial, committed).integrate(stage);
}

void commit_history(const Settings& settings, State& trial, const History& committed) {
  History& t = trial.history;
  Carried& c = trial.carried;
  const Vector3 dz = t.fabric - committed.fabric;
  t.z_cum += std::sqrt(contract(dz, dz) / 2.0);
  t.z_peak = std::max(std::sqrt(contract(t.fabric, t.fabric) / 2.0), t.z_peak);
  t.void_ratio = void_ratio_at(settings.e_init, t.strain);
  c.ce = elastic_stiffness(c.K, c.G);
  c.cep = c.ce;
}

}  // namespace fem::materials::pm4
