#include "bridge/deck_boundaries.hpp"

#include "common/number_text.hpp"

namespace bridge {
namespace {

std::string num(double v) { return common::number_text(v, 6); }

std::string wall_text(Wall w) {
  switch (w) {
    case Wall::Roller: return "roller (x-velocity 0)";
    case Wall::Fixed: return "fixed (x- and y-velocity 0)";
    case Wall::None: return "none (free face)";
  }
  return "?";
}

std::string base_text(const DeckOptions& deck) {
  switch (deck.base) {
    case Base::Contact: return "contact mu = " + num(deck.base_friction) + " (one-sided: stops the approach, Coulomb friction)";
    case Base::Friction: return "friction mu = " + num(deck.base_friction) + " (y-velocity 0, Coulomb friction)";
    case Base::Roller: return "roller (y-velocity 0)";
    case Base::Fixed: return "fixed (x- and y-velocity 0)";
  }
  return "?";
}

/// Grid position of an edge: x of a wall, y of the base.
double position(GridEdge edge, const DeckText& d) {
  if (edge == GridEdge::Left) return d.grid.x0;
  if (edge == GridEdge::Right) return d.grid.x0 + d.grid.nx * d.grid.h;
  return d.base_y;
}

}  // namespace

std::vector<BoundaryChoice> apply_supports(const ExtractedBoundaries& supports, const BoundaryOptionsGiven& given,
                                           DeckOptions& deck) {
  std::vector<BoundaryChoice> out;
  const SupportLine* left = supports.line(GridEdge::Left);
  const SupportLine* right = supports.line(GridEdge::Right);
  const SupportLine* base = supports.line(GridEdge::Base);
  auto wall_of = [](const SupportLine* l) { return !l ? Wall::None : l->kind == SupportKind::Fixed ? Wall::Fixed : Wall::Roller; };
  auto choose_wall = [&](GridEdge edge, const SupportLine* line, bool option_given, Wall& wall) {
    BoundaryChoice c;
    c.edge = edge;
    if (line) c.line = *line;
    if (option_given) c.source = edge == GridEdge::Left ? "--left-wall" : "--right-wall";
    else if (!supports.from_model) c.source = "default (no FEM supports in the model file)";
    else {
      wall = wall_of(line);
      c.source = line ? "FEM support" : "FEM side without support";
    }
    c.condition = wall_text(wall);
    out.push_back(std::move(c));
  };
  choose_wall(GridEdge::Left, left, given.left, deck.left);
  choose_wall(GridEdge::Right, right, given.right, deck.right);
  BoundaryChoice b;
  b.edge = GridEdge::Base;
  if (base) b.line = *base;
  if (given.base) b.source = "--base";
  else if (!supports.from_model) b.source = "default (no FEM supports in the model file)";
  else if (!base) b.source = "default (the FEM model has no support on its base)";
  else {
    // A fixed FEM base becomes the frictional contact (--base-friction); --base fixed makes it fixed.
    deck.base = base->kind == SupportKind::Fixed ? Base::Contact : Base::Roller;
    b.source = "FEM support";
  }
  b.condition = base_text(deck);
  out.push_back(std::move(b));
  if (supports.from_model) {  // with --extent only the base height is taken (when it lies inside that grid)
    GridAnchors anchors;
    if (left && deck.left != Wall::None) anchors.left = left->coordinate;
    if (right && deck.right != Wall::None) anchors.right = right->coordinate;
    if (base && !given.base_y) anchors.base = base->coordinate;
    deck.anchors = anchors;
  }
  return out;
}

std::string boundary_text(const BoundaryChoice& c, const DeckText& d) {
  std::string s = edge_name(c.edge) + (c.edge == GridEdge::Base ? " at y = " : " at x = ") + num(position(c.edge, d)) +
                  ": " + c.condition + " [" + c.source + "]";
  if (c.line) {
    const char* along = c.edge == GridEdge::Base ? "x" : "y";
    s += "; FEM support line " + std::string(c.edge == GridEdge::Base ? "y = " : "x = ") + num(c.line->coordinate) + ", " +
         (c.line->kind == SupportKind::Fixed ? "fixed" : "roller") + ", " + along + " " + num(c.line->from) + " to " +
         num(c.line->to) + ", nodes " + node_list_text(c.line->nodes);
  }
  return s;
}

nlohmann::ordered_json boundaries_json(const std::vector<BoundaryChoice>& choices, const DeckText& d) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const auto& c : choices) {
    nlohmann::ordered_json j;
    j["edge"] = edge_name(c.edge);
    j[c.edge == GridEdge::Base ? "y" : "x"] = position(c.edge, d);
    j["condition"] = c.condition;
    j["source"] = c.source;
    if (c.line) {
      j["fem_line"] = {{c.edge == GridEdge::Base ? "y" : "x", c.line->coordinate},
                       {"kind", c.line->kind == SupportKind::Fixed ? "fixed" : "roller"},
                       {"from", c.line->from},
                       {"to", c.line->to},
                       {"nodes", c.line->nodes}};
    }
    list.push_back(std::move(j));
  }
  return list;
}

}  // namespace bridge
