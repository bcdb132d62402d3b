#include "fem_tcl/materials/pressure_depend_multi_yield02.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <iterator>

#include "common/input_error.hpp"

namespace fem::materials {

namespace {

using multi_yield::contract;
using multi_yield::deviator;
using multi_yield::kDegree;
using multi_yield::kLowLimit;
using multi_yield::mean;
using multi_yield::StressPoint;
using multi_yield::strain_tensor;
using multi_yield::with_mean;

StressPoint split(const Vector6& t) { return StressPoint{deviator(t), mean(t)}; }

/// The octahedral shear strain 2 sqrt(1/3) |e_dev| of a strain tensor (OpenSees octahedralShear(1)).
double octahedral_strain(const Vector6& e) {
  const Vector6 d = deviator(e);
  return 2.0 * std::sqrt(1.0 / 3.0) * std::sqrt(contract(d, d));
}

/// 6 sin(phi) / (3 - sin(phi)): the stress ratio of triaxial compression at the friction angle phi (degrees).
double compression_ratio(double phi_deg) {
  const double s = std::sin(phi_deg * kDegree);
  return 6.0 * s / (3.0 - s);
}

}  // namespace

PressureDependMultiYield02::PressureDependMultiYield02(int tag, const PressureDependMultiYield02Parameters& params)
    : NDMaterial(tag), params_(params) {
  const std::string where = "nDMaterial PressureDependMultiYield02 " + std::to_string(tag);
  const auto check = [&](bool ok, const std::string& what) {
    if (!ok) throw common::InputError(where, what);
  };
  const auto warn = [&](const std::string& what) { std::cerr << "WARNING " << where << ": " << what << "\n"; };
  auto& p = params_;
  check(p.shear_modulus > 0.0, "expected refShearModul > 0, got " + std::to_string(p.shear_modulus));
  check(p.bulk_modulus > 0.0, "expected refBulkModul > 0, got " + std::to_string(p.bulk_modulus));
  check(p.friction_deg > 0.0 && p.friction_deg < 90.0,
        "expected 0 < frictionAng < 90, got " + std::to_string(p.friction_deg));
  check(p.pt_deg > 0.0, "expected PTAng > 0, got " + std::to_string(p.pt_deg));
  check(p.peak_shear_strain > 0.0, "expected peakShearStra > 0, got " + std::to_string(p.peak_shear_strain));
  check(p.ref_pressure > 0.0, "expected refPress > 0, got " + std::to_string(p.ref_pressure));
  check(p.density >= 0.0, "expected rho >= 0, got " + std::to_string(p.density));
  check(p.void_ratio >= 0.0, "expected e >= 0, got " + std::to_string(p.void_ratio));
  check(p.atmospheric > 0.0, "expected pa > 0, got " + std::to_string(p.atmospheric));
  // OpenSees' quiet corrections (PressureDependMultiYield02's constructor), with its warnings.
  if (p.cohesion < 0.0) { warn("c < 0, set to 0.3"); p.cohesion = 0.3; }
  if (p.pressure_exponent < 0.0) { warn("pressDependCoe < 0, set to 0.5"); p.pressure_exponent = 0.5; }
  if (p.cs1 < 0.0) { warn("cs1 < 0, set to 0.8"); p.cs1 = 0.8; }
  if (p.backbone.empty()) {
    if (p.surfaces <= 0) { warn("noYieldSurf <= 0, 10 surfaces used"); p.surfaces = 10; }
    if (p.surfaces > 100) { warn("noYieldSurf > 100, 100 surfaces used"); p.surfaces = 100; }
  } else {
    check(p.surfaces >= 2 && p.backbone.size() == 2 * static_cast<std::size_t>(p.surfaces),
          "expected 2 x |noYieldSurf| backbone values (shear strain, G / Gmax) for at least 2 surfaces");
  }
  set_up_surfaces();
  init_press_ = -p.ref_pressure;
  trial_ = committed_;
  form_tangent();
}

// OpenSees setUpSurfaces: the stress-ratio sizes M_m and plastic moduli H_m at refPress (multi_yield_surfaces.hpp)
// with the cone of the friction angle (or of the user points' strength), the residual pressure p_r, eta_PT and
// the backbone's octahedral shear strain at eta_PT.
void PressureDependMultiYield02::set_up_surfaces() {
  auto& p = params_;
  const std::string where = "nDMaterial PressureDependMultiYield02 " + std::to_string(tag());
  const double G = p.shear_modulus, pref = -p.ref_pressure;  // compression negative, as OpenSees stores it
  const int n = p.surfaces;
  const double floor = 0.0001 * p.atmospheric;  // a small residual pressure, for numerical purposes only
  std::vector<multi_yield::YieldSurface> s;
  if (p.backbone.empty()) {
    const double m_nys = compression_ratio(p.friction_deg);
    stress_ratio_pt_ = compression_ratio(p.pt_deg);
    residual_pressure_ = std::max(2.0 * p.cohesion / m_nys, floor);
    const double cone = -(pref - residual_pressure_);
    const double peak = std::sqrt(2.0) * cone * m_nys / 3.0;
    const multi_yield::HyperbolicBackbone backbone(G, peak, p.peak_shear_strain, where);
    s = multi_yield::hyperbolic_surfaces(backbone, peak, n, cone);
    const double step = peak / n;
    for (int m = 1; m <= n; ++m) {
      const double t1 = m * step, t2 = t1 + step;
      const double r1 = 3.0 * t1 / std::sqrt(2.0) / cone, r2 = 3.0 * t2 / std::sqrt(2.0) / cone;
      if (r1 <= stress_ratio_pt_ && r2 >= stress_ratio_pt_) {
        const double g1 = backbone.strain(t1), g2 = backbone.strain(t2);
        strain_pt_octa_ = g2 - (r2 - stress_ratio_pt_) / (r2 - r1) * (g2 - g1);
      }
    }
  } else {
    const auto& g = p.backbone;
    multi_yield::validate_user_points(g, where);
    const double tmax = G * g[2 * (n - 1)] * g[2 * (n - 1) + 1];
    const double m_nys = -(std::sqrt(3.0) * tmax - 2.0 * p.cohesion) / pref;
    residual_pressure_ = std::max(2.0 * p.cohesion / m_nys, floor);
    const double cone = -(pref - residual_pressure_);
    const double sin_phi = 3.0 * m_nys / (6.0 + m_nys);
    if (sin_phi < 0.0 || sin_phi > 1.0)
      throw common::InputError(where, "invalid friction angle from the backbone: change refPress or the G/Gmax curve");
    p.friction_deg = std::asin(sin_phi) / kDegree;
    std::cerr << "NOTE " << where << ": friction angle " << p.friction_deg << " from the backbone\n";
    if (p.pt_deg > p.friction_deg) {
      std::cerr << "WARNING " << where << ": PTAng > the friction angle, set to it\n";
      p.pt_deg = p.friction_deg;
    }
    stress_ratio_pt_ = compression_ratio(p.pt_deg);
    s = multi_yield::user_surfaces(G, g, cone, where);
    for (int m = 1; m < n; ++m) {
      const double g1 = g[2 * (m - 1)], g2 = g[2 * m];
      const double r1 = std::sqrt(3.0) * G * g[2 * (m - 1) + 1] * g1 / cone, r2 = std::sqrt(3.0) * G * g[2 * m + 1] * g2 / cone;
      if (r1 <= stress_ratio_pt_ && r2 >= stress_ratio_pt_)  // octahedral from simple shear: sqrt(6) / 3 gamma
        strain_pt_octa_ = std::sqrt(6.0) / 3.0 * (g2 - (r2 - stress_ratio_pt_) / (r2 - r1) * (g2 - g1));
    }
  }
  reference_surfaces_ = multi_yield::MultiYieldSurfaces(std::move(s), multi_yield::Translation::Lenient);
  committed_.surfaces = reference_surfaces_;
}

std::unique_ptr<NDMaterial> PressureDependMultiYield02::copy_for(PlaneType plane) const {
  if (plane != PlaneType::PlaneStrain)
    throw common::InputError("nDMaterial PressureDependMultiYield02 " + std::to_string(tag()),
                             "has no plane-stress form (plane strain only, as OpenSees)");
  auto copy = std::make_unique<PressureDependMultiYield02>(*this);
  copy->revert_to_start();
  return copy;
}

// --- moduli ------------------------------------------------------------------------------------------------

// G / G_r = ((p - p_r) / (p_ref - p_r))^d (p, p_ref as stored: compression negative), at least 1e-10 (OpenSees
// getModulusFactor).
double PressureDependMultiYield02::modulus_factor(double p) const {
  const double scale = std::pow((p - residual_pressure_) / (-params_.ref_pressure - residual_pressure_),
                                params_.pressure_exponent);
  return std::max(1e-10, scale);
}

// Stage 0: the reference moduli; stage 2: scaled to initPress (OpenSees getTangent, stages 0 and 2).
double PressureDependMultiYield02::elastic_factor() const {
  if (stage_ != 2) return 1.0;
  const double ratio = (init_press_ - residual_pressure_) / (-params_.ref_pressure - residual_pressure_);
  if (ratio <= 1e-10) return 1e-10;
  return std::max(1e-10, std::pow(ratio, params_.pressure_exponent));
}

Matrix3 PressureDependMultiYield02::initial_tangent() const {
  double factor = 1.0;
  if (stage_ == 1) {
    // OpenSees switches to plasticity here if it has not yet: a committed stress in tension loses its mean.
    const double p = mean(committed_.stress);
    factor = modulus_factor(!plastic_started_ && p > 0.0 ? 0.0 : p);
  } else if (stage_ == 2) {
    const double p = init_press_ == -params_.ref_pressure ? mean(committed_.stress) : init_press_;
    const double ratio = (p - residual_pressure_) / (-params_.ref_pressure - residual_pressure_);
    factor = ratio <= 1e-10 ? 1e-10 : std::max(1e-10, std::pow(ratio, params_.pressure_exponent));
  }
  return plane_strain_elastic_matrix(params_.bulk_modulus * factor, params_.shear_modulus * factor);
}

// --- the switch to plasticity (OpenSees elast2Plast, initSurfaceUpdate) ------------------------------------

// Surfaces 1..active centred on the committed stress (no tension: a positive mean is dropped), the stress
// brought onto the failure surface where it lies beyond it. The surfaces are stress ratios and stay so.
void PressureDependMultiYield02::start_plastic() {
  plastic_started_ = true;
  Vector6& s = committed_.stress;
  if (mean(s) > 0.0) s = deviator(s);
  const double h = cone().height(mean(s));
  Vector6 dev = deviator(s);
  if (committed_.surfaces.place(dev, h)) s = with_mean(dev, mean(s));
  committed_.surfaces.centre_on(deviator(s), h);
}

// --- the stress update ------------------------------------------------------------------------------------

void PressureDependMultiYield02::set_trial_strain(const Vector3& strain) {
  if (stage_ == 1 && !plastic_started_) {
    init_press_ = mean(committed_.stress);
    start_plastic();  // OpenSees does it to its committed state
  }
  if (stage_ == 2 && init_press_ == -params_.ref_pressure) init_press_ = mean(committed_.stress);
  trial_ = committed_;
  trial_.strain = strain;
  increment_ = strain_tensor(strain - committed_.strain);
  if (stage_ != 1) {
    const double f = elastic_factor();
    const double G = params_.shear_modulus * f, B = params_.bulk_modulus * f;
    trial_.stress = committed_.stress + 2.0 * G * deviator(increment_);
    trial_.stress.head<3>().array() += B * (increment_[0] + increment_[1] + increment_[2]);
    trial_stress_ = split(trial_.stress);
  } else {
    plastic_update();
  }
  stress_ << trial_.stress[0], trial_.stress[1], trial_.stress[3];
  form_tangent();
}

// OpenSees setTrialStress: the elastic trial of a sub-increment from `from`, with the moduli of `from`'s mean
// stress (and Hv's volumetric hardening under compression beyond the largest committed confinement); no tension.
StressPoint PressureDependMultiYield02::elastic_trial(const StressPoint& from, const Vector6& sub) {
  factor_ = modulus_factor(from.mean);
  StressPoint t;
  t.dev = from.dev + deviator(sub) * (2.0 * params_.shear_modulus * factor_);
  double B = params_.bulk_modulus * factor_;
  if (params_.hv != 0.0 && trial_stress_.mean <= max_press_ && mean(sub) < 0.0 && stage_ == 1) {
    const double hp = params_.hv * std::pow(std::abs(trial_stress_.mean - residual_pressure_), params_.pv);
    B = B * hp / (B + hp);
  }
  t.mean = std::min(from.mean + mean(sub) * 3.0 * B, 0.0);
  return t;
}

std::pair<Vector6, double> PressureDependMultiYield02::surface_normal(const StressPoint& stress) const {
  const auto& a = trial_.surfaces[trial_.surfaces.active()];
  const double h = cone().height(stress.mean);
  // d f / d sigma of f = 3/2 (s - h a) : (s - h a) - (h M)^2 with h = p_r - p: the deviator 3 (s - h a), the
  // mean (1/3) d f / d p = s : a - h a : a + 2/3 h M^2.
  const Vector6 n_dev = 3.0 * (stress.dev - a.center * h);
  const double n_vol = contract(stress.dev, a.center) - h * (contract(a.center, a.center) - 2.0 / 3.0 * a.size * a.size);
  double length = std::sqrt(contract(n_dev, n_dev) + 3.0 * n_vol * n_vol);
  if (length <= kLowLimit) length = kLowLimit;  // OpenSees unitT2Vector
  return {n_dev / length, n_vol / length};
}

// OpenSees isLoadReversal: the stress increment from the committed stress points inside the active surface at
// `at`.
bool PressureDependMultiYield02::load_reversal(const StressPoint& at, const StressPoint& trial) const {
  if (trial_.surfaces.active() == 0) return false;
  const auto [n_dev, n_vol] = surface_normal(at);
  const StressPoint current = split(committed_.stress);
  return contract(trial.dev - current.dev, n_dev) + 3.0 * (trial.mean - current.mean) * n_vol < 0.0;
}

void PressureDependMultiYield02::plastic_update() {
  auto& surfaces = trial_.surfaces;
  const multi_yield::Cone cone = this->cone();
  const StressPoint current = split(committed_.stress);
  const Vector6 committed_strain = strain_tensor(committed_.strain);
  sub_increment_ = increment_;
  trial_stress_ = elastic_trial(current, sub_increment_);
  if (surfaces.active() > 0 && load_reversal(current, trial_stress_)) {
    surfaces.recentre_inner(current.dev, cone.height(current.mean));
    surfaces.set_active(0);
  }
  if (surfaces.active() == 0 && !surfaces.crosses_next(trial_stress_.dev, cone.height(trial_stress_.mean))) {
    sub_strain_ = committed_strain + increment_;  // elastic
  } else {
    // Sub-increments (OpenSees setSubStrainRate): one surface spacing of stress each, at most n, but at least one
    // per 1e-5 of octahedral shear strain and of dilative mean strain.
    int substeps = 0;
    if (!increment_.isZero(0.0)) {
      substeps = surfaces.substeps(deviator(increment_), params_.shear_modulus, modulus_factor(current.mean),
                                   cone.height(current.mean));
      substeps = std::max(substeps, static_cast<int>(octahedral_strain(increment_) / 1.0e-5));
      substeps = std::max(substeps, static_cast<int>(mean(increment_) / 1.0e-5));
      sub_increment_ = increment_ / substeps;
    }
    const auto predict = [&](int i, StressPoint& trial) {
      sub_strain_ = committed_strain + sub_increment_ * (i + 1);
      const StressPoint from = i == 0 ? current : trial;
      updated_trial_ = from;
      trial = elastic_trial(from, sub_increment_);
      if (surfaces.active() > 0 && load_reversal(from, trial)) {
        surfaces.recentre_inner(current.dev, cone.height(current.mean));  // on the committed stress, as OpenSees
        surfaces.set_active(0);
      }
    };
    const auto after = [&](int, StressPoint& trial) {
      const double B = params_.bulk_modulus * factor_;
      trial_.pressure_d += 3.0 * mean(sub_increment_) - (trial.mean - updated_trial_.mean) / B;
      trial_.pressure_d = std::max(trial_.pressure_d, 0.0);
    };
    surfaces.integrate(
        substeps, trial_stress_, cone, predict, [&](StressPoint& trial, bool crossed) { flow(trial, crossed); },
        after);
  }
  trial_.stress = with_mean(trial_stress_.dev, trial_stress_.mean);
}

// OpenSees stressCorrection's return and getLoadingFunc: from the contact point on the active surface along
// Q = n_dev + P'' I (Elgamal et al. 2003, the flow rule), with the loading L = n : (s_trial - s_contact) /
// (2 G n_dev : n_dev + 9 B n_vol P'' + H), the denominator held at H/2 or above by reducing P''; crossing into
// the next surface scales L by (H_{m-1} - H_m) / H_{m-1}. A mean stress past zero is cut to zero with the
// deviatoric correction scaled to match.
void PressureDependMultiYield02::flow(StressPoint& trial, bool crossed) {
  const auto& surfaces = trial_.surfaces;
  const int k = surfaces.active();
  const int n = surfaces.count();
  const double f = factor_;
  const double two_g = 2.0 * params_.shear_modulus * f, nine_b = 9.0 * params_.bulk_modulus * f;
  const StressPoint contact{surfaces.contact_point(trial.dev, cone().height(trial.mean)), trial.mean};
  const auto [n_dev, n_vol] = surface_normal(contact);
  double potential = plastic_potential(contact, trial);
  const double H = surfaces[k].modulus;
  const double shear = two_g * contract(n_dev, n_dev);
  const double volumetric = nine_b * n_vol * potential;
  double denominator = shear + volumetric + H * f;
  const double limit = (k == n ? surfaces[k - 1].modulus : H) * f / 2.0;
  if (denominator < limit) {
    potential = (volumetric + limit - denominator) / (nine_b * n_vol);
    denominator = limit;
  }
  const Vector6 w = trial.dev - contact.dev;
  double loading = (contract(n_dev, w) + n_vol * (w[0] + w[1] + w[2])) / denominator;
  if (loading < 0.0) loading = 0.0;
  if (crossed) loading *= (surfaces[k - 1].modulus - H) / surfaces[k - 1].modulus;
  const double t_mean = trial.mean;
  double p = t_mean - potential * 3.0 * params_.bulk_modulus * f * loading;
  Vector6 dev = trial.dev;
  if (p > 0.0 && p != t_mean) {
    dev += n_dev * (t_mean / (t_mean - p) * (-two_g * loading));
    p = 0.0;
  } else if (p > 0.0) {
    p = 0.0;
  } else {
    dev += n_dev * (-two_g * loading);
  }
  trial = StressPoint{deviator(dev), p};
}

namespace {
/// sqrt(3/2 s:s) / (|p| + |p_r|) (OpenSees deviatorRatio).
double stress_ratio(const StressPoint& s, double residual) {
  return std::sqrt(1.5 * contract(s.dev, s.dev)) / (std::abs(s.mean) + std::abs(residual));
}
}  // namespace

// P'' (OpenSees getPlasticPotential; Elgamal et al. 2003 and Yang et al. 2003, the contraction and dilation
// phases): dilation when
// loading beyond the phase transformation (outside the PPZ), none on the PPZ, contraction otherwise; none where
// the void ratio crosses the critical-state line in this step.
double PressureDependMultiYield02::plastic_potential(const StressPoint& contact, const StressPoint& trial) {
  const auto& p = params_;
  const double pr = residual_pressure_;
  double factor_pt = stress_ratio(contact, pr) / stress_ratio_pt_;
  const double current_ratio = stress_ratio(updated_trial_, pr);
  const double trial_ratio = stress_ratio(trial, pr);
  const double shear_loading = contract(updated_trial_.dev, trial.dev);
  const double confinement = (std::abs(contact.mean) + std::abs(pr)) / p.atmospheric;
  double potential = 0.0;
  if (factor_pt >= 1.0 && trial_ratio >= current_ratio && shear_loading >= 0.0) {  // dilation
    update_ppz(contact);
    if (trial_.on_ppz == 2) {
      factor_pt -= 1.0;
      potential = std::pow(confinement, -p.dilation3) * factor_pt * factor_pt *
                  (p.dilation1 + std::pow(trial_.cumu_dilate, p.dilation2));
      potential = std::min(std::abs(potential), 5.0e4);
    }  // on the PPZ (1): none
  } else {  // contraction
    double angle = 1.0;
    if (current_ratio != 0.0) {
      const Vector6 w = trial.dev / (std::abs(trial.mean) + std::abs(pr)) -
                        updated_trial_.dev / (std::abs(updated_trial_.mean) + std::abs(pr));
      const Vector6 wd = deviator(w);
      const double length = std::sqrt(contract(wd, wd));
      if (length != 0.0)
        angle = contract(updated_trial_.dev, w) / length / std::sqrt(contract(updated_trial_.dev, updated_trial_.dev));
    }
    factor_pt = factor_pt * angle - 1.0;
    const double rule = std::max(std::pow(confinement, p.contraction3), 0.1);
    potential = -factor_pt * factor_pt * (p.contraction1 + trial_.max_cumu_dilate * p.contraction2) * rule;
    if (potential > 0.0) potential = -potential;
    if (trial_.on_ppz > 0) trial_.on_ppz = 0;
    if (trial_.on_ppz != -1) translate_ppz();
  }
  if (critical_state(contact)) potential = 0.0;
  return potential;
}

// OpenSees isCriticalState: the void ratio e = e0 + (1 + e0) eps_v of the committed and of the trial strain on
// either side of the critical-state line e_c(p) (at the sub-increment's start and at the contact stress).
bool PressureDependMultiYield02::critical_state(const StressPoint& contact) const {
  const auto& p = params_;
  const auto void_ratio = [&](double volumetric) { return p.void_ratio + volumetric + volumetric * p.void_ratio; };
  const double e_trial = void_ratio(3.0 * mean(sub_strain_));
  const double e_current = void_ratio(committed_.strain[0] + committed_.strain[1]);
  const auto critical = [&](double mean_stress) {
    const double x = std::abs(-mean_stress / p.atmospheric);
    return p.cs3 != 0.0 ? p.cs1 - p.cs2 * std::pow(x, p.cs3) : p.cs1 - p.cs2 * std::log(x);
  };
  const double e_cr1 = critical(contact.mean), e_cr2 = critical(updated_trial_.mean);
  if (e_current < e_cr2 && e_trial < e_cr1) return false;
  if (e_current > e_cr2 && e_trial > e_cr1) return false;
  return true;
}

// The damage of cyclic mobility: (the confinement lost since the largest one, relative to it)^(1/4).
void PressureDependMultiYield02::update_damage() {
  damage_ = 0.0;
  const double lost = (max_press_ - mean(committed_.stress)) / (max_press_ - residual_pressure_);
  if (lost > 0.0) damage_ = std::pow(lost, 0.25);
}

// OpenSees updatePPZ: the perfectly-plastic zone of cyclic mobility in octahedral shear strain (Yang et al.
// 2003): its size grows with the dilative strain accumulated under damage (liquefac1), its centre
// follows the pivot; beyond it the point dilates (on_ppz 2), inside it shears without volume change (1).
void PressureDependMultiYield02::update_ppz(const StressPoint& contact) {
  auto& s = trial_;
  const auto& p = params_;
  const double reversal = contract(deviator(increment_), committed_.pivot_strain_rate);
  if (s.on_ppz < 1) update_damage();
  if (p.liquefaction1 == 0.0) {  // no PPZ
    if (s.on_ppz == 2) {
      s.ppz_pivot = sub_strain_;
      s.cumu_dilate += octahedral_strain(sub_increment_);
    } else {
      s.on_ppz = 2;
      s.ppz_pivot = sub_strain_;
      s.pivot_strain_rate = deviator(increment_);
      if (reversal < 0.0) s.cumu_dilate = 0.0;
    }
    return;
  }
  if (s.on_ppz == 2) {  // dilating: accumulate the dilative strain
    s.ppz_pivot = sub_strain_;
    s.cumu_dilate += octahedral_strain(sub_increment_);
    s.max_cumu_dilate += std::max(damage_, 0.0) * p.liquefaction1 * octahedral_strain(sub_increment_);
    return;
  }
  if ((s.on_ppz == -1 || s.on_ppz == 0) && reversal < 0.0) {
    const double ratio = std::pow((-contact.mean + residual_pressure_) / (p.ref_pressure + residual_pressure_),
                                  1.0 - p.pressure_exponent);
    s.oppo_pre_ppz = s.pre_ppz;
    s.pre_ppz = ratio * strain_pt_octa_;
    if (s.oppo_pre_ppz == 0.0) s.oppo_pre_ppz = s.pre_ppz;
  }
  s.ppz_size = (s.cumu_translate + s.max_cumu_dilate) / 2.0;
  if (s.on_ppz == 0 || (s.on_ppz == 1 && reversal < 0.0)) {  // the new centre, on the line pivot - centre
    const Vector6 w = s.ppz_pivot - s.ppz_center;
    const double length = octahedral_strain(w);
    const double coeff = length == 0.0 ? 0.0 : (s.ppz_size - s.cumu_translate) / length;
    s.ppz_center = s.ppz_pivot - w * coeff;
  }
  if (octahedral_strain(sub_strain_ - s.ppz_center) > s.ppz_size) {  // outside the PPZ
    s.cumu_dilate = 0.0;
    s.on_ppz = 2;
    s.ppz_pivot = sub_strain_;
    s.pivot_strain_rate = deviator(increment_);
    s.cumu_translate = 0.0;
  } else {
    if (s.on_ppz == 0 || s.on_ppz == 1) translate_ppz();
    if (s.on_ppz == -1 || s.on_ppz == 0) s.on_ppz = 1;
  }
}

// OpenSees PPZTranslation: on a reversal the PPZ translates by liquefac2 x damage x the shear strain since the
// pivot.
void PressureDependMultiYield02::translate_ppz() {
  if (params_.liquefaction1 == 0.0) return;
  update_damage();
  const double reversal = contract(deviator(increment_), committed_.pivot_strain_rate);
  if (reversal < 0.0) {
    const double moved = octahedral_strain(deviator(sub_strain_) - deviator(trial_.ppz_pivot));
    trial_.cumu_translate = std::max(trial_.cumu_translate, std::max(damage_, 0.0) * params_.liquefaction2 * moved);
  }
}

// OpenSees getTangent (plane strain rows/columns xx, yy, xy): elastic in stages 0 and 2; in stage 1 the elastic
// moduli at the start of the last sub-increment less, on the active surface, the plastic part
// (9 B^2 n_v^2 I I + 4 G^2 n_dev n_dev) / (9 B n_v^2 + 2 G n_dev : n_dev + H), symmetric (no P'').
void PressureDependMultiYield02::form_tangent() {
  if (stage_ != 1) {
    const double f = elastic_factor();
    tangent_ = plane_strain_elastic_matrix(params_.bulk_modulus * f, params_.shear_modulus * f);
    return;
  }
  double factor = modulus_factor(updated_trial_.mean);
  double G = factor * params_.shear_modulus, B = factor * params_.bulk_modulus;
  if (params_.hv != 0.0 && trial_stress_.mean <= max_press_ && mean(increment_) < 0.0) {
    const double hp = params_.hv * std::pow(std::abs(trial_stress_.mean - residual_pressure_), params_.pv);
    B = B * hp / (B + hp);
  }
  double c1 = 0.0, c2 = 0.0;
  Vector6 n = Vector6::Zero();
  const int k = trial_.surfaces.active();
  if (k > 0) {
    factor = modulus_factor(trial_stress_.mean);
    G = factor * params_.shear_modulus;
    B = factor * params_.bulk_modulus;
    const auto [n_dev, n_vol] = surface_normal(trial_stress_);
    n = n_dev;
    const double ho = 9.0 * B * n_vol * n_vol + 2.0 * G * contract(n_dev, n_dev);
    const double H = factor * trial_.surfaces[k].modulus;
    c1 = 9.0 * B * B * n_vol * n_vol / (ho + H);
    c2 = 4.0 * G * G / (ho + H);
  }
  const double lambda = B - 2.0 * G / 3.0 - c1;
  tangent_ << 2.0 * G + lambda - c2 * n[0] * n[0], lambda - c2 * n[0] * n[1], 0.0,
      lambda - c2 * n[1] * n[0], 2.0 * G + lambda - c2 * n[1] * n[1], 0.0,
      0.0, 0.0, G - c2 * n[3] * n[3];
}

void PressureDependMultiYield02::commit_state() {
  if (stage_ == 1) {
    committed_ = trial_;
    max_press_ = std::min(max_press_, mean(committed_.stress));
  } else {  // OpenSees commits only the stress and strain outside the plastic stage
    committed_.stress = trial_.stress;
    committed_.strain = trial_.strain;
  }
}

void PressureDependMultiYield02::revert_to_last_commit() {
  trial_ = committed_;
  increment_.setZero();
  trial_stress_ = split(trial_.stress);
  stress_ << trial_.stress[0], trial_.stress[1], trial_.stress[3];
  form_tangent();
}

void PressureDependMultiYield02::revert_to_start() {
  committed_ = State{};
  committed_.surfaces = reference_surfaces_;
  plastic_started_ = false;
  init_press_ = -params_.ref_pressure;
  max_press_ = 0.0;
  sub_increment_.setZero();
  sub_strain_.setZero();
  updated_trial_ = StressPoint{};
  factor_ = 1.0;
  damage_ = 0.0;
  revert_to_last_commit();
}

bool PressureDependMultiYield02::update_stage(int stage) {
  if (stage < 0 || stage > 2)
    throw common::InputError("updateMaterialStage -material " + std::to_string(tag()),
                             "PressureDependMultiYield02 stages are 0 (elastic), 1 (plastic) and 2 (pressure-"
                             "dependent elastic), got -stage " + std::to_string(stage));
  stage_ = stage;
  return true;
}

bool PressureDependMultiYield02::set_parameter(std::string_view name, double value) {
  const std::string where = "setParameter " + std::string(name) + " (nDMaterial PressureDependMultiYield02 " +
                            std::to_string(tag()) + ")";
  if (name == "updateMaterialStage") return update_stage(static_cast<int>(value));
  if (name == "shearModulus" || name == "bulkModulus") {
    if (!(value > 0.0)) throw common::InputError(where, "expected a modulus > 0, got " + std::to_string(value));
    (name == "shearModulus" ? params_.shear_modulus : params_.bulk_modulus) = value;  // the surfaces stay
    form_tangent();
    return true;
  }
  if (name == "frictionAngle" || name == "cohesion") {
    if (name == "frictionAngle") {
      if (!(value > 0.0 && value < 90.0))
        throw common::InputError(where, "expected 0 < frictionAngle < 90, got " + std::to_string(value));
      params_.friction_deg = value;
    } else {
      params_.cohesion = value;
    }
    // OpenSees: the surfaces generated again and centred on the committed stress with the active surface kept
    // (setUpSurfaces, initSurfaceUpdate).
    const int active = committed_.surfaces.active();
    set_up_surfaces();
    committed_.surfaces.set_active(active);
    const double h = cone().height(mean(committed_.stress));
    committed_.surfaces.centre_on(deviator(committed_.stress), h);
    trial_.surfaces = committed_.surfaces;
    return true;
  }
  return false;
}

std::optional<std::vector<double>> PressureDependMultiYield02::response(std::string_view name) const {
  if (name == "stress" || name == "stresses") {
    const Vector6& s = committed_.stress;
    const double failure = committed_.surfaces[committed_.surfaces.count()].size;
    const double ratio = stage_ == 1 ? stress_ratio(split(s), residual_pressure_) / failure : 0.0;
    return std::vector<double>{s[0], s[1], s[2], s[3], ratio};
  }
  if (name == "strain" || name == "strains") {
    const Vector3& e = committed_.strain;
    return std::vector<double>{e[0], e[1], e[2]};
  }
  if (name == "tangent") {
    return std::vector<double>(tangent_.data(), tangent_.data() + 9);  // symmetric: rows = columns
  }
  return NDMaterial::response(name);
}

Eigen::MatrixXd PressureDependMultiYield02::backbone(const std::vector<double>& confinements) const {
  const auto& s = committed_.surfaces;
  const int n = s.count();
  const double pr = residual_pressure_;
  Eigen::MatrixXd bb = Eigen::MatrixXd::Zero(n + 1, 2 * static_cast<Eigen::Index>(confinements.size()));
  for (std::size_t k = 0; k < confinements.size(); ++k) {
    const auto c = static_cast<Eigen::Index>(2 * k);
    const double p = confinements[k];
    bb(0, c) = p;
    if (!(p > 0.0)) continue;  // OpenSees: "invalid confinement for backbone recorder", the column left empty
    const double height = p + pr;
    const double factor = std::pow(height / (params_.ref_pressure + pr), params_.pressure_exponent);
    const double G = factor * params_.shear_modulus;
    double stress = 0.0, strain = 0.0;
    for (int m = 1; m <= n; ++m) {
      const double previous_stress = stress, previous_strain = strain;
      stress = s[m].size * height / std::sqrt(3.0);
      if (m == 1) {
        strain = stress / G;
        bb(m, c) = strain;
        bb(m, c + 1) = G;
      } else {
        const double H = factor * s[m - 1].modulus;
        const double elasto_plastic = 2.0 * G * H / (2.0 * G + H);
        strain = 2.0 * (stress - previous_stress) / elasto_plastic + previous_strain;
        bb(m, c) = strain;
        bb(m, c + 1) = stress / strain;
      }
    }
  }
  return bb;
}

nlohmann::json PressureDependMultiYield02::to_json() const {
  const auto& p = params_;
  nlohmann::json j{{"name", std::to_string(tag())},
                   {"type", "PressureDependMultiYield02"},
                   {"nd", 2},
                   {"rho", p.density},
                   {"refShearModul", p.shear_modulus},
                   {"refBulkModul", p.bulk_modulus},
                   {"frictionAng", p.friction_deg},
                   {"peakShearStra", p.peak_shear_strain},
                   {"refPress", p.ref_pressure},
                   {"pressDependCoe", p.pressure_exponent},
                   {"PTAng", p.pt_deg},
                   {"contrac1", p.contraction1},
                   {"contrac3", p.contraction3},
                   {"dilat1", p.dilation1},
                   {"dilat3", p.dilation3},
                   {"noYieldSurf", p.surfaces},
                   {"contrac2", p.contraction2},
                   {"dilat2", p.dilation2},
                   {"liquefac1", p.liquefaction1},
                   {"liquefac2", p.liquefaction2},
                   {"e", p.void_ratio},
                   {"cs1", p.cs1},
                   {"cs2", p.cs2},
                   {"cs3", p.cs3},
                   {"pa", p.atmospheric},
                   {"c", p.cohesion},
                   {"Hv", p.hv},
                   {"Pv", p.pv}};
  if (!p.backbone.empty()) j["backbone"] = p.backbone;
  return j;
}

std::unique_ptr<NDMaterial> parse_pressure_depend_multi_yield02(common::CommandArgs& args) {
  const int tag = args.integer("tag");
  const double nd = args.number("nd");
  if (nd == 3.0) args.fail("fem_tcl models are 2D (plane strain): expected nd = 2, got 3");
  if (nd != 2.0) args.fail("expected nd = 2 (plane strain), got " + std::to_string(nd));
  PressureDependMultiYield02Parameters p;
  p.density = args.number("rho");
  p.shear_modulus = args.number("refShearModul");
  p.bulk_modulus = args.number("refBulkModul");
  p.friction_deg = args.number("frictionAng");
  p.peak_shear_strain = args.number("peakShearStra");
  p.ref_pressure = args.number("refPress");
  p.pressure_exponent = args.number("pressDependCoe");
  p.pt_deg = args.number("PTAng");
  p.contraction1 = args.number("contrac1");
  p.contraction3 = args.number("contrac3");
  p.dilation1 = args.number("dilat1");
  p.dilation3 = args.number("dilat3");
  if (!args.empty()) {
    // OpenSees reads noYieldSurf as a number and truncates it; -100 < n < 0 announces |n| user points.
    const double n = std::clamp(args.number("noYieldSurf"), -1.0e6, 1.0e6);
    if (n < 0.0 && n > -100.0) {
      const int count = -static_cast<int>(n);
      if (count < 2) args.fail("expected at least 2 user-defined yield surfaces, got noYieldSurf " + std::to_string(n));
      p.surfaces = count;
      for (int i = 0; i < 2 * count; ++i) p.backbone.push_back(args.number(i % 2 == 0 ? "shear strain r" : "G/Gmax"));
    } else {
      p.surfaces = static_cast<int>(n);
    }
  }
  double* optional[] = {&p.contraction2, &p.dilation2, &p.liquefaction1, &p.liquefaction2, &p.void_ratio, &p.cs1,
                        &p.cs2, &p.cs3, &p.atmospheric, &p.cohesion, &p.hv, &p.pv};
  const char* names[] = {"contrac2", "dilat2", "liquefac1", "liquefac2", "e", "cs1", "cs2", "cs3", "pa", "c", "Hv", "Pv"};
  for (std::size_t i = 0; i < std::size(optional) && !args.empty(); ++i) *optional[i] = args.number(names[i]);
  args.expect_end();
  return std::make_unique<PressureDependMultiYield02>(tag, p);
}

}  // namespace fem::materials
