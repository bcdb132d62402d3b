// Queries (nodeDisp ... getLoadFactor) in OpenSees' "%35.20f" format, record, recorder, print -JSON.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <vector>

#include "common/atomic_file.hpp"
#include "fem_tcl/recorders/recorders.hpp"
#include "fem_tcl/tcl/commands.hpp"

namespace fem::tcl {

std::string format_values(const double* values, std::size_t n) {
  std::string out;
  char buffer[400];
  for (std::size_t i = 0; i < n; ++i) {
    std::snprintf(buffer, sizeof buffer, "%35.20f", values[i]);
    out += buffer;
  }
  return out;
}

namespace {

/// Appends `word` to a space-separated Tcl list of plain words.
void append_word(std::string& list, const std::string& word) {
  if (!list.empty()) list += ' ';
  list += word;
}

enum class NodeQuantity { Disp, Vel, Accel, Coord, Reaction };

std::string node_query(Context& ctx, common::CommandArgs& args, NodeQuantity q) {
  const int tag = args.integer("nodeTag");
  int dof = 0;
  if (!args.empty()) dof = args.integer(q == NodeQuantity::Coord ? "dim" : "dof");
  args.expect_end();
  const domain::Node& n = ctx.domain.node(tag, args.command());
  const double* v = nullptr;
  switch (q) {
    case NodeQuantity::Disp: v = n.disp.data(); break;
    case NodeQuantity::Vel: v = n.vel.data(); break;
    case NodeQuantity::Accel: v = n.accel.data(); break;
    case NodeQuantity::Coord: v = n.crd.data(); break;
    case NodeQuantity::Reaction: v = n.reaction.data(); break;
  }
  const int count = q == NodeQuantity::Coord ? 2 : n.ndf;
  if (dof == 0) return format_values(v, count);
  if (dof < 1 || dof > count) {
    args.fail("expected " + std::string(q == NodeQuantity::Coord ? "dim" : "dof") + " 1.." + std::to_string(count) +
              " (node " + std::to_string(tag) + " has " + std::to_string(count) + "), got " + std::to_string(dof));
  }
  return format_values(v + dof - 1, 1);
}

}  // namespace

std::string cmd_node_disp(Context& c, common::CommandArgs& a) { return node_query(c, a, NodeQuantity::Disp); }
std::string cmd_node_vel(Context& c, common::CommandArgs& a) { return node_query(c, a, NodeQuantity::Vel); }
std::string cmd_node_accel(Context& c, common::CommandArgs& a) { return node_query(c, a, NodeQuantity::Accel); }
std::string cmd_node_coord(Context& c, common::CommandArgs& a) { return node_query(c, a, NodeQuantity::Coord); }
std::string cmd_node_reaction(Context& c, common::CommandArgs& a) { return node_query(c, a, NodeQuantity::Reaction); }

std::string cmd_ele_response(Context& ctx, common::CommandArgs& args) {
  const int tag = args.integer("eleTag");
  std::vector<std::string> response;
  while (!args.empty()) response.push_back(args.word("response"));
  if (response.empty()) args.fail("missing response (e.g. stress, stresses, forces, material 1 strain)");
  domain::Element& e = ctx.domain.element(tag, args.command());
  const auto values = e.response(response);
  if (!values) args.fail("element " + std::to_string(tag) + " (" + e.type_name() + ") has no response '" + response[0] + "'");
  return format_values(values->data(), values->size());
}

/// OpenSees `getNDF <nodeTag>`: the node's number of dofs, or without a tag the model builder's.
std::string cmd_get_ndf(Context& ctx, common::CommandArgs& args) {
  if (args.empty()) return std::to_string(ctx.ndf);
  const int tag = args.integer("nodeTag");
  args.expect_end();
  return std::to_string(ctx.domain.node(tag, args.command()).ndf);
}

std::string cmd_get_node_tags(Context& ctx, common::CommandArgs& args) {
  args.expect_end();
  std::string out;
  for (const auto& [tag, n] : ctx.domain.nodes()) append_word(out, std::to_string(tag));
  return out;
}

std::string cmd_get_ele_tags(Context& ctx, common::CommandArgs& args) {
  args.expect_end();
  std::string out;
  for (const auto& [tag, e] : ctx.domain.elements()) append_word(out, std::to_string(tag));
  return out;
}

std::string cmd_ele_nodes(Context& ctx, common::CommandArgs& args) {
  const int tag = args.integer("eleTag");
  args.expect_end();
  const domain::Element& e = ctx.domain.element(tag, args.command());
  std::string out;
  for (int a = 0; a < e.num_nodes(); ++a) append_word(out, std::to_string(e.nodes()[a]->tag));
  return out;
}

std::string cmd_reactions(Context& ctx, common::CommandArgs& args) {
  if (args.flag("-incInertia") || args.flag("-dynamic") || args.flag("-rayleigh")) {
    args.fail("only static reactions (no flag) are supported");
  }
  args.expect_end();
  ctx.domain.compute_reactions();
  return {};
}

std::string cmd_get_load_factor(Context& ctx, common::CommandArgs& args) {
  const int tag = args.integer("patternTag");
  args.expect_end();
  const domain::LoadPattern* p = ctx.domain.find_pattern(tag);
  if (!p) args.fail("load pattern " + std::to_string(tag) + " does not exist");
  const double f = p->last_factor();
  return format_values(&f, 1);
}

std::string cmd_test_iter(Context& ctx, common::CommandArgs& args) {
  args.expect_end();
  if (!ctx.analysis) return "0";
  return std::to_string(ctx.analysis->test().norms().size());
}

std::string cmd_test_norm(Context& ctx, common::CommandArgs& args) {
  args.expect_end();
  std::string out;
  if (!ctx.analysis) return out;
  char buffer[64];
  for (double n : ctx.analysis->test().norms()) {
    std::snprintf(buffer, sizeof buffer, "%.17g", n);
    append_word(out, buffer);
  }
  return out;
}

std::string cmd_min_jacobian(Context& ctx, common::CommandArgs& args) {
  const bool ratio = args.flag("-ratio");
  args.expect_end();
  if (ctx.domain.elements().empty()) args.fail("the model has no elements");
  const domain::MeshQuality q = ctx.domain.mesh_quality();
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", ratio ? q.min_ratio : q.min_det_j);
  return std::string(buffer) + " " + std::to_string(ratio ? q.min_ratio_element : q.min_det_j_element);
}

std::string cmd_mesh_quality(Context& ctx, common::CommandArgs& args) {
  if (args.flag("-warn")) {
    const double r = args.number("-warn ratio");
    if (!(r >= 0.0 && r < 1.0)) args.fail("expected 0 <= -warn ratio < 1 (0 disables the threshold warning)");
    ctx.domain.set_mesh_warning_ratio(r);
  }
  args.expect_end();
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", ctx.domain.mesh_warning_ratio());
  return buffer;
}

std::string cmd_record(Context& ctx, common::CommandArgs& args) {
  args.expect_end();
  ctx.domain.record();
  return {};
}

std::string cmd_recorder(Context& ctx, common::CommandArgs& args) {
  return std::to_string(ctx.domain.add_recorder(recorders::parse_recorder(args, ctx.domain, ctx.time_series)));
}

namespace {

void write_json_list(std::ostream& os, const char* indent, const std::vector<std::string>& items) {
  os << "[\n";
  for (std::size_t i = 0; i < items.size(); ++i) {
    os << indent << "\t" << items[i] << (i + 1 < items.size() ? ",\n" : "\n");
  }
  if (items.empty()) os << "\n";
  os << indent << "]";
}

void write_model_json(Context& ctx, std::ostream& os) {
  std::vector<std::string> uniaxial, materials, nodes, elements;
  for (const auto& [tag, m] : ctx.uniaxial_materials) uniaxial.push_back(m->to_json().dump());
  for (const auto& [tag, m] : ctx.materials) materials.push_back(m->to_json().dump());
  for (const auto& [tag, n] : ctx.domain.nodes()) {
    nlohmann::ordered_json j;
    j["name"] = tag;
    j["ndf"] = n->ndf;
    j["crd"] = {n->crd[0], n->crd[1]};
    if (n->has_mass) j["mass"] = std::vector<double>(n->mass.data(), n->mass.data() + n->ndf);
    nodes.push_back(j.dump());
  }
  for (const auto& [tag, e] : ctx.domain.elements()) elements.push_back(e->to_json().dump());
  // Supports (fem_tcl's addition: OpenSees 3.8's print -JSON writes no SP or MP constraints). One entry per
  // line, dofs 1-based as in the Tcl commands: {"node": n, "fix": [fx, fy <, fp>]} (one flag per dof of the
  // node), {"retained": r, "constrained": c, "dofs": [..]}.
  std::vector<std::string> fixes, ties;
  for (const auto& [tag, n] : ctx.domain.nodes()) {
    if (std::none_of(n->fixed.begin(), n->fixed.begin() + n->ndf, [](bool f) { return f; })) continue;
    nlohmann::ordered_json j;
    j["node"] = tag;
    j["fix"] = nlohmann::ordered_json::array();
    for (int d = 0; d < n->ndf; ++d) j["fix"].push_back(n->fixed[static_cast<std::size_t>(d)] ? 1 : 0);
    fixes.push_back(j.dump());
  }
  for (const auto& c : ctx.domain.equal_dofs()) {
    nlohmann::ordered_json j;
    j["retained"] = c.retained;
    j["constrained"] = c.constrained;
    j["dofs"] = nlohmann::ordered_json::array();
    for (int d : c.dofs) j["dofs"].push_back(d + 1);
    ties.push_back(j.dump());
  }
  os << "{\n\"StructuralAnalysisModel\": {\n";
  os << "\t\"BIM\": \"unknown\",\n\t\"description\": \"\",\n\t\"engineer\": \"\",\n";
  os << "\t\"units\": {\n\t\t\"force\": \"\",\n\t\t\"length\": \"\",\n\t\t\"time\": \"\",\n\t\t\"temperature\": \"\"\n\t},\n";
  os << "\t\"properties\": {\n\t\t\"uniaxialMaterials\": ";
  write_json_list(os, "\t\t", uniaxial);
  os << ",\n\t\t\"ndMaterials\": ";
  write_json_list(os, "\t\t", materials);
  os << ",\n\t\t\"sections\": ";
  write_json_list(os, "\t\t", {});
  os << ",\n\t\t\"crdTransformations\": ";
  write_json_list(os, "\t\t", {});
  os << "\n\t},\n\t\"geometry\": {\n\t\t\"nodes\": ";
  write_json_list(os, "\t\t", nodes);
  os << ",\n\t\t\"elements\": ";
  write_json_list(os, "\t\t", elements);
  os << "\n\t},\n\t\"constraints\": {\n\t\t\"fix\": ";
  write_json_list(os, "\t\t", fixes);
  os << ",\n\t\t\"equalDOF\": ";
  write_json_list(os, "\t\t", ties);
  os << "\n\t}\n}\n}\n";
}

}  // namespace

namespace {
/// OpenSees' text print of a node (Node::Print, flag 0): coordinates, displacements, velocities,
/// unbalanced load and reaction.
void print_node(std::ostream& out, const domain::Node& n) {
  const auto values = [&](const char* what, const double* v, int count) {
    out << "\n\t" << what;
    for (int d = 0; d < count; ++d) out << (d ? " " : "") << v[d];
  };
  out << "\n Node: " << n.tag;
  values("Coordinates  : ", n.crd.data(), 2);
  values("Disps: ", n.disp.data(), n.ndf);
  values("Velocities   : ", n.vel.data(), n.ndf);
  values("unbalanced Load: ", n.load.data(), n.ndf);
  values("Reaction: ", n.reaction.data(), n.ndf);
  out << "\n";
}
/// An element: tag, type, nodes and resisting forces (its dofs per node of Element::form_resisting_force).
void print_element(std::ostream& out, domain::Element& e, int tag) {
  out << "\nElement: " << tag << " type: " << e.type_name() << "\n\tConnected Nodes:";
  for (int a = 0; a < e.num_nodes(); ++a) out << ' ' << e.nodes()[a]->tag;
  out << "\n\tResisting force:";
  domain::ElementVector f;
  e.form_resisting_force(f);
  for (int i = 0; i < e.num_dofs(); ++i) out << ' ' << f[i];
  out << "\n";
}
/// Tags after -node / -ele (OpenSees' optional `-flag f` is read and ignored: one level of detail here).
std::vector<int> print_tags(common::CommandArgs& args) {
  if (args.flag("-flag")) args.integer("-flag value");
  std::vector<int> tags;
  while (auto t = args.optional_integer()) tags.push_back(*t);
  return tags;
}
}  // namespace

/// `print -JSON <-file f>` (the model for fem2mpm), or OpenSees' text print: `print <file> <-node <-flag f>
/// tags..> <-ele <-flag f> tags..>` (no tags: every node / element; neither option: the whole model), to
/// the file or, as OpenSees' opserr, to stderr.
std::string cmd_print(Context& ctx, common::CommandArgs& args) {
  bool json = false, nodes = false, elements = false;
  std::string file;
  std::vector<int> node_tags, element_tags;
  while (!args.empty()) {
    if (args.flag("-JSON")) json = true;
    else if (args.flag("-file")) file = args.word("-file name");
    else if (args.flag("-node")) { nodes = true; node_tags = print_tags(args); }
    else if (args.flag("-ele")) { elements = true; element_tags = print_tags(args); }
    else if (args.peek().rfind('-', 0) == 0) args.fail("unsupported option '" + args.peek() + "' (-JSON, -file, -node, -ele)");
    else file = args.word("file name");
  }
  if (json) {
    if (nodes || elements) args.fail("-JSON prints the whole model; give -node / -ele without it");
    if (file.empty()) {
      write_model_json(ctx, std::cout);
      std::cout.flush();
      return {};
    }
    common::AtomicTextFile out(file);
    write_model_json(ctx, out.stream());
    out.commit();
    return {};
  }
  if (!nodes && !elements) nodes = elements = true;
  std::ostringstream text;
  text.precision(10);
  if (nodes) {
    if (node_tags.empty()) for (const auto& [tag, n] : ctx.domain.nodes()) node_tags.push_back(tag);
    for (int tag : node_tags) print_node(text, ctx.domain.node(tag, args.command()));
  }
  if (elements) {
    if (element_tags.empty()) for (const auto& [tag, e] : ctx.domain.elements()) element_tags.push_back(tag);
    for (int tag : element_tags) print_element(text, ctx.domain.element(tag, args.command()), tag);
  }
  if (file.empty()) {
    std::cerr << text.str();
    return {};
  }
  common::AtomicTextFile out(file);
  out.stream() << text.str();
  out.commit();
  return {};
}

}  // namespace fem::tcl
