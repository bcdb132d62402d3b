#pragma once
// The explicit registration table of `element <type> ...` parsers: one line per element type.
#include <map>
#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "common/command_args.hpp"
#include "fem_tcl/domain/domain.hpp"
#include "fem_tcl/materials/nd_material.hpp"
#include "fem_tcl/materials/uniaxial_material.hpp"

namespace fem::elements {

/// What an element parser may look up: the nodes (domain) and the defined materials.
struct ElementBuildContext {
  domain::Domain& domain;
  const std::map<int, std::unique_ptr<materials::NDMaterial>>& materials;
  /// `uniaxialMaterial`s (zeroLength); null when the caller has none.
  const materials::UniaxialMaterialMap* uniaxial = nullptr;

  /// Throws common::InputError naming `args`' command when the material does not exist.
  const materials::NDMaterial& material(common::CommandArgs& args, int tag) const;
  /// Throws common::InputError naming `args`' command when the uniaxialMaterial does not exist.
  const materials::UniaxialMaterial& uniaxial_material(common::CommandArgs& args, int tag) const;
  /// The four nodes; throws for a missing or repeated node tag.
  std::array<domain::Node*, 4> quad_nodes(common::CommandArgs& args, const std::array<int, 4>& tags) const;
};

/// Builds one element from `element <type> tag ...`; `args` start at the tag. Throws common::InputError.
using ElementParser = std::unique_ptr<domain::Element> (*)(common::CommandArgs& args, const ElementBuildContext& ctx);

struct ElementParserEntry {
  std::string_view type;
  std::string_view usage;
  ElementParser parse;
  int nodes = 4;  ///< nodes per element (block2D builds 4-node ones)
};

std::span<const ElementParserEntry> element_parsers();
const ElementParserEntry* find_element_parser(std::string_view type);

/// "PlaneStrain" / "PlaneStress" (also OpenSees' "...2D" spellings); anything else is an error.
materials::PlaneType parse_plane_type(common::CommandArgs& args, const std::string& word);

}  // namespace fem::elements
