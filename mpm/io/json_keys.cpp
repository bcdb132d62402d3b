#include "mpm/io/json_keys.hpp"

#include <cmath>

#include "common/input_error.hpp"

namespace mpm::io {

std::string json_kind(const nlohmann::json& value) {
  if (value.is_null()) return "null";
  if (value.is_boolean()) return std::string("a boolean (") + (value.get<bool>() ? "true" : "false") + ")";
  if (value.is_number()) return "the number " + value.dump();
  if (value.is_string()) return "the string " + value.dump();
  if (value.is_array()) return "an array";
  return "an object";
}

StrictObject::StrictObject(const nlohmann::json& value, std::string file, std::string path)
    : value_(value), file_(std::move(file)), path_(std::move(path)) {
  if (!value_.is_object())
    throw common::InputError(path_.empty() ? file_ : file_ + ": " + path_,
                             "expected a JSON object, got " + json_kind(value_));
}

std::string StrictObject::path_of(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

std::string StrictObject::where(const std::string& key) const { return file_ + ": " + path_of(key); }

void StrictObject::fail(const std::string& key, const std::string& what) const {
  throw common::InputError(where(key), what);
}

bool StrictObject::has(const std::string& key) const { return value_.contains(key); }

const nlohmann::json& StrictObject::required(const std::string& key) {
  if (!value_.contains(key)) fail(key, "missing (required)");
  taken_.insert(key);
  return value_.at(key);
}

const nlohmann::json* StrictObject::optional(const std::string& key) {
  if (!value_.contains(key)) return nullptr;
  taken_.insert(key);
  return &value_.at(key);
}

namespace {
double as_number(const StrictObject& o, const std::string& key, const nlohmann::json& v) {
  if (!v.is_number()) o.fail(key, "expected a number, got " + json_kind(v));
  return v.get<double>();
}
long long as_integer(const StrictObject& o, const std::string& key, const nlohmann::json& v) {
  if (v.is_number_integer()) return v.get<long long>();
  if (v.is_number_float()) {
    const double d = v.get<double>();
    if (std::isfinite(d) && d == std::floor(d) && std::abs(d) < 9e15) return static_cast<long long>(d);
  }
  o.fail(key, "expected an integer, got " + json_kind(v));
}
bool as_boolean(const StrictObject& o, const std::string& key, const nlohmann::json& v) {
  if (!v.is_boolean()) o.fail(key, "expected true or false, got " + json_kind(v));
  return v.get<bool>();
}
std::string as_string(const StrictObject& o, const std::string& key, const nlohmann::json& v) {
  if (!v.is_string()) o.fail(key, "expected a string, got " + json_kind(v));
  return v.get<std::string>();
}
}  // namespace

double StrictObject::number(const std::string& key) { return as_number(*this, key, required(key)); }
double StrictObject::number_in(const std::string& key, const common::NumberRange& range) {
  const double v = number(key);
  if (const std::string problem = common::number_problem(v, range); !problem.empty()) fail(key, problem);
  return v;
}
double StrictObject::number_or(const std::string& key, double fallback) {
  const auto* v = optional(key);
  return v ? as_number(*this, key, *v) : fallback;
}
long long StrictObject::integer(const std::string& key) { return as_integer(*this, key, required(key)); }
long long StrictObject::integer_or(const std::string& key, long long fallback) {
  const auto* v = optional(key);
  return v ? as_integer(*this, key, *v) : fallback;
}
bool StrictObject::boolean(const std::string& key) { return as_boolean(*this, key, required(key)); }
bool StrictObject::boolean_or(const std::string& key, bool fallback) {
  const auto* v = optional(key);
  return v ? as_boolean(*this, key, *v) : fallback;
}
std::string StrictObject::string(const std::string& key) { return as_string(*this, key, required(key)); }
std::string StrictObject::string_or(const std::string& key, const std::string& fallback) {
  const auto* v = optional(key);
  return v ? as_string(*this, key, *v) : fallback;
}
StrictObject StrictObject::object(const std::string& key) { return StrictObject(required(key), file_, path_of(key)); }

void StrictObject::accept_only(const std::string& key, const std::vector<nlohmann::json>& honoured,
                               const std::string& why) {
  const auto* v = optional(key);
  if (!v) return;
  for (const auto& h : honoured)
    if (*v == h) return;
  std::string list;
  for (const auto& h : honoured) list += (list.empty() ? "" : " or ") + h.dump();
  fail(key, "unsupported value " + v->dump() + " (only " + list + " is accepted: " + why + ")");
}

void StrictObject::finish() const {
  for (auto it = value_.begin(); it != value_.end(); ++it)
    if (!taken_.count(it.key())) fail(it.key(), "unsupported key");
}

int read_axis(StrictObject& entry, int dim) {
  const long long dir = entry.integer("dir");
  if (dir < 0 || dir >= dim)
    entry.fail("dir", std::string(dim == 3 ? "expected 0 (x), 1 (y) or 2 (z)" : "expected 0 (x) or 1 (y)") + ", got " +
                          std::to_string(dir));
  return static_cast<int>(dir);
}

}  // namespace mpm::io
