#pragma once
// CB-Geo's math functions (the deck's `math_functions` array, include/functions/linear_function.h): a
// function of time that scales a load. Only CB-Geo's "Linear" type is read: a table of (x, f(x)) points,
// interpolated linearly between them and held at the first and last value outside them.
#include <map>
#include <vector>

namespace mpm::io {

class StrictObject;

/// CB-Geo "Linear": f(x) piecewise linear through (xvalues[k], fxvalues[k]), f(x0) for x < x0 and
/// f(x_last) for x > x_last (CB-Geo LinearFunction::value).
struct LinearFunction {
  std::vector<double> x, fx;  ///< x strictly increasing, at least one point
  double value(double at) const;
};

/// Reads `math_functions` from the root object (absent or []: none): each entry {"id", "type":
/// "Linear", "xvalues": [...], "fxvalues": [...]}. Errors name the entry and key: an unknown type,
/// arrays of different lengths or of non-numbers, x not strictly increasing, a duplicate id.
std::map<unsigned, LinearFunction> read_math_functions(StrictObject& root);

}  // namespace mpm::io
