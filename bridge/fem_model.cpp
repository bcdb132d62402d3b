#include "bridge/fem_model.hpp"

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "common/input_error.hpp"

namespace bridge {
namespace {

using nlohmann::json;

std::string where(const std::filesystem::path& file, const std::string& key) {
  return file.string() + ": " + key;
}

/// A JSON value that may be a string or a number, as text ("3" or 3 -> "3").
std::string name_text(const json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number_integer()) return std::to_string(v.get<long long>());
  return v.dump();
}

long tag_of(const json& obj, const std::string& where_text) {
  const auto it = obj.find("name");
  if (it == obj.end()) throw common::InputError(where_text, "missing \"name\"");
  if (it->is_number_integer()) return it->get<long>();
  if (it->is_string()) {
    try {
      std::size_t used = 0;
      const long tag = std::stol(it->get<std::string>(), &used);
      if (used == it->get<std::string>().size()) return tag;
    } catch (const std::exception&) {
    }
  }
  throw common::InputError(where_text, "expected an integer tag in \"name\", got " + it->dump());
}

void add_node(FemModel& model, const json& j, const std::string& where_text) {
  FemNode node;
  node.tag = tag_of(j, where_text);
  const auto crd = j.find("crd");
  if (crd == j.end() || !crd->is_array() || crd->size() < 2 || !(*crd)[0].is_number() || !(*crd)[1].is_number())
    throw common::InputError(where_text, "expected \"crd\": [x, y] (a 2D model, -ndm 2)");
  if (crd->size() != 2) throw common::InputError(where_text, "expected a 2D model (-ndm 2), \"crd\" has " +
                                                                 std::to_string(crd->size()) + " values");
  node.crd = Eigen::Vector2d((*crd)[0].get<double>(), (*crd)[1].get<double>());
  if (model.node_by_tag.count(node.tag)) throw common::InputError(where_text, "duplicate node tag " + std::to_string(node.tag));
  model.node_by_tag[node.tag] = static_cast<int>(model.nodes.size());
  model.nodes.push_back(node);
}

void add_element(FemModel& model, const json& j, const std::string& where_text) {
  FemElement e;
  e.tag = tag_of(j, where_text);
  const std::string type = j.value("type", std::string());
  if (type == "SSPquad") {
    e.kind = ElementKind::SSPquad;
  } else if (type == "FourNodeQuad" || type == "quad") {
    e.kind = ElementKind::Quad;
  } else {
    throw common::InputError(where_text, "element " + std::to_string(e.tag) + ": unsupported element type '" + type +
                                             "' (expected SSPquad or FourNodeQuad/quad)");
  }
  const auto nodes = j.find("nodes");
  if (nodes == j.end() || !nodes->is_array() || nodes->size() != 4)
    throw common::InputError(where_text, "element " + std::to_string(e.tag) + ": expected \"nodes\" with 4 node tags");
  for (int a = 0; a < 4; ++a) {
    if (!(*nodes)[a].is_number_integer())
      throw common::InputError(where_text, "element " + std::to_string(e.tag) + ": node tags must be integers");
    e.node_tags[a] = (*nodes)[a].get<long>();
  }
  if (const auto t = j.find("thickness"); t != j.end() && t->is_number()) e.thickness = t->get<double>();
  if (const auto m = j.find("material"); m != j.end()) e.material = name_text(*m);
  if (const auto r = j.find("masspervolume"); r != j.end() && r->is_number()) e.mass_per_volume = r->get<double>();
  if (const auto b = j.find("bodyForces"); b != j.end() && b->is_array() && b->size() == 2 && (*b)[0].is_number() &&
                                           (*b)[1].is_number())
    e.body_force = Eigen::Vector2d((*b)[0].get<double>(), (*b)[1].get<double>());
  if (model.element_by_tag.count(e.tag))
    throw common::InputError(where_text, "duplicate element tag " + std::to_string(e.tag));
  model.element_by_tag[e.tag] = static_cast<int>(model.elements.size());
  model.elements.push_back(e);
}

void add_material(FemModel& model, const json& j) {
  FemMaterial m;
  m.name = name_text(j.value("name", json("")));
  m.type = j.value("type", std::string());
  auto opt = [&](const char* key) -> std::optional<double> {
    const auto it = j.find(key);
    if (it != j.end() && it->is_number()) return it->get<double>();
    return std::nullopt;
  };
  m.E = opt("E");
  m.nu = opt("nu");
  m.rho = opt("rho");
  m.phi_deg = opt("phi");
  m.cohesion = opt("c");
  m.psi_deg = opt("psi");
  m.tension = opt("tension");
  model.materials[m.name] = m;
}

/// Resolves element node tags to indices and checks the model is not empty.
void finish(FemModel& model, const std::filesystem::path& file) {
  if (model.nodes.empty()) throw common::InputError(where(file, "geometry.nodes"), "no nodes in the model");
  if (model.elements.empty()) throw common::InputError(where(file, "geometry.elements"), "no elements in the model");
  for (auto& e : model.elements) {
    for (int a = 0; a < 4; ++a) {
      const auto it = model.node_by_tag.find(e.node_tags[a]);
      if (it == model.node_by_tag.end())
        throw common::InputError(where(file, "geometry.elements"), "element " + std::to_string(e.tag) +
                                                                       " uses node " + std::to_string(e.node_tags[a]) +
                                                                       ", which is not in geometry.nodes");
      e.nodes[a] = it->second;
    }
  }
}

/// OpenSees 3.8 writes one node, element or material per line. When the whole text is not valid
/// JSON (a bare word in a DruckerPrager entry), read the geometry entries line by line.
FemModel parse_line_by_line(const std::string& text, const std::filesystem::path& file) {
  FemModel model;
  model.source = file;
  std::istringstream in(text);
  std::string line;
  enum class Section { None, Nodes, Elements, Materials } section = Section::None;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.find("\"nodes\":") != std::string::npos && line.find('{') == std::string::npos) { section = Section::Nodes; continue; }
    if (line.find("\"elements\":") != std::string::npos && line.find('{') == std::string::npos) { section = Section::Elements; continue; }
    if (line.find("\"ndMaterials\":") != std::string::npos && line.find('{') == std::string::npos) { section = Section::Materials; continue; }
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    if (line[first] == ']') { section = Section::None; continue; }
    if (line[first] != '{' || section == Section::None) continue;
    std::string entry = line.substr(first);
    while (!entry.empty() && (entry.back() == ',' || entry.back() == ' ' || entry.back() == '\r')) entry.pop_back();
    const std::string at = file.string() + ":" + std::to_string(line_no);
    const json j = json::parse(entry, nullptr, false);
    if (j.is_discarded()) {
      if (section == Section::Materials) {  // the invalid entry OpenSees writes; materials come from options
        model.materials_readable = false;
        continue;
      }
      throw common::InputError(at, "cannot parse this entry as JSON");
    }
    if (section == Section::Nodes) add_node(model, j, at);
    else if (section == Section::Elements) add_element(model, j, at);
    else add_material(model, j);
  }
  finish(model, file);
  return model;
}

}  // namespace

int FemModel::node_index(long tag) const {
  const auto it = node_by_tag.find(tag);
  return it == node_by_tag.end() ? -1 : it->second;
}

int FemModel::element_index(long tag) const {
  const auto it = element_by_tag.find(tag);
  return it == element_by_tag.end() ? -1 : it->second;
}

FemModel parse_fem_model(const std::string& text, const std::filesystem::path& file) {
  const json root = json::parse(text, nullptr, false);
  if (root.is_discarded()) return parse_line_by_line(text, file);
  const auto sam = root.find("StructuralAnalysisModel");
  if (sam == root.end() || !sam->is_object())
    throw common::InputError(where(file, "StructuralAnalysisModel"), "missing (expected OpenSees `print -JSON` output)");
  const auto geometry = sam->find("geometry");
  if (geometry == sam->end() || !geometry->is_object())
    throw common::InputError(where(file, "StructuralAnalysisModel.geometry"), "missing");
  FemModel model;
  model.source = file;
  const auto nodes = geometry->find("nodes");
  if (nodes != geometry->end() && nodes->is_array())
    for (std::size_t i = 0; i < nodes->size(); ++i) add_node(model, (*nodes)[i], where(file, "geometry.nodes[" + std::to_string(i) + "]"));
  const auto elements = geometry->find("elements");
  if (elements != geometry->end() && elements->is_array())
    for (std::size_t i = 0; i < elements->size(); ++i)
      add_element(model, (*elements)[i], where(file, "geometry.elements[" + std::to_string(i) + "]"));
  if (const auto props = sam->find("properties"); props != sam->end() && props->is_object())
    if (const auto mats = props->find("ndMaterials"); mats != props->end() && mats->is_array())
      for (const auto& m : *mats)
        if (m.is_object()) add_material(model, m);
  finish(model, file);
  return model;
}

FemModel read_fem_model(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw common::InputError(file.string(), "cannot open the model file (expected `print -JSON` output)");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return parse_fem_model(buffer.str(), file);
}

}  // namespace bridge
