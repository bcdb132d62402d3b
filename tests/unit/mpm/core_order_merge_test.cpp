// Unit tests of the shared re-sort (mpm/core/order_merge.hpp): for any thread count the merged order
// must be the serial one, element for element, which is what keeps the engine's state the same for 1
// and 2 threads. The reference is std::stable_sort of the live particles by (key, id); the inputs are
// random previous orders with movers and removed particles at chosen rates, including none, every
// particle moving, a range with no kept particle, and movers that sort before or after every kept one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "mpm/core/order_merge.hpp"

namespace {

using mpm::core::OrderMerge;

/// A step's outcome: particle k (iteration index) had key old_key[k] (sorted along k) and now has key[k],
/// or -1 when it was removed.
struct Outcome {
  std::vector<std::int64_t> old_key, key;
  std::vector<std::uint32_t> id;
};

Outcome random_outcome(std::mt19937& rng, std::size_t n, double move_rate, double remove_rate,
                       std::int64_t key_range) {
  Outcome o;
  std::uniform_int_distribution<std::int64_t> any_key(0, key_range - 1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  o.old_key.resize(n);
  for (auto& k : o.old_key) k = any_key(rng);
  std::sort(o.old_key.begin(), o.old_key.end());
  // ids unique and increasing inside each key's run, as the engine's order has them.
  o.id.resize(n);
  std::iota(o.id.begin(), o.id.end(), 0u);
  o.key = o.old_key;
  for (std::size_t k = 0; k < n; ++k) {
    const double r = u(rng);
    if (r < remove_rate)
      o.key[k] = -1;
    else if (r < remove_rate + move_rate)
      while (o.key[k] == o.old_key[k]) o.key[k] = any_key(rng);
  }
  return o;
}

std::vector<std::uint32_t> serial_order(const Outcome& o) {
  std::vector<std::uint32_t> live;
  for (std::size_t k = 0; k < o.key.size(); ++k)
    if (o.key[k] >= 0) live.push_back(static_cast<std::uint32_t>(k));
  std::stable_sort(live.begin(), live.end(), [&](std::uint32_t a, std::uint32_t b) {
    return o.key[a] != o.key[b] ? o.key[a] < o.key[b] : o.id[a] < o.id[b];
  });
  return live;
}

std::vector<std::uint32_t> merged_order(const Outcome& o, int threads, std::size_t* movers = nullptr) {
  const auto status = [&](std::size_t k) {
    if (o.key[k] < 0) return OrderMerge::Status::Removed;
    return o.key[k] == o.old_key[k] ? OrderMerge::Status::Kept : OrderMerge::Status::Moved;
  };
  const auto before = [&](std::uint32_t a, std::uint32_t b) {
    return o.key[a] != o.key[b] ? o.key[a] < o.key[b] : o.id[a] < o.id[b];
  };
  OrderMerge merge;
  const std::size_t m = merge.find_movers(o.key.size(), threads, status);
  if (movers) *movers = m;
  std::vector<std::uint32_t> out(o.key.size());
  out.resize(merge.merge(out.data(), [&](std::size_t k) { return o.key[k] < 0; }, before));
  return out;
}

TEST(OrderMerge, EqualsTheSerialSortForAnyThreadCount) {
  std::mt19937 rng(20261204);
  const double move_rates[] = {0.0, 0.001, 0.03, 0.5, 1.0};
  const double remove_rates[] = {0.0, 0.01};
  for (std::size_t n : {0u, 1u, 3u, 17u, 1000u, 20000u})
    for (double move : move_rates)
      for (double remove : remove_rates) {
        const Outcome o = random_outcome(rng, n, move, remove, 2 + static_cast<std::int64_t>(n) / 4);
        const std::vector<std::uint32_t> expected = serial_order(o);
        for (int threads : {1, 2, 3, 8}) {
          SCOPED_TRACE(testing::Message() << "n " << n << " move " << move << " remove " << remove << " threads "
                                          << threads);
          EXPECT_EQ(merged_order(o, threads), expected);
        }
      }
}

TEST(OrderMerge, MoversBeforeAndAfterEveryKeptParticleAndAnEmptyRange) {
  // 12 particles on keys 10 .. 21; with 3 threads the middle range (4 .. 7) keeps none: its particles
  // move to the very front and the very back.
  Outcome o;
  for (std::int64_t k = 0; k < 12; ++k) o.old_key.push_back(10 + k);
  o.key = o.old_key;
  o.key[4] = 0;
  o.key[5] = 99;
  o.key[6] = 1;
  o.key[7] = -1;
  o.id.resize(12);
  std::iota(o.id.begin(), o.id.end(), 0u);
  for (int threads : {1, 2, 3, 4, 12, 16}) {
    std::size_t movers = 0;
    EXPECT_EQ(merged_order(o, threads, &movers), serial_order(o)) << threads << " threads";
    EXPECT_EQ(movers, 3u);
  }
  EXPECT_EQ(serial_order(o).front(), 4u);
  EXPECT_EQ(serial_order(o).back(), 5u);
}

}  // namespace
