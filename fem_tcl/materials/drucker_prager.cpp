#include "fem_tcl/materials/drucker_prager.hpp"

#include <Eigen/LU>
#include <cmath>
#include <iostream>
#include <string>

#include "common/number_text.hpp"

namespace fem::materials {
namespace {

constexpr double kOneThird = 1.0 / 3.0;
constexpr double kTwoThirds = 2.0 / 3.0;
const double kRoot23 = std::sqrt(2.0 / 3.0);

using Vector6d = DruckerPrager::Vector6d;
using Matrix6d = DruckerPrager::Matrix6d;

/// Second-order identity in Voigt form.
Vector6d identity2() {
  Vector6d one = Vector6d::Zero();
  one.head<3>().setOnes();
  return one;
}

/// 1 (x) 1 in Voigt form.
Matrix6d volumetric4() {
  Matrix6d m = Matrix6d::Zero();
  m.topLeftCorner<3, 3>().setOnes();
  return m;
}

/// Deviatoric projector, contravariant form (s = 2G IIdev eps with engineering shear strains): 1/2 on shears.
Matrix6d deviatoric4() {
  Matrix6d m = Matrix6d::Zero();
  m.topLeftCorner<3, 3>().setConstant(-kOneThird);
  m.diagonal().head<3>().setConstant(kTwoThirds);
  m.diagonal().tail<3>().setConstant(0.5);
  return m;
}

/// Norm of a stress-like tensor stored in Voigt form (weight 2 on the shears).
double stress_norm(const Vector6d& t) {
  return std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2] + 2.0 * (t[3] * t[3] + t[4] * t[4] + t[5] * t[5]));
}

/// Norm of a strain-like tensor with engineering shears (weight 1/2 on the shears), as OpenSees' state.
double strain_norm(const Vector6d& e) {
  return std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2] + 0.5 * (e[3] * e[3] + e[4] * e[4] + e[5] * e[5]));
}

void require_finite(int tag, const char* name, double v) {
  if (!std::isfinite(v))
    throw common::InputError("nDMaterial DruckerPrager " + std::to_string(tag),
                             std::string("expected a finite ") + name + ", got " + std::to_string(v));
}

}  // namespace

DruckerPrager::DruckerPrager(int tag, const DruckerPragerParameters& params)
    : NDMaterial(tag), params_(params), k_ref_(params.bulk_modulus), g_ref_(params.shear_modulus),
      k_(params.bulk_modulus), g_(params.shear_modulus) {
  const std::string where = "nDMaterial DruckerPrager " + std::to_string(tag);
  const double values[] = {params.bulk_modulus, params.shear_modulus, params.sigma_y, params.rho, params.rho_bar,
                           params.k_inf, params.k_o, params.delta1, params.delta2, params.hardening,
                           params.theta, params.density, params.p_atm};
  const char* names[] = {"K", "G", "sigma_y", "rho", "rho_bar", "Kinf", "Ko", "delta1", "delta2", "H", "theta",
                         "density", "atm"};
  for (int i = 0; i < 13; ++i) require_finite(tag, names[i], values[i]);
  if (!(params.bulk_modulus > 0.0)) throw common::InputError(where, "expected K > 0, got " + std::to_string(params.bulk_modulus));
  if (!(params.shear_modulus > 0.0)) throw common::InputError(where, "expected G > 0, got " + std::to_string(params.shear_modulus));
  if (!(params.density >= 0.0)) throw common::InputError(where, "expected density >= 0, got " + std::to_string(params.density));
  // OpenSees' manual: 0 <= theta <= 1, the share of isotropic hardening in H (the rest kinematic); outside
  // it the hardening moduli change sign and the return gives NaN (found by fuzzing: theta 1e308).
  if (!(params.theta >= 0.0 && params.theta <= 1.0))
    throw common::InputError(where, "expected 0 <= theta <= 1 (the isotropic share of the hardening), got " +
                                        common::number_text(params.theta, 6));
  update_tension_strength();
  initialize();
}

void DruckerPrager::update_tension_strength() {
  // T0 = sqrt(2/3) sigma_y / rho: the cone's apex in I1 (OpenSees uses 1e10 when rho = 0).
  t0_ = params_.rho == 0.0 ? 1e10 : kRoot23 * params_.sigma_y / params_.rho;
}

void DruckerPrager::initialize() {
  eps_.setZero();
  eps_p_n_.setZero();
  eps_p_n1_.setZero();
  sigma_.setZero();
  beta_n_.setZero();
  beta_n1_.setZero();
  alpha1_n_ = alpha1_n1_ = alpha2_n_ = alpha2_n1_ = 0.0;
  modulus_flag_ = true;
  h_prime_ = (1.0 - params_.theta) * params_.hardening;
  ce_ = k_ * volumetric4() + 2.0 * g_ * deviatoric4();
  cep_ = ce_;
  state_.setZero();
  condense();
}

std::unique_ptr<NDMaterial> DruckerPrager::copy_for(PlaneType plane) const {
  if (plane != PlaneType::PlaneStrain)
    throw common::InputError("nDMaterial DruckerPrager " + std::to_string(tag()),
                             "plane stress is not supported (OpenSees' DruckerPrager has PlaneStrain and 3D copies)");
  auto copy = std::make_unique<DruckerPrager>(tag(), params_);
  // OpenSees' getCopy constructs a new DruckerPragerPlaneStrain from the current mK, mG, rho, ...: the copy
  // starts in the start state and in materialState 2, whatever the original's state.
  copy->k_ = copy->k_ref_ = k_;
  copy->g_ = copy->g_ref_ = g_;
  copy->initialize();
  return copy;
}

double DruckerPrager::k_iso(double alpha1) const {
  return params_.sigma_y + params_.theta * params_.hardening * alpha1 +
         (params_.k_inf - params_.k_o) * (1.0 - std::exp(-params_.delta1 * alpha1));
}

double DruckerPrager::k_iso_prime(double alpha1) const {
  return params_.theta * params_.hardening + (params_.k_inf - params_.k_o) * params_.delta1 * std::exp(-params_.delta1 * alpha1);
}

double DruckerPrager::tension_strength(double alpha2) const { return t0_ * std::exp(-params_.delta2 * alpha2); }

void DruckerPrager::update_elastic_parameters() {
  // materialState 1: K and G scale with sqrt(1 + p / p_atm), p the mean pressure (compression positive,
  // floored at 0) of the stress at hand; done once per switch into state 1 (OpenSees' mFlag).
  if (elastic_flag_ == 1 && modulus_flag_) {
    double mean_pressure = -kOneThird * (sigma_[0] + sigma_[1] + sigma_[2]);
    if (mean_pressure < 0.0) mean_pressure = 0.0;
    const double factor = std::pow(1.0 + mean_pressure / params_.p_atm, 0.5);
    k_ = k_ref_ * factor;
    g_ = g_ref_ * factor;
    ce_ = k_ * volumetric4() + 2.0 * g_ * deviatoric4();
    modulus_flag_ = false;
  } else if (elastic_flag_ != 1) {
    modulus_flag_ = true;
  }
}

void DruckerPrager::set_trial_strain(const Vector3& strain) {
  // Plane strain: ezz = gyz = gxz = 0 (DruckerPragerPlaneStrain::setTrialStrain).
  eps_.setZero();
  eps_[0] = strain[0];
  eps_[1] = strain[1];
  eps_[3] = strain[2];
  integrate();
  condense();
}

void DruckerPrager::condense() {
  static constexpr int idx[3] = {0, 1, 3};
  for (int i = 0; i < 3; ++i) {
    strain2d_[i] = eps_[idx[i]];
    stress2d_[i] = sigma_[idx[i]];
    for (int j = 0; j < 3; ++j) tangent2d_(i, j) = cep_(idx[i], idx[j]);
  }
}

void DruckerPrager::integrate() {
  const Vector6d one = identity2();
  const double rho = params_.rho, rho_bar = params_.rho_bar, delta2 = params_.delta2;

  // Trial state: plastic strain, hardening variables and back stress frozen at their committed values.
  eps_p_n1_ = eps_p_n_;
  alpha1_n1_ = alpha1_n_;
  alpha2_n1_ = alpha2_n_;
  beta_n1_ = beta_n_;
  sigma_ = ce_ * (eps_ - eps_p_n1_);
  double i1 = sigma_[0] + sigma_[1] + sigma_[2];
  Vector6d s = sigma_ - (i1 / 3.0) * one;
  Vector6d eta = s - beta_n_;
  double norm_eta = stress_norm(eta);
  double f1 = norm_eta + rho * i1 - kRoot23 * k_iso(alpha1_n1_);
  double f2 = i1 - tension_strength(alpha2_n1_);

  update_elastic_parameters();

  const auto set_state = [&](double invariant_1, double eta_norm) {
    const double trace_ep = eps_p_n1_[0] + eps_p_n1_[1] + eps_p_n1_[2];
    const Vector6d dev_ep = eps_p_n1_ - kOneThird * trace_ep * one;
    state_ << invariant_1, eta_norm, trace_ep, strain_norm(dev_ep), strain_norm(eps_p_n1_);
  };

  constexpr double f_tol = 0.0;
  constexpr double g_tol = -1.0e-10;
  if ((f1 <= f_tol && f2 <= f_tol) || elastic_flag_ < 2) {
    cep_ = ce_;
    set_state(i1, norm_eta);
    return;
  }

  // Active surfaces: cone (0) and tension cutoff (1).
  bool active[2] = {f1 > f_tol, f2 > f_tol};
  bool okay = false;
  int count = 1;
  double alpha1 = alpha1_n_, alpha2 = alpha2_n_;
  Vector6d n = Vector6d::Zero();
  Eigen::Vector2d gamma = Eigen::Vector2d::Zero();
  Eigen::Matrix2d g_inv = Eigen::Matrix2d::Identity();

  // Residual and Jacobian of the return (OpenSees' R and g). The tension row is never assembled: OpenSees
  // tests Jact(i) == 2 for it, which never holds (README quirk 12), so R(1) = 0 and g(1,1) = 1.
  const auto assemble = [&](Eigen::Vector2d& r, Eigen::Matrix2d& g) {
    g = Eigen::Matrix2d::Identity();
    r.setZero();
    if (active[0] || active[1]) {
      r[0] = norm_eta - (2.0 * g_ + kTwoThirds * h_prime_) * gamma[0] + rho * i1 - 9.0 * k_ * rho * rho_bar * gamma[0] -
             9.0 * k_ * rho * gamma[1] - kRoot23 * k_iso(alpha1);
      g(0, 0) = -2.0 * g_ - kTwoThirds * (h_prime_ + k_iso_prime(alpha1)) - 9.0 * k_ * rho * rho_bar;
    }
    if (active[0] && active[1]) {
      g(0, 1) = -9.0 * k_ * rho;
      g(1, 0) = rho_bar * (-9.0 * k_ + delta2 * tension_strength(alpha2));
    }
  };

  while (!okay) {
    alpha1 = alpha1_n_;
    alpha2 = alpha2_n_;
    n = norm_eta < 1.0e-13 ? Vector6d::Zero() : Vector6d(eta / norm_eta);
    gamma.setZero();
    Eigen::Vector2d r;
    Eigen::Matrix2d g;
    assemble(r, g);
    g_inv = g.inverse();
    // Newton iterations on the consistency parameters (at most 10, |R| <= 1e-10).
    for (int m = 0; r.norm() > 1e-10 && m < 10; ++m) {
      gamma -= g_inv * r;
      alpha1 = alpha1_n_ + kRoot23 * gamma[0];
      alpha2 = alpha2_n_ + rho_bar * gamma[0] + gamma[1];
      assemble(r, g);
      g_inv = g.inverse();
    }
    f1 = norm_eta - (2.0 * g_ + kTwoThirds * h_prime_) * gamma[0] + rho * i1 - 9.0 * k_ * rho * rho_bar * gamma[0] -
         9.0 * k_ * rho * gamma[1] - kRoot23 * k_iso(alpha1);
    f2 = i1 - 9.0 * k_ * rho_bar * gamma[0] - 9.0 * k_ * gamma[1] - tension_strength(alpha2);
    (void)f1;
    if (count > 100) break;

    // Kuhn-Tucker checks of the active set (OpenSees' order and tolerances).
    if (active[0] && !active[1]) {
      if (f2 >= f_tol) {
        active[1] = true;
        ++count;
      } else {
        okay = true;
      }
    } else if (!active[0] && active[1]) {
      okay = true;
    } else {
      if (gamma[0] <= g_tol && gamma[1] > g_tol) {
        active[0] = false;
        ++count;
      } else if (gamma[0] > g_tol && gamma[1] <= g_tol) {
        active[1] = false;
        ++count;
      } else {
        // Both multipliers positive: done. (Both non-positive would make OpenSees loop forever; accept.)
        okay = true;
      }
    }
    if (count > 3 && !okay) {
      active[0] = active[1] = true;
      count += 100;
    }
    if (count > 3)
      std::cerr << "DruckerPrager " << tag() << ": Jact = (" << active[0] << ", " << active[1] << ") count = " << count
                << "\n";
  }

  // Update the state with the converged multipliers.
  alpha1_n1_ = alpha1;
  alpha2_n1_ = alpha2;
  Vector6d n_covariant = n;
  n_covariant.tail<3>() *= 2.0;
  eps_p_n1_ = eps_p_n_ + (rho_bar * gamma[0] + gamma[1]) * one + gamma[0] * n_covariant;
  sigma_ -= (3.0 * k_ * rho_bar * gamma[0] + 3.0 * k_ * gamma[1]) * one + 2.0 * g_ * gamma[0] * n;
  s -= 2.0 * g_ * gamma[0] * n;
  i1 -= 9.0 * k_ * rho_bar * gamma[0] + 9.0 * k_ * gamma[1];
  beta_n1_ = beta_n_ - (kTwoThirds * h_prime_ * gamma[0]) * n;
  eta = s - beta_n1_;
  norm_eta = stress_norm(eta);

  // Algorithmic tangent as OpenSees 3.8 builds it (README quirk 12: the last term uses the post-return norm).
  Vector6d b1 = Vector6d::Zero(), b2 = Vector6d::Zero();
  if (active[0]) b1 = 2.0 * g_ * n + 3.0 * k_ * rho * one;
  if (active[1]) b2 = 3.0 * k_ * one;
  const Vector6d temp1 = g_inv(0, 0) * b1 + g_inv(0, 1) * b2;
  const Vector6d temp2 = rho_bar * temp1 + g_inv(1, 0) * b1 + g_inv(1, 1) * b2;
  cep_ = ce_ + 3.0 * k_ * one * temp2.transpose() + 2.0 * g_ * n * temp1.transpose();
  // OpenSees divides by norm_eta unguarded; at an exact apex (norm 0) it would produce inf/NaN: skip the term.
  if (norm_eta > 0.0) cep_ -= (4.0 * g_ * g_ / norm_eta * gamma[0]) * (deviatoric4() - n * n.transpose());
  if (cep_.squaredNorm() < 1e-10) {
    std::cerr << "DruckerPrager " << tag() << ": NormCep = " << cep_.squaredNorm() << "\n";
    cep_ = 1.0e-3 * ce_;
  }
  set_state(i1, norm_eta);
}

void DruckerPrager::commit_state() {
  eps_p_n_ = eps_p_n1_;
  alpha1_n_ = alpha1_n1_;
  alpha2_n_ = alpha2_n1_;
  beta_n_ = beta_n1_;
}

void DruckerPrager::revert_to_start() { initialize(); }

void DruckerPrager::set_strength_reduction(double factor) {
  const std::string where = "nDMaterial DruckerPrager " + std::to_string(tag());
  if (!(factor > 0.0) || !std::isfinite(factor)) {
    throw common::InputError(where, "expected a strength reduction factor > 0, got " + std::to_string(factor));
  }
  // Reductions compose (tan phi / F1 / F2 = tan phi / (F1 F2)), so the step from the factor in force is applied.
  const double step = factor / strength_factor_;
  const auto tan_of = [&](double rho, const char* name) {
    const double a = rho / std::sqrt(2.0);
    if (!(12.0 * a * a < 1.0)) {
      throw common::InputError(where, std::string("cannot reduce its strength: ") + name + " = " + std::to_string(rho) +
                                          " >= 1/sqrt(6) has no plane-strain Mohr-Coulomb friction angle");
    }
    return 3.0 * a / std::sqrt(1.0 - 12.0 * a * a);
  };
  const auto rho_of = [](double t) { return std::sqrt(2.0) * t / std::sqrt(9.0 + 12.0 * t * t); };
  const double t = tan_of(params_.rho, "rho"), t_bar = tan_of(params_.rho_bar, "rho_bar");
  const double reduced = t / step;
  const double cohesion_scale = std::sqrt(9.0 + 12.0 * t * t) / std::sqrt(9.0 + 12.0 * reduced * reduced) / step;
  params_.rho = rho_of(reduced);
  params_.rho_bar = rho_of(t_bar / step);
  params_.sigma_y *= cohesion_scale;
  params_.k_inf *= cohesion_scale;
  params_.k_o *= cohesion_scale;
  params_.hardening *= cohesion_scale;
  h_prime_ = (1.0 - params_.theta) * params_.hardening;
  update_tension_strength();
  strength_factor_ = factor;
}

bool DruckerPrager::set_parameter(std::string_view name, double value) {
  if (name == "materialState") {
    elastic_flag_ = static_cast<int>(value);
  } else if (name == "frictionalStrength") {
    params_.rho = value;
    update_tension_strength();
  } else if (name == "nonassociativeTerm") {
    params_.rho_bar = value;
  } else if (name == "cohesiveIntercept") {
    params_.sigma_y = value;
    update_tension_strength();
  } else if (name == "shearModulus") {
    g_ = value;
    ce_ = k_ * volumetric4() + 2.0 * g_ * deviatoric4();
  } else if (name == "bulkModulus") {
    k_ = value;
    ce_ = k_ * volumetric4() + 2.0 * g_ * deviatoric4();
  } else {
    return false;
  }
  return true;
}

std::optional<std::vector<double>> DruckerPrager::response(std::string_view name) const {
  if (name == "state") return std::vector<double>(state_.data(), state_.data() + 5);
  return NDMaterial::response(name);
}

nlohmann::json DruckerPrager::to_json() const {
  // OpenSees 3.8 prints a bare word here (invalid JSON); this is valid JSON with the command's parameter names.
  return nlohmann::json{{"name", std::to_string(tag())},
                        {"type", "DruckerPrager"},
                        {"K", k_},
                        {"G", g_},
                        {"sigma_y", params_.sigma_y},
                        {"rho", params_.rho},
                        {"rho_bar", params_.rho_bar},
                        {"Kinf", params_.k_inf},
                        {"Ko", params_.k_o},
                        {"delta1", params_.delta1},
                        {"delta2", params_.delta2},
                        {"H", params_.hardening},
                        {"theta", params_.theta},
                        {"density", params_.density},
                        {"atm", params_.p_atm},
                        {"materialState", elastic_flag_}};
}

std::unique_ptr<NDMaterial> parse_drucker_prager(common::CommandArgs& args) {
  const int tag = args.integer("tag");
  DruckerPragerParameters p{};
  p.bulk_modulus = args.number("K");
  p.shear_modulus = args.number("G");
  p.sigma_y = args.number("sigma_y");
  p.rho = args.number("rho");
  p.rho_bar = args.number("rho_bar");
  p.k_inf = args.number("Kinf");
  p.k_o = args.number("Ko");
  p.delta1 = args.number("delta1");
  p.delta2 = args.number("delta2");
  p.hardening = args.number("H");
  p.theta = args.number("theta");
  if (!args.empty()) p.density = args.number("density");
  if (!args.empty()) p.p_atm = args.number("atm");
  args.expect_end();
  return std::make_unique<DruckerPrager>(tag, p);
}

}  // namespace fem::materials
