#include "fem_tcl/materials/pm4silt.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "common/input_error.hpp"
#include "common/number_text.hpp"

// Reimplemented from OpenSees' PM4Silt.cpp (commit 2890cb36). The model's equations are cited by section of
// Boulanger & Ziotopoulou (2018), Report UCD/CGM-18/01 ("the manual"), section 2 (model formulation) and
// section 3 (default parameters); OpenSees' function names are given where the algorithm is OpenSees' own. The
// explicit stress integration is PM4Sand's (pm4_integration.cpp, with PM4Sand's quirks 6 to 8 of pm4sand.cpp);
// PM4Silt.cpp's three departures from it are quirks 4, 6 and 7 (pm4::Model::elastic_stage_moduli, pm4::Variant).
// OpenSees' behaviour is kept where it departs from the manual or looks accidental, because scripts must give
// OpenSees' numbers:
//  1. S_u <= 0 takes S_u = Su_Rat sigma'yy of the stress at the first initialisation (FirstCall, reset), the
//     vertical normal stress, not sigma'vc of a K0 state in general; once set, S_u stays, and a later
//     initialisation recomputes Su_Rat = S_u / sigma'yy. ru_max, z_max and ce < 0 are derived then from Su_Rat
//     (z_max = 10 for Su_Rat <= 0.25, 20 above 0.5, 40 Su_Rat between; ce = min(1.3, 0.5 + 1.2 <Su_Rat - 0.25>))
//     and stay; p_min = max(min(p0, p_cs / 8), P_atm / 200), or (1 - ru_max) p0 / 2 when ru_max is given.
//  2. The critical-state line goes through (p_cs = 2 S_u / M, eInit): its intercept uses the input eInit, and so
//     does the initial state parameter, while the integration uses the void ratio of the total strain (the
//     elastic stage's consolidation strain included).
//  3. The secondary defaults (h0, eInit, lambda, nb_wet, nb_dry, nd, Ado, cz, Cgd, Ckaf, m_m, CG_consol; Su_factor
//     <= 0) are applied here at construction; OpenSees applies them at the first initialisation (the only visible
//     difference: eInit < 0 in the elastic stage's void ratio of `state`). nu < 0 is 0.3, nu = 0.5 is 0.49.
//  4. The elastic stage keeps the moduli of the last commit (PM4Silt.cpp's elastic_integrator calls no
//     GetElasticModuli): `poissonRatio` and `refShearModulus` act from the next commit on.
//  5. The stress is scaled back onto the bounding surface at commit only where |syy - sxx| < 1e-5 (OpenSees: "for
//     non K0 condition"), in stage 1.
//  6. The plastic stage sets the void ratio only inside the schemes (an elastic or sub-stepped trial reports the
//     committed one in `state`); `state` reports the trial's alpha, fabric, alpha_in and plastic multiplier
//     (PM4Sand: the committed ones).
//  7. The first Runge-Kutta stage floors a negative denominator Kp + 2G - K D n : r (IntScheme 3).
//  8. The contraction's C_dz has no lower bound, C_zpk2 no cap below 1, C_pzp no guard against p_zp = 0
//     (unlike PM4Sand.cpp).
//  9. A copy for an element (copy_for, OpenSees getCopy) recomputes M from phi_cv = asin(M / 2) in degrees, as
//     OpenSees' getCopy passes it (a round trip that may change M's last bit).
// 10. `tracker` is (0, D, 0) with D the dilatancy of the last GetStateDependent call (trial, never committed).
// Deliberately not matched: OpenSees' stage flag (me2p) is one static variable shared by every PM4Silt in the
// process; here each material (and each integration point's copy) has its own, and copies take their parent's.
// IntScheme and TanType outside 1..5 and 0..2 are refused (OpenSees runs unknown schemes as 5), negative ones are
// the defaults; TolF / TolR < 0 mean the defaults 1e-7 / 1e-10 (OpenSees would use the negative value); P_atm < 0
// means 101.3 (OpenSees uses it and its moduli are not numbers). Refused (OpenSees checks none): G_o, h_po <= 0,
// Den < 0, S_u <= 0 with Su_Rat <= 0, P_atm = 0, nu > 0.5, phicv outside (0, 60) degrees (M must stay below the
// bounding ratio at p = 0, 2 sin 60), lambda = 0, nb_dry = 0, z_max = 0; and by the commands, Su_factor <= 0,
// G_o <= 0, nu outside [0, 0.5] (nu = 0.5 is 0.4999, as OpenSees' GetElasticModuli makes it).
// revert_to_last_commit restores the whole committed state (OpenSees' does nothing); FirstCall resets the trial
// to the new committed state (OpenSees keeps the trial stress until the next trial). Before the first
// initialisation p_cs and Gamma are 0 (OpenSees leaves them unset). OpenSees' messages are not printed.

namespace fem::materials {

namespace {

using pm4::contract;
using pm4::deviator;
using pm4::identity;
using pm4::kRootHalf;
using pm4::kSmall;
using pm4::macaulay;
using pm4::mean_stress;
using pm4::norm;

using pm4::kPi;  // the value OpenSees' PM4Silt uses for phi_cv -> Mc and phi_max
constexpr double kOneThird = 1.0 / 3.0;
constexpr double kTwoThirds = 2.0 / 3.0;
constexpr double kMdMax = 1.4142136;  // OpenSees' cap of Md (sqrt(2) to 8 digits)

std::string number_text(double v) { return common::number_text(v, 10); }

}  // namespace

// --- parameters ---------------------------------------------------------------------------------------------

PM4SiltParameters resolve_parameters(const PM4SiltParameters& given, const std::string& where) {
  const auto check = [&](bool ok, const std::string& what) {
    if (!ok) throw common::InputError(where, what);
  };
  const auto or_default = [](double v, double fallback) { return v < 0.0 ? fallback : v; };
  PM4SiltParameters p = given;
  check(given.Su > 0.0 || given.Su_Rat > 0.0,
        "Su_Rat: expected Su_Rat > 0 when S_u <= 0 (S_u is then Su_Rat sigma'v), got S_u " + number_text(given.Su) +
            " and Su_Rat " + number_text(given.Su_Rat));
  check(given.G0 > 0.0, "G_o: expected G_o > 0, got " + number_text(given.G0));
  check(given.hpo > 0.0, "h_po: expected h_po > 0, got " + number_text(given.hpo));
  check(given.density >= 0.0, "Den: expected Den >= 0, got " + number_text(given.density));
  // The constructor (nu, nG, phicv) and the checks at the top of initialize(stress) (the rest).
  p.Su_factor = given.Su_factor > 0.0 ? given.Su_factor : 1.0;
  p.P_atm = or_default(given.P_atm, 101.3);
  check(p.P_atm > 0.0, "P_atm: expected P_atm > 0 (or < 0 for the default 101.3), got " + number_text(given.P_atm));
  p.nu = or_default(given.nu, 0.3);
  check(p.nu <= 0.5, "nu: expected nu <= 0.5, got " + number_text(given.nu));
  if (p.nu == 0.5) p.nu = 0.49;  // OpenSees: "using 0.49 instead"
  p.nG = or_default(given.nG, 0.75);
  p.h0 = or_default(given.h0, 0.5);
  p.e_init = or_default(given.e_init, 0.9);
  p.lambda = or_default(given.lambda, 0.06);
  check(p.lambda > 0.0, "lambda: expected lambda > 0, got " + number_text(given.lambda));
  p.phi_cv = or_default(given.phi_cv, 32.0);
  check(p.phi_cv > 0.0 && p.phi_cv < 60.0,
        "phicv: expected 0 < phicv < 60 degrees (the bounding surface's phi_max), got " + number_text(p.phi_cv));
  p.nb_wet = or_default(given.nb_wet, 0.8);
  p.nb_dry = or_default(given.nb_dry, 0.5);
  check(p.nb_dry > 0.0, "nb_dry: expected nb_dry > 0, got " + number_text(given.nb_dry));
  p.nd = or_default(given.nd, 0.3);
  p.Ado = or_default(given.Ado, 0.8);
  check(given.z_max != 0.0, "z_max: expected z_max > 0 (or < 0 for the default), got 0");
  p.cz = or_default(given.cz, 100.0);
  p.Cgd = or_default(given.Cgd, 3.0);
  p.Ckaf = or_default(given.Ckaf, 4.0);
  p.m = or_default(given.m, 0.01);
  p.CG_consol = or_default(given.CG_consol, 2.0);
  pm4::resolve_integration_options(p.scheme, p.tangent_type, p.tol_f, p.tol_r, 1e-7, 1e-10, where);
  return p;
}

// --- construction, copies -----------------------------------------------------------------------------------

// OpenSees' constructor and initialize(): zero stress, the moduli at p = P_atm, p_min = P_atm / 200. The bounding
// surface's cap (manual section 2, bounding surface dense of critical): Mb,max = 2 sin(60 deg) and
// C_Mb = 1 / ((Mb,max / M)^(1 / nb_dry) - 1).
PM4Silt::PM4Silt(int tag, const PM4SiltParameters& given)
    : Material(tag, "PM4Silt", "G_o", resolve_parameters(given, "nDMaterial PM4Silt " + std::to_string(tag)),
               pm4::Variant{.void_ratio_before_elastic_check = false, .rk4_floors_negative_denominator = true}) {
  Mb_max_ = 2.0 * std::sin(60.0 / 180.0 * kPi);
  C_Mb_ = 1.0 / (std::pow(Mb_max_ / Mc_, 1.0 / params_.nb_dry) - 1.0);
  start(params_.e_init);
}

// OpenSees getCopy: a new material from the current parameters, phi_cv recovered from M (quirk 9), fresh state.
std::unique_ptr<PM4Silt::Material> PM4Silt::fresh_copy() const {
  PM4SiltParameters p = params_;
  p.phi_cv = std::asin(Mc_ / 2.0) * 180.0 / kPi;
  return std::make_unique<PM4Silt>(tag(), p);
}

// --- the model ----------------------------------------------------------------------------------------------

// Manual section 2, critical state: xi = e - e_cs with the linear critical-state line
// e_cs = Gamma - lambda ln(101.3 p / (P_atm Su_factor)) (OpenSees GetKsi), p not below p_min.
double PM4Silt::state_parameter(double void_ratio, double p) const {
  const double pn = p <= p_min_ ? p_min_ : p;
  return void_ratio - Gamma_ + params_.lambda * std::log(101.3 * pn / (params_.P_atm * params_.Su_factor));
}

// Manual section 2, bounding and dilatancy surfaces: dense of critical (xi < 0) Mb = M ((1 + C_Mb) /
// (p / p_cs + C_Mb))^nb_dry, loose Mb = M exp(-nb_wet xi / lambda); Md = M exp(nd xi / lambda), at most 1.4142136.
void PM4Silt::surfaces(double xi, double p, double& Mb, double& Md) const {
  Md = std::min(kMdMax, Mc_ * std::exp(params_.nd * xi / params_.lambda));
  if (xi < 0.0) Mb = Mc_ * std::pow((1.0 + C_Mb_) / (p / p_cs_ + C_Mb_), params_.nb_dry);
  else Mb = Mc_ * std::exp(-params_.nb_wet * xi / params_.lambda);
}

// Quirk 4: the elastic stage keeps the carried moduli (those of the last commit or initialisation).
void PM4Silt::elastic_stage_moduli(const Vector3& committed_stress, double& K, double& G) {
  (void)committed_stress;
  (void)K;
  (void)G;
}

// Manual section 2, elastic moduli: G = G_o P_atm (p / P_atm)^nG C_SR (1 + z_cum / z_max) / (1 + C_GD z_cum / z_max),
// C_SR = 1 - 0.5 min(1, (M / Mb)^4); during post-shaking reconsolidation reduced by
// F_consol = 1 - (1 - G_c,min / G) <1 - M / Md>^0.25 with G_c,min = 8 p / lambda / (1 + (CG_consol - 1)
// z_cum / (z_cum + z_max)) (manual, post-shaking reconsolidation). Sets the current stress ratio M = q / p.
void PM4Silt::elastic_moduli(const Vector3& stress, double& K, double& G) {
  Carried& c = trial_.carried;
  const History& t = trial_.history;
  const PM4SiltParameters& P = params_;
  double pn = mean_stress(stress);
  if (pn <= p_min_) pn = p_min_;
  const double qn = 2.0 * std::sqrt(std::pow(0.5 * (stress[0] - stress[1]), 2) + std::pow(stress[2], 2));
  c.Mcur = qn / pn;
  const double c_sr = 1.0 - 0.5 * std::min(1.0, std::pow(c.Mcur / c.Mb, 4));
  const double z_ratio = t.z_cum / P.z_max;
  if (stage_ == 0) {
    G = P.G0 * P.P_atm;
  } else {
    G = P.G0 * P.P_atm * std::pow(pn / P.P_atm, P.nG) * c_sr * (1.0 + z_ratio) / (1.0 + z_ratio * P.Cgd);
    if (post_shake_) {
      const double G_c_min = 8.0 * pn / P.lambda * (1.0 / (1.0 + (P.CG_consol - 1.0) * (t.z_cum / (t.z_cum + P.z_max))));
      const double F_consol = 1.0 - (1.0 - G_c_min / G) * std::pow(macaulay(1.0 - c.Mcur / c.Md), 0.25);
      G *= F_consol;
    }
  }
  K = pm4::bulk_modulus(G, P.nu);
}

// The state-dependent surfaces, plastic modulus and dilatancy (OpenSees GetStateDependent; manual section 2):
//  - Mb and Md from the state parameter (surfaces()); image back-stress ratios alpha_b,d = sqrt(1/2) (M_b,d - m) n;
//  - plastic modulus Kp = 2/3 h p (alpha_b - alpha) : n with PM4Sand's hardening h (C_ka, C_zpk1,2, C_pzp2, the
//    memory of alpha_in and alpha_in_true);
//  - dilation (past the rotated dilatancy surface M_d / C_rot1): A_d = Ado C_zin2 / (z_cum^2 / z_max
//    <1 - <-z : n> / (sqrt(2) z_peak)>^3 ce^2 C_pzp C_zin1 + 1), D = A_d (alpha_d - alpha) : n, eased towards
//    D_rot = A_d <-z : n> / (sqrt(2) z_max) (alpha_dr - alpha) : n / 3 below the bounding surface;
//  - contraction: h_p = h_po exp(-0.7 + 0.2 <3 - xi / lambda>^2), C_wet = min(1, 1 / (1 + (0.02 / b : n)^4) +
//    1 / (1 + (xi / (0.1 lambda))^2)), A_dc = Ado (1 + <z : n>) / (h_p C_dz C_wet),
//    D = min(A_dc ((alpha - alpha_in) : n + C_in)^2, Ado) (alpha_d - alpha) : n / ((alpha_d - alpha) : n + 0.1),
//    scaled by C_pmin from 0 at 2 p_min to 1 at 8 p_min;
//  - R = n + D / 3 I (plastic flow direction).
PM4Silt::Hardening PM4Silt::state_dependent(const Vector3& stress, const Vector3& alpha, const Vector3& fabric,
                                            double G, double void_ratio) {
  Carried& c = trial_.carried;
  const History& t = trial_.history;
  const PM4SiltParameters& P = params_;
  Hardening hd;
  double p = mean_stress(stress);
  if (p <= p_min_) p = p_min_;
  const double xi = state_parameter(void_ratio, p);
  hd.n = pm4::yield_normal(stress, alpha);
  const Vector3& n = hd.n;
  surfaces(xi, p, c.Mb, c.Md);
  const Vector3 alpha_b = n * (kRootHalf * (c.Mb - P.m));
  hd.alpha_d = n * (kRootHalf * (c.Md - P.m));

  const double z_cum = t.z_cum, z_peak = t.z_peak, z_max = P.z_max;
  const double c_zpk1 = z_peak / (z_cum + z_max / 5.0);
  const double c_zpk2 = z_peak / (z_cum + z_max / 100.0);
  const double c_pzp2 = macaulay(c.p_zp - p) / (macaulay(c.p_zp - p) + p_min_);
  const double c_g1 = P.h0 / 200.0;
  constexpr double c_kp = 2.0;

  hd.b = alpha_b - alpha;
  const double b_n = contract(hd.b, n);
  const double alpha_in_n = macaulay(contract(alpha - t.alpha_in, n));
  const double alpha_in_true_n = macaulay(contract(alpha - t.alpha_in_true, n));
  const double c_ka = 1.0 + P.Ckaf / (1.0 + std::pow(2.5 * alpha_in_true_n, 2)) * c_pzp2 * c_zpk1;
  if (std::abs(b_n) < kSmall) {
    hd.h = 1.0e10;  // OpenSees: avoids the division by zero on the bounding surface
  } else {
    hd.h = 1.5 * G * P.h0 / p / (std::exp(alpha_in_n) - 1.0 + c_g1) / std::sqrt(std::abs(b_n)) * c_ka /
           (1.0 + c_kp * z_peak / z_max * macaulay(b_n) * std::sqrt(1.0 - c_zpk2));
    if (contract(alpha - t.alpha_in_p, n) <= 0.0) hd.h = hd.h * (alpha_in_n + c_g1) / (alpha_in_true_n + c_g1);
  }
  hd.Kp = kTwoThirds * hd.h * p * b_n;

  const double z_n = contract(fabric, n);
  const double c_zin1 = macaulay(1.0 - std::exp(-2.0 * std::abs((contract(t.fabric_in, n) - z_n) / z_max)));
  const double z_minus = macaulay(contract(-fabric, n)) * kRootHalf;  // <-z : n> / sqrt(2)
  const double c_rot1 = std::max(1.0 + 2.0 * z_minus / z_max * (1.0 - c_zin1), 1.0);
  const double M_dr = c.Md / c_rot1;
  const double to_rotated = contract(n * (kRootHalf * (M_dr - P.m)) - alpha, n);
  const double to_dilatancy = contract(hd.alpha_d - alpha, n);
  if (to_rotated <= 0.0) {  // dilation
    const double c_pzp = 1.0 / (1.0 + std::pow(2.5 * p / c.p_zp, 5.0));
    const double c_zin2 = (1.0 + c_zin1 * (z_cum - z_peak) / (3.0 * z_max)) / (1.0 + 3.0 * c_zin1 * (z_cum - z_peak) / (3.0 * z_max));
    const double A_d = P.Ado * c_zin2 /
                       ((std::pow(z_cum, 2) / z_max) * std::pow(1.0 - z_minus / z_peak, 3) * std::pow(P.ce, 2.0) *
                            c_pzp * c_zin1 + 1.0);
    hd.D = A_d * to_dilatancy;
    const double D_rot = A_d * z_minus / z_max * to_rotated / 3.0;
    if (hd.D > D_rot) hd.D = hd.D + (D_rot - hd.D) * macaulay(c.Mb - c.Mcur) / (macaulay(c.Mb - c.Mcur) + 0.01);
    if (p_min_ <= p && p <= 2.0 * p_min_) hd.D = std::min(hd.D, -3.5 * P.Ado * macaulay(c.Mb - c.Md) * (2.0 * p_min_ - p) / p_min_);
  } else {  // contraction
    hd.Kp = std::max(0.0, hd.Kp);  // OpenSees bounds Kp to >= 0 here, following FLAC
    const double h_p = P.hpo * std::exp(-0.7 + 0.2 * std::pow(macaulay(3.0 - xi / P.lambda), 2.0));
    const double c_rot2 = 1.0 - c_zpk2;
    const double c_dz = (1.0 - c_rot2 * std::sqrt(2.0) * z_peak / z_max) * (z_max / (z_max + c_rot2 * z_cum));
    const double c_wet = std::min(1.0, (1.0 / (1.0 + std::pow(0.02 / b_n, 4.0)) + 1.0 / (1.0 + std::pow(xi / P.lambda / 0.1, 2.0))));
    const double A_dc = P.Ado * (1.0 + macaulay(z_n)) / (h_p * c_dz * c_wet);
    const double c_in = macaulay(z_n) * std::sqrt(2.0) / z_max;
    hd.D = std::min(A_dc * std::pow(contract(alpha - t.alpha_in, n) + c_in, 2.0), P.Ado) * to_dilatancy /
           (to_dilatancy + 0.10);
    double c_pmin = 1.0;
    if (p < 2.0 * p_min_) c_pmin = 0.0;
    else if (p < 8.0 * p_min_) c_pmin = (p - 2.0 * p_min_) / (6.0 * p_min_);
    hd.D *= c_pmin;
  }
  hd.R = n + kOneThird * hd.D * identity();
  tracker_[1] = hd.D;
  return hd;
}

// --- initialisation -------------------------------------------------------------------------------------------

// OpenSees' initialize(stress) (FirstCall, reset), quirks 1 and 2: a p0 below P_atm / 200 is raised to it (the
// difference kept as a stress offset, so the reported stress, hence the equilibrium, is unchanged); S_u or Su_Rat
// from sigma'yy; p_cs = 2 S_u / M (manual section 2: S_u is the critical-state strength at eInit); p_min, z_max
// and ce as quirk 1 (manual section 3, the secondary parameters); the critical-state line through (p_cs, eInit):
// Gamma = eInit + lambda ln(101.3 p_cs / P_atm); Mb and Md at (eInit, p0). The back-stress ratio is set to the
// stress ratio, a stress ratio beyond the outer of the bounding and dilatancy surfaces scaled onto it (the
// difference kept as offset); the fabric and the reversal memory are cleared, alpha_in set to alpha.
void PM4Silt::initialize(const Vector3& stress) {
  const Vector3 initial = stress;
  PM4SiltParameters& P = params_;
  const double p0 = begin_initialization(initial, P.P_atm / 200.0);
  Carried& c = trial_.carried;
  // S_u from Su_Rat needs a compressive sigma'yy: at zero or tensile effective stress OpenSees takes the log of
  // p_cs <= 0 below and every stress after it is NaN (found by fuzzing: an undrained DSS at zero effective stress).
  if (P.Su <= 0.0 && !(initial[1] > 0.0))
    throw common::InputError(where(), "S_u = Su_Rat sigma'yy needs a compressive vertical effective stress when the "
                                      "material initialises (FirstCall), got sigma'yy = " + number_text(-initial[1]) +
                                      " (consolidate first, or give S_u)");
  if (P.Su <= 0.0) P.Su = P.Su_Rat * initial[1];
  else P.Su_Rat = P.Su / initial[1];
  p_cs_ = 2.0 * P.Su / Mc_;
  if (P.ru_max < 0.0) {
    p_min_ = std::min(p0, p_cs_ / 8.0);
  } else {
    P.ru_max = std::min(0.99, P.ru_max);
    p_min_ = (1.0 - P.ru_max) * p0 / 2.0;
  }
  p_min_ = std::max(p_min_, P.P_atm / 200.0);
  if (P.z_max < 0.0) P.z_max = P.Su_Rat <= 0.25 ? 10.0 : (P.Su_Rat > 0.50 ? 20.0 : 40.0 * P.Su_Rat);
  if (P.ce < 0.0) P.ce = std::min(1.3, 0.5 + 1.2 * macaulay(P.Su_Rat - 0.25));
  Gamma_ = P.e_init + P.lambda * std::log(101.3 * 2.0 * P.Su / Mc_ / P.P_atm);
  surfaces(state_parameter(P.e_init, p0), p0, c.Mb, c.Md);
  cap_initial_stress_ratio(initial, p0);
  tracker_.setZero();
  finish_initialization(p0, trial_.history.alpha);  // alpha_in = alpha
}

// --- the commit, commands, JSON, the command -------------------------------------------------------------------

// Quirk 5: the stress ratio is scaled back onto the bounding surface at commit only where |syy - sxx| < 1e-5.
bool PM4Silt::corrects_at_commit(const Vector3& stress) const { return std::abs(stress[1] - stress[0]) < 1e-5; }

// PM4Silt's own setParameter name (OpenSees PM4Silt::setParameter / updateParameter).
bool PM4Silt::set_model_parameter(std::string_view name, double value) {
  if (name == "Su_factor") {
    if (!(value > 0.0)) parameter_error(name, "Su_factor: expected Su_factor > 0, got " + number_text(value));
    params_.Su_factor = value;
    return true;
  }
  return false;
}

// PM4Silt's keys besides the shared ones (pm4::Material::to_json): OpenSees' argument names, and p_cs.
void PM4Silt::add_json(nlohmann::json& entry) const {
  const PM4SiltParameters& p = params_;
  entry.update({{"S_u", p.Su},
                {"Su_Rat", p.Su_Rat},
                {"G_o", p.G0},
                {"h_po", p.hpo},
                {"Su_factor", p.Su_factor},
                {"nG", p.nG},
                {"eInit", p.e_init},
                {"lambda", p.lambda},
                {"nb_wet", p.nb_wet},
                {"nb_dry", p.nb_dry},
                {"ru_max", p.ru_max},
                {"m_m", p.m},
                {"CG_consol", p.CG_consol},
                {"p_cs", p_cs_}});
}

std::unique_ptr<NDMaterial> parse_pm4silt(common::CommandArgs& args) {
  PM4SiltParameters p;
  const int tag = args.integer("tag");
  p.Su = args.number("S_u");
  p.Su_Rat = args.number("Su_Rat");
  p.G0 = args.number("G_o");
  p.hpo = args.number("h_po");
  p.density = args.number("Den");
  // The optional arguments in OpenSees' order.
  double scheme = -1.0, tangent_type = -1.0;
  const std::array<std::pair<const char*, double*>, 24> optional{{
      {"Su_factor", &p.Su_factor}, {"P_atm", &p.P_atm}, {"nu", &p.nu}, {"nG", &p.nG}, {"h0", &p.h0},
      {"eInit", &p.e_init}, {"lambda", &p.lambda}, {"phicv", &p.phi_cv}, {"nb_wet", &p.nb_wet},
      {"nb_dry", &p.nb_dry}, {"nd", &p.nd}, {"Ado", &p.Ado}, {"ru_max", &p.ru_max}, {"z_max", &p.z_max},
      {"cz", &p.cz}, {"ce", &p.ce}, {"Cgd", &p.Cgd}, {"Ckaf", &p.Ckaf}, {"m_m", &p.m}, {"CG_consol", &p.CG_consol},
      {"IntScheme", &scheme}, {"TanType", &tangent_type}, {"TolF", &p.tol_f}, {"TolR", &p.tol_r}}};
  pm4::read_optional_arguments(args, optional);
  p.scheme = pm4::whole_argument(args, scheme, "IntScheme");
  p.tangent_type = pm4::whole_argument(args, tangent_type, "TanType");
  return std::make_unique<PM4Silt>(tag, p);
}

}  // namespace fem::materials
