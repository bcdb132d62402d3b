#include "bridge/up_options.hpp"

#include <algorithm>
#include <sstream>

#include "bridge/fem_state_reader.hpp"
#include "common/finite_number.hpp"
#include "common/input_error.hpp"
#include "common/printable_text.hpp"

namespace bridge {

std::optional<PorePressureOptions> pore_pressure_options(const UpOptionText& o) {
  if (o.pore_pressure.empty()) return std::nullopt;
  PorePressureOptions up;
  up.file = o.pore_pressure;
  if (!o.pp_nodes.empty()) up.nodes = parse_tag_list(o.pp_nodes, "--pp-nodes");
  if (o.reference_time) up.reference_time = common::checked_number(*o.reference_time, common::NumberRange::any(), "--reference-time");
  up.strain = o.strain;
  return up;
}

LiquefiedOptions liquefied_options(const UpOptionText& o) {
  LiquefiedOptions lo;
  lo.threshold = o.liquefied;
  lo.strength_step = o.strength_step;
  lo.max_materials = o.max_liquefied_materials;
  lo.effective_friction = o.effective_friction;
  const int rules = int{!o.liquefied_table.empty()} + int{o.residual_ratio.has_value()} + int{!o.n160cs.empty()};
  if (rules > 1)
    throw common::InputError("--liquefied-table", "give one residual strength rule: --liquefied-table, --residual-ratio or "
                                                  "--residual-n160cs");
  if (!o.liquefied_table.empty()) {
    lo.rule = LiquefiedOptions::Rule::Table;
    lo.table_file = o.liquefied_table;
    lo.table = read_strength_table(o.liquefied_table);
  } else if (o.residual_ratio) {
    lo.rule = LiquefiedOptions::Rule::Ratio;
    lo.ratio = *o.residual_ratio;
  } else if (!o.n160cs.empty()) {
    lo.rule = LiquefiedOptions::Rule::Penetration;
    std::string list = o.n160cs;
    std::replace(list.begin(), list.end(), ',', ' ');
    std::istringstream items(list);
    for (std::string item; items >> item;) {
      const auto colon = item.find(':');
      double n = 0;
      try {
        std::size_t used = 0;
        if (colon == std::string::npos || colon == 0) throw std::invalid_argument(item);
        n = std::stod(item.substr(colon + 1), &used);
        if (used != item.size() - colon - 1) throw std::invalid_argument(item);
      } catch (const std::exception&) {
        throw common::InputError("--residual-n160cs", "expected MATERIAL:N[,MATERIAL:N...] (the FEM material tag and its "
                                                      "(N1)60cs-Sr), got '" + common::printable(item) + "'");
      }
      lo.n160cs[item.substr(0, colon)] = n;
    }
  }
  if (o.void_redistribution == "significant") lo.void_redistribution = VoidRedistribution::Significant;
  else if (o.void_redistribution == "negligible") lo.void_redistribution = VoidRedistribution::Negligible;
  else throw common::InputError("--void-redistribution", "expected significant or negligible, got '" + o.void_redistribution + "'");
  if (!o.liquefied_softening.empty()) {
    if (lo.rule == LiquefiedOptions::Rule::Table)
      throw common::InputError("--liquefied-softening", "not with --liquefied-table (its rows give the softening)");
    lo.peak_factor = o.liquefied_softening[0];
    lo.pd_peak = o.liquefied_softening[1];
    lo.pd_residual = o.liquefied_softening[2];
  }
  check_liquefied_options(lo);
  return lo;
}

}  // namespace bridge
