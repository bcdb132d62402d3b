#pragma once
// Structured test meshes for the bridge verification tests: nx x ny four-node elements on
// [0, lx] x [0, ly], interior nodes perturbed deterministically (so that no result is exact only by
// symmetry), then displaced by a smooth field to give the "current" configuration.
#include <cmath>
#include <functional>

#include "bridge/transfer_state.hpp"

namespace bridge_test {

using bridge::Stress6;
using bridge::Vec2;

struct MeshSpec {
  int nx = 8, ny = 8;
  double lx = 2.0, ly = 1.5;
  double perturb = 0.2;    ///< interior node shift, fraction of the element size
  int gauss_points = 1;    ///< 1 (SSPquad) or 4 (quad)
  double density = 1900;
  bool deform = true;      ///< apply a smooth displacement field
};

inline bridge::TransferState make_state(const MeshSpec& s, const std::function<Stress6(const Vec2&)>& stress) {
  bridge::TransferState st;
  const double hx = s.lx / s.nx, hy = s.ly / s.ny;
  for (int j = 0; j <= s.ny; ++j)
    for (int i = 0; i <= s.nx; ++i) {
      Vec2 x(i * hx, j * hy);
      if (i > 0 && i < s.nx && j > 0 && j < s.ny) {
        // Deterministic pseudo-random shift in [-perturb, perturb] of the element size.
        const double a = std::sin(12.9898 * i + 78.233 * j) * 43758.5453;
        const double b = std::sin(39.3468 * i + 11.135 * j) * 24634.6345;
        x += Vec2((2 * (a - std::floor(a)) - 1) * s.perturb * hx, (2 * (b - std::floor(b)) - 1) * s.perturb * hy);
      }
      st.reference.push_back(x);
      st.displacement.push_back(s.deform ? Vec2(0.02 * std::sin(x.y()) + 0.01 * x.x() * x.y(), -0.015 * x.x() * x.x())
                                         : Vec2::Zero());
      st.velocity.push_back(Vec2::Zero());
    }
  bridge::MpmMaterial m;
  m.density = s.density;
  m.youngs_modulus = 1e7;
  m.poisson_ratio = 0.3;
  st.materials = {m};
  long tag = 1;
  for (int j = 0; j < s.ny; ++j)
    for (int i = 0; i < s.nx; ++i) {
      bridge::TransferElement e;
      e.tag = tag++;
      const int n0 = j * (s.nx + 1) + i;
      e.nodes = {n0, n0 + 1, n0 + s.nx + 2, n0 + s.nx + 1};
      e.gauss_points = s.gauss_points;
      e.density = s.density;
      st.elements.push_back(e);
    }
  st.index_gauss_points();
  st.gauss_stress.resize(st.gauss_offset.back());
  const auto pts = bridge::opensees_gauss_points(s.gauss_points);
  for (std::size_t e = 0; e < st.elements.size(); ++e) {
    const auto x = st.current_nodes(st.elements[e]);
    for (std::size_t g = 0; g < pts.size(); ++g)
      st.gauss_stress[st.gauss_offset[e] + g] = stress(bridge::map_point(x, pts[g].x(), pts[g].y()));
  }
  return st;
}

}  // namespace bridge_test
