#pragma once
// Saving and restoring the material points of an element (domain::ElementState), and reducing their strength:
// the pieces SSPquad and FourNodeQuad share for `strengthReduction`.
#include <memory>
#include <span>
#include <vector>

#include "fem_tcl/domain/element.hpp"
#include "fem_tcl/materials/nd_material.hpp"

namespace fem::elements {

/// Copies of an element's material points, in order.
struct MaterialPointsState final : domain::ElementState {
  std::vector<std::unique_ptr<materials::NDMaterial>> points;
};

inline std::unique_ptr<domain::ElementState> save_material_points(
    std::span<const std::unique_ptr<materials::NDMaterial>> points) {
  auto state = std::make_unique<MaterialPointsState>();
  for (const auto& m : points) state->points.push_back(m->clone());
  return state;
}

/// Replaces each material point by a copy of the saved one (the saved state stays usable for another restore).
inline void restore_material_points(std::span<std::unique_ptr<materials::NDMaterial>> points,
                                    const domain::ElementState& saved) {
  const auto& state = dynamic_cast<const MaterialPointsState&>(saved);
  for (std::size_t i = 0; i < points.size() && i < state.points.size(); ++i) points[i] = state.points[i]->clone();
}

/// Sets the reduction factor on every point with a reducible strength; false when no point has one.
inline bool reduce_material_points_strength(std::span<std::unique_ptr<materials::NDMaterial>> points, double factor) {
  bool any = false;
  for (auto& m : points) {
    if (materials::ReducibleStrength* s = m->reducible_strength()) {
      s->set_strength_reduction(factor);
      any = true;
    }
  }
  return any;
}

}  // namespace fem::elements
