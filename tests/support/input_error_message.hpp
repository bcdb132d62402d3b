#pragma once
// The message of a user-input error, for tests that check what an error names.
#include <functional>
#include <string>

#include "common/input_error.hpp"

namespace test_support {

/// The message of the common::InputError that `f` throws, or "" when it throws none.
inline std::string input_error_message(const std::function<void()>& f) {
  try {
    f();
  } catch (const common::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace test_support
