#include "fem_tcl/materials/pm4sand.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "common/input_error.hpp"
#include "common/number_text.hpp"

// Reimplemented from OpenSees' PM4Sand.cpp (commit 2890cb36). The manual's equations are cited by section of
// Boulanger & Ziotopoulou (2017), Report UCD/CGM-17/01 ("the manual"); OpenSees' function names are given where
// the algorithm (not the model) is OpenSees' own. OpenSees' behaviour is kept where it departs from the manual or
// looks accidental, because scripts must give OpenSees' numbers (the explicit integration, OpenSees integrate() to
// Stress_Correction with quirks 6 to 8, is shared with PM4Silt in pm4_integration.cpp):
//  1. Ado and z_max (negative = default) are computed when the model is initialised from a stress (FirstCall,
//     reset), from the state parameter at that stress and the input Dr; until then they stay -1 (a script that
//     never sends FirstCall runs stage 1 with z_max = -1, as in OpenSees).
//  2. ce's default is 0.5 for Dr < 0.55, 0.2 for Dr > 0.75 and linear between (OpenSees: "different from manual,
//     but matches FLAC"); ce = 0 also means the default (OpenSees tests ce > 0).
//  3. Cdr is capped at 10, Ckaf clamped to [4, 35], Fsed_min capped at 0.99, given or derived.
//  4. Stage 0 is linear elastic with G = G0 P_atm (no p dependence); in stage 0 the back-stress ratio follows the
//     stress ratio (alpha = s / p where p > p_min).
//  5. The stress is scaled back onto the bounding surface at commit when the stress ratio exceeds Mb (stage 1).
//  6. The moduli, Mb, Md, the current stress ratio, Kp, the plastic multiplier, p_zp and z_xp carry over from one
//     trial to the next (OpenSees keeps them in plain members); the elastic matrix used at the start of a trial is
//     the one of the last trial or commit, so `poissonRatio` and `refShearModulus` act from the next commit on.
//  7. The forward-Euler scheme evaluates n, D, h at the elastic trial stress of the whole step (the vector OpenSees'
//     integrator writes into before the scheme runs); the stress correction, failing after 25 iterations, leaves
//     the uncorrected stress (OpenSees' fallback bisects between two aliases of the same vector).
//  8. In the modified-Euler scheme a sub-step accepted at the smallest step (dT = 1e-4) with too large an error
//     keeps the fabric of its start and may overshoot T = 1 by less than dT_min.
//  9. The elasto-plastic tangent OpenSees stores at commit is built from zero vectors and equals the elastic
//     matrix: TanType 1 and 2 return the elastic matrix of the last commit (or elastic trial), TanType 0 the
//     current one.
// Deliberately not matched: OpenSees' stage flag (me2p) is one static variable shared by every PM4Sand in the
// process; here each material (and each integration point's copy) has its own, and copies take their parent's.
// TolF / TolR < 0 mean the default 1e-8 here (OpenSees would use the negative value); IntScheme and TanType
// outside 1..5 and 0..2 are refused (OpenSees maps unknown schemes to 5 silently); Dr outside [0, 1], G0 <= 0,
// hpo <= 0, Den < 0, P_atm = 0, emax <= emin, nu > 0.5 and phicv outside (0, 90) are refused (OpenSees checks
// none). revert_to_last_commit restores the whole committed state, the carried members included (OpenSees'
// revertToLastCommit does nothing; its next trial restarts from the committed history anyway). Mb and Md start at
// M (OpenSees leaves them unset until the first initialisation). OpenSees' messages ("1 initialize", "activate
// post shaking reconsolidation", "Warning, Mb is larger than 2, using Ado = 1.5", "Delta 2: p < 0") are not
// printed.

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

constexpr double kOneThird = 1.0 / 3.0;
constexpr double kTwoThirds = 2.0 / 3.0;

std::string number_text(double v) { return common::number_text(v, 10); }

}  // namespace

// --- parameters ---------------------------------------------------------------------------------------------

PM4SandParameters resolve_parameters(const PM4SandParameters& given, const std::string& where) {
  const auto check = [&](bool ok, const std::string& what) {
    if (!ok) throw common::InputError(where, what);
  };
  const auto or_default = [](double v, double fallback) { return v < 0.0 ? fallback : v; };
  PM4SandParameters p = given;
  check(given.Dr >= 0.0 && given.Dr <= 1.0, "Dr: expected a relative density 0 <= Dr <= 1, got " + number_text(given.Dr));
  check(given.G0 > 0.0, "G0: expected G0 > 0, got " + number_text(given.G0));
  check(given.hpo > 0.0, "hpo: expected hpo > 0, got " + number_text(given.hpo));
  check(given.density >= 0.0, "Den: expected Den >= 0, got " + number_text(given.density));
  const double Dr = given.Dr;
  p.P_atm = or_default(given.P_atm, 101.3);
  check(p.P_atm > 0.0, "P_atm: expected P_atm > 0 (or < 0 for the default 101.3), got " + number_text(given.P_atm));
  // Manual section 4.1 and OpenSees' constructor: h0 = max(0.3, (0.25 + Dr) / 2).
  p.h0 = or_default(given.h0, std::max(0.3, (0.25 + Dr) / 2.0));
  p.emax = or_default(given.emax, 0.8);
  p.emin = or_default(given.emin, 0.5);
  check(p.emax > p.emin, "emax, emin: expected emax > emin, got " + number_text(p.emax) + " and " + number_text(p.emin));
  p.nb = or_default(given.nb, 0.5);
  p.nd = or_default(given.nd, 0.1);
  p.cz = or_default(given.cz, 250.0);
  if (!(given.ce > 0.0)) p.ce = Dr > 0.75 ? 0.2 : (Dr < 0.55 ? 0.5 : 0.5 - (Dr - 0.55) * 1.5);
  p.phi_cv = or_default(given.phi_cv, 33.0);
  check(p.phi_cv > 0.0 && p.phi_cv < 90.0, "phicv: expected 0 < phicv < 90 degrees, got " + number_text(p.phi_cv));
  p.nu = or_default(given.nu, 0.3);
  check(p.nu <= 0.5, "nu: expected nu <= 0.5, got " + number_text(p.nu));
  if (p.nu == 0.5) p.nu = 0.4999;  // OpenSees' GetElasticModuli
  p.Cgd = or_default(given.Cgd, 2.0);
  p.Cdr = std::min(or_default(given.Cdr, 5.0 + 25.0 * (Dr - 0.35)), 10.0);
  p.Ckaf = std::clamp(or_default(given.Ckaf, 5.0 + 220.0 * std::pow(Dr - 0.26, 3)), 4.0, 35.0);
  p.Q = or_default(given.Q, 10.0);
  p.R = or_default(given.R, 1.5);
  p.m = or_default(given.m, 0.01);
  p.Fsed_min = std::min(or_default(given.Fsed_min, 0.03 * std::exp(2.6 * Dr)), 0.99);
  p.p_sedo = or_default(given.p_sedo, p.P_atm / 5.0);
  pm4::resolve_integration_options(p.scheme, p.tangent_type, p.tol_f, p.tol_r, 1e-8, 1e-8, where);
  return p;
}

// --- construction, copies -----------------------------------------------------------------------------------

// OpenSees' constructor and initialize(): zero stress, the moduli at p = P_atm, p_min = P_atm / 200 (and the
// dilatancy cut-off's 5 p_min until the first initialisation). PM4Sand.cpp's driver is pm4::Variant's default: the
// void ratio before the elastic check, RK4 as is.
PM4Sand::PM4Sand(int tag, const PM4SandParameters& given)
    : Material(tag, "PM4Sand", "G0", resolve_parameters(given, "nDMaterial PM4Sand " + std::to_string(tag)),
               pm4::Variant{}) {
  e_init_ = params_.emax - (params_.emax - params_.emin) * params_.Dr;
  p_min2_ = p_min_ * 5.0;
  start(e_init_);
}

// OpenSees getCopy: a new material from the current parameters (e0 again from Dr, PostShake off), fresh state.
std::unique_ptr<PM4Sand::Material> PM4Sand::fresh_copy() const { return std::make_unique<PM4Sand>(tag(), params_); }

// --- the model ----------------------------------------------------------------------------------------------

// The relative state parameter xi_R = Dr,cs - Dr with Bolton's critical-state relative density
// Dr,cs = R / (Q - ln(100 p / P_atm)) (manual section 2, "Critical state"), p not below p_min.
double PM4Sand::state_parameter(double Dr, double p) const {
  const double pn = p <= p_min_ ? p_min_ : p;
  return params_.R / (params_.Q - std::log(100.0 * pn / params_.P_atm)) - Dr;
}

// The elastic stage recomputes G0 P_atm and K from the committed stress (OpenSees' elastic_integrator, with the
// 3-argument GetElasticModuli: pm4::Material::plain_moduli).
void PM4Sand::elastic_stage_moduli(const Vector3& committed_stress, double& K, double& G) {
  plain_moduli(committed_stress, K, G);
}

// Manual section 2, "Elastic moduli": G = G0 P_atm sqrt(p / P_atm) C_SR (1 + z_cum / z_max) / (1 + C_GD z_cum / z_max),
// C_SR = 1 - C_SR,0 min(1, (M / Mb)^m_SR) with C_SR,0 = 0.5, m_SR = 4; reduced by F_sed during post-shaking
// reconsolidation ("Post-shaking reconsolidation"). Sets the current stress ratio M = q / p.
void PM4Sand::elastic_moduli(const Vector3& stress, double& K, double& G) {
  Carried& c = trial_.carried;
  const History& t = trial_.history;
  double pn = mean_stress(stress);
  if (pn <= p_min_) pn = p_min_;
  const double qn = 2.0 * std::sqrt(std::pow(0.5 * (stress[0] - stress[1]), 2) + std::pow(stress[2], 2));
  c.Mcur = qn / pn;
  const double c_sr = 1.0 - 0.5 * std::min(1.0, std::pow(c.Mcur / c.Mb, 4));
  const double z_ratio = t.z_cum / params_.z_max;
  if (stage_ == 0) {
    G = params_.G0 * params_.P_atm;
  } else {
    G = params_.G0 * params_.P_atm * std::sqrt(pn / params_.P_atm) * c_sr * (1.0 + z_ratio) / (1.0 + z_ratio * params_.Cgd);
    if (post_shake_) {
      const double p = mean_stress(stress);
      const double p_sed = params_.p_sedo * (t.z_cum / (t.z_cum + params_.z_max)) * std::pow(macaulay(1.0 - c.Mcur / c.Md), 0.25);
      const double f_sed = std::min(params_.Fsed_min + (1.0 - params_.Fsed_min) * (p / 20.0 / (p_sed + kSmall)), 1.0);
      G *= f_sed;
    }
  }
  K = pm4::bulk_modulus(G, params_.nu);
}

// The state-dependent surfaces, plastic modulus and dilatancy (OpenSees GetStateDependent; manual section 2):
//  - bounding and dilatancy ratios Mb = M exp(-nb xi), Md = M exp(nd xi) for xi <= 0; loose of critical
//    OpenSees uses exp(-nb xi / 4) and exp(4 nd xi) ("Bounding, dilatancy and critical state surfaces");
//  - image back-stress ratios alpha_b,d = sqrt(1/2) (M_b,d - m) n;
//  - plastic modulus Kp = 2/3 h p (alpha_b - alpha) : n with the hardening h of "Plastic modulus" (C_ka for
//    sustained static shear, the fabric terms C_zpk1,2 and C_pzp2, the memory of alpha_in and alpha_in_true);
//  - dilatancy D: dilation ("Dilatancy") with the rotated dilatancy surface M_d / C_rot1 and the fabric terms
//    C_zin1,2, C_pzp, C_pmin; contraction ("Contraction") with h_p, C_dz, C_in and the low-p cut-off C_pmin2;
//  - R = n + D / 3 I (plastic flow direction).
PM4Sand::Hardening PM4Sand::state_dependent(const Vector3& stress, const Vector3& alpha, const Vector3& fabric,
                                            double G, double void_ratio) {
  const double Dr = relative_density_at(void_ratio);
  Carried& c = trial_.carried;
  const History& t = trial_.history;
  const PM4SandParameters& P = params_;
  Hardening hd;
  double p = mean_stress(stress);
  if (p <= p_min_) p = p_min_;
  const double xi = state_parameter(Dr, p);
  hd.n = pm4::yield_normal(stress, alpha);
  const Vector3& n = hd.n;
  if (xi <= 0.0) {
    c.Mb = Mc_ * std::exp(-P.nb * xi);
    c.Md = Mc_ * std::exp(P.nd * xi);
  } else {
    c.Mb = Mc_ * std::exp(-P.nb / 4.0 * xi);
    c.Md = Mc_ * std::exp(P.nd * 4.0 * xi);
  }
  const Vector3 alpha_b = kRootHalf * (c.Mb - P.m) * n;
  hd.alpha_d = kRootHalf * (c.Md - P.m) * n;

  const double z_cum = t.z_cum, z_peak = t.z_peak, z_max = P.z_max;
  const double c_zpk1 = z_peak / (z_cum + z_max / 5.0);
  const double c_zpk2 = std::min(z_peak / (z_cum + z_max / 100.0), 1.0 - kSmall);
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
    if (contract(alpha - t.alpha_in_p, n) <= 0.0) hd.h *= (alpha_in_n + c_g1) / (alpha_in_true_n + c_g1);
  }
  hd.Kp = kTwoThirds * hd.h * p * b_n;

  const double z_n = contract(fabric, n);
  const double c_zin1 = macaulay(1.0 - std::exp(-2.0 * std::abs((contract(t.fabric_in, n) - z_n) / z_max)));
  const double c_rot1 = std::max(1.0 + 2.0 * macaulay(-z_n) / (std::sqrt(2.0) * z_max) * (1.0 - c_zin1), 1.0);
  const double M_dr = c.Md / c_rot1;
  const double to_rotated = contract(kRootHalf * (M_dr - P.m) * n - alpha, n);
  const double to_dilatancy = contract(hd.alpha_d - alpha, n);
  if (to_rotated <= 0.0) {  // dilation
    const double c_pzp = c.p_zp == 0.0 ? 1.0 : 1.0 / (1.0 + std::pow(2.5 * p / c.p_zp, 5.0));
    const double c_pmin = 1.0 / (1.0 + std::pow(p_min2_ / p, 2));
    const double c_zin2 = (1.0 + c_zin1 * (z_cum - z_peak) / 3.0 / z_max) / (1.0 + 3.0 * c_zin1 * (z_cum - z_peak) / 3.0 / z_max);
    const double fabric_term = std::pow(1.0 - macaulay(-z_n) * kRootHalf / z_peak, 3);
    const double A_d = P.Ado * c_zin2 /
                       ((z_cum * z_cum / z_max) * fabric_term * P.ce * P.ce * c_pzp * c_pmin * c_zin1 + 1.0);
    hd.D = A_d * to_dilatancy;
    const double D_rot = A_d * macaulay(-z_n) / (std::sqrt(2.0) * z_max) * to_rotated / P.Cdr;
    if (hd.D > D_rot) hd.D += (D_rot - hd.D) * macaulay(c.Mb - c.Mcur) / (macaulay(c.Mb - c.Mcur) + 0.01);
    if (p_min_ <= p && p <= 2.0 * p_min_) hd.D = std::min(hd.D, -3.5 * P.Ado * macaulay(c.Mb - c.Md) * (2.0 * p_min_ - p) / p_min_);
  } else {  // contraction
    hd.Kp = std::max(0.0, hd.Kp);  // OpenSees bounds Kp to >= 0 here, following FLAC
    const double h_p = P.hpo * std::exp(-0.7 + 7.0 * std::pow(macaulay(0.5 - xi), 2.0));
    const double c_rot2 = 1.0 - c_zpk2;
    const double c_dz = std::max((1.0 - c_rot2 * std::sqrt(2.0) * z_peak / z_max) * (z_max / (z_max + c_rot2 * z_cum)),
                                 1.0 / (1.0 + z_max / 2.0));
    const double A_dc = P.Ado * (1.0 + macaulay(z_n)) / h_p / c_dz;
    const double c_in = 2.0 * macaulay(z_n) / std::sqrt(2.0) / z_max;
    hd.D = std::min(A_dc * std::pow(contract(alpha - t.alpha_in, n) + c_in, 2), 1.5 * P.Ado) * to_dilatancy /
           (to_dilatancy + 0.16);
    double c_pmin2 = 1.0;
    if (p < 2.0 * p_min_) c_pmin2 = 0.0;
    else if (p < 18.0 * p_min_) c_pmin2 = (p - 2.0 * p_min_) / (16.0 * p_min_);
    hd.D *= c_pmin2;
  }
  hd.R = n + kOneThird * hd.D * identity();
  return hd;
}

// --- initialisation -------------------------------------------------------------------------------------------

// OpenSees' initialize(stress) (FirstCall, reset): p_min = max(p0, P_atm) / 200; the back-stress ratio set to the
// stress ratio, the fabric and the reversal memory cleared; Ado and z_max computed if still unset (manual section
// 4.1: z_max = min(0.7 exp(-6.1 xi0), 20); Ado from the peak and critical dilatancy angles,
// Ado = 2.5 (asin(Mb / 2) - asin(M / 2)) / (Mb - Md) dense of critical, 1.24 loose). A stress ratio beyond the
// outer of the bounding and dilatancy surfaces is scaled onto it, the difference kept as a stress offset (so the
// reported stress, hence the equilibrium, is unchanged); a p below p_min is raised to p_min the same way.
void PM4Sand::initialize(const Vector3& stress) {
  const Vector3 initial = stress;
  p_min_ = std::max(mean_stress(initial) / 200.0, params_.P_atm / 200.0);
  p_min2_ = p_min_ * 10.0;
  const double p0 = begin_initialization(initial, p_min_);
  Carried& c = trial_.carried;
  const double xi = state_parameter(params_.Dr, p0);
  if (params_.z_max < 0.0) params_.z_max = std::min(0.7 * std::exp(-6.1 * xi), 20.0);
  if (xi < 0.0) {
    c.Mb = Mc_ * std::exp(-params_.nb * xi);
    c.Md = Mc_ * std::exp(params_.nd * xi);
    if (params_.Ado < 0.0) {
      params_.Ado = c.Mb > 2.0 ? 1.5 : 2.5 * (std::asin(c.Mb / 2.0) - std::asin(Mc_ / 2.0)) / (c.Mb - c.Md);
    }
  } else {
    c.Mb = Mc_ * std::exp(-params_.nb / 4.0 * xi);
    c.Md = Mc_ * std::exp(params_.nd * 4.0 * xi);
    if (params_.Ado < 0.0) params_.Ado = 1.24;
  }
  cap_initial_stress_ratio(initial, p0);
  finish_initialization(p0, Vector3::Zero());  // alpha_in = 0
}

// --- JSON, the command ---------------------------------------------------------------------------------------

// PM4Sand's keys besides the shared ones (pm4::Material::to_json): OpenSees' argument names, and e0.
void PM4Sand::add_json(nlohmann::json& entry) const {
  const PM4SandParameters& p = params_;
  entry.update({{"Dr", p.Dr},
                {"G0", p.G0},
                {"hpo", p.hpo},
                {"emax", p.emax},
                {"emin", p.emin},
                {"nb", p.nb},
                {"Cdr", p.Cdr},
                {"Q", p.Q},
                {"R", p.R},
                {"m", p.m},
                {"Fsed_min", p.Fsed_min},
                {"p_sedo", p.p_sedo},
                {"e_init", e_init_}});
}

std::unique_ptr<NDMaterial> parse_pm4sand(common::CommandArgs& args) {
  PM4SandParameters p;
  const int tag = args.integer("tag");
  p.Dr = args.number("Dr");
  p.G0 = args.number("G0");
  p.hpo = args.number("hpo");
  p.density = args.number("Den");
  // The optional arguments in OpenSees' order.
  double scheme = -1.0, tangent_type = -1.0;
  const std::array<std::pair<const char*, double*>, 24> optional{{
      {"P_atm", &p.P_atm}, {"h0", &p.h0}, {"emax", &p.emax}, {"emin", &p.emin}, {"nb", &p.nb}, {"nd", &p.nd},
      {"Ado", &p.Ado}, {"z_max", &p.z_max}, {"cz", &p.cz}, {"ce", &p.ce}, {"phicv", &p.phi_cv}, {"nu", &p.nu},
      {"Cgd", &p.Cgd}, {"Cdr", &p.Cdr}, {"Ckaf", &p.Ckaf}, {"Q", &p.Q}, {"R", &p.R}, {"m", &p.m},
      {"Fsed_min", &p.Fsed_min}, {"p_sedo", &p.p_sedo}, {"IntScheme", &scheme}, {"TanType", &tangent_type},
      {"TolF", &p.tol_f}, {"TolR", &p.tol_r}}};
  pm4::read_optional_arguments(args, optional);
  p.scheme = pm4::whole_argument(args, scheme, "IntScheme");
  p.tangent_type = pm4::whole_argument(args, tangent_type, "TanType");
  return std::make_unique<PM4Sand>(tag, p);
}

}  // namespace fem::materials
