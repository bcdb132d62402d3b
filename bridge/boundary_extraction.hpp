#pragma once
// The FEM supports (fix, equalDOF from fem_tcl's print -JSON "constraints" block) turned into the MPM
// grid's boundaries (issue 9, item 1). A support line is a chain of boundary edges of the mesh whose two
// nodes share a fixed dof:
//   - a vertical line of x-fixed nodes on the model's left or right side -> a wall there (roller; fixed
//     when the nodes are fixed in y too);
//   - a horizontal line of y-fixed nodes under the model -> the base (roller; a line fixed in x and y is
//     the frictional base, or fixed on request).
// Everything else that is fixed (a single point, an inclined line, a line inside the model or on its top)
// cannot be carried by CB-Geo's grid-edge constraints and is returned as a warning naming the nodes.
// equalDOF ties between coincident nodes (tied mesh blocks) join the material (the MPM grid is continuous
// anyway); ties between distinct points (periodic or tied sides) have no MPM counterpart: a warning, and
// those sides are free unless another support or an option makes them walls.
#include <optional>
#include <string>
#include <vector>

#include "bridge/fem_model.hpp"

namespace bridge {

enum class GridEdge { Left, Right, Base };
enum class SupportKind { Roller, Fixed };

/// One FEM support line carried to an edge of the MPM grid (reference coordinates, model length units).
struct SupportLine {
  GridEdge edge = GridEdge::Left;
  SupportKind kind = SupportKind::Roller;
  double coordinate = 0;       ///< x of a wall, y of the base
  double from = 0, to = 0;     ///< extent of its nodes along the line (y for a wall, x for the base)
  std::vector<long> nodes;     ///< FEM node tags, sorted along the line
};

struct ExtractedBoundaries {
  bool from_model = false;             ///< the model file carries its supports
  std::vector<SupportLine> lines;      ///< at most one per grid edge
  std::vector<std::string> warnings;   ///< supports and ties that cannot be represented (nodes named)
  std::vector<std::string> notes;      ///< what was merged or ignored, for the report

  const SupportLine* line(GridEdge edge) const;
};

/// The supports of `model` as grid boundaries. With no "constraints" block in the file (OpenSees' own
/// print -JSON) from_model is false, a note says so and the boundaries are left to the options.
ExtractedBoundaries extract_boundaries(const FemModel& model);

/// "left wall" / "right wall" / "base".
std::string edge_name(GridEdge edge);

/// A short list of node tags for messages: "3 7 12", or "1 2 3 ... 40 (25 nodes)".
std::string node_list_text(const std::vector<long>& tags);

}  // namespace bridge
