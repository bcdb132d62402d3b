#include "fem_tcl/materials/pm4_common.hpp"

#include <algorithm>
#include <cmath>

#include "common/input_error.hpp"
#include "common/number_text.hpp"

namespace fem::materials::pm4 {

Matrix3 elastic_stiffness(double K, double G) {
  const double a = K + 4.0 / 3.0 * G;
  const double b = K - 2.0 / 3.0 * G;
  Matrix3 c;
  c << a, b, 0.0, b, a, 0.0, 0.0, 0.0, G;
  return c;
}

double yield_function(const Vector3& stress, const Vector3& alpha, double m) {
  const double p = mean_stress(stress);
  return norm(deviator(stress) - p * alpha) - kRootHalf * m * p;
}

Vector3 yield_normal(const Vector3& stress, const Vector3& alpha) {
  const double p = mean_stress(stress);
  if (std::abs(p) < kSmall) return Vector3(0.0, 0.0, kRootHalf);
  const Vector3 n = deviator(stress) - p * alpha;
  const double length = norm(n);
  return length < kSmall ? n : Vector3(n / length);
}

double elastic_fraction(const Vector3& stress, const Vector3& dsigma, const Vector3& alpha, double m, double tol_f,
                        double a0, double a1) {
  const auto f_at = [&](double a) { return yield_function(stress + a * dsigma, alpha, m); };
  double f0 = f_at(a0), f1 = f_at(a1);
  double a = a0;
  for (int i = 1; i <= 10; ++i) {
    a = a1 - f1 * (a1 - a0) / (f1 - f0);
    const double f = f_at(a);
    if (std::abs(f) < tol_f) break;
    if (f * f0 < 0.0) {
      a1 = a;
      f1 = f;
    } else {
      f1 = f1 * f0 / (f0 + f);
      a0 = a;
      f0 = f;
    }
    if (i == 10) {  // not found: OpenSees treats the whole increment as plastic
      a = 0.0;
      break;
    }
  }
  if (a > 1.0 - kSmall) a = 1.0;
  if (a < kSmall) a = 0.0;
  if (std::isnan(a)) a = 0.0;
  return a;
}

// The scan as OpenSees writes it: a pass walks from a0 in steps of (a1 - a0) / 20 while f stays inside; the
// first point outside closes the bracket (if the last inside point was clearly inside) or restarts the scan
// from the unloading point with the shorter range. Once a bracket is found every later pass moves a0 by at most
// one step (the inner loop leaves after one point), which is what OpenSees does.
double elastic_fraction_after_unloading(const Vector3& stress, const Vector3& dsigma, const Vector3& alpha, double m,
                                        double tol_f) {
  constexpr int kSub = 20;
  double a0 = 0.0, a1 = 1.0;
  const double f_start = yield_function(stress, alpha, m);
  double f0 = f_start;
  bool bracketed = false;
  for (int pass = 1; pass < 10; ++pass) {
    const double da = (a1 - a0) / kSub;
    for (int k = 1; k < kSub; ++k) {
      const double a = a0 + da;
      const double f = yield_function(stress + a * dsigma, alpha, m);
      if (f > tol_f) {
        a1 = a;
        if (f0 < -tol_f) {
          bracketed = true;
        } else {
          a0 = 0.0;
          f0 = f_start;
        }
        break;
      }
      a0 = a;
      f0 = f;
      if (bracketed) break;
    }
  }
  return elastic_fraction(stress, dsigma, alpha, m, tol_f, a0, a1);
}

int strain_substeps(const Vector3& strain_increment, double max_increment) {
  double largest = strain_increment[0];
  for (int i = 1; i < 3; ++i) {
    if (std::abs(strain_increment[i]) > std::abs(largest)) largest = strain_increment[i];
  }
  if (!(std::abs(largest) > max_increment)) return 1;
  // A strain increment of more than kMaxSubsteps sub-steps (10 = 1000 % strain in one step at OpenSees'
  // 1e-5) is a diverging iteration, not a load step: fail the step (the analysis reverts it) instead of
  // grinding through billions of sub-steps (found by fuzzing: a 1e9 kN load on a PM4Sand element).
  constexpr double kMaxSubsteps = 1e6;
  const double steps = std::floor(std::abs(largest) / max_increment) + 1.0;
  if (!(steps <= kMaxSubsteps)) {
    throw common::NumericalError("PM4: a strain increment of " + common::number_text(largest, 4) +
                                 " in one step (more than 1e6 sub-steps of " + common::number_text(max_increment, 2) +
                                 "): the iteration diverged");
  }
  return static_cast<int>(steps);
}

}  // namespace fem::materials::pm4
