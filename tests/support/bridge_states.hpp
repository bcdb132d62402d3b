#pragma once
// Small fem2mpm transfer states built in code for the bridge's unit tests (no FEM run needed).
#include <array>
#include <vector>

#include "bridge/transfer_state.hpp"

namespace test_support {

/// A state at rest: `nodes` (reference coordinates, m) and one-point `quads` (node indices, counter-
/// clockwise), one elastic material (kg/m3, Pa), zero stress.
inline bridge::TransferState resting_state(const std::vector<bridge::Vec2>& nodes,
                                           const std::vector<std::array<int, 4>>& quads, double density,
                                           double youngs_modulus, double poisson_ratio) {
  bridge::TransferState st;
  st.reference = nodes;
  st.displacement.assign(nodes.size(), bridge::Vec2::Zero());
  st.velocity.assign(nodes.size(), bridge::Vec2::Zero());
  for (const auto& q : quads) {
    bridge::TransferElement e;
    e.nodes = q;
    e.density = density;
    st.elements.push_back(e);
  }
  bridge::MpmMaterial mat;
  mat.density = density;
  mat.youngs_modulus = youngs_modulus;
  mat.poisson_ratio = poisson_ratio;
  st.materials = {mat};
  st.index_gauss_points();
  st.gauss_stress.assign(st.elements.size(), bridge::Stress6{});
  return st;
}

}  // namespace test_support
