#include "mpm/io/math_functions.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/number_text.hpp"
#include "mpm/io/deck_rules.hpp"
#include "mpm/io/json_keys.hpp"

namespace mpm::io {

using nlohmann::json;

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

LinearFunction read_linear(StrictObject& f) {
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
  return fn;
}

SinFunction read_sin(StrictObject& f) {
  SinFunction fn;
  fn.a = f.number_in("a", kFiniteRange);
  fn.x0 = f.number_in("x0", kFiniteRange);
  if (f.has("xrange")) {
    const std::vector<double> range = finite_numbers(f, "xrange");
    if (range.size() != 2 || !(range[0] <= range[1]))
      f.fail("xrange", "expected [min, max] with min <= max");
    fn.x_min = range[0];
    fn.x_max = range[1];
  }
  return fn;
}

}  // namespace

std::map<unsigned, MathFunction> read_math_functions(StrictObject& root) {
  std::map<unsigned, MathFunction> out;
  const json* list = root.optional("math_functions");
  if (list == nullptr) return out;
  if (!list->is_array()) root.fail("math_functions", "expected an array of functions");
  for (std::size_t k = 0; k < list->size(); ++k) {
    StrictObject f((*list)[k], root.file(), "math_functions[" + std::to_string(k) + "]");
    const long long id = f.integer("id");
    if (id < 0) f.fail("id", "expected an integer >= 0, got " + std::to_string(id));
    const std::string type = f.string("type");
    if (type != "Linear" && type != "Sin") f.fail("type", "unsupported math function \"" + type + "\" (expected Linear or Sin)");
    MathFunction fn = type == "Linear" ? MathFunction(read_linear(f)) : MathFunction(read_sin(f));
    f.finish();
    if (!out.emplace(static_cast<unsigned>(id), std::move(fn)).second)
      f.fail("id", "duplicate math function id " + std::to_string(id));
  }
  return out;
}

const MathFunction& math_function_of(StrictObject& entry, const std::map<unsigned, MathFunction>& functions) {
  const long long id = entry.integer("math_function_id");
  const auto f = id >= 0 ? functions.find(static_cast<unsigned>(id)) : functions.end();
  if (f == functions.end())
    entry.fail("math_function_id", "no math function with id " + std::to_string(id) + " in math_functions");
  return f->second;
}

}  // namespace mpm::io
