#pragma once
// Strict reading of one JSON object of an input deck: every key must be taken by the reader, and
// finish() turns each key left over into an error naming it ("mpm.json: analysis.newmark: unsupported
// key"). CB-Geo ignores unknown keys silently; a typo in a deck must never run a different model.
#include <nlohmann/json.hpp>

#include "common/finite_number.hpp"

#include <set>
#include <string>

namespace mpm::io {

class StrictObject {
 public:
  /// `file` names the JSON file in messages, `path` the object's key path ("" for the root).
  /// Throws common::InputError when `value` is not an object.
  StrictObject(const nlohmann::json& value, std::string file, std::string path);

  bool has(const std::string& key) const;
  /// The value of `key`; an error naming the key when it is missing.
  const nlohmann::json& required(const std::string& key);
  /// The value of `key`, or nullptr when it is absent.
  const nlohmann::json* optional(const std::string& key);

  double number(const std::string& key);
  /// number(key), checked against `range` (finite always): "mpm.json: materials[0].density: expected a number > 0, got -1".
  double number_in(const std::string& key, const common::NumberRange& range);
  double number_or(const std::string& key, double fallback);
  long long integer(const std::string& key);
  long long integer_or(const std::string& key, long long fallback);
  bool boolean(const std::string& key);
  bool boolean_or(const std::string& key, bool fallback);
  std::string string(const std::string& key);
  std::string string_or(const std::string& key, const std::string& fallback);
  StrictObject object(const std::string& key);

  /// A key CB-Geo knows but that changes nothing here: accepted only with one of the given values
  /// (the values this program honours); absent is fine.
  void accept_only(const std::string& key, const std::vector<nlohmann::json>& honoured, const std::string& why);

  /// Errors on the first key that was never taken.
  void finish() const;

  /// "file: path.key" for messages.
  std::string where(const std::string& key) const;
  std::string path_of(const std::string& key) const;
  const std::string& file() const { return file_; }
  [[noreturn]] void fail(const std::string& key, const std::string& what) const;

 private:
  const nlohmann::json& value_;
  std::string file_;
  std::string path_;
  std::set<std::string> taken_;
};

/// Short description of a JSON value's kind for messages ("a string", "an array", ...).
std::string json_kind(const nlohmann::json& value);

/// The deck's `dir` key of `entry` (a constraint, a load, the base acceleration): 0 (x), 1 (y) or, with
/// `dim` 3, 2 (z); fails naming the key otherwise.
int read_axis(StrictObject& entry, int dim = 2);

}  // namespace mpm::io
