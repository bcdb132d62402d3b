#include "common/number_text.hpp"

#include <sstream>

namespace common {

std::string number_text(double value, int significant_digits) {
  std::ostringstream os;
  os.precision(significant_digits);
  os << value;
  return os.str();
}

}  // namespace common
