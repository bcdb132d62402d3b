#pragma once
// The particle order after a step, shared by the threads (Engine::resort_particles). The live particles
// that kept their sort key are still in order along the previous iteration order; the few that changed
// it (the movers) are sorted on their own and merged in. Both passes split the iteration indices into
// contiguous ranges (one per thread, or the engine's chunks):
//   1. each range lists its movers and counts its kept particles (find_movers, or the caller while it
//      writes the new keys: start / open / record);
//   2. after the movers are sorted, each range merges its kept particles with the movers that fall
//      between its first kept particle and the next range's (a binary search), writing from
//      (kept particles of the ranges before it) + (movers before its first kept particle).
// The result is the serial merge's, element for element, for any thread count (and without OpenMP).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace mpm::core {

class OrderMerge {
 public:
  enum class Status { Removed, Kept, Moved };

  /// Pass 1 over the iteration indices [0, n) with `threads` threads; status(k) says what particle k did.
  /// Returns the number of movers.
  template <class StatusOf>
  std::size_t find_movers(std::size_t n, int threads, StatusOf status) {
    const auto ranges = static_cast<std::size_t>(std::max(1, threads));
    start(ranges, threads);
#pragma omp parallel for num_threads(threads_) schedule(static, 1)
    for (std::size_t t = 0; t < ranges; ++t) {
      const std::size_t begin = n * t / ranges, end = n * (t + 1) / ranges;
      open(t, begin, end);
      for (std::size_t k = begin; k < end; ++k) record(t, k, status(k));
    }
    return collect_movers();
  }

  /// Pass 1 done by the caller while it visits the particles (Engine::g2p_chunk, as it writes the new
  /// keys): the iteration indices cut into `ranges` consecutive ranges (pass 2 then runs over them with
  /// `threads` threads); each range is opened, then told the status of each of its indices in order, by
  /// one thread at a time; collect_movers() returns the number of movers.
  void start(std::size_t ranges, int threads) {
    threads_ = std::max(1, threads);
    ranges_.resize(ranges);
  }
  void open(std::size_t r, std::size_t begin, std::size_t end) {
    Range& range = ranges_[r];
    range.begin = begin;
    range.end = end;
    range.movers.clear();
    range.kept = 0;
    range.first_kept = kNone;
  }
  void record(std::size_t r, std::size_t k, Status s) {
    Range& range = ranges_[r];
    if (s == Status::Kept) {
      if (range.kept++ == 0) range.first_kept = k;
    } else if (s == Status::Moved) {
      range.movers.push_back(static_cast<std::uint32_t>(k));
    }
  }
  std::size_t collect_movers() {
    movers_.clear();
    for (const Range& r : ranges_) movers_.insert(movers_.end(), r.movers.begin(), r.movers.end());
    return movers_.size();
  }

  /// Pass 2: the movers sorted by `before` and merged with the kept particles (in order along k: those
  /// neither removed(k) nor among pass 1's movers) into out[0 .. count); returns the count.
  template <class Removed, class Before>
  std::size_t merge(std::uint32_t* out, Removed removed, Before before) {
    std::sort(movers_.begin(), movers_.end(), before);
    // Thread t's movers: [ranges_[t].first_mover, ranges_[t + 1].first_mover); the first thread's start at 0.
    std::size_t next = movers_.size(), kept_before = 0;
    for (std::size_t t = ranges_.size(); t-- > 0;) {
      Range& r = ranges_[t];
      if (t == 0) {
        r.first_mover = 0;
      } else if (r.first_kept != kNone) {
        const auto p = static_cast<std::uint32_t>(r.first_kept);
        r.first_mover = static_cast<std::size_t>(
            std::partition_point(movers_.begin(), movers_.end(), [&](std::uint32_t m) { return before(m, p); }) -
            movers_.begin());
      } else {
        r.first_mover = next;
      }
      r.last_mover = next;
      next = r.first_mover;
    }
    for (Range& r : ranges_) {
      r.out = kept_before + r.first_mover;
      kept_before += r.kept;
    }
    const std::vector<std::uint32_t>& movers = movers_;
#pragma omp parallel for num_threads(threads_) schedule(static, 1)
    for (std::size_t t = 0; t < ranges_.size(); ++t) {
      const Range& r = ranges_[t];
      std::size_t o = r.out, m = r.first_mover;
      if (r.kept > 0) {
        // This range's own movers, ascending: the indices that are neither kept nor removed.
        auto own_mover = std::lower_bound(r.movers.begin(), r.movers.end(), static_cast<std::uint32_t>(r.first_kept));
        for (std::size_t k = r.first_kept; k < r.end; ++k) {
          if (own_mover != r.movers.end() && *own_mover == k) {
            ++own_mover;
            continue;
          }
          if (removed(k)) continue;
          const auto p = static_cast<std::uint32_t>(k);
          while (m < r.last_mover && before(movers[m], p)) out[o++] = movers[m++];
          out[o++] = p;
        }
      }
      while (m < r.last_mover) out[o++] = movers[m++];
    }
    return kept_before + movers_.size();
  }

 private:
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  struct alignas(64) Range {  // one cache line per range: the threads of pass 1 count in their own
    std::size_t begin = 0, end = 0;
    std::vector<std::uint32_t> movers;  ///< this range's movers, ascending
    std::size_t kept = 0, first_kept = kNone;
    std::size_t first_mover = 0, last_mover = 0, out = 0;
  };
  int threads_ = 1;
  std::vector<Range> ranges_;
  std::vector<std::uint32_t> movers_;
};

}  // namespace mpm::core
