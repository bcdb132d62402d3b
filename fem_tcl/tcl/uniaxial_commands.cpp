// `uniaxialMaterial <type> tag ...`: the springs and dashpots of zeroLength elements.
#include "fem_tcl/materials/uniaxial_material.hpp"
#include "fem_tcl/tcl/commands.hpp"

namespace fem::tcl {

std::string cmd_uniaxial_material(Context& ctx, common::CommandArgs& args) {
  if (!ctx.model_defined) args.fail("no model defined; start the script with 'model basic -ndm 2 -ndf 2'");
  const std::string type = args.word("type");
  const materials::UniaxialParserEntry* entry = materials::find_uniaxial_material_parser(type);
  if (!entry) {
    std::string known;
    for (const auto& e : materials::uniaxial_material_parsers()) known += (known.empty() ? "" : ", ") + std::string(e.type);
    args.fail("unknown uniaxialMaterial type '" + type + "' (known: " + known + ")");
  }
  std::vector<std::string> words;
  while (!args.empty()) words.push_back(args.word("argument"));
  common::CommandArgs sub("uniaxialMaterial " + type + (words.empty() ? "" : " " + words[0]), std::string(entry->usage),
                          words);
  std::unique_ptr<materials::UniaxialMaterial> material = entry->parse(sub);
  const int tag = material->tag();
  if (ctx.uniaxial_materials.count(tag)) sub.fail("uniaxialMaterial " + std::to_string(tag) + " already exists");
  ctx.uniaxial_materials.emplace(tag, std::move(material));
  return {};
}

}  // namespace fem::tcl
