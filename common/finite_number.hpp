#pragma once
// The one validation layer for numbers that come from users (options, JSON keys, Tcl words, file
// columns): finite, inside a range, integral where an integer is meant. Each check returns what is
// wrong as text ("" when the value is fine), so that every caller names its own option, key or
// command in the one-line error (PETSc's PetscCheck / deal.II's AssertThrow with the caller's context).
#include <cstdint>
#include <limits>
#include <string>

namespace common {

/// An interval of admissible values. NaN and +-inf are never admissible: a user-given number must be
/// finite, whatever its range.
struct NumberRange {
  double low = -std::numeric_limits<double>::infinity();
  double high = std::numeric_limits<double>::infinity();
  bool low_closed = false;
  bool high_closed = false;
  std::string noun = "a number";  ///< how text() names the value ("an angle in degrees")

  static NumberRange any() { return {}; }
  static NumberRange positive() { return make(0, std::numeric_limits<double>::infinity(), false, false); }
  static NumberRange non_negative() { return make(0, std::numeric_limits<double>::infinity(), true, false); }
  /// [low, high]
  static NumberRange closed(double low, double high) { return make(low, high, true, true); }
  /// [low, high)
  static NumberRange closed_open(double low, double high) { return make(low, high, true, false); }
  /// (low, high)
  static NumberRange open(double low, double high) { return make(low, high, false, false); }
  /// (low, high]
  static NumberRange open_closed(double low, double high) { return make(low, high, false, true); }
  static NumberRange make(double low, double high, bool low_closed, bool high_closed) {
    NumberRange r;
    r.low = low;
    r.high = high;
    r.low_closed = low_closed;
    r.high_closed = high_closed;
    return r;
  }

  /// The same range, named `noun` in messages.
  NumberRange named(std::string name) const {
    NumberRange r = *this;
    r.noun = std::move(name);
    return r;
  }

  bool contains(double value) const;
  /// "a finite number", "a number > 0", "a number in [0, 1)".
  std::string text() const;
};

/// "" when `value` is finite and inside `range`, else "expected <range>, got <value>".
std::string number_problem(double value, const NumberRange& range = NumberRange::any());

/// Throws common::InputError("<where>: expected ..., got ...") unless `value` is admissible; returns it.
double checked_number(double value, const NumberRange& range, const std::string& where);

/// "" when `value` is a whole number in [low, high] (so it converts to an integer exactly).
std::string integer_problem(double value, double low, double high);

/// Largest count of items of `item_bytes` bytes each that this process may allocate for one array:
/// a fraction of the physical memory (so that a bad count is an error naming its source, not
/// std::bad_alloc or the OOM killer).
std::uint64_t allocation_limit(std::uint64_t item_bytes);

/// "" when `count` items of `item_bytes` fit allocation_limit(), else
/// "<count> <what> (<bytes>) is more than this machine can hold (limit <n>)".
std::string size_problem(double count, std::uint64_t item_bytes, const std::string& what);

}  // namespace common
