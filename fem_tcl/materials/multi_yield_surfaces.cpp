#include "fem_tcl/materials/multi_yield_surfaces.hpp"

#include <algorithm>

#include "common/input_error.hpp"

namespace fem::materials::multi_yield {

double smallest_nonnegative_root(double A, double B, double C, const char* what) {
  const auto fail = [what](const char* why) {
    throw common::NumericalError(std::string("multi-yield surfaces: ") + why + " when " + what);
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

// --- surface generation (OpenSees setUpSurfaces) -----------------------------------------------------------

HyperbolicBackbone::HyperbolicBackbone(double G, double peak_strength, double peak_strain, const std::string& where)
    : shear_modulus(G) {
  if (!(G * peak_strain > peak_strength))
    throw common::InputError(where, "G x peakShearStra must exceed the octahedral shear strength " +
                                        std::to_string(peak_strength));
  ref_strain = peak_strain * peak_strength / (G * peak_strain - peak_strength);
}

double plastic_modulus(double G, double elasto_plastic) {
  if (2.0 * G - elasto_plastic <= 0.0) return kUpLimit;
  return std::clamp(2.0 * G * elasto_plastic / (2.0 * G - elasto_plastic), 0.0, kUpLimit);
}

// Between surfaces m and m+1 the backbone's elasto-plastic modulus 2 d tau / d gamma = 2 G H / (2 G + H) gives
// H = 2 G Hep / (2 G - Hep) (OpenSees setUpSurfaces); the failure surface has H = 0.
std::vector<YieldSurface> hyperbolic_surfaces(const HyperbolicBackbone& backbone, double peak_strength, int n,
                                              double cone) {
  std::vector<YieldSurface> s(static_cast<std::size_t>(n) + 1);
  const double step = peak_strength / n;
  for (int m = 1; m <= n; ++m) {
    const double t1 = m * step, t2 = t1 + step;
    const double hep = 2.0 * (t2 - t1) / (backbone.strain(t2) - backbone.strain(t1));
    s[m].size = 3.0 * t1 / std::sqrt(2.0) / cone;
    s[m].modulus = m == n ? 0.0 : plastic_modulus(backbone.shear_modulus, hep);
  }
  return s;
}

void validate_user_points(const std::vector<double>& g, const std::string& where) {
  const int n = static_cast<int>(g.size() / 2);
  for (int m = 0; m < n; ++m) {
    const bool ok = g[2 * m] > 0.0 && g[2 * m + 1] > 0.0 &&
                    (m == 0 || (g[2 * m] > g[2 * m - 2] && g[2 * m] * g[2 * m + 1] > g[2 * m - 2] * g[2 * m - 1]));
    if (!ok)
      throw common::InputError(where, "backbone point " + std::to_string(m + 1) +
                                          ": expected positive shear strains and G/Gmax with the strain and the "
                                          "stress G (G/Gmax) strain increasing from point to point");
  }
}

std::vector<YieldSurface> user_surfaces(double G, const std::vector<double>& g, double cone, const std::string& where) {
  validate_user_points(g, where);
  const int n = static_cast<int>(g.size() / 2);
  std::vector<YieldSurface> s(static_cast<std::size_t>(n) + 1);
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
  return s;
}

// --- the surfaces at a stress -------------------------------------------------------------------------------

double MultiYieldSurfaces::yield_value(int m, const Vector6& dev, double h) const {
  const YieldSurface& f = (*this)[m];
  const Vector6 r = dev - f.center * h;
  const double sz = f.size * h;
  return 1.5 * contract(r, r) - sz * sz;
}

bool MultiYieldSurfaces::crosses_next(const Vector6& dev, double h) const {
  if (active_ == count()) return false;
  return yield_value(active_ + 1, dev, h) > 0.0;
}

Vector6 MultiYieldSurfaces::contact_point(const Vector6& dev, double h) const {
  const YieldSurface& a = (*this)[active_];
  const Vector6 centre = a.center * h;
  const Vector6 rel = dev - centre;
  return centre + rel * (a.size * h / mises(rel));
}

void MultiYieldSurfaces::scale_onto(Vector6& dev, int k, double h) const {
  const int n = count();
  const YieldSurface& s = (*this)[k];
  const double sz = s.size * h;
  for (int guard = 0; guard < 100; ++guard) {
    const double diff = yield_value(k, dev, h);
    if (k < n && diff < 0.0) {
      const double ms = std::sqrt(sz * sz + diff);
      dev += std::max((sz - ms) / ms, 1e-13) * (dev - s.center * h);
      continue;
    }
    if (k == n && std::abs(diff) > kLowLimit) dev *= sz / std::sqrt(diff + sz * sz);
    return;
  }
}

bool MultiYieldSurfaces::place(Vector6& dev, double h) {
  active_ = 0;
  if (std::sqrt(contract(dev, dev)) == 0.0) return false;
  const int n = count();
  int k = 0;
  while (yield_value(k + 1, dev, h) > 0.0) {
    ++k;
    if (k == n) {  // outside the failure surface: brought onto it (its centre is the origin, it never moves)
      const double sz = (*this)[n].size * h, diff = yield_value(n, dev, h);
      if (std::abs(diff) > kLowLimit) dev = dev * (sz / std::sqrt(diff + sz * sz));
      active_ = n;
      return true;
    }
  }
  active_ = k;
  return false;
}

void MultiYieldSurfaces::centre_on(const Vector6& dev, double h) {
  if (active_ == 0) return;
  const double ms = mises(dev);
  const int last = active_ < count() ? active_ : active_ - 1;  // the failure surface does not move
  for (int m = 1; m <= last; ++m) (*this)[m].center = dev * (1.0 - (*this)[m].size * h / ms) / h;
}

void MultiYieldSurfaces::recentre_inner(const Vector6& dev, double h) {
  const YieldSurface& a = (*this)[active_];
  for (int m = 1; m < active_; ++m) {
    const double ratio = (*this)[m].size / a.size;
    (*this)[m].center = (dev + (a.center * h - dev) * ratio) / h;
  }
}

void MultiYieldSurfaces::translate_active(const Vector6& dev, double h) {
  if (active_ == count()) return;
  YieldSurface& a = (*this)[active_];
  const YieldSurface& outer = (*this)[active_ + 1];
  const Vector6 centre = a.center * h, outer_centre = outer.center * h;
  const double size = a.size * h, outer_size = outer.size * h;
  const Vector6 t1 = dev - centre;
  const Vector6 t2 = centre - outer_centre;
  double A = contract(t1, t1), B = 2.0 * contract(t1, t2), C = contract(t2, t2) - 2.0 / 3.0 * outer_size * outer_size;
  double x = smallest_nonnegative_root(A, B, C, "finding the conjugate point on the outer surface");
  if (std::abs(x - 1.0) < kLowLimit) x = 1.0;
  if (x < 1.0) {
    if (translation_ == Translation::Lenient) return;
    throw common::NumericalError("multi-yield surfaces: the stress lies outside the next surface");
  }
  const double ratio = a.size / outer.size;
  const Vector6 direction = deviator((centre + x * t1) * (1.0 - ratio) - (centre - outer_centre * ratio));
  if (std::sqrt(contract(direction, direction)) < kLowLimit) return;
  A = contract(direction, direction);
  B = -2.0 * contract(t1, direction);
  if (std::abs(B) < kLowLimit) B = 0.0;
  C = contract(t1, t1) - 2.0 / 3.0 * size * size;
  if (std::abs(C) < kLowLimit || std::abs(C) / contract(t1, t1) < kLowLimit) return;
  if (translation_ == Translation::Strict && std::abs(B) < 1e-10 && std::abs(C) < 1e-10) return;
  if (B > 0.0 || C < 0.0) throw common::NumericalError("multi-yield surfaces: an inconsistent surface motion");
  a.center += direction * (smallest_nonnegative_root(A, B, C, "moving the active surface") / h);
}

int MultiYieldSurfaces::substeps(const Vector6& de_dev, double G, double modulus_factor, double h) const {
  const int n = count();
  const double two_g = 2.0 * G * modulus_factor;
  double modulus = two_g;
  if (active_ > 0) {
    const double H = (*this)[active_].modulus * modulus_factor;
    modulus = two_g * H / (two_g + H);
  }
  const double total = mises(de_dev * modulus);
  const double single = (*this)[n].size * h / n;
  return std::min(static_cast<int>(total / single) + 1, n);
}

}  // namespace fem::materials::multi_yield
