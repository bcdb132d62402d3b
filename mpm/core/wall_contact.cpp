// The gap test of the one-sided frictional contact (NodeConstraint::one_sided): a wall node stops the
// approach and carries friction only where the material touches the wall, i.e. where a particle's domain
// reaches it: gap = s (x_wall - x_p) - l_p <= 0 along the wall's normal (s the outward sign, l_p the
// particle's half-size), for a particle in one of the cells that share the node (four in 2D, eight in 3D;
// the normal along any axis; one that has passed the wall has a negative gap). The wall is the face of the node's run of contact nodes along the normal
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

NodeConstraint<kDim> Engine::constraint_now(std::int32_t c) const {
  NodeConstraint<kDim> nc = constraints_[static_cast<std::size_t>(c)];
  if (!touching_[static_cast<std::size_t>(c)]) nc.friction_dir = -1;  // a free node (its normal is free)
  return nc;
}

std::array<int, kDim> Engine::node_axes(std::size_t node) const {
  std::array<int, kDim> at{};
  for (int d = 0; d < kDim; ++d) {
    const auto n = static_cast<std::size_t>(nodes_per_axis_[d]);
    at[d] = static_cast<int>(node % n);
    node /= n;
  }
  return at;
}

std::size_t Engine::node_at(const std::array<int, kDim>& at) const {
  std::size_t node = static_cast<std::size_t>(at[kDim - 1]);
  for (int d = kDim - 2; d >= 0; --d) node = node * static_cast<std::size_t>(nodes_per_axis_[d]) + static_cast<std::size_t>(at[d]);
  return node;
}

void Engine::set_up_wall_contacts() {
  touching_.assign(constraints_.size(), 1);
  const auto contact = [&](std::size_t node) -> const NodeConstraint<kDim>* {
    const std::int32_t c = constraint_of_[node];
    if (c < 0 || !constraints_[static_cast<std::size_t>(c)].one_sided()) return nullptr;
    return &constraints_[static_cast<std::size_t>(c)];
  };
  // The cells that share a node along the wall: 2^(kDim - 1), the node's lower or upper neighbour on each
  // tangential axis (bit b of `side` for the b-th axis other than the normal).
  constexpr int kSides = 1 << (kDim - 1);
  for (std::size_t node = 0; node < nodes_; ++node) {
    const NodeConstraint<kDim>* nc = contact(node);
    if (!nc) continue;
    // Walk inwards (against the outward normal, along its axis dn) while the next node is a contact of the
    // same wall: a base given as several node rows (a grid that extends below it, GIMP's halo) has one
    // face, the top row.
    const int dn = nc->friction_dir, inward = nc->sign_n > 0 ? -1 : 1;
    const std::array<int, kDim> at = node_axes(node);
    int face = at[dn];
    for (;;) {
      std::array<int, kDim> next = at;
      next[dn] = face + inward;
      if (next[dn] < 0 || next[dn] >= nodes_per_axis_[dn]) break;
      const NodeConstraint<kDim>* o = contact(node_at(next));
      if (!o || o->friction_dir != dn || o->sign_n != nc->sign_n) break;
      face = next[dn];
    }
    // The cells that share the node and those between it and the wall face (a node behind the face is
    // inside the wall), in the grid: the particles that may touch the face there.
    const std::size_t cells_begin = contact_cells_.size();
    for (int across = std::min(at[dn], face) - 1; across <= std::max(at[dn], face); ++across) {
      if (across < 0 || across >= cells_per_axis_[dn]) continue;
      for (int side = 0; side < kSides; ++side) {
        std::array<int, kDim> cell{};
        cell[dn] = across;
        bool inside = true;
        for (int d = 0, bit = 0; d < kDim; ++d) {
          if (d == dn) continue;
          cell[d] = at[d] - 1 + ((side >> bit++) & 1);
          inside = inside && cell[d] >= 0 && cell[d] < cells_per_axis_[d];
        }
        if (!inside) continue;
        std::int64_t index = cell[kDim - 1];  // the lattice cell, axis 0 fastest (as cell_key)
        for (int d = kDim - 2; d >= 0; --d) index = index * cells_per_axis_[d] + cell[d];
        contact_cells_.push_back(index);
      }
    }
    contact_nodes_.push_back({static_cast<std::size_t>(constraint_of_[node]), face, cells_begin, contact_cells_.size()});
  }
}

void Engine::find_wall_contacts() {
  if (contact_nodes_.empty()) return;
  const auto cell_of_particle = [&](std::uint32_t p) { return cell_of(cur_.key[p]); };
  const auto& h = grid_.spacing;
  for (const WallContactNode& w : contact_nodes_) {
    const NodeConstraint<kDim>& nc = constraints_[w.constraint];
    const int dn = nc.friction_dir;
    const double wall = grid_.origin[dn] + w.face * h[dn];
    // A particle of the node's cells on the inner side whose domain reaches the face, or one that has
    // passed it (gap < 0), touches it.
    bool touching = false;
    for (std::size_t k = w.cells_begin; k < w.cells_end && !touching; ++k) {
      const std::int64_t index = contact_cells_[k];
      // order_ is sorted by key, i.e. by cell first: the cell's particles are one run of it.
      const auto first = std::lower_bound(order_.begin(), order_.end(), index,
                                          [&](std::uint32_t p, std::int64_t key) { return cell_of_particle(p) < key; });
      for (auto it = first; it != order_.end() && cell_of_particle(*it) == index && !touching; ++it) {
        const std::uint32_t p = *it;
        const double x = cur_.position[dn][p];
        const double half = cur_.half_size[dn][p] * h[dn];
        touching = nc.sign_n * (wall - x) - half <= kContactGapTolerance * h[dn];
      }
    }
    touching_[w.constraint] = touching ? 1 : 0;
  }
}

}  // namespace mpm::core
