#pragma once
// fem2mpm's u-p options (--pore-pressure and the liquefied strength, bridge/README.md "Pore pressure and
// liquefaction") from their command-line text to what pore_pressure.hpp and liquefied_strength.hpp take.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "bridge/liquefied_strength.hpp"
#include "bridge/pore_pressure.hpp"

namespace bridge {

/// The u-p options as given (CLI11 fills them).
struct UpOptionText {
  std::string pore_pressure, pp_nodes, strain, liquefied_table, n160cs;
  std::optional<double> reference_time, residual_ratio;
  double liquefied = 0.7, strength_step = 0.05;
  std::size_t max_liquefied_materials = 20;
  std::string void_redistribution = "significant";
  std::vector<double> liquefied_softening;  ///< K E1 E2, or empty
  bool effective_friction = false;
};

/// The options that mean nothing without --pore-pressure (an error names the one given).
inline constexpr std::array<const char*, 12> kUpOptionsNeedingPorePressure = {
    "--pp-nodes", "--reference-time", "--strain", "--liquefied", "--liquefied-table", "--residual-ratio",
    "--residual-n160cs", "--void-redistribution", "--liquefied-softening", "--strength-step", "--max-liquefied-materials",
    "--effective-friction"};

/// nullopt without --pore-pressure; else the file, --pp-nodes parsed, --reference-time checked (finite), --strain.
/// Throws common::InputError naming the option.
std::optional<PorePressureOptions> pore_pressure_options(const UpOptionText& text);

/// The liquefied-strength options: at most one rule (--liquefied-table read and checked line by line,
/// --residual-ratio, --residual-n160cs MATERIAL:N,...), --void-redistribution, --liquefied-softening (not with a
/// table), checked (check_liquefied_options). Throws common::InputError naming the option or the table's line.
LiquefiedOptions liquefied_options(const UpOptionText& text);

}  // namespace bridge
