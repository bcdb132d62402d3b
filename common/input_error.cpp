#include "common/input_error.hpp"

namespace common {

InputError::InputError(const std::string& where, const std::string& what)
    : std::runtime_error(where.empty() ? what : where + ": " + what) {}

}  // namespace common
