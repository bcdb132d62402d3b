#include "fem_tcl/materials/material_registry.hpp"

#include <array>

#include "fem_tcl/materials/drucker_prager.hpp"
#include "fem_tcl/materials/elastic_isotropic.hpp"
#include "fem_tcl/materials/mohr_coulomb.hpp"
#include "fem_tcl/materials/pm4sand.hpp"
#include "fem_tcl/materials/pm4silt.hpp"
#include "fem_tcl/materials/pressure_depend_multi_yield02.hpp"
#include "fem_tcl/materials/pressure_independ_multi_yield.hpp"

namespace fem::materials {

namespace {
// One line per material type (add a line here and the sources to CMakeLists.txt).
constexpr std::array kParsers{
    MaterialParserEntry{"ElasticIsotropic", parse_elastic_isotropic},
    MaterialParserEntry{"DruckerPrager", parse_drucker_prager},
    MaterialParserEntry{"MohrCoulomb", parse_mohr_coulomb},
    MaterialParserEntry{"PressureIndependMultiYield", parse_pressure_independ_multi_yield},
    MaterialParserEntry{"PressureDependMultiYield02", parse_pressure_depend_multi_yield02},
    MaterialParserEntry{"PM4Sand", parse_pm4sand},
    MaterialParserEntry{"PM4Silt", parse_pm4silt},
};
}  // namespace

std::span<const MaterialParserEntry> nd_material_parsers() { return kParsers; }

MaterialParser find_nd_material_parser(std::string_view type) {
  for (const auto& entry : nd_material_parsers()) {
    if (entry.type == type) return entry.parse;
  }
  return nullptr;
}

}  // namespace fem::materials
