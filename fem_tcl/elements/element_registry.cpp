#include "fem_tcl/elements/element_registry.hpp"

#include <array>

#include "fem_tcl/elements/four_node_quad.hpp"
#include "fem_tcl/elements/four_node_quad_up.hpp"
#include "fem_tcl/elements/ssp_quad.hpp"
#include "fem_tcl/elements/ssp_quad_up.hpp"
#include "fem_tcl/elements/tri31.hpp"
#include "fem_tcl/elements/zero_length.hpp"

namespace fem::elements {

namespace {
// One line per element type.
constexpr std::array kParsers{
    ElementParserEntry{"SSPquad", "element SSPquad tag i j k l matTag PlaneStrain|PlaneStress thick <b1 b2>",
                       parse_ssp_quad},
    ElementParserEntry{"SSPquadUP",
                       "element SSPquadUP tag i j k l matTag t fBulk fDen k1 k2 e alpha <b1 b2> <Pup Plow Pleft Pright>",
                       parse_ssp_quad_up},
    ElementParserEntry{"SSPQuadUP",
                       "element SSPQuadUP tag i j k l matTag t fBulk fDen k1 k2 e alpha <b1 b2> <Pup Plow Pleft Pright>",
                       parse_ssp_quad_up},
    ElementParserEntry{"quadUP", "element quadUP tag i j k l thick matTag bulk fmass hPerm vPerm <b1 <b2 <t>>>",
                       parse_four_node_quad_up},
    ElementParserEntry{"quad", "element quad tag i j k l thick PlaneStrain|PlaneStress matTag <p rho b1 b2>",
                       parse_four_node_quad},
    ElementParserEntry{"FourNodeQuad",
                       "element FourNodeQuad tag i j k l thick PlaneStrain|PlaneStress matTag <p rho b1 b2>",
                       parse_four_node_quad},
    ElementParserEntry{"tri31", "element tri31 tag i j k thick PlaneStrain|PlaneStress matTag <pressure rho b1 b2>",
                       parse_tri31, 3},
    ElementParserEntry{"Tri31", "element Tri31 tag i j k thick PlaneStrain|PlaneStress matTag <pressure rho b1 b2>",
                       parse_tri31, 3},
    ElementParserEntry{"zeroLength",
                       "element zeroLength tag iNode jNode -mat m1 .. -dir d1 .. <-orient x1 x2 x3 <yp1 yp2 yp3>> "
                       "<-doRayleigh <0|1>>",
                       parse_zero_length, 2},
};
}  // namespace

std::span<const ElementParserEntry> element_parsers() { return kParsers; }

const ElementParserEntry* find_element_parser(std::string_view type) {
  for (const auto& e : element_parsers()) {
    if (e.type == type) return &e;
  }
  return nullptr;
}

const materials::NDMaterial& ElementBuildContext::material(common::CommandArgs& args, int tag) const {
  auto it = materials.find(tag);
  if (it == materials.end()) args.fail("nDMaterial " + std::to_string(tag) + " does not exist");
  return *it->second;
}

const materials::UniaxialMaterial& ElementBuildContext::uniaxial_material(common::CommandArgs& args, int tag) const {
  const auto it = uniaxial ? uniaxial->find(tag) : materials::UniaxialMaterialMap::const_iterator{};
  if (!uniaxial || it == uniaxial->end()) args.fail("uniaxialMaterial " + std::to_string(tag) + " does not exist");
  return *it->second;
}

void ElementBuildContext::find_nodes(common::CommandArgs& args, std::span<const int> tags,
                                     std::span<domain::Node*> nodes) const {
  for (std::size_t i = 0; i < tags.size(); ++i) {
    nodes[i] = domain.find_node(tags[i]);
    if (!nodes[i]) args.fail("node " + std::to_string(tags[i]) + " does not exist");
    for (std::size_t j = 0; j < i; ++j) {
      if (tags[j] == tags[i]) args.fail("node " + std::to_string(tags[i]) + " appears twice (collapsed element)");
    }
  }
}

std::array<domain::Node*, 4> ElementBuildContext::quad_nodes(common::CommandArgs& args,
                                                             const std::array<int, 4>& tags) const {
  std::array<domain::Node*, 4> nodes{};
  find_nodes(args, tags, nodes);
  return nodes;
}

void ElementBuildContext::require_dofs(common::CommandArgs& args, std::span<domain::Node* const> nodes, int ndf) const {
  for (const domain::Node* n : nodes) {
    if (n->ndf == ndf) continue;
    args.fail("node " + std::to_string(n->tag) + " has " + std::to_string(n->ndf) + " dofs (model -ndf " +
              std::to_string(n->ndf) + "), this element needs " + std::to_string(ndf) +
              (ndf == 3 ? " (ux, uy, p): build its nodes after 'model basic -ndm 2 -ndf 3'"
                        : ": a solid element's nodes come from 'model basic -ndm 2 -ndf 2' (a u-p soil uses "
                          "SSPquadUP or quadUP)"));
  }
}

nlohmann::ordered_json continuum_element_json(const domain::Element& element, std::string_view type, double thickness,
                                              double pressure, double rho, const domain::Vector2& body, int material_tag) {
  nlohmann::ordered_json j;
  j["name"] = element.tag();
  j["type"] = type;
  j["nodes"] = nlohmann::ordered_json::array();
  for (int a = 0; a < element.num_nodes(); ++a) j["nodes"].push_back(element.nodes()[static_cast<std::size_t>(a)]->tag);
  j["thickness"] = thickness;
  j["surfacePressure"] = pressure;
  j["masspervolume"] = rho;
  j["bodyForces"] = {body[0], body[1]};
  j["material"] = std::to_string(material_tag);
  return j;
}

materials::PlaneType parse_plane_type(common::CommandArgs& args, const std::string& word) {
  if (word == "PlaneStrain" || word == "PlaneStrain2D") return materials::PlaneType::PlaneStrain;
  if (word == "PlaneStress" || word == "PlaneStress2D") return materials::PlaneType::PlaneStress;
  args.fail("expected PlaneStrain or PlaneStress, got '" + word + "'");
}

}  // namespace fem::elements
