// The gap test of the one-sided frictional contact (NodeConstraint::one_sided): a wall node stops the
// approach and carries friction only where the material touches the wall, i.e. where a particle's domain
// reaches it: gap = s (x_wall - x_p) - l_p <= 0 along the wall's normal (s the outward sign, l_p the
// particle's half-size), for a particle in one of the four cells that share the node (one that has passed
// the wall has a negative gap). The wall is the face of the node's run of contact nodes along the normal
// (set_up_wall_contacts): a base given as several node rows is one rigid body whose face is the top row.
//
// Why: on a single velocity field the wall node also carries particles that have left the wall. Under FLIP
// and APIC its normal velocity has noise of either sign; the contact stops every approach and keeps every
// separation, so the particles beside the wall can ratchet away from it but never back: the lowest
// particle row of a 2 m x 1 m block sliding on the base rose 92 mm in 2 s under FLIP and 24 mm under APIC
// (mpm/README.md "Friction and flutter"). With the gap test a lifted particle falls back under its weight
// until it touches again (rise 0-7 mm). This is the displacement check of
// MPM contact algorithms (Lemiale, Hurmane & Nairn 2010, "Material point method simulation of equal
// channel angular pressing involving large plastic strain and contact through sharp corners", CMES 70,
// 41-66; Nairn's contact detection by a separation gap) with the wall as the rigid body.
#include <algorithm>

#include "mpm/core/engine.hpp"

namespace mpm::core {

/// Round-off allowance of the gap test, in cells: a particle generated with its domain edge on the wall
/// touches it.
constexpr double kContactGapTolerance = 1.0e-9;

NodeConstraint Engine::constraint_now(std::int32_t c) const {
  NodeConstraint nc = constraints_[static_cast<std::size_t>(c)];
  if (!touching_[static_cast<std::size_t>(c)]) nc.friction_dir = -1;  // a free node (its normal is free)
  return nc;
}

void Engine::set_up_wall_contacts() {
  touching_.assign(constraints_.size(), 1);
  const auto contact = [&](std::size_t node) -> const NodeConstraint* {
    const std::int32_t c = constraint_of_[node];
    if (c < 0 || !constraints_[static_cast<std::size_t>(c)].one_sided()) return nullptr;
    return &constraints_[static_cast<std::size_t>(c)];
  };
  const auto row = node_row_stride();
  for (std::size_t node = 0; node < nodes_; ++node) {
    const NodeConstraint* nc = contact(node);
    if (!nc) continue;
    // Walk inwards (against the outward normal) while the next node is a contact of the same wall: a
    // base given as several node rows (a grid that extends below it, GIMP's halo) has one face, the top row.
    const int dn = nc->friction_dir, inward = nc->sign_n > 0 ? -1 : 1;
    int at[2] = {static_cast<int>(node % row), static_cast<int>(node / row)};
    for (;;) {
      int next[2] = {at[0], at[1]};
      next[dn] += inward;
      if (next[dn] < 0 || next[dn] >= nodes_per_axis_[dn]) break;
      const NodeConstraint* o = contact(static_cast<std::size_t>(next[0]) + static_cast<std::size_t>(next[1]) * row);
      if (!o || o->friction_dir != dn || o->sign_n != nc->sign_n) break;
      at[dn] = next[dn];
    }
    contact_nodes_.push_back({node, static_cast<std::size_t>(constraint_of_[node]), at[dn]});
  }
}

void Engine::find_wall_contacts() {
  if (contact_nodes_.empty()) return;
  const auto cell_of_particle = [&](std::uint32_t p) { return cell_of(cur_.key[p]); };
  const auto& h = grid_.spacing;
  for (const auto& [node, c, face] : contact_nodes_) {
    const NodeConstraint& nc = constraints_[c];
    const int dn = nc.friction_dir, dt = 1 - dn;
    const int at[2] = {static_cast<int>(node % node_row_stride()), static_cast<int>(node / node_row_stride())};
    const double wall = grid_.origin[dn] + face * h[dn];
    // The cells that share the node and those between it and the wall face (a node behind the face is
    // inside the wall): a particle on the inner side whose domain reaches the face, or one that has passed
    // it (gap < 0), touches it.
    bool touching = false;
    for (int across = std::min(at[dn], face) - 1; across <= std::max(at[dn], face) && !touching; ++across) {
      for (int side = at[dt] - 1; side <= at[dt] && !touching; ++side) {
        if (across < 0 || across >= cells_per_axis_[dn] || side < 0 || side >= cells_per_axis_[dt]) continue;
        int cell[2];
        cell[dn] = across;
        cell[dt] = side;
        const std::int64_t index =
            static_cast<std::int64_t>(cell[0]) + static_cast<std::int64_t>(cell[1]) * cells_per_axis_[0];
        // order_ is sorted by key, i.e. by cell first: the cell's particles are one run of it.
        const auto first = std::lower_bound(order_.begin(), order_.end(), index,
                                            [&](std::uint32_t p, std::int64_t k) { return cell_of_particle(p) < k; });
        for (auto it = first; it != order_.end() && cell_of_particle(*it) == index && !touching; ++it) {
          const std::uint32_t p = *it;
          const double x = cur_.position[dn][p];
          const double half = cur_.half_size[dn][p] * h[dn];
          touching = nc.sign_n * (wall - x) - half <= kContactGapTolerance * h[dn];
        }
      }
    }
    touching_[c] = touching ? 1 : 0;
  }
}

}  // namespace mpm::core
