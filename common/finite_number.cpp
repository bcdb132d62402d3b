#include "common/finite_number.hpp"

#include <unistd.h>

#include <cmath>

#include "common/input_error.hpp"
#include "common/number_text.hpp"

namespace common {

bool NumberRange::contains(double value) const {
  if (!std::isfinite(value)) return false;
  if (low_closed ? value < low : !(value > low)) return false;
  if (high_closed ? value > high : !(value < high)) return false;
  return true;
}

std::string NumberRange::text() const {
  const bool has_low = std::isfinite(low), has_high = std::isfinite(high);
  if (!has_low && !has_high) return noun == "a number" ? "a finite number" : noun + " (finite)";
  if (!has_high) return noun + (low_closed ? " >= " : " > ") + number_text(low, 10);
  if (!has_low) return noun + (high_closed ? " <= " : " < ") + number_text(high, 10);
  return noun + " in " + (low_closed ? "[" : "(") + number_text(low, 10) + ", " + number_text(high, 10) +
         (high_closed ? "]" : ")");
}

std::string number_problem(double value, const NumberRange& range) {
  if (range.contains(value)) return {};
  return "expected " + range.text() + ", got " + number_text(value, 10);
}

double checked_number(double value, const NumberRange& range, const std::string& where) {
  const std::string problem = number_problem(value, range);
  if (!problem.empty()) throw InputError(where, problem);
  return value;
}

std::string integer_problem(double value, double low, double high) {
  if (std::isfinite(value) && value == std::floor(value) && value >= low && value <= high) return {};
  return "expected an integer in " + number_text(low, 15) + ".." + number_text(high, 15) + ", got " + number_text(value, 10);
}

std::uint64_t allocation_limit(std::uint64_t item_bytes) {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
  // Half the physical memory for one array (4 GiB when the size cannot be read).
  const double total = pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 8.0 * (1ull << 30);
  return static_cast<std::uint64_t>(0.5 * total / static_cast<double>(item_bytes ? item_bytes : 1));
}

std::string size_problem(double count, std::uint64_t item_bytes, const std::string& what) {
  const std::uint64_t limit = allocation_limit(item_bytes);
  if (std::isfinite(count) && count >= 0 && count <= static_cast<double>(limit)) return {};
  return number_text(count, 6) + " " + what + " (" + number_text(count * static_cast<double>(item_bytes) / (1 << 20), 4) +
         " MiB) is more than this machine can hold (at most " + std::to_string(limit) + ")";
}

}  // namespace common
