#include "core/base/sort_by_key.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

using Items = std::vector<std::pair<double, std::size_t>>;

/// The order the function promises, by std::sort with the stated comparator.
Items sorted_by_std(Items items) {
  std::sort(items.begin(), items.end(), [](const auto& p, const auto& q) {
    return p.first < q.first || (p.first == q.first && p.second < q.second);
  });
  return items;
}

/// Pairs with the given keys and the indices 0..n-1 in a shuffled order.
Items with_shuffled_indices(const std::vector<double>& keys, test::Mulberry32& rng) {
  Items items;
  for (std::size_t k = 0; k < keys.size(); ++k) items.emplace_back(keys[k], k);
  for (std::size_t k = items.size(); k > 1; --k) {
    std::swap(items[k - 1].second, items[static_cast<std::size_t>(rng.next() * k)].second);
  }
  return items;
}

void expect_same_bits(const Items& got, const Items& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t k = 0; k < got.size(); ++k) {
    EXPECT_EQ(std::signbit(got[k].first), std::signbit(want[k].first)) << k;
    EXPECT_EQ(got[k].first, want[k].first) << k;
    EXPECT_EQ(got[k].second, want[k].second) << k;
  }
}

void expect_sorted_like_std(const std::vector<double>& keys, test::Mulberry32& rng) {
  Items items = with_shuffled_indices(keys, rng);
  const Items want = sorted_by_std(items);
  sort_by_key_then_index(items);
  expect_same_bits(items, want);
}

TEST(SortByKey, SpreadKeysSortLikeStdSort) {
  test::Mulberry32 rng(11);
  for (int round = 0; round < 200; ++round) {
    std::vector<double> keys(static_cast<std::size_t>(rng.next() * 300));
    for (double& x : keys) x = rng.uniform(-1000, 1000);
    expect_sorted_like_std(keys, rng);
  }
}

TEST(SortByKey, RepeatedKeysAreOrderedByIndex) {
  // Few distinct values, each many times, and signed zeros (equal keys: by index).
  test::Mulberry32 rng(12);
  for (int round = 0; round < 200; ++round) {
    std::vector<double> keys(static_cast<std::size_t>(rng.next() * 200));
    for (double& x : keys) {
      const int pick = static_cast<int>(rng.next() * 5);
      x = pick == 0 ? 0.0 : pick == 1 ? -0.0 : std::floor(rng.uniform(-3, 3));
    }
    expect_sorted_like_std(keys, rng);
  }
}

TEST(SortByKey, CrowdedBucketsAndWideRanges) {
  test::Mulberry32 rng(13);
  // Most keys in one tiny cluster and one far outlier: one bucket holds nearly all of them
  // (sorted there by std::sort).
  std::vector<double> crowded;
  for (int k = 0; k < 300; ++k) crowded.push_back(1.0 + rng.uniform(0, 1e-9));
  crowded.push_back(1e6);
  expect_sorted_like_std(crowded, rng);
  // A range that overflows (hi - lo = inf) and one so narrow that n / (hi - lo) overflows:
  // both fall back to std::sort.
  expect_sorted_like_std({1e308, -1e308, 0.5, -0.5, 1e308, 3.0}, rng);
  const double tiny = std::numeric_limits<double>::denorm_min();
  expect_sorted_like_std({tiny, 0.0, tiny, 0.0, -0.0, tiny}, rng);
  // Every key equal, and the smallest inputs.
  expect_sorted_like_std(std::vector<double>(50, 7.25), rng);
  expect_sorted_like_std({}, rng);
  expect_sorted_like_std({2.0}, rng);
  expect_sorted_like_std({2.0, 1.0}, rng);
}

}  // namespace
}  // namespace bezier::core
