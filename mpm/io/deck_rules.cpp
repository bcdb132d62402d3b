#include "mpm/io/deck_rules.hpp"

#include <cmath>

#include "common/number_text.hpp"
#include "common/printable_text.hpp"

namespace mpm::io {

std::string dilation_problem(double dilation_deg, double friction_deg) {
  if (dilation_deg <= friction_deg) return {};
  return "expected a dilation angle <= the friction angle (" + common::number_text(friction_deg, 10) + " degrees), got " +
         common::number_text(dilation_deg, 10);
}

std::string separation_volume_ratio_problem(double ratio) {
  if (ratio == 0 || (std::isfinite(ratio) && ratio > 1)) return {};
  return "expected 0 (never separate) or a volume ratio > 1, got " + common::number_text(ratio, 10);
}

std::string run_name_problem(const std::string& uuid) {
  bool plain = !uuid.empty() && uuid.size() <= 255 && uuid != "." && uuid != "..";
  for (char c : uuid)
    plain = plain && ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
                      c == '-' || c == '.' || c == '+');
  if (plain) return {};
  return "expected a plain folder name (letters, digits, '_', '-', '.', '+'; not '.' or '..'), got '" +
         common::printable(uuid) + "'";
}

}  // namespace mpm::io
