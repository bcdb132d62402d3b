#pragma once
// Numbers in messages and reports, written the same way by every program.
#include <string>

namespace common {

/// `value` with `significant_digits` significant digits in the stream's default floating-point format
/// (std::ostream precision: "0.25", "1e-05", "-9.81"), as error messages and notes quote user values.
std::string number_text(double value, int significant_digits);

}  // namespace common
