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
  /// The nodes of `tags`, in order, into `nodes`; throws for a missing or repeated node tag.
  void find_nodes(common::CommandArgs& args, std::span<const int> tags, std::span<domain::Node*> nodes) const;
  /// The four nodes; throws for a missing or repeated node tag.
  std::array<domain::Node*, 4> quad_nodes(common::CommandArgs& args, const std::array<int, 4>& tags) const;
  /// Throws common::InputError naming `args`' command when a node's ndf is not `ndf` (a u-p element needs
  /// 3-dof nodes, a solid 2-dof ones: OpenSees' setDomain refuses both mixes).
  void require_dofs(common::CommandArgs& args, std::span<domain::Node* const> nodes, int ndf) const;
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

/// OpenSees' `print -JSON` entry of a quad or triangle: name, type, nodes, thickness, surfacePressure,
/// masspervolume, bodyForces, material.
nlohmann::ordered_json continuum_element_json(const domain::Element& element, std::string_view type, double thickness,
                                              double pressure, double rho, const domain::Vector2& body, int material_tag);

/// "PlaneStrain" / "PlaneStress" (also OpenSees' "...2D" spellings); anything else is an error.
materials::PlaneType parse_plane_type(common::CommandArgs& args, const std::string& word);

}  // namespace fem::elements
