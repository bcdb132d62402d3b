#pragma once
// The explicit registration table of `nDMaterial <type> ...` parsers: one line per material type.
// Each parse function lives next to its class and reads the words after the type (starting at the tag).
#include <memory>
#include <span>
#include <string_view>

#include "common/command_args.hpp"
#include "fem_tcl/materials/nd_material.hpp"

namespace fem::materials {

/// Builds one material from `nDMaterial <type> tag ...`; `args` start at the tag. Throws common::InputError.
using MaterialParser = std::unique_ptr<NDMaterial> (*)(common::CommandArgs& args);

struct MaterialParserEntry {
  std::string_view type;  ///< the OpenSees type word, e.g. "ElasticIsotropic"
  MaterialParser parse;
};

/// The table of known `nDMaterial` types.
std::span<const MaterialParserEntry> nd_material_parsers();

/// The parser for `type`, or nullptr when the type is unknown.
MaterialParser find_nd_material_parser(std::string_view type);

}  // namespace fem::materials
