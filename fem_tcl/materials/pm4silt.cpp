#include "fem_tcl/materials/pm4silt.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "common/input_error.hpp"

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

constexpr double kPi = 3.14159265359;  // the value OpenSees' PM4Silt uses for phi_cv -> Mc and phi_max
constexpr double kOneThird = 1.0 / 3.0;
constexpr double kTwoThirds = 2.0 / 3.0;
constexpr double kMdMax = 1.4142136;  // OpenSees' cap of Md (sqrt(2) to 8 digits)

std::string number_text(double v) {
  std::ostringstream os;
  os.precision(10);
  os << v;
  return os.str();
}

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
  p.scheme = given.scheme < 0 ? 5 : given.scheme;
  check(p.scheme >= 1 && p.scheme <= 5,
        "IntScheme: expected 1 (modified Euler), 2 (forward Euler), 3 (Runge-Kutta 4), 4 or 5 (forward / modified "
        "Euler with at most 1e-5 strain per sub-step), got " + std::to_string(given.scheme));
  p.tangent_type = given.tangent_type < 0 ? 0 : given.tangent_type;
  check(p.tangent_type >= 0 && p.tangent_type <= 2,
        "TanType: expected 0 (elastic), 1 or 2 (elastic matrix of the last commit), got " +
            std::to_string(given.tangent_type));
  p.tol_f = or_default(given.tol_f, 1e-7);
  p.tol_r = or_default(given.tol_r, 1e-10);
  check(p.tol_f > 0.0, "TolF: expected TolF > 0, got " + number_text(given.tol_f));
  check(p.tol_r > 0.0, "TolR: expected TolR > 0, got " + number_text(given.tol_r));
  return p;
}

// --- construction, copies -----------------------------------------------------------------------------------

// OpenSees' constructor and initialize(): zero stress, the moduli at p = P_atm, p_min = P_atm / 200. The bounding
// surface's cap (manual section 2, bounding surface dense of critical): Mb,max = 2 sin(60 deg) and
// C_Mb = 1 / ((Mb,max / M)^(1 / nb_dry) - 1).
PM4Silt::PM4Silt(int tag, const PM4SiltParameters& given) : NDMaterial(tag) {
  params_ = resolve_parameters(given, where());
  Mc_ = 2.0 * std::sin(params_.phi_cv / 180.0 * kPi);
  Mb_max_ = 2.0 * std::sin(60.0 / 180.0 * kPi);
  C_Mb_ = 1.0 / (std::pow(Mb_max_ / Mc_, 1.0 / params_.nb_dry) - 1.0);
  p_min_ = params_.P_atm / 200.0;
  History& h = committed_.history;
  Carried& c = committed_.carried;
  h.void_ratio = params_.e_init;
  h.z_peak = params_.z_max / 100000.0;
  c.Mb = c.Md = Mc_;  // OpenSees leaves them unset until the first initialisation
  elastic_moduli_plain(Vector3(params_.P_atm, params_.P_atm, 0.0), c.K, c.G);
  c.ce = c.cep = pm4::elastic_stiffness(c.K, c.G);
  trial_ = committed_;
  publish();
}

std::unique_ptr<NDMaterial> PM4Silt::copy_for(PlaneType plane) const {
  if (plane != PlaneType::PlaneStrain)
    throw common::InputError(where(), "PM4Silt is a plane-strain (2D) model: it has no plane-stress form");
  // OpenSees getCopy: a new material from the current parameters (phi_cv recovered from M, quirk 9), fresh state;
  // the stage is the parent's (OpenSees' stage flag is shared by all PM4Silt materials).
  PM4SiltParameters p = params_;
  p.phi_cv = std::asin(Mc_ / 2.0) * 180.0 / kPi;
  auto copy = std::make_unique<PM4Silt>(tag(), p);
  copy->stage_ = stage_;
  return copy;
}

void PM4Silt::publish() {
  const History& t = trial_.history;
  stress_ = -(t.stress + t.stress_offset);
  strain_ = -t.strain;
  tangent_ = params_.tangent_type == 0 ? trial_.carried.ce : trial_.carried.cep;
}

Vector6 PM4Silt::stress_3d() const {
  Vector6 s = Vector6::Zero();
  s << stress_[0], stress_[1], 0.5 * (stress_[0] + stress_[1]), stress_[2], 0.0, 0.0;
  return s;
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

// G = G_o P_atm (stage 0) or G_o P_atm sqrt(p / P_atm) (OpenSees' 3-argument GetElasticModuli, used by the
// constructor); K = 2 (1 + nu) / (3 (1 - 2 nu)) G.
void PM4Silt::elastic_moduli_plain(const Vector3& stress, double& K, double& G) const {
  double pn = mean_stress(stress);
  if (pn <= p_min_) pn = p_min_;
  G = stage_ == 0 ? params_.G0 * params_.P_atm : params_.G0 * params_.P_atm * std::sqrt(pn / params_.P_atm);
  K = pm4::bulk_modulus(G, params_.nu);
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
  trial_.history = committed_.history;  // an uncommitted trial is dropped
  History& t = trial_.history;
  Carried& c = trial_.carried;
  PM4SiltParameters& P = params_;
  double p0 = mean_stress(initial);
  if (p0 < P.P_atm / 200.0) {
    p0 = P.P_atm / 200.0;
    t.stress = p0 * identity();
    t.stress_offset = initial - t.stress;
    t.alpha.setZero();
  } else {
    t.stress = initial;
    t.stress_offset.setZero();
    t.alpha = deviator(initial) / p0;
  }
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
  const double M_cut = std::max(c.Mb, c.Md);
  const double M_in = std::sqrt(2.0) * norm(deviator(t.stress)) / p0;
  if (M_in > M_cut) {
    const Vector3 r = (t.stress - p0 * identity()) / p0 * M_cut / M_in;
    t.stress = p0 * identity() + r * p0;
    t.stress_offset = initial - t.stress;
    t.alpha = r * (M_cut - P.m) / M_cut;
  }
  t.z_cum = 0.0;
  elastic_moduli(t.stress, c.K, c.G);
  c.ce = c.cep = pm4::elastic_stiffness(c.K, c.G);
  c.Kp = 100.0 * c.G;
  t.alpha_in = t.alpha;
  t.alpha_in_p.setZero();
  t.alpha_in_true = t.alpha_in_max = t.alpha_in_min = t.alpha;
  t.fabric.setZero();
  t.fabric_in.setZero();
  t.z_peak = P.z_max / 100000.0;
  c.p_zp = std::max(p0, p_min_) / 100.0;
  c.z_xp = 0.0;
  c.p_zp_unset = true;
  tracker_.setZero();
  committed_ = trial_;
  publish();
}

// --- the stress update ----------------------------------------------------------------------------------------

// The shared explicit integration (pm4_integration.hpp) with PM4Silt's moduli and surfaces and PM4Silt.cpp's
// variant of the driver (quirks 4, 6, 7).
pm4::Settings PM4Silt::settings() const {
  pm4::Settings s;
  s.scheme = static_cast<pm4::Scheme>(params_.scheme);
  s.m = params_.m;
  s.tol_f = params_.tol_f;
  s.cz = params_.cz;
  s.z_max = params_.z_max;
  s.Mc = Mc_;
  s.p_min = p_min_;
  s.e_init = params_.e_init;
  s.variant.void_ratio_before_elastic_check = false;
  s.variant.rk4_floors_negative_denominator = true;
  return s;
}

void PM4Silt::set_trial_strain(const Vector3& strain) {
  trial_.history = committed_.history;  // the carried members stay as the last trial left them
  trial_.history.strain = -strain;
  pm4::integrate(*this, settings(), stage_, trial_, committed_.history);
  publish();
}

// --- commit / revert ------------------------------------------------------------------------------------------

// OpenSees commitState: the moduli at the new stress; in stage 1 a stress ratio beyond Mb is scaled back onto the
// bounding surface (alpha onto its image) where syy and sxx are within 1e-5 (quirk 5); then the shared part
// (z_cum, z_peak, the void ratio, the elastic matrix).
void PM4Silt::commit_state() {
  History& t = trial_.history;
  Carried& c = trial_.carried;
  elastic_moduli(t.stress, c.K, c.G);
  if (c.Mcur > c.Mb && stage_ != 0 && std::abs(t.stress[1] - t.stress[0]) < 1e-5) {
    const double p = mean_stress(t.stress);
    const Vector3 r = deviator(t.stress) * (c.Mb / c.Mcur / p);
    t.stress = p * identity() + r * p;
    t.alpha = r * (c.Mb - params_.m) / c.Mb;
  }
  pm4::commit_history(settings(), trial_, committed_.history);
  committed_ = trial_;
  publish();
}

void PM4Silt::revert_to_last_commit() {
  trial_ = committed_;
  publish();
}

void PM4Silt::revert_to_start() { initialize(trial_.history.stress); }

// --- commands -------------------------------------------------------------------------------------------------

bool PM4Silt::update_stage(int stage) {
  if (stage != 0 && stage != 1)
    throw common::InputError("updateMaterialStage -material " + std::to_string(tag()),
                             "PM4Silt stages are 0 (elastic) and 1 (plastic), got stage " + std::to_string(stage));
  stage_ = stage;
  return true;
}

bool PM4Silt::set_parameter(std::string_view name, double value) {
  const auto fail = [&](const std::string& what) {
    throw common::InputError("setParameter " + std::string(name) + " (" + where() + ")", what);
  };
  if (name == "updateMaterialStage" || name == "materialState") {
    if (value != std::floor(value)) fail("expected an integer stage (0 or 1), got " + number_text(value));
    return update_stage(static_cast<int>(value));
  }
  if (name == "FirstCall") {  // re-initialise from the committed stress (any value, as OpenSees)
    initialize(committed_.history.stress);
    return true;
  }
  if (name == "PostShake") {  // post-shaking reconsolidation on (any value, as OpenSees)
    post_shake_ = true;
    elastic_moduli(trial_.history.stress, trial_.carried.K, trial_.carried.G);
    committed_.carried.K = trial_.carried.K;
    committed_.carried.G = trial_.carried.G;
    committed_.carried.Mcur = trial_.carried.Mcur;
    return true;
  }
  if (name == "Su_factor") {
    if (!(value > 0.0)) fail("Su_factor: expected Su_factor > 0, got " + number_text(value));
    params_.Su_factor = value;
    return true;
  }
  if (name == "IntegrationScheme") {
    const int scheme = static_cast<int>(value);
    if (value != std::floor(value) || scheme < 1 || scheme > 5)
      fail("IntegrationScheme: expected 1, 2, 3, 4 or 5, got " + number_text(value));
    params_.scheme = scheme;
    return true;
  }
  if (name == "refShearModulus" || name == "ShearModulus") {
    if (!(value > 0.0)) fail("G_o: expected G_o > 0, got " + number_text(value));
    params_.G0 = value;
    return true;
  }
  if (name == "poissonRatio") {  // OpenSees' GetElasticModuli takes nu >= 0.5 as 0.4999
    if (!(value >= 0.0 && value <= 0.5)) fail("nu: expected 0 <= nu <= 0.5, got " + number_text(value));
    params_.nu = value == 0.5 ? 0.4999 : value;
    return true;
  }
  if (name == "voidRatio") {  // eInit such that the current volumetric strain gives e = value
    const double strain_v = pm4::trace(trial_.history.strain);
    params_.e_init = (value + strain_v) / (1.0 - strain_v);
    return true;
  }
  return false;
}

std::optional<std::vector<double>> PM4Silt::response(std::string_view name) const {
  const auto list = [](const Vector3& v) { return std::vector<double>{v[0], v[1], v[2]}; };
  const History& t = trial_.history;
  const History& n = committed_.history;
  if (name == "stress" || name == "stresses") return list(stress_);
  if (name == "strain" || name == "strains") return list(strain_);
  if (name == "alpha" || name == "backstressratio") return list(n.alpha);
  if (name == "fabric") return list(n.fabric);
  if (name == "alpha_in" || name == "alphain") return list(n.alpha_in);
  if (name == "tracker" || name == "trackers") return list(tracker_);
  if (name == "state") {  // OpenSees getState (model sign convention: compression positive; trial values, quirk 6)
    std::vector<double> s;
    s.reserve(16);
    for (const Vector3* v : {&t.elastic_strain, &t.alpha, &t.fabric, &t.alpha_in}) s.insert(s.end(), v->data(), v->data() + 3);
    s.push_back(t.void_ratio);
    s.push_back(trial_.carried.dgamma);
    s.push_back(trial_.carried.G);
    s.push_back(trial_.carried.Kp);
    return s;
  }
  return NDMaterial::response(name);
}

nlohmann::json PM4Silt::to_json() const {
  const PM4SiltParameters& p = params_;
  return nlohmann::json{{"name", std::to_string(tag())},
                        {"type", "PM4Silt"},
                        {"S_u", p.Su},
                        {"Su_Rat", p.Su_Rat},
                        {"G_o", p.G0},
                        {"h_po", p.hpo},
                        {"Den", p.density},
                        {"Su_factor", p.Su_factor},
                        {"P_atm", p.P_atm},
                        {"nu", p.nu},
                        {"nG", p.nG},
                        {"h0", p.h0},
                        {"eInit", p.e_init},
                        {"lambda", p.lambda},
                        {"phicv", p.phi_cv},
                        {"nb_wet", p.nb_wet},
                        {"nb_dry", p.nb_dry},
                        {"nd", p.nd},
                        {"Ado", p.Ado},
                        {"ru_max", p.ru_max},
                        {"z_max", p.z_max},
                        {"cz", p.cz},
                        {"ce", p.ce},
                        {"Cgd", p.Cgd},
                        {"Ckaf", p.Ckaf},
                        {"m_m", p.m},
                        {"CG_consol", p.CG_consol},
                        {"IntScheme", p.scheme},
                        {"TanType", p.tangent_type},
                        {"TolF", p.tol_f},
                        {"TolR", p.tol_r},
                        {"p_cs", p_cs_},
                        {"materialStage", stage_}};
}

std::unique_ptr<NDMaterial> parse_pm4silt(common::CommandArgs& args) {
  PM4SiltParameters p;
  const int tag = args.integer("tag");
  p.Su = args.number("S_u");
  p.Su_Rat = args.number("Su_Rat");
  p.G0 = args.number("G_o");
  p.hpo = args.number("h_po");
  p.density = args.number("Den");
  // The optional arguments in OpenSees' order (OPS_PM4SiltMaterial reads them all as doubles).
  double scheme = -1.0, tangent_type = -1.0;
  const std::array<std::pair<const char*, double*>, 24> optional{{
      {"Su_factor", &p.Su_factor}, {"P_atm", &p.P_atm}, {"nu", &p.nu}, {"nG", &p.nG}, {"h0", &p.h0},
      {"eInit", &p.e_init}, {"lambda", &p.lambda}, {"phicv", &p.phi_cv}, {"nb_wet", &p.nb_wet},
      {"nb_dry", &p.nb_dry}, {"nd", &p.nd}, {"Ado", &p.Ado}, {"ru_max", &p.ru_max}, {"z_max", &p.z_max},
      {"cz", &p.cz}, {"ce", &p.ce}, {"Cgd", &p.Cgd}, {"Ckaf", &p.Ckaf}, {"m_m", &p.m}, {"CG_consol", &p.CG_consol},
      {"IntScheme", &scheme}, {"TanType", &tangent_type}, {"TolF", &p.tol_f}, {"TolR", &p.tol_r}}};
  for (const auto& [what, target] : optional) {
    if (args.empty()) break;
    *target = args.number(what);
  }
  args.expect_end();
  const auto whole = [&](double v, const char* what) {
    if (v >= 0.0 && v != std::floor(v)) args.fail(std::string("expected an integer ") + what + ", got " + number_text(v));
    return v < 0.0 ? -1 : static_cast<int>(std::min(v, 1e6));
  };
  p.scheme = whole(scheme, "IntScheme");
  p.tangent_type = whole(tangent_type, "TanType");
  return std::make_unique<PM4Silt>(tag, p);
}

}  // namespace fem::materials
