#pragma once
// User-input errors: the one kind of error a user can fix. Internal invariants use assert().
#include <stdexcept>
#include <string>

namespace common {

/// An error in user input (a file, a line, a command, a key). The message is one line that names
/// where the problem is and what was expected, e.g. "mpm.json: analysis.dt: expected a number > 0, got -1".
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
  /// "<where>: <what>", where `where` is a file, "file:line", a command or a JSON key path.
  InputError(const std::string& where, const std::string& what);
};

/// An output that could not be written (disk full, no permission, a failed close): exit status 1.
class OutputError : public std::runtime_error {
 public:
  explicit OutputError(const std::string& message) : std::runtime_error(message) {}
};

/// A numerical failure the user should see (singular system, NaN in the state, non-convergence).
class NumericalError : public std::runtime_error {
 public:
  explicit NumericalError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace common
