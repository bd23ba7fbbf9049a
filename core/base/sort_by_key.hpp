#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace bezier::core {

/// Sorts (key, index) pairs by key, ties by index: the order
///   p.first < q.first || (p.first == q.first && p.second < q.second)
/// gives with std::sort (the indices distinct, so the order is total and the result the same
/// list). Precondition: finite keys (a NaN or an infinite key makes it std::sort with that
/// comparator).
///
/// Method: the keys are distributed into n buckets of equal width over [lo, hi], their least
/// and greatest (bucket of x: floor(fl(fl(x - lo) * f)), f = fl(n / (hi - lo)), the last
/// bucket also taking any x whose product reaches n), a counting pass placing each bucket's
/// pairs together in input order, then each bucket sorted on its own: by insertion up to
/// kInsertionLimit pairs, by std::sort beyond; when no bucket is larger, by one insertion
/// pass over the whole list, which moves no pair out of its bucket. Why the buckets come in
/// key order: each step of the bucket formula is monotone in x (a rounded subtraction of a
/// fixed lo, a rounded product by a fixed f > 0, the floor and the cap), so a smaller key
/// never lands in a later bucket than a larger one (and a pair in a later bucket has the
/// larger key); sorting within buckets then sorts the whole. When hi - lo is not positive,
/// or f is not finite (a range so narrow that n over it overflows, or one that overflows
/// itself), everything is sorted by std::sort instead.
///
/// Cost: O(n) for keys spread evenly over their range (the sweeps' x coordinates), against
/// std::sort's n log n comparisons; O(n log n) at worst (keys in one bucket). Two work arrays
/// of n + 1 counts and n pairs, allocated here.
inline void sort_by_key_then_index(std::vector<std::pair<double, std::size_t>>& items) {
  using Item = std::pair<double, std::size_t>;
  constexpr auto before = [](const Item& p, const Item& q) {
    return p.first < q.first || (p.first == q.first && p.second < q.second);
  };
  constexpr std::size_t kInsertionLimit = 16;
  const std::size_t n = items.size();
  if (n < 2) return;
  // The work arrays first: every double register is lost across a call (an allocation), and
  // a running minimum that is still needed after one is kept in memory by the compiler, so
  // that each step of its loop waits for the store of the step before.
  std::vector<std::size_t> start(n + 1, 0);
  std::vector<Item> placed(n);
  double lo = items[0].first, hi = items[0].first;
  bool finite = true;
  for (const Item& item : items) {
    finite = finite && std::isfinite(item.first);
    lo = item.first < lo ? item.first : lo;
    hi = hi < item.first ? item.first : hi;
  }
  const double f = static_cast<double>(n) / (hi - lo);
  if (!finite || !(hi - lo > 0.0) || !std::isfinite(f)) {
    std::sort(items.begin(), items.end(), before);
    return;
  }
  const auto bucket_of = [lo, f, n](double x) {
    // v >= 0 (x >= lo, f > 0): the signed conversion, one instruction, gives its floor.
    const double v = (x - lo) * f;
    return v < static_cast<double>(n) ? static_cast<std::size_t>(static_cast<std::int64_t>(v))
                                      : n - 1;
  };
  for (const Item& item : items) ++start[bucket_of(item.first) + 1];
  std::size_t largest = 0;
  for (std::size_t b = 0; b < n; ++b) {
    largest = std::max(largest, start[b + 1]);
    start[b + 1] += start[b];
  }
  // start[b] is used as bucket b's next free place.
  for (const Item& item : items) placed[start[bucket_of(item.first)]++] = item;
  if (largest <= kInsertionLimit) {
    // Every bucket small: one insertion pass over the whole list. A pair never moves past
    // the start of its bucket (the pairs of earlier buckets have smaller keys, and equal
    // keys share a bucket), so this is each bucket's insertion sort without a loop over
    // the buckets.
    for (std::size_t k = 1; k < n; ++k) {
      const Item moving = placed[k];
      std::size_t m = k;
      for (; m > 0 && before(moving, placed[m - 1]); --m) placed[m] = placed[m - 1];
      placed[m] = moving;
    }
  } else {
    // After the placing, start[b] is where bucket b ends (and bucket b + 1 begins).
    for (std::size_t b = 0; b < n; ++b) {
      const std::size_t first = b == 0 ? 0 : start[b - 1], end = start[b];
      if (end - first > kInsertionLimit) {
        std::sort(placed.begin() + static_cast<std::ptrdiff_t>(first),
                  placed.begin() + static_cast<std::ptrdiff_t>(end), before);
        continue;
      }
      for (std::size_t k = first + 1; k < end; ++k) {
        const Item moving = placed[k];
        std::size_t m = k;
        for (; m > first && before(moving, placed[m - 1]); --m) placed[m] = placed[m - 1];
        placed[m] = moving;
      }
    }
  }
  items = std::move(placed);
}

}  // namespace bezier::core
