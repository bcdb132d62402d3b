#pragma once
// The MPM deck's boundaries from the FEM supports (boundary_extraction) and the options: every option the
// user gives wins; without one, a grid edge gets the FEM support on that side (a roller or fixed wall, the
// base), a side with no support is a free face (no wall, the runout area extends beyond it). Also the text
// and JSON the report gives for each edge.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "bridge/boundary_extraction.hpp"
#include "bridge/mpm_deck.hpp"

namespace bridge {

/// The options the user gave explicitly (they override the FEM supports).
struct BoundaryOptionsGiven {
  bool left = false, right = false, base = false, base_y = false;
};

/// What one grid edge became.
struct BoundaryChoice {
  GridEdge edge = GridEdge::Left;
  std::string condition;              ///< "roller", "fixed", "none (free face)", "friction mu = 0.4", ...
  std::string source;                 ///< "FEM support", "--left-wall", "default", ...
  std::optional<SupportLine> line;    ///< the FEM support line it came from, if any
};

/// Sets deck.left/right/base, deck.anchors (and so the default grid) from `supports` where no option was
/// given, and returns one choice per grid edge.
std::vector<BoundaryChoice> apply_supports(const ExtractedBoundaries& supports, const BoundaryOptionsGiven& given,
                                           DeckOptions& deck);

/// One line for the terminal summary, with the grid position and the FEM nodes' extent.
std::string boundary_text(const BoundaryChoice& choice, const DeckText& deck);

/// The report's "boundaries" list.
nlohmann::ordered_json boundaries_json(const std::vector<BoundaryChoice>& choices, const DeckText& deck);

}  // namespace bridge
