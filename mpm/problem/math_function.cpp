#include "mpm/problem/math_function.hpp"

#include <algorithm>
#include <cmath>

namespace mpm {

double LinearFunction::value(double at) const {
  if (at <= x.front()) return fx.front();
  if (at >= x.back()) return fx.back();
  const std::size_t k = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), at) - x.begin());  // x[k-1] <= at < x[k]
  const double t = (at - x[k - 1]) / (x[k] - x[k - 1]);
  return fx[k - 1] + t * (fx[k] - fx[k - 1]);
}

double SinFunction::value(double at) const {
  if (at < x_min || at > x_max) return 0.0;
  return std::sin(a * (at - x0));
}

}  // namespace mpm
