#include "bridge/boundary_extraction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <set>


namespace bridge {
namespace {

struct Fixity {
  bool x = false, y = false;
};

/// Union-find over node indices: coincident nodes tied in both dofs become one node.
class NodeUnion {
 public:
  explicit NodeUnion(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  int find(int i) {
    while (parent_[static_cast<std::size_t>(i)] != i) i = parent_[static_cast<std::size_t>(i)] = parent_[static_cast<std::size_t>(parent_[static_cast<std::size_t>(i)])];
    return i;
  }
  void join(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
  }

 private:
  std::vector<int> parent_;
};

/// A boundary edge of the mesh carried to a grid edge.
struct EdgeOnLine {
  GridEdge edge;
  bool fixed_both;  ///< the two nodes are fixed in both directions
  int a, b;         ///< canonical node indices
};

std::vector<long> tags_of(const FemModel& model, const std::set<int>& nodes) {
  std::vector<long> tags;
  for (int i : nodes) tags.push_back(model.nodes[static_cast<std::size_t>(i)].tag);
  std::sort(tags.begin(), tags.end());
  return tags;
}

}  // namespace

const SupportLine* ExtractedBoundaries::line(GridEdge edge) const {
  for (const auto& l : lines)
    if (l.edge == edge) return &l;
  return nullptr;
}

std::string edge_name(GridEdge edge) {
  switch (edge) {
    case GridEdge::Left: return "left wall";
    case GridEdge::Right: return "right wall";
    case GridEdge::Base: return "base";
  }
  return "?";
}

std::string node_list_text(const std::vector<long>& tags) {
  std::string s;
  const std::size_t shown = tags.size() <= 12 ? tags.size() : 10;
  for (std::size_t i = 0; i < shown; ++i) {
    if (i) s += ' ';
    s += std::to_string(tags[i]);
  }
  if (shown < tags.size()) s += " ... " + std::to_string(tags.back()) + " (" + std::to_string(tags.size()) + " nodes)";
  return s;
}

ExtractedBoundaries extract_boundaries(const FemModel& model) {
  ExtractedBoundaries out;
  out.from_model = model.has_constraints;
  if (!model.boundary_devices.empty()) {
    std::string tags;
    for (std::size_t i = 0; i < model.boundary_devices.size() && i < 8; ++i) {
      if (i) tags += ' ';
      tags += std::to_string(model.boundary_devices[i]);
    }
    if (model.boundary_devices.size() > 8) tags += " ... (" + std::to_string(model.boundary_devices.size()) + " elements)";
    out.warnings.push_back("zeroLength elements " + tags + " (springs and dashpots of the FEM boundary) have no MPM "
                           "counterpart and are not transferred; the MPM boundaries come from the supports and options");
  }
  if (!model.has_constraints) {
    out.notes.push_back(model.source.string() + ": no supports in the model file (OpenSees' print -JSON writes no fix or "
                        "equalDOF; fem_tcl's does): the MPM boundaries come from the options (--left-wall, --right-wall, --base)");
    return out;
  }
  const std::size_t n = model.nodes.size();
  const auto crd = [&](int i) { return model.nodes[static_cast<std::size_t>(i)].crd; };
  std::vector<char> used(n, 0);
  double xmin = std::numeric_limits<double>::infinity(), ymin = xmin, xmax = -xmin, ymax = -xmin;
  for (const auto& e : model.elements)
    for (int k = 0; k < node_count(e.kind); ++k) {
      const int a = e.nodes[static_cast<std::size_t>(k)];
      used[static_cast<std::size_t>(a)] = 1;
      xmin = std::min(xmin, crd(a).x()); xmax = std::max(xmax, crd(a).x());
      ymin = std::min(ymin, crd(a).y()); ymax = std::max(ymax, crd(a).y());
    }
  const double tol = 1e-6 * std::max(xmax - xmin, ymax - ymin);

  // equalDOF: coincident nodes tied in both dofs are one material point; everything else has no MPM form.
  NodeUnion canonical(n);
  std::vector<long> joined, slip, distant;
  for (const auto& t : model.ties) {
    // A tie of the pore pressure alone (dof 3 of u-p nodes) constrains no motion.
    if (!std::count(t.dofs.begin(), t.dofs.end(), 1) && !std::count(t.dofs.begin(), t.dofs.end(), 2)) continue;
    const int r = model.node_index(t.retained), c = model.node_index(t.constrained);
    const bool both = std::count(t.dofs.begin(), t.dofs.end(), 1) && std::count(t.dofs.begin(), t.dofs.end(), 2);
    const bool coincident = (crd(r) - crd(c)).norm() <= tol;
    auto& list = coincident ? (both ? joined : slip) : distant;
    list.push_back(t.retained);
    list.push_back(t.constrained);
    if (coincident && both) canonical.join(r, c);
  }
  if (!joined.empty())
    out.notes.push_back(std::to_string(joined.size() / 2) + " equalDOF ties join coincident nodes (tied mesh blocks): "
                        "one continuous MPM material there");
  if (!slip.empty())
    out.warnings.push_back("equalDOF ties of one dof between coincident nodes " + node_list_text(slip) +
                           " (a slip or hinge interface) cannot be represented in MPM: the material is continuous there");
  if (!distant.empty())
    out.warnings.push_back("equalDOF ties between distinct points (periodic or tied sides), nodes " + node_list_text(distant) +
                           ", cannot be represented in MPM (no periodic boundary): those nodes are free unless a support "
                           "or an option (--left-wall, --right-wall) puts a wall there");

  std::vector<Fixity> fix(n);
  std::vector<char> used_canonical(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    if (used[i]) used_canonical[static_cast<std::size_t>(canonical.find(static_cast<int>(i)))] = 1;
  std::set<int> unused_fixed;
  for (const auto& f : model.fixes) {
    const int i = canonical.find(model.node_index(f.node));
    if (!used_canonical[static_cast<std::size_t>(i)]) {
      unused_fixed.insert(model.node_index(f.node));
      continue;
    }
    fix[static_cast<std::size_t>(i)].x = fix[static_cast<std::size_t>(i)].x || f.x;
    fix[static_cast<std::size_t>(i)].y = fix[static_cast<std::size_t>(i)].y || f.y;
  }
  if (!unused_fixed.empty())
    out.notes.push_back("fixed nodes " + node_list_text(tags_of(model, unused_fixed)) + " belong to no element: ignored");

  // Boundary edges: element sides that only one element has (after joining tied nodes).
  std::map<std::pair<int, int>, std::pair<int, int>> sides;  // (a, b) -> (count, element index)
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const int corners = node_count(model.elements[e].kind);
    for (int k = 0; k < corners; ++k) {
      const int a = canonical.find(model.elements[e].nodes[static_cast<std::size_t>(k)]);
      const int b = canonical.find(model.elements[e].nodes[static_cast<std::size_t>((k + 1) % corners)]);
      auto& s = sides[{std::min(a, b), std::max(a, b)}];
      ++s.first;
      s.second = static_cast<int>(e);
    }
  }
  std::vector<Fixity> covered(n);
  std::set<int> inclined, misplaced;
  std::vector<EdgeOnLine> on_lines;
  for (const auto& [key, s] : sides) {
    if (s.first != 1) continue;
    const auto [a, b] = key;
    const Fixity& fa = fix[static_cast<std::size_t>(a)];
    const Fixity& fb = fix[static_cast<std::size_t>(b)];
    const bool fx = fa.x && fb.x, fy = fa.y && fb.y;
    if (!fx && !fy) continue;
    const auto& el = model.elements[static_cast<std::size_t>(s.second)];
    Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
    for (int k = 0; k < node_count(el.kind); ++k) centroid += crd(el.nodes[static_cast<std::size_t>(k)]) / node_count(el.kind);
    const Eigen::Vector2d pa = crd(a), pb = crd(b);
    const bool vertical = std::abs(pa.x() - pb.x()) <= tol, horizontal = std::abs(pa.y() - pb.y()) <= tol;
    if (vertical && fx) {
      const bool material_right = centroid.x() > pa.x();
      if (material_right && std::abs(pa.x() - xmin) <= tol) on_lines.push_back({GridEdge::Left, fy, a, b});
      else if (!material_right && std::abs(pa.x() - xmax) <= tol) on_lines.push_back({GridEdge::Right, fy, a, b});
      else { misplaced.insert({a, b}); continue; }
      covered[static_cast<std::size_t>(a)].x = covered[static_cast<std::size_t>(b)].x = true;
      if (fy) covered[static_cast<std::size_t>(a)].y = covered[static_cast<std::size_t>(b)].y = true;
    } else if (horizontal && fy) {
      if (centroid.y() > pa.y() && std::abs(pa.y() - ymin) <= tol) on_lines.push_back({GridEdge::Base, fx, a, b});
      else { misplaced.insert({a, b}); continue; }
      covered[static_cast<std::size_t>(a)].y = covered[static_cast<std::size_t>(b)].y = true;
      if (fx) covered[static_cast<std::size_t>(a)].x = covered[static_cast<std::size_t>(b)].x = true;
    } else if (!vertical && !horizontal) {
      inclined.insert({a, b});
    }
  }

  for (GridEdge edge : {GridEdge::Left, GridEdge::Right, GridEdge::Base}) {
    std::set<int> nodes, fixed_nodes;
    bool all_fixed = true;
    for (const auto& l : on_lines) {
      if (l.edge != edge) continue;
      nodes.insert({l.a, l.b});
      if (l.fixed_both) fixed_nodes.insert({l.a, l.b});
      all_fixed = all_fixed && l.fixed_both;
    }
    if (nodes.empty()) continue;
    SupportLine line;
    line.edge = edge;
    line.kind = all_fixed ? SupportKind::Fixed : SupportKind::Roller;
    const int along = edge == GridEdge::Base ? 0 : 1;
    std::vector<int> sorted(nodes.begin(), nodes.end());
    std::sort(sorted.begin(), sorted.end(), [&](int p, int q) { return crd(p)[along] < crd(q)[along]; });
    line.coordinate = crd(sorted.front())[1 - along];
    line.from = crd(sorted.front())[along];
    line.to = crd(sorted.back())[along];
    for (int i : sorted) line.nodes.push_back(model.nodes[static_cast<std::size_t>(i)].tag);
    if (!all_fixed && !fixed_nodes.empty())
      out.warnings.push_back(edge_name(edge) + ": nodes " + node_list_text(tags_of(model, fixed_nodes)) + " are fixed in " +
                             (edge == GridEdge::Base ? "x" : "y") + " too, the others not: the MPM " + edge_name(edge) +
                             " is a roller over its whole length");
    out.lines.push_back(std::move(line));
  }

  // Every fixed dof not carried by a line is named.
  std::set<int> lost_inclined, lost_misplaced, lost_point;
  for (std::size_t i = 0; i < n; ++i) {
    const bool lost = (fix[i].x && !covered[i].x) || (fix[i].y && !covered[i].y);
    if (!lost) continue;
    const int idx = static_cast<int>(i);
    if (inclined.count(idx)) lost_inclined.insert(idx);
    else if (misplaced.count(idx)) lost_misplaced.insert(idx);
    else lost_point.insert(idx);
  }
  auto lost = [&](const std::set<int>& nodes, const std::string& why) {
    if (!nodes.empty())
      out.warnings.push_back("FEM supports at nodes " + node_list_text(tags_of(model, nodes)) +
                             " cannot be represented on the MPM grid (" + why + "): not carried over");
  };
  lost(lost_inclined, "an inclined support line; the grid's walls and base are vertical and horizontal");
  lost(lost_misplaced, "a support line inside the model or on a side the material lies below or beside; only the "
                       "model's outer left, right and bottom sides become grid edges");
  lost(lost_point, "a single point, or fixed only along its own line; a wall needs a vertical line of x-fixed nodes, "
                   "the base a horizontal line of y-fixed nodes");
  return out;
}

}  // namespace bridge
