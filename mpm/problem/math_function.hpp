#pragma once
// CB-Geo's math functions (include/functions/): functions of time that scale a load (base_acceleration,
// concentrated_nodal_forces, particle_surface_traction); mpm/io/math_functions.hpp reads them from a deck.
#include <limits>
#include <variant>
#include <vector>

namespace mpm {

/// CB-Geo "Linear": f(x) piecewise linear through (xvalues[k], fxvalues[k]), f(x0) for x < x0 and
/// f(x_last) for x > x_last (CB-Geo LinearFunction::value).
struct LinearFunction {
  std::vector<double> x, fx;  ///< x strictly increasing, at least one point
  double value(double at) const;
};

/// CB-Geo "Sin": f(x) = sin(a (x - x0)) for x in [x_min, x_max], else 0 (CB-Geo SinFunction::value). As in
/// CB-Geo the range defaults to [the smallest positive double, the largest double], so f(0) = 0.
struct SinFunction {
  double a = 0, x0 = 0;
  double x_min = std::numeric_limits<double>::min(), x_max = std::numeric_limits<double>::max();
  double value(double at) const;
};

/// One of CB-Geo's math functions.
class MathFunction {
 public:
  /// f = 1: a load without a math_function_id is not scaled (CB-Geo's scalar 1).
  MathFunction() : f_(LinearFunction{{0.0}, {1.0}}) {}
  MathFunction(LinearFunction f) : f_(std::move(f)) {}  // NOLINT(google-explicit-constructor): a function is one of its types
  MathFunction(SinFunction f) : f_(f) {}                // NOLINT(google-explicit-constructor)
  double value(double at) const {
    return std::visit([at](const auto& f) { return f.value(at); }, f_);
  }

 private:
  std::variant<LinearFunction, SinFunction> f_;
};

}  // namespace mpm
