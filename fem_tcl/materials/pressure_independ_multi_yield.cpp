#include "fem_tcl/materials/pressure_independ_multi_yield.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>

#include "common/input_error.hpp"

namespace fem::materials {

namespace {

using multi_yield::contract;
using multi_yield::deviator;
using multi_yield::kDegree;
using multi_yield::mises;
using multi_yield::strain_tensor;
using multi_yield::with_mean;
double mean_stress(const Vector6& t) { return multi_yield::mean(t); }

/// The pressure-independent model's surfaces are stresses: a cone height of 1 (multi_yield_surfaces.hpp).
constexpr double kFlat = 1.0;

}  // namespace

PressureIndependMultiYield::PressureIndependMultiYield(int tag, const PressureIndependMultiYieldParameters& params)
    : NDMaterial(tag), params_(params) {
  const std::string where = "nDMaterial PressureIndependMultiYield " + std::to_string(tag);
  const auto check = [&](bool ok, const std::string& what) {
    if (!ok) throw common::InputError(where, what);
  };
  auto& p = params_;
  check(p.shear_modulus > 0.0, "expected refShearModul > 0, got " + std::to_string(p.shear_modulus));
  check(p.bulk_modulus > 0.0, "expected refBulkModul > 0, got " + std::to_string(p.bulk_modulus));
  check(p.peak_shear_strain > 0.0, "expected peakShearStra > 0, got " + std::to_string(p.peak_shear_strain));
  check(p.ref_pressure > 0.0, "expected refPress > 0, got " + std::to_string(p.ref_pressure));
  check(p.density >= 0.0, "expected rho >= 0, got " + std::to_string(p.density));
  check(p.friction_deg < 90.0, "expected frictionAng < 90, got " + std::to_string(p.friction_deg));
  // OpenSees' quiet corrections, with its warnings.
  const auto warn = [&](const std::string& what) { std::cerr << "WARNING " << where << ": " << what << "\n"; };
  if (p.friction_deg < 0.0) { warn("frictionAng < 0, set to 0"); p.friction_deg = 0.0; }
  check(p.friction_deg > 0.0 || p.cohesion > 0.0, "expected cohesi > 0 when frictionAng = 0");
  if (p.cohesion < 0.0) { warn("cohesi < 0, set to 0"); p.cohesion = 0.0; }
  if (p.pressure_exponent < 0.0) { warn("pressDependCoe < 0, set to 0"); p.pressure_exponent = 0.0; }
  if (p.pressure_exponent > 0.0 && p.friction_deg == 0.0) { warn("pressDependCoe > 0 with frictionAng = 0, set to 0"); p.pressure_exponent = 0.0; }
  if (p.backbone.empty()) {
    if (p.surfaces <= 0) { warn("noYieldSurf <= 0, 10 surfaces used"); p.surfaces = 10; }
    if (p.surfaces > 100) { warn("noYieldSurf > 100, 100 surfaces used"); p.surfaces = 100; }
  } else {
    check(p.surfaces >= 2 && p.backbone.size() == 2 * static_cast<std::size_t>(p.surfaces),
          "expected 2 x |noYieldSurf| backbone values (shear strain, G / Gmax) for at least 2 surfaces");
  }
  defined_ = p;
  set_up_surfaces();
  committed_.shear_modulus = p.shear_modulus;
  committed_.bulk_modulus = p.bulk_modulus;
  trial_ = committed_;
  tangent_ = plane_strain_elastic_matrix(p.bulk_modulus, p.shear_modulus);
}

// The surfaces of the reference state (OpenSees setUpSurfaces): sizes M_m and plastic moduli H_m from the
// backbone. Between surfaces m and m+1 the elasto-plastic modulus 2 d tau / d gamma = 2 G H / (2 G + H) of
// the segment gives H = 2 G Hep / (2 G - Hep); the last (failure) surface has H = 0.
void PressureIndependMultiYield::set_up_surfaces() {
  params_ = defined_;  // reduced by the factor of a strength reduction (reducible_strength.hpp)
  auto& p = params_;
  p.cohesion /= strength_factor_;
  p.friction_deg = std::atan(std::tan(p.friction_deg * kDegree) / strength_factor_) / kDegree;
  for (std::size_t i = 1; i < p.backbone.size(); i += 2) p.backbone[i] /= strength_factor_;
  const std::string where = "nDMaterial PressureIndependMultiYield " + std::to_string(tag());
  const double G = p.shear_modulus, pref = -p.ref_pressure;  // compression negative, as OpenSees stores it
  const int n = p.surfaces;
  std::vector<Surface> s;
  if (p.backbone.empty()) {
    double peak = 0.0, cone = 1.0;
    residual_pressure_ = 0.0;
    if (p.friction_deg > 0.0) {
      const double sin_phi = std::sin(p.friction_deg * kDegree);
      const double m_nys = 6.0 * sin_phi / (3.0 - sin_phi);
      residual_pressure_ = 3.0 * p.cohesion / (std::sqrt(2.0) * m_nys);
      cone = -(pref - residual_pressure_);
      peak = std::sqrt(2.0) * cone * m_nys / 3.0;
    } else {
      peak = 2.0 * std::sqrt(2.0) * p.cohesion / 3.0;
    }
    const multi_yield::HyperbolicBackbone backbone(G, peak, p.peak_shear_strain, where);
    s = multi_yield::hyperbolic_surfaces(backbone, peak, n, p.friction_deg > 0.0 ? cone : 1.0);
  } else {
    const auto& g = p.backbone;
    multi_yield::validate_user_points(g, where);
    const double tmax = G * g[2 * (n - 1)] * g[2 * (n - 1) + 1];
    double cone = 1.0;
    residual_pressure_ = 0.0;
    if (p.friction_deg > 0.0) {  // the friction angle that carries tmax at pref with the given cohesion
      const double m_nys = -(std::sqrt(3.0) * tmax - 2.0 * p.cohesion) / pref;
      if (m_nys <= 0.0) {
        p.cohesion = std::sqrt(3.0) / 2.0 * tmax;
        p.friction_deg = 0.0;
      } else {
        const double sin_phi = 3.0 * m_nys / (6.0 + m_nys);
        if (sin_phi < 0.0 || sin_phi > 1.0)
          throw common::InputError(where, "invalid friction angle from the backbone: change refPress or the G/Gmax curve");
        residual_pressure_ = std::max(2.0 * p.cohesion / m_nys, 0.01 * pref);
        cone = -(pref - residual_pressure_);
        p.friction_deg = std::asin(sin_phi) / kDegree;
      }
    } else {
      p.cohesion = std::sqrt(3.0) / 2.0 * tmax;
    }
    if (p.friction_deg == 0.0) p.pressure_exponent = 0.0;
    s = multi_yield::user_surfaces(G, g, cone, where);
  }
  committed_.surfaces = multi_yield::MultiYieldSurfaces(std::move(s), multi_yield::Translation::Strict);
}

std::unique_ptr<NDMaterial> PressureIndependMultiYield::copy_for(PlaneType plane) const {
  if (plane != PlaneType::PlaneStrain)
    throw common::InputError("nDMaterial PressureIndependMultiYield " + std::to_string(tag()),
                             "has no plane-stress form (plane strain only, as OpenSees)");
  auto copy = std::make_unique<PressureIndependMultiYield>(*this);
  copy->revert_to_start();
  return copy;
}

Matrix3 PressureIndependMultiYield::initial_tangent() const {
  return plane_strain_elastic_matrix(trial_.bulk_modulus, trial_.shear_modulus);
}

// --- the switch to plasticity (OpenSees elast2Plast, paramScaling, initSurfaceUpdate) -----------------

void PressureIndependMultiYield::start_plastic(State& s) const {
  s.plastic_started = true;
  if (mean_stress(s.stress) > 0.0 && params_.friction_deg > 0.0) s.stress = deviator(s.stress);  // no tension
  scale_to_confinement(s, true);
  place_surfaces(s);
}

// The active surface is the outermost one the stress lies beyond; surfaces 1..active are centred so that the
// stress lies on them. Beyond the failure surface the stress is brought onto it.
void PressureIndependMultiYield::place_surfaces(State& s) const {
  Vector6 dev = deviator(s.stress);
  if (s.surfaces.place(dev, kFlat)) s.stress = with_mean(dev, mean_stress(s.stress));
  s.surfaces.centre_on(deviator(s.stress), kFlat);
}

void PressureIndependMultiYield::scale_to_confinement(State& s, bool moduli) const {
  if (params_.friction_deg == 0.0) return;
  const double height = -(mean_stress(s.stress) - residual_pressure_);
  const double scale = std::pow(-height / (-params_.ref_pressure - residual_pressure_), params_.pressure_exponent);
  if (moduli) {
    s.shear_modulus *= scale;
    s.bulk_modulus *= scale;
  }
  for (int m = 1; m <= s.surfaces.count(); ++m) {
    s.surfaces[m] = Surface{Vector6::Zero(), s.surfaces[m].size * height, s.surfaces[m].modulus * scale};
  }
}

void PressureIndependMultiYield::set_strength_reduction(double factor) {
  if (!(factor > 0.0) || !std::isfinite(factor))
    throw common::InputError("nDMaterial PressureIndependMultiYield " + std::to_string(tag()),
                             "expected a strength reduction factor > 0, got " + std::to_string(factor));
  strength_factor_ = factor;
  set_up_surfaces();  // the reference surfaces of the reduced strength
  if (committed_.plastic_started) {
    scale_to_confinement(committed_, false);
    place_surfaces(committed_);
  }
  revert_to_last_commit();
}

// --- the stress update ------------------------------------------------------------------------------

void PressureIndependMultiYield::set_trial_strain(const Vector3& strain) {
  if (stage_ == 1 && !committed_.plastic_started) start_plastic(committed_);  // OpenSees does it to its committed state
  trial_ = committed_;
  trial_.strain = strain;
  const Vector6 de = strain_tensor(strain - committed_.strain);
  if (stage_ != 1) {
    const double G = trial_.shear_modulus, K = trial_.bulk_modulus;
    trial_.stress = committed_.stress + 2.0 * G * deviator(de);
    trial_.stress.head<3>().array() += K * (de[0] + de[1] + de[2]);
  } else {
    plastic_update(de);
  }
  stress_ << trial_.stress[0], trial_.stress[1], trial_.stress[3];
  form_tangent();
}

void PressureIndependMultiYield::plastic_update(const Vector6& de) {
  const double G = trial_.shear_modulus;
  auto& surfaces = trial_.surfaces;
  const Vector6 committed_dev = deviator(committed_.stress);
  const Vector6 de_dev = deviator(de);
  // Load reversal: the increment points inside the active surface; the inner surfaces are re-centred so
  // they touch at the committed stress (Mroz), and the point is elastic again.
  if (surfaces.active() > 0) {
    const Surface& a = surfaces[surfaces.active()];
    const Vector6 normal = committed_dev - a.center;
    const double length = std::sqrt(contract(normal, normal));
    if (length > 0.0 && contract(2.0 * G * de_dev, normal) / length < 0.0) {
      surfaces.recentre_inner(committed_dev, kFlat);
      surfaces.set_active(0);
    }
  }
  const int substeps = de.isZero(0.0) ? 0 : surfaces.substeps(de_dev, G, 1.0, kFlat);
  // The trial deviator returned onto the active surface along its normal at the contact point, with the
  // plastic modulus of that surface (OpenSees stressCorrection, getLoadingFunc).
  const auto flow = [&](multi_yield::StressPoint& trial, bool crossed) {
    const int k = surfaces.active();
    const Surface& a = surfaces[k];
    const Vector6 contact = surfaces.contact_point(trial.dev, kFlat);
    const Vector6 normal = (contact - a.center) / std::sqrt(contract(contact - a.center, contact - a.center));
    double loading = contract(normal, trial.dev - contact) / (2.0 * G + a.modulus);
    if (crossed) {
      const double inner = surfaces[k - 1].modulus;
      loading *= (inner - a.modulus) / inner;
    }
    trial.dev = deviator(trial.dev - 2.0 * G * loading * normal);
  };
  multi_yield::StressPoint trial{committed_dev, 0.0};
  surfaces.integrate(
      substeps, trial, multi_yield::Cone{},
      [&](int, multi_yield::StressPoint& t) { t.dev += 2.0 * G * de_dev / substeps; }, flow,
      [](int, multi_yield::StressPoint&) {});
  const double p = mean_stress(committed_.stress) + trial_.bulk_modulus * (de[0] + de[1] + de[2]);
  trial_.stress = with_mean(trial.dev, p);
}

// OpenSees' tangent: elastic, less 6 G^2 / ((2 G + H) M^2) (s - a) (s - a)^T on the active surface.
void PressureIndependMultiYield::form_tangent() {
  const double G = trial_.shear_modulus;
  tangent_ = plane_strain_elastic_matrix(trial_.bulk_modulus, G);
  if (stage_ != 1 || trial_.surfaces.active() == 0) return;
  const Surface& a = trial_.surfaces[trial_.surfaces.active()];
  const Vector6 rel = deviator(trial_.stress) - a.center;
  const Eigen::Vector3d r(rel[0], rel[1], rel[3]);
  tangent_ -= 6.0 * G * G / (2.0 * G + a.modulus) / (a.size * a.size) * (r * r.transpose());
}

void PressureIndependMultiYield::revert_to_last_commit() {
  trial_ = committed_;
  stress_ << trial_.stress[0], trial_.stress[1], trial_.stress[3];
  form_tangent();
}

void PressureIndependMultiYield::revert_to_start() {
  set_up_surfaces();
  committed_.strain.setZero();
  committed_.stress.setZero();
  committed_.shear_modulus = params_.shear_modulus;
  committed_.bulk_modulus = params_.bulk_modulus;
  committed_.plastic_started = false;
  revert_to_last_commit();
}

bool PressureIndependMultiYield::update_stage(int stage) {
  if (stage != 0 && stage != 1)
    throw common::InputError("updateMaterialStage -material " + std::to_string(tag()),
                             "PressureIndependMultiYield stages are 0 (elastic) and 1 (plastic), got " + std::to_string(stage));
  stage_ = stage;
  return true;
}

bool PressureIndependMultiYield::set_parameter(std::string_view name, double value) {
  if (name == "updateMaterialStage" || name == "materialState") return update_stage(static_cast<int>(value));
  if (name == "shearModulus") {
    committed_.shear_modulus = trial_.shear_modulus = value;
  } else if (name == "bulkModulus") {
    committed_.bulk_modulus = trial_.bulk_modulus = value;
  } else {
    return false;
  }
  form_tangent();
  return true;
}

std::optional<std::vector<double>> PressureIndependMultiYield::response(std::string_view name) const {
  if (name == "stress" || name == "stresses") {
    const Vector6& s = trial_.stress;
    const double failure = trial_.surfaces[params_.surfaces].size;
    const double ratio = stage_ == 1 ? mises(deviator(s)) / failure : 0.0;
    return std::vector<double>{s[0], s[1], s[2], s[3], ratio};
  }
  return NDMaterial::response(name);
}

nlohmann::json PressureIndependMultiYield::to_json() const {
  const auto& p = defined_;
  return nlohmann::json{{"name", std::to_string(tag())},
                        {"type", "PressureIndependMultiYield"},
                        {"rho", p.density},
                        {"refShearModul", p.shear_modulus},
                        {"refBulkModul", p.bulk_modulus},
                        {"cohesi", p.cohesion},
                        {"peakShearStra", p.peak_shear_strain},
                        {"frictionAng", p.friction_deg},
                        {"refPress", p.ref_pressure},
                        {"pressDependCoe", p.pressure_exponent},
                        {"noYieldSurf", p.surfaces}};
}

std::unique_ptr<NDMaterial> parse_pressure_independ_multi_yield(common::CommandArgs& args) {
  const int tag = args.integer("tag");
  const int nd = args.integer("nd");
  if (nd != 2) args.fail("fem_tcl builds 2D models: expected nd = 2, got " + std::to_string(nd));
  PressureIndependMultiYieldParameters p;
  p.density = args.number("rho");
  p.shear_modulus = args.number("refShearModul");
  p.bulk_modulus = args.number("refBulkModul");
  p.cohesion = args.number("cohesi");
  p.peak_shear_strain = args.number("peakShearStra");
  if (!args.empty()) p.friction_deg = args.number("frictionAng");
  if (!args.empty()) p.ref_pressure = args.number("refPress");
  if (!args.empty()) p.pressure_exponent = args.number("pressDependCoe");
  if (!args.empty()) {
    p.surfaces = args.integer("noYieldSurf");
    if (p.surfaces < 0) {
      if (p.surfaces <= -40) args.fail("expected at most 39 user-defined yield surfaces, got " + std::to_string(-p.surfaces));
      p.surfaces = -p.surfaces;
      for (int i = 0; i < 2 * p.surfaces; ++i) p.backbone.push_back(args.number(i % 2 == 0 ? "shear strain r" : "G/Gmax"));
    }
  }
  args.expect_end();
  return std::make_unique<PressureIndependMultiYield>(tag, p);
}

}  // namespace fem::materials
