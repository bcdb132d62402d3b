#pragma once
// Reads the words of one command (a Tcl command's arguments, already split by Tcl) with typed getters
// that throw common::InputError naming the command and what was expected, plus the usage line:
//   "nDMaterial ElasticIsotropic: expected E (a number), got 'abc'; usage: nDMaterial ElasticIsotropic tag E nu <rho>"
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/input_error.hpp"

namespace common {

class CommandArgs {
 public:
  /// `command`: how errors name it ("element SSPquad 3"); `usage`: the syntax line.
  CommandArgs(std::string command, std::string usage, std::vector<std::string> words)
      : command_(std::move(command)), usage_(std::move(usage)), words_(std::move(words)) {}

  std::size_t remaining() const { return words_.size() - next_; }
  bool empty() const { return remaining() == 0; }
  /// The next word without consuming it ("" when none).
  const std::string& peek() const;
  /// Index of the next word (for callers that need to rewind or report positions).
  std::size_t position() const { return next_; }

  std::string word(std::string_view what);
  /// An integer in Tcl's syntax (decimal, optional sign); "1.5" is an error, as Tcl_GetInt.
  int integer(std::string_view what);
  /// A finite double in Tcl's syntax (strtod, whole word); "nan", "inf" and overflowing words are errors.
  double number(std::string_view what);
  /// Consumes the next word if it equals `flag` (e.g. "-tension"); returns whether it did.
  bool flag(std::string_view flag);
  /// Consumes and returns the next word if it parses as a number; otherwise leaves it. A word that
  /// parses but is not finite ("nan", "-inf") is an error.
  std::optional<double> optional_number();
  /// Consumes and returns the next word if it parses as an integer; otherwise leaves it.
  std::optional<int> optional_integer();
  /// Throws if any word is left ("unexpected argument 'x'").
  void expect_end() const;

  /// Throws InputError "<command>: <what>; usage: <usage>".
  [[noreturn]] void fail(const std::string& what) const;
  const std::string& command() const { return command_; }
  const std::string& usage() const { return usage_; }

  /// The syntax check only (a number word, finite or not; overflow is not a number).
  static std::optional<double> parse_number(std::string_view text);
  /// parse_number, and finite.
  static std::optional<double> parse_finite_number(std::string_view text);
  static std::optional<int> parse_integer(std::string_view text);
  /// The elements of a Tcl list (Tcl_SplitList's rules: white space separates, {..} groups with nesting and
  /// "..." quotes, a backslash escapes the next character); nullopt for an unmatched brace or quote.
  static std::optional<std::vector<std::string>> split_list(std::string_view text);

 private:
  std::string command_;
  std::string usage_;
  std::vector<std::string> words_;
  std::size_t next_ = 0;
};

}  // namespace common
