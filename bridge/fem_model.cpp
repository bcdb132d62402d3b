#include "bridge/fem_model.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string_view>
#include <sstream>

#include "common/input_error.hpp"
#include "common/json_file.hpp"
#include "common/number_text.hpp"

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

void insert_node(FemModel& model, const FemNode& node, const std::string& where_text) {
  if (!model.node_by_tag.emplace(node.tag, static_cast<int>(model.nodes.size())).second)
    throw common::InputError(where_text, "duplicate node tag " + std::to_string(node.tag));
  model.nodes.push_back(node);
}

void insert_element(FemModel& model, const FemElement& e, const std::string& where_text) {
  if (!model.element_by_tag.emplace(e.tag, static_cast<int>(model.elements.size())).second)
    throw common::InputError(where_text, "duplicate element tag " + std::to_string(e.tag));
  model.elements.push_back(e);
}

/// One flat JSON object on one line, as OpenSees and fem_tcl write geometry entries:
/// {"key": value, ...} with values a number, a "string" (no escapes), an array of up to 8 numbers,
/// null, true or false. Parsed without allocation; anything else makes parse() return false and the
/// caller falls back to the full JSON parser (which also produces the error messages).
struct FlatValue {
  enum class Kind { Number, String, Array, Other } kind = Kind::Other;
  double number = 0;
  bool integral = false;          ///< a number token without '.', 'e' or 'E'
  std::string_view text;          ///< the string, or the number's token
  std::array<double, 8> items{};
  int count = 0;
};

class FlatEntry {
 public:
  using Value = FlatValue;

  bool parse(std::string_view s) {
    count_ = 0;
    std::size_t i = 0;
    auto ws = [&] { while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r')) ++i; };
    auto token_end = [&](std::size_t k) {
      while (k < s.size() && s[k] != ',' && s[k] != '}' && s[k] != ']' && s[k] != ' ' && s[k] != '\t') ++k;
      return k;
    };
    auto number = [&](double& v, std::string_view& tok) {
      const std::size_t end = token_end(i);
      tok = s.substr(i, end - i);
      const char* b = tok.data();
      if (!tok.empty() && *b == '+') ++b;
      const auto res = std::from_chars(b, tok.data() + tok.size(), v);
      // from_chars also reads "nan" and "inf", which are not JSON: the JSON parser reports them
      if (res.ec != std::errc() || res.ptr != tok.data() + tok.size() || !std::isfinite(v)) return false;
      i = end;
      return true;
    };
    ws();
    if (i >= s.size() || s[i++] != '{') return false;
    for (;;) {
      ws();
      if (i < s.size() && s[i] == '}' && count_ == 0) { ++i; break; }
      if (i >= s.size() || s[i++] != '"' || count_ == static_cast<int>(fields_.size())) return false;
      const std::size_t key_end = s.find('"', i);
      if (key_end == std::string_view::npos) return false;
      auto& [key, value] = fields_[static_cast<std::size_t>(count_++)];
      key = s.substr(i, key_end - i);
      value = Value{};
      i = key_end + 1;
      ws();
      if (i >= s.size() || s[i++] != ':') return false;
      ws();
      if (i >= s.size()) return false;
      const char c = s[i];
      if (c == '"') {
        const std::size_t end = s.find('"', i + 1);
        if (end == std::string_view::npos) return false;
        value.kind = Value::Kind::String;
        value.text = s.substr(i + 1, end - i - 1);
        if (value.text.find('\\') != std::string_view::npos) return false;
        i = end + 1;
      } else if (c == '[') {
        ++i;
        value.kind = Value::Kind::Array;
        ws();
        if (i < s.size() && s[i] == ']') {
          ++i;
        } else {
          for (;;) {
            ws();
            std::string_view tok;
            if (value.count == static_cast<int>(value.items.size()) || !number(value.items[static_cast<std::size_t>(value.count)], tok)) return false;
            ++value.count;
            ws();
            if (i < s.size() && s[i] == ',') { ++i; continue; }
            if (i < s.size() && s[i] == ']') { ++i; break; }
            return false;
          }
        }
      } else if (c == '-' || c == '+' || (c >= '0' && c <= '9')) {
        value.kind = Value::Kind::Number;
        if (!number(value.number, value.text)) return false;
        value.integral = value.text.find_first_of(".eE") == std::string_view::npos;
      } else if (s.substr(i, 4) == "null" || s.substr(i, 4) == "true" || s.substr(i, 5) == "false") {
        i = token_end(i);
      } else {
        return false;
      }
      ws();
      if (i < s.size() && s[i] == ',') { ++i; continue; }
      if (i < s.size() && s[i] == '}') { ++i; break; }
      return false;
    }
    ws();
    return i == s.size();
  }

  const Value* find(std::string_view key) const {
    for (int k = 0; k < count_; ++k)
      if (fields_[static_cast<std::size_t>(k)].first == key) return &fields_[static_cast<std::size_t>(k)].second;
    return nullptr;
  }

  /// An integer tag: an integral number, or a string of digits.
  std::optional<long> tag(std::string_view key) const {
    const Value* v = find(key);
    if (!v) return std::nullopt;
    long out = 0;
    if (v->kind == Value::Kind::Number && v->integral) {
      const auto res = std::from_chars(v->text.data() + (v->text[0] == '+'), v->text.data() + v->text.size(), out);
      if (res.ec == std::errc()) return out;
    }
    if (v->kind == Value::Kind::String) {
      const auto res = std::from_chars(v->text.data(), v->text.data() + v->text.size(), out);
      if (res.ec == std::errc() && res.ptr == v->text.data() + v->text.size()) return out;
    }
    return std::nullopt;
  }

 private:
  std::array<std::pair<std::string_view, Value>, 16> fields_{};
  int count_ = 0;
};

/// The element kinds by OpenSees type word (false: not one of them).
bool element_kind(std::string_view type, ElementKind& kind, bool& pore_pressure) {
  pore_pressure = false;
  if (type == "SSPquad") kind = ElementKind::SSPquad;
  else if (type == "FourNodeQuad" || type == "quad") kind = ElementKind::Quad;
  else if (type == "Tri31") kind = ElementKind::Tri31;
  else if (type == "SSPquadUP") kind = ElementKind::SSPquad, pore_pressure = true;
  else if (type == "FourNodeQuadUP" || type == "quadUP") kind = ElementKind::Quad, pore_pressure = true;
  else return false;
  return true;
}

/// A node's "ndf": 1 to 6 dofs; nullopt when the entry has none (the node is then taken as 2-dof).
std::optional<int> ndf_of(double value, bool integral, const std::string& where_text) {
  if (!integral || value < 1 || value > 6)
    throw common::InputError(where_text, "expected \"ndf\" to be a whole number of dofs 1 to 6, got " +
                                             common::number_text(value, 6));
  return static_cast<int>(value);
}

/// The fast path for a node line; false when the entry is not in the plain form (use the JSON parser).
bool add_node_fast(FemModel& model, const FlatEntry& f, const std::string& where_text) {
  const auto tag = f.tag("name");
  const auto* crd = f.find("crd");
  if (!tag || !crd || crd->kind != FlatEntry::Value::Kind::Array || crd->count != 2) return false;
  FemNode node;
  node.tag = *tag;
  if (const auto* ndf = f.find("ndf")) {
    if (ndf->kind != FlatEntry::Value::Kind::Number) return false;
    node.ndf = *ndf_of(ndf->number, ndf->integral, where_text);
  }
  node.crd = Eigen::Vector2d(crd->items[0], crd->items[1]);
  insert_node(model, node, where_text);
  return true;
}

/// The fast path for an element line; false when the entry is not in the plain form.
bool add_element_fast(FemModel& model, const FlatEntry& f, const std::string& where_text) {
  using Kind = FlatEntry::Value::Kind;
  const auto tag = f.tag("name");
  const auto* type = f.find("type");
  const auto* nodes = f.find("nodes");
  if (!tag || !type || type->kind != Kind::String || !nodes || nodes->kind != Kind::Array) return false;
  FemElement e;
  e.tag = *tag;
  if (!element_kind(type->text, e.kind, e.pore_pressure)) return false;
  if (nodes->count != node_count(e.kind)) return false;
  for (int a = 0; a < node_count(e.kind); ++a) {
    const double v = nodes->items[static_cast<std::size_t>(a)];
    if (v != std::floor(v) || std::abs(v) > 9e15) return false;
    e.node_tags[static_cast<std::size_t>(a)] = static_cast<long>(v);
  }
  if (const auto* t = f.find("thickness"); t && t->kind == Kind::Number) e.thickness = t->number;
  if (const auto* m = f.find("material")) {
    if (m->kind != Kind::String && !(m->kind == Kind::Number && m->integral)) return false;
    e.material = std::string(m->text);
  }
  if (const auto* r = f.find("masspervolume"); r && r->kind == Kind::Number) e.mass_per_volume = r->number;
  if (const auto* b = f.find("bodyForces"); b && b->kind == Kind::Array && b->count == 2)
    e.body_force = Eigen::Vector2d(b->items[0], b->items[1]);
  insert_element(model, e, where_text);
  return true;
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
  if (const auto ndf = j.find("ndf"); ndf != j.end()) {
    if (!ndf->is_number()) throw common::InputError(where_text, "expected \"ndf\" to be a number, got " + ndf->dump());
    node.ndf = *ndf_of(ndf->get<double>(), ndf->is_number_integer(), where_text);
  }
  insert_node(model, node, where_text);
}

void add_element(FemModel& model, const json& j, const std::string& where_text) {
  FemElement e;
  e.tag = tag_of(j, where_text);
  const std::string type = j.value("type", std::string());
  if (type == "ZeroLength") {
    model.boundary_devices.push_back(e.tag);
    return;
  }
  if (!element_kind(type, e.kind, e.pore_pressure))
    throw common::InputError(where_text, "element " + std::to_string(e.tag) + ": unsupported element type '" + type +
                                             "' (expected SSPquad, FourNodeQuad/quad, Tri31, SSPquadUP or FourNodeQuadUP)");
  const int count = node_count(e.kind);
  const auto nodes = j.find("nodes");
  if (nodes == j.end() || !nodes->is_array() || nodes->size() != static_cast<std::size_t>(count))
    throw common::InputError(where_text, "element " + std::to_string(e.tag) + ": expected \"nodes\" with " +
                                             std::to_string(count) + " node tags");
  for (int a = 0; a < count; ++a) {
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
  insert_element(model, e, where_text);
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
  // E and nu from a bulk and a shear modulus: E = 9 K G / (3 K + G), nu = (3 K - 2 G) / (2 (3 K + G)).
  const auto from_bulk_and_shear = [&m](std::optional<double> K, std::optional<double> G) {
    if (K && G && 3 * *K + *G > 0) {
      m.E = 9 * *K * *G / (3 * *K + *G);
      m.nu = (3 * *K - 2 * *G) / (2 * (3 * *K + *G));
    }
  };
  if (m.type == "DruckerPrager") {  // fem_tcl's entry (OpenSees 3.8 writes invalid JSON for it)
    from_bulk_and_shear(opt("K"), opt("G"));
    m.rho = opt("density");
    m.dp_sigma_y = opt("sigma_y");
    m.dp_rho = opt("rho");
    m.dp_rho_bar = opt("rho_bar");
    model.materials[m.name] = m;
    return;
  }
  if (m.type == "PM4Sand" || m.type == "PM4Silt") {  // fem_tcl's entries (OpenSees 3.8 prints a text block)
    m.pm4_G0 = opt(m.type == "PM4Sand" ? "G0" : "G_o");
    m.pm4_P_atm = opt("P_atm");
    m.phi_cv_deg = opt("phicv");
    m.nu = opt("nu");
    m.rho = opt("Den");
    model.materials[m.name] = m;
    return;
  }
  if (m.type == "PressureDependMultiYield02") {  // fem_tcl's entry (OpenSees 3.8 prints a bare word)
    from_bulk_and_shear(opt("refBulkModul"), opt("refShearModul"));
    m.rho = opt("rho");
    m.multi_yield_cohesion = opt("c");
    m.multi_yield_friction_deg = opt("frictionAng");
    model.materials[m.name] = m;
    return;
  }
  if (m.type == "PressureIndependMultiYield") {  // fem_tcl's entry (multi_yield_match.hpp)
    from_bulk_and_shear(opt("refBulkModul"), opt("refShearModul"));
    m.rho = opt("rho");
    m.multi_yield_cohesion = opt("cohesi");
    m.multi_yield_friction_deg = opt("frictionAng");
    model.materials[m.name] = m;
    return;
  }
  m.E = opt("E");
  m.nu = opt("nu");
  m.rho = opt("rho");
  m.phi_deg = opt("phi");
  m.cohesion = opt("c");
  m.psi_deg = opt("psi");
  m.tension = opt("tension");
  model.materials[m.name] = m;
}

/// One "constraints.fix" entry: {"node": tag, "fix": [0|1, 0|1]}, one flag per dof (a third for a u-p node's
/// pore pressure).
void add_fix(FemModel& model, const json& j, const std::string& where_text) {
  const auto node = j.find("node");
  const auto fix = j.find("fix");
  const bool flags_ok = fix != j.end() && fix->is_array() && (fix->size() == 2 || fix->size() == 3) &&
                        std::all_of(fix->begin(), fix->end(), [](const json& v) { return v.is_number_integer() && (v == 0 || v == 1); });
  if (!j.is_object() || node == j.end() || !node->is_number_integer() || !flags_ok)
    throw common::InputError(where_text, "expected {\"node\": tag, \"fix\": [0 or 1, 0 or 1]} (a third flag for a u-p "
                                         "node's pore pressure), got " + j.dump());
  model.fixes.push_back({node->get<long>(), (*fix)[0] == 1, (*fix)[1] == 1, fix->size() == 3 && (*fix)[2] == 1});
}

/// One "constraints.equalDOF" entry: {"retained": tag, "constrained": tag, "dofs": [1, 2 and/or 3]} (3: a u-p
/// node's pore pressure).
void add_tie(FemModel& model, const json& j, const std::string& where_text) {
  const auto retained = j.find("retained"), constrained = j.find("constrained"), dofs = j.find("dofs");
  const bool dofs_ok = dofs != j.end() && dofs->is_array() && !dofs->empty() &&
                       std::all_of(dofs->begin(), dofs->end(), [](const json& v) { return v.is_number_integer() && v >= 1 && v <= 3; });
  if (!j.is_object() || retained == j.end() || !retained->is_number_integer() || constrained == j.end() ||
      !constrained->is_number_integer() || !dofs_ok)
    throw common::InputError(where_text, "expected {\"retained\": tag, \"constrained\": tag, \"dofs\": [1, 2 and/or 3]}, got " + j.dump());
  FemTie t{retained->get<long>(), constrained->get<long>(), {}};
  for (const auto& d : *dofs) t.dofs.push_back(d.get<int>());
  model.ties.push_back(std::move(t));
}

/// Resolves element node tags to indices and checks the model is not empty.
void finish(FemModel& model, const std::filesystem::path& file) {
  if (model.nodes.empty()) throw common::InputError(where(file, "geometry.nodes"), "no nodes in the model");
  if (model.elements.empty()) throw common::InputError(where(file, "geometry.elements"), "no elements in the model");
  for (auto& e : model.elements) {
    for (int a = 0; a < node_count(e.kind); ++a) {
      const auto it = model.node_by_tag.find(e.node_tags[a]);
      if (it == model.node_by_tag.end())
        throw common::InputError(where(file, "geometry.elements"), "element " + std::to_string(e.tag) +
                                                                       " uses node " + std::to_string(e.node_tags[a]) +
                                                                       ", which is not in geometry.nodes");
      e.nodes[a] = it->second;
    }
  }
  auto known = [&](long tag, const std::string& key) {
    if (!model.node_by_tag.count(tag))
      throw common::InputError(where(file, key), "node " + std::to_string(tag) + " is not in geometry.nodes");
  };
  for (const auto& f : model.fixes) known(f.node, "constraints.fix");
  for (const auto& t : model.ties) {
    known(t.retained, "constraints.equalDOF");
    known(t.constrained, "constraints.equalDOF");
  }
}

/// A text block's first line, quoted in a note (printable, at most 80 characters).
std::string quoted_line(std::string_view line) {
  const auto first = line.find_first_not_of(" \t\r");
  std::string text(first == std::string_view::npos ? std::string_view() : line.substr(first, 80));
  while (!text.empty() && (text.back() == ' ' || text.back() == '\r')) text.pop_back();
  for (char& c : text)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
  return "'" + text + "'";
}

/// The numbers after `key` on a text line ("\tConnected external nodes:  1 2 4 3 ").
std::vector<double> numbers_after(std::string_view line, std::string_view key) {
  std::vector<double> out;
  const auto at = line.find(key);
  if (at == std::string_view::npos) return out;
  std::istringstream words{std::string(line.substr(at + key.size()))};
  for (double v; words >> v;) out.push_back(v);
  return out;
}

/// OpenSees 3.8's FourNodeQuadUP::Print writes a text block, not JSON, into print -JSON's element list
/// (SRC/element/UP-ucsd/FourNodeQuadUP.cpp, Print: "FourNodeQuadUP, element id:  N", "Connected external nodes:",
/// "thickness:", "mass density:" (the fluid's), "surface pressure:", "body forces:", the material's own Print,
/// then the Gauss-point stresses). The element is read from it: nodes, thickness, body forces, and the
/// material tag where the material prints one (PM4Sand / PM4Silt "... Material, tag: N", a JSON entry's
/// "name"); PressureDependMultiYield02 prints none, and the element's material is then left to the options.
class QuadUpTextBlock {
 public:
  static bool starts(std::string_view line) { return line.find("FourNodeQuadUP, element id:") != std::string_view::npos; }
  bool active() const { return active_; }

  void start(std::string_view line, std::string at) {
    active_ = true;
    at_ = std::move(at);
    element_ = FemElement{};
    element_.kind = ElementKind::Quad;
    element_.pore_pressure = true;
    const auto id = numbers_after(line, "element id:");
    tag_ok_ = id.size() == 1 && id[0] == std::floor(id[0]);
    if (tag_ok_) element_.tag = static_cast<long>(id[0]);
    nodes_ok_ = false;
    material_named_ = false;
  }

  /// One line of the block.
  void feed(std::string_view line) {
    if (const auto n = numbers_after(line, "Connected external nodes:"); !n.empty()) {
      nodes_ok_ = n.size() == 4;
      for (std::size_t a = 0; a < 4 && nodes_ok_; ++a) {
        nodes_ok_ = n[a] == std::floor(n[a]) && std::abs(n[a]) < 9e15;
        element_.node_tags[a] = static_cast<long>(n[a]);
      }
    } else if (const auto t = numbers_after(line, "thickness:"); t.size() == 1) {
      element_.thickness = t[0];
    } else if (const auto b = numbers_after(line, "body forces:"); b.size() == 2) {
      element_.body_force = Eigen::Vector2d(b[0], b[1]);
    } else if (const auto m = numbers_after(line, "Material, tag:"); m.size() == 1 && !material_named_) {
      element_.material = common::number_text(m[0], 17);
      material_named_ = true;
    } else if (const auto brace = line.find('{'); brace != std::string_view::npos && !material_named_) {
      const auto close = line.find('}', brace);
      const json j = json::parse(line.substr(brace, close == std::string_view::npos ? 0 : close - brace + 1), nullptr, false);
      if (j.is_object() && j.contains("name")) {
        element_.material = name_text(j["name"]);
        material_named_ = true;
      }
    }
  }

  /// The element read (throws InputError naming the block's first line when its id or nodes are missing).
  FemElement finish(std::vector<std::string>& skipped) {
    active_ = false;
    if (!tag_ok_ || !nodes_ok_)
      throw common::InputError(at_, "OpenSees' FourNodeQuadUP text block: expected \"element id: N\" and \"Connected "
                                    "external nodes:\" with 4 node tags");
    if (!material_named_)
      skipped.push_back(at_ + ": FourNodeQuadUP element " + std::to_string(element_.tag) + " (OpenSees' text block): its "
                        "material prints no tag (PressureDependMultiYield02): the material from the options");
    return element_;
  }

 private:
  bool active_ = false, tag_ok_ = false, nodes_ok_ = false, material_named_ = false;
  std::string at_;
  FemElement element_;
};

/// OpenSees 3.8 and fem_tcl write one node, element or material per line: read the entries line by
/// line (fast, and tolerant of the bare word OpenSees writes in DruckerPrager entries: that material is
/// then left to the options). nullopt when the text is not in that layout.
std::optional<FemModel> parse_line_by_line(const std::string& text, const std::filesystem::path& file,
                                           std::string& failure) {
  FemModel model;
  model.source = file;
  std::istringstream in(text);
  std::string line;
  enum class Section { None, Nodes, Elements, Materials, Fixes, Ties } section = Section::None;
  FlatEntry flat;
  QuadUpTextBlock quad_up;
  bool in_text_block = false;  // inside a material's or element's text block (OpenSees' non-JSON Print)
  std::size_t quad_up_blocks = 0;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string here = file.string() + ":" + std::to_string(line_no);
    if (section == Section::Elements && QuadUpTextBlock::starts(line)) {
      if (quad_up.active()) insert_element(model, quad_up.finish(model.skipped), here);
      quad_up.start(line, here);
      ++quad_up_blocks;
      continue;
    }
    if (quad_up.active()) {
      const auto lead = line.find_first_not_of(" \t\r");
      if (lead == std::string::npos || (line[lead] != ',' && line[lead] != ']')) {
        quad_up.feed(line);
        continue;
      }
      insert_element(model, quad_up.finish(model.skipped), here);
    }
    if (line.find("\"nodes\":") != std::string::npos && line.find('{') == std::string::npos) { section = Section::Nodes; continue; }
    if (line.find("\"elements\":") != std::string::npos && line.find('{') == std::string::npos) { section = Section::Elements; continue; }
    if (line.find("\"ndMaterials\":") != std::string::npos && line.find('{') == std::string::npos) { section = Section::Materials; continue; }
    if (line.find("\"constraints\":") != std::string::npos) model.has_constraints = true;
    if (line.find("\"fix\":") != std::string::npos && line.find('{') == std::string::npos) { section = Section::Fixes; continue; }
    if (line.find("\"equalDOF\":") != std::string::npos && line.find('{') == std::string::npos) { section = Section::Ties; continue; }
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    if (line[first] == ']') { section = Section::None; in_text_block = false; continue; }
    if (line[first] != '{' && line[first] != ',' && (section == Section::Materials || section == Section::Elements)) {
      // OpenSees 3.8's Print of PM4Sand, PM4Silt, PressureDependMultiYield02, Viscous, ... (a text block): skipped,
      // named once per block.
      if (!in_text_block) {
        const std::string what = section == Section::Materials ? "ndMaterials" : "elements";
        model.skipped.push_back(here + ": " + what + ": OpenSees' text block " + quoted_line(line) +
                                " is not JSON: skipped" +
                                (section == Section::Materials ? " (give that material with --material)" : ""));
        if (section == Section::Materials) model.materials_readable = false;
      }
      in_text_block = true;
      continue;
    }
    in_text_block = false;
    if (line[first] != '{' || section == Section::None) continue;
    std::string entry = line.substr(first);
    while (!entry.empty() && (entry.back() == ',' || entry.back() == ' ' || entry.back() == '\r')) entry.pop_back();
    const std::string at = file.string() + ":" + std::to_string(line_no);
    if (section != Section::Materials && flat.parse(entry) &&
        (section == Section::Nodes ? add_node_fast(model, flat, at) : add_element_fast(model, flat, at)))
      continue;
    const json j = json::parse(entry, nullptr, false);
    if (section == Section::Fixes || section == Section::Ties) {
      const std::string key = section == Section::Fixes ? "constraints.fix" : "constraints.equalDOF";
      if (j.is_discarded()) throw common::InputError(at + ": " + key, "cannot parse this entry as JSON");
      if (section == Section::Fixes) add_fix(model, j, at + ": " + key);
      else add_tie(model, j, at + ": " + key);
      continue;
    }
    if (j.is_discarded()) {
      if (section == Section::Materials) {  // the invalid entry OpenSees writes; materials come from options
        model.materials_readable = false;
        continue;
      }
      failure = at + ": cannot parse this entry as JSON";
      try {
        common::parse_json_text(entry, at);  // the parser's own reason, with the key
      } catch (const common::InputError& e) {
        failure = e.what();
      }
      return std::nullopt;  // not the one-entry-per-line layout after all
    }
    if (section == Section::Nodes) add_node(model, j, at);
    else if (section == Section::Elements) add_element(model, j, at);
    else add_material(model, j);
  }
  if (quad_up.active()) insert_element(model, quad_up.finish(model.skipped), file.string());
  if (quad_up_blocks > 0)
    model.skipped.push_back(file.string() + ": " + std::to_string(quad_up_blocks) + " FourNodeQuadUP elements read from "
                            "OpenSees' text blocks (not JSON): nodes, thickness, body forces, material tag");
  if (model.nodes.empty() || model.elements.empty()) return std::nullopt;  // not that layout
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
  std::string line_failure;
  if (auto lines = parse_line_by_line(text, file, line_failure)) return std::move(*lines);
  const json root = json::parse(text, nullptr, false);
  if (root.is_discarded()) {
    if (!line_failure.empty()) throw common::InputError(line_failure);
    common::parse_json_text(text, file.string());  // throws the parser's reason, naming the key
    throw common::InputError(file.string(), "not valid JSON, and not in print -JSON's one-entry-per-line layout");
  }
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
  if (const auto cons = sam->find("constraints"); cons != sam->end()) {
    if (!cons->is_object())
      throw common::InputError(where(file, "StructuralAnalysisModel.constraints"), "expected an object with \"fix\" and \"equalDOF\" lists");
    model.has_constraints = true;
    auto list = [&](const char* key, auto add) {
      const auto it = cons->find(key);
      if (it == cons->end()) return;
      const std::string k = std::string("constraints.") + key;
      if (!it->is_array()) throw common::InputError(where(file, k), "expected a list");
      for (std::size_t i = 0; i < it->size(); ++i) add(model, (*it)[i], where(file, k + "[" + std::to_string(i) + "]"));
    };
    list("fix", add_fix);
    list("equalDOF", add_tie);
  }
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
