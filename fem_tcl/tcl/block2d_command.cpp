// `block2D numX numY startNode startEle eleType eleArgs <-numEleNodes 4> {1 x y 2 x y 3 x y 4 x y <5 x y .. 9 x y>}`:
// OpenSees' structured quadrilateral mesh generator (OpenSees 3.8, TclCommand_doBlock2D in
// SRC/modelbuilder/tcl/TclModelBuilder.cpp). The nodes come from the 9-node Lagrange map of
// fem_tcl/elements/block2d.hpp; each element is made, as in OpenSees, by evaluating
//   element <eleType> <tag> <n1> <n2> <n3> <n4> <eleArgs>
// in the caller's scope, so eleArgs are the element type's own arguments after its nodes (SSPquad:
// matTag type thick <b1 b2>; quad: thick type matTag <p rho b1 b2>) and any Tcl substitution left in them
// happens then, as in OpenSees. Differences, all errors where OpenSees warns or goes on: a missing
// corner point, a repeated point, numX or numY < 1, a node or element tag already in use (checked before
// anything is created), an element type fem_tcl does not have, a block with crossed corners or zero area,
// and `-numEleNodes 9` (fem_tcl has no 9-node element).
#include <tcl.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "fem_tcl/elements/block2d.hpp"
#include "fem_tcl/elements/element_registry.hpp"
#include "fem_tcl/tcl/commands.hpp"

namespace fem::tcl {

namespace {

/// The words of a Tcl list (the block's point list, `{1 0 0 2 10 0 ...}`).
std::vector<std::string> split_list(Context& ctx, common::CommandArgs& args, const std::string& list, std::string_view what) {
  int count = 0;
  const char** items = nullptr;
  if (Tcl_SplitList(ctx.interp, list.c_str(), &count, &items) != TCL_OK) {
    args.fail("expected " + std::string(what) + " as a Tcl list: " + Tcl_GetStringResult(ctx.interp));
  }
  std::vector<std::string> words(items, items + count);
  Tcl_Free(reinterpret_cast<char*>(items));
  return words;
}

elements::Block2dPoints parse_points(Context& ctx, common::CommandArgs& args, const std::string& list) {
  const std::vector<std::string> words = split_list(ctx, args, list, "the block points {1 x y 2 x y ...}");
  if (words.size() % 3 != 0) {
    args.fail("expected the block points as triples 'point x y' (points 1-4 required, 5-9 optional), got " +
              std::to_string(words.size()) + " words");
  }
  elements::Block2dPoints points;
  for (std::size_t k = 0; k < words.size(); k += 3) {
    const auto id = common::CommandArgs::parse_integer(words[k]);
    if (!id || *id < 1 || *id > 9) args.fail("expected a block point number 1-9, got '" + words[k] + "'");
    if (points[*id - 1]) args.fail("block point " + words[k] + " is given twice");
    const auto x = common::CommandArgs::parse_number(words[k + 1]);
    const auto y = common::CommandArgs::parse_number(words[k + 2]);
    if (!x || !y || !std::isfinite(*x) || !std::isfinite(*y)) {
      args.fail("expected finite coordinates x y for block point " + words[k] + ", got '" + words[k + 1] + " " +
                words[k + 2] + "'");
    }
    points[*id - 1] = domain::Vector2(*x, *y);
  }
  for (int k = 0; k < 4; ++k) {
    if (!points[k]) args.fail("block corner point " + std::to_string(k + 1) + " is missing (points 1-4 are required)");
  }
  return points;
}

/// The most nodes one block2D makes (a typo such as 100000 x 100000 fails at once instead of exhausting memory).
constexpr long long kMaxBlockNodes = 20'000'000;

}  // namespace

std::string cmd_block2d(Context& ctx, common::CommandArgs& args) {
  if (!ctx.model_defined) args.fail("no model defined; start the script with 'model basic -ndm 2 -ndf 2'");
  const int num_x = args.integer("numX");
  const int num_y = args.integer("numY");
  const int start_node = args.integer("startNode");
  const int start_ele = args.integer("startEle");
  const std::string type = args.word("eleType");
  const std::string ele_args = args.word("eleArgs");
  if (args.flag("-numEleNodes")) {
    const int n = args.integer("-numEleNodes value");
    if (n == 9) {
      args.fail("-numEleNodes 9: fem_tcl has no 9-node element (OpenSees' 9_4_QuadUP / quad9n are not implemented); "
                "use 4-node elements (-numEleNodes 4, the default)");
    }
    if (n != 4) args.fail("expected -numEleNodes 4 or 9, got " + std::to_string(n));
  }
  const std::string point_list = args.word("the block points {1 x y 2 x y 3 x y 4 x y ...}");
  args.expect_end();
  if (num_x < 1 || num_y < 1) {
    args.fail("expected numX and numY >= 1, got " + std::to_string(num_x) + " and " + std::to_string(num_y));
  }
  // The block's size and last tags before anything is allocated: (numX + 1) (numY + 1) nodes from
  // startNode, numX numY elements from startEle, all within Tcl's (and OpenSees') int tags.
  const long long nodes = (static_cast<long long>(num_x) + 1) * (static_cast<long long>(num_y) + 1);
  const long long elements = static_cast<long long>(num_x) * num_y;
  if (nodes > kMaxBlockNodes) {
    args.fail("a block of " + std::to_string(nodes) + " nodes is beyond fem_tcl's limit of " +
              std::to_string(kMaxBlockNodes) + " per block (about 1 GB per million nodes in the analysis)");
  }
  constexpr long long kMaxTag = std::numeric_limits<int>::max();
  if (start_node + nodes - 1 > kMaxTag || start_ele + elements - 1 > kMaxTag) {
    args.fail("the block's tags would pass " + std::to_string(kMaxTag) + " (nodes " + std::to_string(start_node) + "-" +
              std::to_string(start_node + nodes - 1) + ", elements " + std::to_string(start_ele) + "-" +
              std::to_string(start_ele + elements - 1) + ")");
  }
  // block2D makes 4-node elements here (-numEleNodes 9 is refused above).
  if (const auto* entry = elements::find_element_parser(type); !entry || entry->nodes != 4) {
    std::string known;
    for (const auto& e : elements::element_parsers())
      if (e.nodes == 4) known += (known.empty() ? "" : ", ") + std::string(e.type);
    args.fail((entry ? "element type '" + type + "' has " + std::to_string(entry->nodes) + " nodes; block2D makes 4-node elements"
                     : "unknown element type '" + type + "'") + " (4-node types: " + known + ")");
  }
  const elements::Block2dPoints points = parse_points(ctx, args, point_list);
  if (const auto bad = elements::block2d_invalid_corners(points)) args.fail(*bad);
  const std::vector<domain::Vector2> coords = elements::block2d_node_coords(num_x, num_y, points);
  if (const auto bad = elements::block2d_invalid_element(num_x, num_y, coords)) {
    args.fail("the block's points do not map onto valid elements: " + *bad +
              "; give the mid-side points 5-8 near their edges and the centre 9 inside");
  }
  // every tag free before anything is created
  const int num_nodes = static_cast<int>(coords.size());
  for (int k = 0; k < num_nodes; ++k) {
    if (ctx.domain.find_node(start_node + k)) {
      args.fail("node " + std::to_string(start_node + k) + " already exists (the block's nodes are " +
                std::to_string(start_node) + "-" + std::to_string(start_node + num_nodes - 1) + ")");
    }
  }
  const int num_elements = num_x * num_y;
  for (int k = 0; k < num_elements; ++k) {
    if (ctx.domain.find_element(start_ele + k)) {
      args.fail("element " + std::to_string(start_ele + k) + " already exists (the block's elements are " +
                std::to_string(start_ele) + "-" + std::to_string(start_ele + num_elements - 1) + ")");
    }
  }
  for (int k = 0; k < num_nodes; ++k) ctx.domain.add_node(start_node + k, coords[k].x(), coords[k].y(), ctx.ndf, args.command());
  for (int j = 0; j < num_y; ++j) {
    for (int i = 0; i < num_x; ++i) {
      const int tag = start_ele + i + j * num_x;
      std::ostringstream command;
      command << "element " << type << ' ' << tag;
      for (int offset : elements::block2d_element_nodes(num_x, i, j)) command << ' ' << start_node + offset;
      command << ' ' << ele_args;
      const std::string script = command.str();
      if (Tcl_EvalEx(ctx.interp, script.c_str(), static_cast<int>(script.size()), 0) != TCL_OK) {
        throw common::InputError(args.command(), "element " + std::to_string(tag) + " (block element (" +
                                                     std::to_string(i) + ", " + std::to_string(j) + "), '" + script +
                                                     "'): " + Tcl_GetStringResult(ctx.interp));
      }
    }
  }
  return {};
}

}  // namespace fem::tcl
