#include "mpm/io/math_functions.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/number_text.hpp"
#include "mpm/io/json_keys.hpp"

namespace mpm::io {

using nlohmann::json;

double LinearFunction::value(double at) const {
  if (at <= x.front()) return fx.front();
  if (at >= x.back()) return fx.back();
  const std::size_t k = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), at) - x.begin());  // x[k-1] <= at < x[k]
  const double t = (at - x[k - 1]) / (x[k] - x[k - 1]);
  return fx[k - 1] + t * (fx[k] - fx[k - 1]);
}

namespace {
std::vector<double> finite_numbers(StrictObject& f, const std::string& key) {
  const json& a = f.required(key);
  if (!a.is_array() || a.empty()) f.fail(key, "expected a non-empty array of numbers");
  std::vector<double> out;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (!a[k].is_number() || !std::isfinite(a[k].get<double>()))
      f.fail(key, "entry " + std::to_string(k) + ": expected a finite number, got " + json_kind(a[k]));
    out.push_back(a[k].get<double>());
  }
  return out;
}
}  // namespace

std::map<unsigned, LinearFunction> read_math_functions(StrictObject& root) {
  std::map<unsigned, LinearFunction> out;
  const json* list = root.optional("math_functions");
  if (list == nullptr) return out;
  if (!list->is_array()) root.fail("math_functions", "expected an array of functions");
  for (std::size_t k = 0; k < list->size(); ++k) {
    StrictObject f((*list)[k], root.file(), "math_functions[" + std::to_string(k) + "]");
    const long long id = f.integer("id");
    if (id < 0) f.fail("id", "expected an integer >= 0, got " + std::to_string(id));
    const std::string type = f.string("type");
    if (type != "Linear") f.fail("type", "unsupported math function \"" + type + "\" (expected Linear)");
    LinearFunction fn;
    fn.x = finite_numbers(f, "xvalues");
    fn.fx = finite_numbers(f, "fxvalues");
    if (fn.x.size() != fn.fx.size())
      f.fail("fxvalues", "expected as many values as xvalues (" + std::to_string(fn.x.size()) + "), got " +
                             std::to_string(fn.fx.size()));
    for (std::size_t i = 1; i < fn.x.size(); ++i)
      if (!(fn.x[i] > fn.x[i - 1]))
        f.fail("xvalues", "expected strictly increasing values, got " + common::number_text(fn.x[i - 1], 10) +
                              " then " + common::number_text(fn.x[i], 10) + " (entries " + std::to_string(i - 1) +
                              " and " + std::to_string(i) + ")");
    f.finish();
    if (!out.emplace(static_cast<unsigned>(id), std::move(fn)).second)
      f.fail("id", "duplicate math function id " + std::to_string(id));
  }
  return out;
}

}  // namespace mpm::io
