#include "common/command_args.hpp"

#include <cerrno>
#include <cmath>
#include <climits>
#include <cstdlib>

#include "common/printable_text.hpp"

namespace common {

const std::string& CommandArgs::peek() const {
  static const std::string none;
  return empty() ? none : words_[next_];
}

void CommandArgs::fail(const std::string& what) const {
  throw InputError(command_, usage_.empty() ? what : what + "; usage: " + usage_);
}

std::string CommandArgs::word(std::string_view what) {
  if (empty()) fail("missing " + std::string(what));
  return words_[next_++];
}

std::optional<double> CommandArgs::parse_number(std::string_view text) {
  if (text.empty()) return std::nullopt;
  const std::string s(text);
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(s.c_str(), &end);
  while (end && (*end == ' ' || *end == '\t')) ++end;
  if (end == s.c_str() || *end != '\0') return std::nullopt;
  // ERANGE: an overflow (+-HUGE_VAL) is an error; an underflow (1e-310, 1e-400) is the nearest
  // denormal or zero, as Tcl reads it.
  if (errno == ERANGE && std::isinf(value)) return std::nullopt;
  return value;
}

std::optional<double> CommandArgs::parse_finite_number(std::string_view text) {
  const auto value = parse_number(text);
  if (value && !std::isfinite(*value)) return std::nullopt;
  return value;
}

std::optional<int> CommandArgs::parse_integer(std::string_view text) {
  if (text.empty()) return std::nullopt;
  const std::string s(text);
  char* end = nullptr;
  errno = 0;
  const long value = std::strtol(s.c_str(), &end, 10);
  while (end && (*end == ' ' || *end == '\t')) ++end;
  if (end == s.c_str() || *end != '\0' || errno == ERANGE || value < INT_MIN || value > INT_MAX) return std::nullopt;
  return static_cast<int>(value);
}

int CommandArgs::integer(std::string_view what) {
  if (empty()) fail("missing " + std::string(what) + " (an integer)");
  const auto value = parse_integer(words_[next_]);
  if (!value) fail("expected " + std::string(what) + " (an integer), got '" + printable(words_[next_]) + "'");
  ++next_;
  return *value;
}

double CommandArgs::number(std::string_view what) {
  if (empty()) fail("missing " + std::string(what) + " (a number)");
  const auto value = parse_number(words_[next_]);
  if (!value) fail("expected " + std::string(what) + " (a number), got '" + printable(words_[next_]) + "'");
  if (!std::isfinite(*value)) fail("expected " + std::string(what) + " (a finite number), got '" + printable(words_[next_]) + "'");
  ++next_;
  return *value;
}

bool CommandArgs::flag(std::string_view flag) {
  if (!empty() && words_[next_] == flag) {
    ++next_;
    return true;
  }
  return false;
}

std::optional<double> CommandArgs::optional_number() {
  if (empty()) return std::nullopt;
  auto value = parse_number(words_[next_]);
  if (value && !std::isfinite(*value)) fail("expected a finite number, got '" + printable(words_[next_]) + "'");
  if (value) ++next_;
  return value;
}

std::optional<int> CommandArgs::optional_integer() {
  if (empty()) return std::nullopt;
  auto value = parse_integer(words_[next_]);
  if (value) ++next_;
  return value;
}

void CommandArgs::expect_end() const {
  if (!empty()) fail("unexpected argument '" + printable(words_[next_]) + "'");
}

std::optional<std::vector<std::string>> CommandArgs::split_list(std::string_view text) {
  std::vector<std::string> out;
  std::size_t i = 0;
  const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; };
  while (true) {
    while (i < text.size() && space(text[i])) ++i;
    if (i == text.size()) return out;
    std::string element;
    if (text[i] == '{') {
      int depth = 1;
      std::size_t j = i + 1;
      for (; j < text.size() && depth > 0; ++j) {
        if (text[j] == '\\' && j + 1 < text.size()) { ++j; continue; }
        depth += text[j] == '{' ? 1 : text[j] == '}' ? -1 : 0;
      }
      if (depth != 0) return std::nullopt;
      element = std::string(text.substr(i + 1, j - i - 2));
      i = j;
    } else if (text[i] == '"') {
      std::size_t j = i + 1;
      for (; j < text.size() && text[j] != '"'; ++j) {
        if (text[j] == '\\' && j + 1 < text.size()) ++j;
        element += text[j];
      }
      if (j == text.size()) return std::nullopt;
      i = j + 1;
    } else {
      for (; i < text.size() && !space(text[i]); ++i) {
        if (text[i] == '\\' && i + 1 < text.size()) ++i;
        element += text[i];
      }
    }
    out.push_back(std::move(element));
  }
}

}  // namespace common
