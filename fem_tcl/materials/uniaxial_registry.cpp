#include <array>

#include "fem_tcl/materials/uniaxial_elastic.hpp"
#include "fem_tcl/materials/uniaxial_material.hpp"
#include "fem_tcl/materials/uniaxial_viscous.hpp"

namespace fem::materials {

namespace {
// One line per uniaxial material type (add a line here and the sources to CMakeLists.txt).
constexpr std::array kParsers{
    UniaxialParserEntry{"Elastic", "uniaxialMaterial Elastic tag E <eta> <Eneg>", parse_uniaxial_elastic},
    UniaxialParserEntry{"Viscous", "uniaxialMaterial Viscous tag C alpha <minVel>", parse_uniaxial_viscous},
};
}  // namespace

std::span<const UniaxialParserEntry> uniaxial_material_parsers() { return kParsers; }

const UniaxialParserEntry* find_uniaxial_material_parser(std::string_view type) {
  for (const auto& entry : kParsers) {
    if (entry.type == type) return &entry;
  }
  return nullptr;
}

}  // namespace fem::materials
