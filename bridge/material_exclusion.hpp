#pragma once
// fem2mpm --exclude-material: FEM materials left out of the MPM run. A stiff foundation that does not flow
// costs an explicit MPM run twice: its particles are updated every step, and its P-wave speed sets the time
// step for all (dt = cfl h / c_p). The runout needs only its surface, which the MPM base gives as a
// boundary (--base-y at its top): "model only what a scene needs". The excluded elements, their Gauss
// points and their materials are removed from the transfer state before anything is mapped, so that
// every later step (stress recovery, particles, pore pressures, the report's totals) sees the rest only;
// their nodes stay (the boundaries and the grid's extent are the FEM model's).
#include <string>
#include <vector>

#include "bridge/transfer_state.hpp"

namespace bridge {

/// What was left out, for the report.
struct ExcludedMaterials {
  std::vector<std::string> names;  ///< FEM material tags, as given
  std::size_t elements = 0;
  double mass = 0;                 ///< kg per unit thickness (density x reference area)
  double top = 0;                  ///< the highest y of an excluded element's node now, m (where the base belongs)
};

/// Removes the elements of the FEM materials `names` (their tags in the model file) and those materials
/// (the others keep their order; MPM material ids renumbered 0, 1, ...). InputError naming `option` for a
/// material no element uses, or when nothing would be left.
ExcludedMaterials exclude_materials(TransferState& state, const std::vector<std::string>& names,
                                    const std::string& option);

}  // namespace bridge
