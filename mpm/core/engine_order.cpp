// The order in which the step visits the particles and its chunks (one thread's share, cut at cell
// boundaries): part of the Engine, apart from engine.cpp because it runs once a step, outside the
// per-particle phases that each CPU variant of the step inlines.
#include <algorithm>
#include <cassert>

#include "mpm/core/engine.hpp"

namespace mpm::core {

// ---------------------------------------------------------------------------------------------------
// Sorting: order_ = live particles by (key, id), the key the cell and its stencil quadrant (cell_key).
// A counting sort by key of the previous order, then an insertion sort by id inside each key's run
// (nearly sorted already); after a step in which few particles changed key, a merge of those few into
// the rest (resort_particles, shared by the threads: order_merge.hpp). The result depends only on the
// particle state, so a resumed run iterates in the same order as the uninterrupted one.
// ---------------------------------------------------------------------------------------------------
void Engine::sort_particles() {
  std::fill(bucket_.begin(), bucket_.end(), 0u);
  // order_ holds the storage indices to sort, in their previous order (nearly sorted already).
  const std::size_t n_old = order_.size();
  for (std::size_t k = 0; k < n_old; ++k) {
    const std::int64_t key = cur_.key[order_[k]];
    if (key != kRemoved) ++bucket_[static_cast<std::size_t>(key) + 1];
  }
  for (std::size_t c = 0; c + 1 < bucket_.size(); ++c) bucket_[c + 1] += bucket_[c];
  const std::size_t n = bucket_.back();
  for (std::size_t k = 0; k < n_old; ++k) {
    const std::uint32_t p = order_[k];
    const std::int64_t key = cur_.key[p];
    if (key != kRemoved) sorted_[bucket_[static_cast<std::size_t>(key)]++] = p;
  }
  // bucket_[c] now holds the end of cell c; sort each cell's run by id.
  std::size_t start = 0;
  for (std::size_t c = 0; c + 1 < bucket_.size(); ++c) {
    const std::size_t end = bucket_[c];
    for (std::size_t a = start + 1; a < end; ++a) {
      const std::uint32_t p = sorted_[a];
      const std::int64_t id = cur_.id[p];
      std::size_t b = a;
      while (b > start && cur_.id[sorted_[b - 1]] > id) {
        sorted_[b] = sorted_[b - 1];
        --b;
      }
      sorted_[b] = p;
    }
    start = end;
  }
  order_.assign(sorted_.begin(), sorted_.begin() + static_cast<std::ptrdiff_t>(n));
  cut_chunks();
}

/// After a step, when few particles changed key: the particles that kept theirs are still in (key,
/// id) order along the previous order, so the new order is their sequence merged with the few others
/// sorted, in one pass instead of the counting sort. (key, id) is unique, so the order is the one
/// sort_particles() gives. g2p_chunk recorded which particles kept, changed or lost their key, per
/// chunk (merge_).
void Engine::resort_particles() {
  const std::size_t n_old = order_.size();  // the step's particles
  const std::size_t movers = merge_.collect_movers();  // recorded by g2p_chunk, chunk by chunk
  order_.resize(n_old);
  if (movers > n_old / 16) {  // many: the counting sort is cheaper than sorting them
    for (std::size_t k = 0; k < n_old; ++k) order_[k] = static_cast<std::uint32_t>(k);
    sort_particles();
    return;
  }
  const auto before = [&](std::uint32_t a, std::uint32_t b) {
    return cur_.key[a] != cur_.key[b] ? cur_.key[a] < cur_.key[b] : cur_.id[a] < cur_.id[b];
  };
  order_.resize(merge_.merge(order_.data(), [&](std::size_t k) { return cur_.key[k] == kRemoved; }, before));
  cut_chunks();
}

/// The chunks of the sorted particles (order_), each chunk's band and the active node box (their union).
void Engine::cut_chunks() {
  const std::size_t n = order_.size();
  // Chunks of about kChunkParticles particles, cut at cell boundaries. Their number and extent depend
  // only on the particle state (not on the thread count): threads take chunks dynamically, each chunk
  // scatters into its own band, and bands are summed in chunk order.
  chunks_ = n == 0 ? 0 : (n + kChunkParticles - 1) / kChunkParticles;
  chunk_[0] = 0;
  for (std::size_t c = 1; c < chunks_; ++c) {
    std::size_t k = std::max(chunk_[c - 1], n * c / chunks_);
    while (k > 0 && k < n && cell_of(cur_.key[order_[k]]) == cell_of(cur_.key[order_[k - 1]])) ++k;
    chunk_[c] = k;
  }
  chunk_[chunks_] = n;
  // Each chunk's band: every node its particles' stencils can reach (cell - 1 .. cell + 2 per axis).
  const auto chunks = static_cast<std::ptrdiff_t>(chunks_);
#pragma omp parallel for num_threads(threads_) schedule(static)
  for (std::ptrdiff_t c = 0; c < chunks; ++c) {
    std::array<int, kDim> lo = cells_per_axis_, hi;  // the chunk's cells per axis
    hi.fill(-1);
    std::int64_t previous_cell = kRemoved;  // a cell's particles are consecutive: one division per cell
    for (std::size_t k = chunk_[c]; k < chunk_[c + 1]; ++k) {
      std::int64_t cell = cell_of(cur_.key[order_[k]]);
      if (cell == previous_cell) continue;
      previous_cell = cell;
      for (int d = 0; d < kDim; ++d) {  // the cell's index per axis, axis 0 fastest
        const int at = static_cast<int>(d < kDim - 1 ? cell % cells_per_axis_[d] : cell);
        if (d < kDim - 1) cell /= cells_per_axis_[d];
        lo[d] = std::min(lo[d], at);
        hi[d] = std::max(hi[d], at);
      }
    }
    Band& b = bands_[static_cast<std::size_t>(c)];
    if (hi[0] < 0) {  // an empty chunk (its cell's particles all went to the chunk before)
      b = Band{};
      continue;
    }
    for (int d = 0; d < kDim; ++d) {
      b.lo[d] = std::max(lo[d] - 1, 0);
      b.hi[d] = std::min(hi[d] + 3, nodes_per_axis_[d]);
    }
  }
  // The active node box: the union of the bands.
  box_lo_.fill(0);
  box_hi_.fill(0);
  if (chunks_ > 0) {
    box_lo_ = nodes_per_axis_;
    for (std::size_t c = 0; c < chunks_; ++c) {
      if (bands_[c].size() == 0) continue;
      for (int d = 0; d < kDim; ++d) {
        box_lo_[d] = std::min(box_lo_[d], bands_[c].lo[d]);
        box_hi_[d] = std::max(box_hi_[d], bands_[c].hi[d]);
      }
    }
  }
  std::size_t offset = 0;
  for (std::size_t c = 0; c < chunks_; ++c) {
    bands_[c].offset = offset;
    offset += bands_[c].size();
  }
  if (pool_.size() < offset) pool_.resize(offset);  // grows rarely; no allocation in a steady state
  // Chunks follow the outermost axis (the rows in 2D): their bands' last index on it ascends (an empty
  // band has none).
  constexpr int outer = kDim - 1;
  std::size_t first = 0;
  for (int j = box_lo_[outer]; j < box_hi_[outer]; ++j) {
    while (first < chunks_ && bands_[first].hi[outer] <= j) ++first;
    row_first_chunk_[static_cast<std::size_t>(j)] = first;
  }
}

}  // namespace mpm::core
