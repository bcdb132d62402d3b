#include "fem_tcl/materials/pressure_independ_multi_yield.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>

#include "common/input_error.hpp"
#include "constitutive/stress_invariants.hpp"

namespace fem::materials {

namespace {

constexpr double kLowLimit = 1e-15;  // OpenSees' LOW_LIMIT
constexpr double kUpLimit = 1e30;    // OpenSees' UP_LIMIT: the plastic modulus of a surface that adds no strain
constexpr double kDegree = 3.14159265358979 / 180.0;  // with the value of pi this material has in OpenSees

/// a : b of two symmetric tensors stored as (xx yy zz xy yz xz).
double contract(const Vector6& a, const Vector6& b) {
  return a.head<3>().dot(b.head<3>()) + 2.0 * a.tail<3>().dot(b.tail<3>());
}
using constitutive::mean_stress;  // (sxx + syy + szz) / 3 of the full (xx yy zz xy yz xz) tensor
Vector6 deviator(const Vector6& t) {
  Vector6 d = t;
  d.head<3>().array() -= mean_stress(t);
  return d;
}
/// The von Mises measure sqrt(3/2 t:t) of a deviatoric tensor.
double mises(const Vector6& dev) { return std::sqrt(1.5 * contract(dev, dev)); }
Vector6 with_mean(const Vector6& dev, double p) {
  Vector6 t = deviator(dev);
  t.head<3>().array() += p;
  return t;
}

/// The smallest non-negative root of A x^2 + B x + C = 0, as the surface translation needs it (OpenSees'
/// secondOrderEqn); throws common::NumericalError when there is none.
double smallest_nonnegative_root(double A, double B, double C, const char* what) {
  const auto fail = [what](const char* why) {
    throw common::NumericalError(std::string("PressureIndependMultiYield: ") + why + " when " + what);
  };
  if (A == 0.0) fail("a degenerate surface motion (A = 0)");
  if (C == 0.0) return 0.0;
  if (B == 0.0) {
    if (C / A > 0.0) fail("complex roots");
    return std::sqrt(-C / A);
  }
  const double det = B * B - 4.0 * A * C;
  if (det < 0.0) fail("complex roots");
  double x1 = (B > 0.0 ? -B - std::sqrt(det) : -B + std::sqrt(det)) / (2.0 * A);
  double x2 = C / (A * x1);
  if (x1 < 0.0 && x2 < 0.0) {
    if (std::abs(x1) < kLowLimit) x1 = 0.0;
    else if (std::abs(x2) < kLowLimit) x2 = 0.0;
  }
  if (x1 < 0.0 && x2 < 0.0) fail("negative roots");
  if (x1 < 0.0) return x2;
  if (x2 < 0.0) return x1;
  return std::min(x1, x2);
}

/// f = 3/2 (s - a) : (s - a) - M^2 of a surface at the deviator s: > 0 outside it (OpenSees yieldFunc).
double yield_value(const PressureIndependMultiYield::Surface& f, const Vector6& dev) {
  const Vector6 r = dev - f.center;
  return 1.5 * contract(r, r) - f.size * f.size;
}

/// Engineering strain (exx eyy gxy) -> plane-strain tensor (xx yy zz xy yz xz).
Vector6 strain_tensor(const Vector3& e) {
  Vector6 t = Vector6::Zero();
  t << e[0], e[1], 0.0, 0.5 * e[2], 0.0, 0.0;
  return t;
}

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
  std::vector<Surface> s(static_cast<std::size_t>(n) + 1);
  const auto plastic_modulus = [G](double elasto_plastic) {
    if (2.0 * G - elasto_plastic <= 0.0) return kUpLimit;
    return std::clamp(2.0 * G * elasto_plastic / (2.0 * G - elasto_plastic), 0.0, kUpLimit);
  };
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
    if (!(G * p.peak_shear_strain > peak))
      throw common::InputError(where, "G x peakShearStra must exceed the octahedral shear strength " + std::to_string(peak));
    const double ref_strain = p.peak_shear_strain * peak / (G * p.peak_shear_strain - peak);
    const auto hyperbola_strain = [&](double tau) { return tau * ref_strain / (G * ref_strain - tau); };
    const double step = peak / n;
    for (int m = 1; m <= n; ++m) {
      const double t1 = m * step, t2 = t1 + step;
      const double hep = 2.0 * (t2 - t1) / (hyperbola_strain(t2) - hyperbola_strain(t1));
      s[m].size = 3.0 * t1 / std::sqrt(2.0) / (p.friction_deg > 0.0 ? cone : 1.0);
      s[m].modulus = m == n ? 0.0 : plastic_modulus(hep);
    }
  } else {
    const auto& g = p.backbone;
    for (int m = 0; m < n; ++m) {
      const bool ok = g[2 * m] > 0.0 && g[2 * m + 1] > 0.0 &&
                      (m == 0 || (g[2 * m] > g[2 * m - 2] && g[2 * m] * g[2 * m + 1] > g[2 * m - 2] * g[2 * m - 1]));
      if (!ok)
        throw common::InputError(where, "backbone point " + std::to_string(m + 1) +
                                            ": expected positive shear strains and G/Gmax with the strain and the "
                                            "stress G (G/Gmax) strain increasing from point to point");
    }
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
    for (int m = 1; m < n; ++m) {
      const double e1 = g[2 * (m - 1)], t1 = G * g[2 * (m - 1) + 1] * e1;
      const double e2 = g[2 * m], t2 = G * g[2 * m + 1] * e2;
      const double hep = 2.0 * (t2 - t1) / (e2 - e1);
      const double h = 2.0 * G - hep <= 0.0 ? kUpLimit : 2.0 * G * hep / (2.0 * G - hep);
      if (!(h > 0.0))
        throw common::InputError(where, "surface " + std::to_string(m) + " has a plastic modulus <= 0: modify the G/Gmax curve");
      s[m].size = std::sqrt(3.0) * t1 / cone;
      s[m].modulus = std::min(h, kUpLimit);
      if (m == n - 1) s[n].size = std::sqrt(3.0) * t2 / cone;
    }
  }
  committed_.surfaces = std::move(s);
  committed_.active = 0;
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
  s.active = 0;
  const Vector6 dev = deviator(s.stress);
  if (std::sqrt(contract(dev, dev)) == 0.0) return;
  const int n = params_.surfaces;
  int k = 0;
  while (yield_value(s.surfaces[k + 1], dev) > 0.0) {
    ++k;
    if (k == n) {  // outside the failure surface: brought onto it (its centre is the origin, it never moves)
      const double sz = s.surfaces[n].size, diff = yield_value(s.surfaces[n], dev);
      const Vector6 on_surface = std::abs(diff) > kLowLimit ? Vector6(dev * (sz / std::sqrt(diff + sz * sz))) : dev;
      s.stress = with_mean(on_surface, mean_stress(s.stress));
      s.active = n;
      centre_on_stress(s);
      return;
    }
  }
  s.active = k;
  centre_on_stress(s);
}

void PressureIndependMultiYield::scale_to_confinement(State& s, bool moduli) const {
  if (params_.friction_deg == 0.0) return;
  const double height = -(mean_stress(s.stress) - residual_pressure_);
  const double scale = std::pow(-height / (-params_.ref_pressure - residual_pressure_), params_.pressure_exponent);
  if (moduli) {
    s.shear_modulus *= scale;
    s.bulk_modulus *= scale;
  }
  for (std::size_t m = 1; m < s.surfaces.size(); ++m) {
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

// Surfaces 1..active re-centred on the line from the origin through the stress, so the stress lies on each.
void PressureIndependMultiYield::centre_on_stress(State& s) {
  if (s.active == 0) return;
  const Vector6 dev = deviator(s.stress);
  const double ms = mises(dev);
  const int n = static_cast<int>(s.surfaces.size()) - 1;
  const int last = s.active < n ? s.active : s.active - 1;  // the failure surface does not move
  for (int m = 1; m <= last; ++m) s.surfaces[m].center = dev * (1.0 - s.surfaces[m].size / ms);
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

bool PressureIndependMultiYield::crosses_next_surface(const Vector6& dev) const {
  const int n = params_.surfaces;
  if (trial_.active == n) return false;
  return yield_value(trial_.surfaces[trial_.active + 1], dev) > 0.0;
}

void PressureIndependMultiYield::plastic_update(const Vector6& de) {
  const int n = params_.surfaces;
  const double G = trial_.shear_modulus;
  const Vector6 committed_dev = deviator(committed_.stress);
  const Vector6 de_dev = deviator(de);
  // Load reversal: the increment points inside the active surface; the inner surfaces are re-centred so
  // they touch at the committed stress (Mroz), and the point is elastic again.
  if (trial_.active > 0) {
    const Surface& a = trial_.surfaces[trial_.active];
    const Vector6 normal = committed_dev - a.center;
    const double length = std::sqrt(contract(normal, normal));
    if (length > 0.0 && contract(2.0 * G * de_dev, normal) / length < 0.0) {
      for (int m = 1; m < trial_.active; ++m) {
        const double ratio = trial_.surfaces[m].size / a.size;
        trial_.surfaces[m].center = committed_dev + (a.center - committed_dev) * ratio;
      }
      trial_.active = 0;
    }
  }
  // Sub-increments: about one surface spacing of stress each, at most n.
  int substeps = 0;
  if (!de.isZero(0.0)) {
    double modulus = 2.0 * G;
    if (trial_.active > 0) {
      const double H = trial_.surfaces[trial_.active].modulus;
      modulus = 2.0 * G * H / (2.0 * G + H);
    }
    const double total = mises(de_dev * modulus);
    const double single = trial_.surfaces[n].size / n;
    substeps = std::min(static_cast<int>(total / single) + 1, n);
  }
  Vector6 dev = committed_dev;
  for (int i = 0; i < substeps; ++i) {
    dev += 2.0 * G * de_dev / substeps;
    if (trial_.active == 0 && !crosses_next_surface(dev)) continue;
    if (trial_.active == 0) trial_.active = 1;
    correct_stress(dev, false);
    move_active_surface(dev);
  }
  const double p = mean_stress(committed_.stress) + trial_.bulk_modulus * (de[0] + de[1] + de[2]);
  trial_.stress = with_mean(dev, p);
}

// The trial deviator returned onto the active surface along its normal at the contact point, with the
// plastic modulus of that surface; crossing into the next one repeats it there (OpenSees stressCorrection).
void PressureIndependMultiYield::correct_stress(Vector6& dev, bool crossed) {
  for (int guard = 0; guard <= params_.surfaces; ++guard) {
    const double G = trial_.shear_modulus;
    const Surface& a = trial_.surfaces[trial_.active];
    const Vector6 rel = dev - a.center;
    const Vector6 contact = a.center + rel * (a.size / mises(rel));
    const Vector6 normal = (contact - a.center) / std::sqrt(contract(contact - a.center, contact - a.center));
    double loading = contract(normal, dev - contact) / (2.0 * G + a.modulus);
    if (crossed) {
      const double inner = trial_.surfaces[trial_.active - 1].modulus;
      loading *= (inner - a.modulus) / inner;
    }
    dev = deviator(dev - 2.0 * G * loading * normal);
    scale_onto_surface(dev, trial_.active);
    if (!crosses_next_surface(dev)) return;
    ++trial_.active;
    crossed = true;
  }
}

// Brings the deviator onto surface k from inside (scaling about its centre; OpenSees deviatorScaling).
void PressureIndependMultiYield::scale_onto_surface(Vector6& dev, int k) const {
  const int n = params_.surfaces;
  const Surface& s = trial_.surfaces[k];
  for (int guard = 0; guard < 100; ++guard) {
    const double diff = yield_value(s, dev);
    if (k < n && diff < 0.0) {
      const double ms = std::sqrt(s.size * s.size + diff);
      dev += std::max((s.size - ms) / ms, 1e-13) * (dev - s.center);
      continue;
    }
    if (k == n && std::abs(diff) > kLowLimit) dev *= s.size / std::sqrt(diff + s.size * s.size);
    return;
  }
}

// Mroz's translation of the active surface towards the conjugate point of the next one, by just as much
// that the stress lies on it (OpenSees updateActiveSurface).
void PressureIndependMultiYield::move_active_surface(const Vector6& dev) {
  const int n = params_.surfaces;
  if (trial_.active == n) return;
  Surface& a = trial_.surfaces[trial_.active];
  const Surface& outer = trial_.surfaces[trial_.active + 1];
  const Vector6 t1 = dev - a.center;
  const Vector6 t2 = a.center - outer.center;
  double A = contract(t1, t1), B = 2.0 * contract(t1, t2), C = contract(t2, t2) - 2.0 / 3.0 * outer.size * outer.size;
  double x = smallest_nonnegative_root(A, B, C, "finding the conjugate point on the outer surface");
  if (std::abs(x - 1.0) < kLowLimit) x = 1.0;
  if (x < 1.0) throw common::NumericalError("PressureIndependMultiYield: the stress lies outside the next surface");
  const double ratio = a.size / outer.size;
  const Vector6 direction = deviator((a.center + x * t1) * (1.0 - ratio) - (a.center - outer.center * ratio));
  if (std::sqrt(contract(direction, direction)) < kLowLimit) return;
  A = contract(direction, direction);
  B = -2.0 * contract(t1, direction);
  if (std::abs(B) < kLowLimit) B = 0.0;
  C = contract(t1, t1) - 2.0 / 3.0 * a.size * a.size;
  if (std::abs(C) < kLowLimit || std::abs(C) / contract(t1, t1) < kLowLimit) return;
  if (std::abs(B) < 1e-10 && std::abs(C) < 1e-10) return;
  if (B > 0.0 || C < 0.0) throw common::NumericalError("PressureIndependMultiYield: an inconsistent surface motion");
  a.center += direction * smallest_nonnegative_root(A, B, C, "moving the active surface");
}

// OpenSees' tangent: elastic, less 6 G^2 / ((2 G + H) M^2) (s - a) (s - a)^T on the active surface.
void PressureIndependMultiYield::form_tangent() {
  const double G = trial_.shear_modulus;
  tangent_ = plane_strain_elastic_matrix(trial_.bulk_modulus, G);
  if (stage_ != 1 || trial_.active == 0) return;
  const Surface& a = trial_.surfaces[trial_.active];
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
