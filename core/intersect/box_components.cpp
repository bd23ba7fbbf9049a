#include "core/intersect/box_components.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <cassert>
#include <limits>
#include <numeric>

namespace bezier::core {

namespace {

using Id = std::uint32_t;  // a box's index (box_components refuses more than 2^32 - 1 boxes)
constexpr Id kNone = std::numeric_limits<Id>::max();
constexpr double kNever = -std::numeric_limits<double>::infinity();

/// Union-find with union by size and path halving.
class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n), size_(n, 1) {
    std::iota(parent_.begin(), parent_.end(), std::size_t{0});
  }

  std::size_t find(std::size_t i) {
    while (parent_[i] != i) {
      parent_[i] = parent_[parent_[i]];
      i = parent_[i];
    }
    return i;
  }

  void unite(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
  }

 private:
  std::vector<std::size_t> parent_;
  std::vector<std::size_t> size_;
};

/// The segment tree over the s end points. A box is stored at its canonical nodes (the
/// O(log k) nodes whose ranges tile its s interval); "open" means it has not ended at the
/// sweep's current t.
class SweepTree {
 public:
  SweepTree(std::size_t leaves, DisjointSets& sets)
      : nodes_(2 * std::bit_ceil(std::max<std::size_t>(leaves, 1))), leaves_(leaves), sets_(sets) {}

  /// Stores box `id` (s indices [lo, hi], ending at t = end) at sweep position now,
  /// uniting it with every open box stored whose s interval meets [lo, hi].
  void insert(Id id, std::size_t lo, std::size_t hi, double end, double now) {
    Insertion in{id, lo, hi, end, now};
    insert(in, 1, 0, leaves_ - 1);
  }

 private:
  struct Node {
    /// The open box stored here that ends last (the others stored here meet it, since all
    /// of them cover this node's range and are open together, so they are already joined).
    double own_end = kNever;
    /// The box stored in this subtree (this node included) that ends last.
    double last_end = kNever;
    Id own = kNone;
    Id last = kNone;
    /// Every open box stored in the subtree is in one component (then `last`'s, when open).
    bool joined = true;
  };

  struct Insertion {
    Id id;
    std::size_t lo, hi;
    double end, now;
  };

  /// Unites the box with every open box in the subtree of node v (all of which meet it).
  void gather(const Insertion& in, std::size_t v, std::size_t l, std::size_t r) {
    Node& n = nodes_[v];
    if (n.last_end < in.now) return;  // nothing open below
    if (n.joined) {
      sets_.unite(in.id, n.last);
      return;
    }
    if (n.own_end >= in.now) sets_.unite(in.id, n.own);
    const std::size_t mid = l + (r - l) / 2;
    gather(in, 2 * v, l, mid);
    gather(in, 2 * v + 1, mid + 1, r);
    n.joined = true;
  }

  void insert(const Insertion& in, std::size_t v, std::size_t l, std::size_t r) {
    if (r < in.lo || in.hi < l) return;
    Node& n = nodes_[v];
    // A box stored here covers [l, r], which meets [lo, hi].
    if (n.own_end >= in.now) sets_.unite(in.id, n.own);
    if (in.lo <= l && r <= in.hi) {
      gather(in, v, l, r);
      if (in.end > n.own_end) {
        n.own = in.id;
        n.own_end = in.end;
      }
      if (in.end > n.last_end) {
        n.last = in.id;
        n.last_end = in.end;
      }
      n.joined = true;  // every open box below is now in the box's component
      return;
    }
    const bool had_open = n.last_end >= in.now;
    const bool was_joined = n.joined;
    const Id previous_last = n.last;
    const std::size_t mid = l + (r - l) / 2;
    insert(in, 2 * v, l, mid);
    insert(in, 2 * v + 1, mid + 1, r);
    if (in.end > n.last_end) {
      n.last = in.id;
      n.last_end = in.end;
    }
    n.joined = !had_open || (was_joined && sets_.find(previous_last) == sets_.find(in.id));
  }

  std::vector<Node> nodes_;
  std::size_t leaves_;
  DisjointSets& sets_;
};

}  // namespace

std::vector<std::size_t> box_components(std::span<const ClosedBox> boxes) {
  const std::size_t k = boxes.size();
  if (k >= kNone) throw std::length_error("box_components: too many boxes");
  // Each s end point's rank among the distinct ones: the tree's leaves.
  std::vector<std::pair<double, std::size_t>> ends;  // (value, 2 i for s.lo, 2 i + 1 for s.hi)
  ends.reserve(2 * k);
  for (std::size_t i = 0; i < k; ++i) {
    const ClosedBox& b = boxes[i];
    assert(b.t.lo <= b.t.hi && b.s.lo <= b.s.hi);
    ends.emplace_back(b.s.lo, 2 * i);
    ends.emplace_back(b.s.hi, 2 * i + 1);
  }
  std::sort(ends.begin(), ends.end());
  std::vector<std::size_t> rank(2 * k);
  std::size_t distinct = 0;
  for (std::size_t j = 0; j < ends.size(); ++j) {
    if (j > 0 && ends[j].first != ends[j - 1].first) ++distinct;
    rank[ends[j].second] = distinct;
  }

  std::vector<std::size_t> order(k);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return boxes[a].t.lo != boxes[b].t.lo ? boxes[a].t.lo < boxes[b].t.lo : a < b;
  });

  DisjointSets sets(k);
  SweepTree tree(k == 0 ? 0 : distinct + 1, sets);
  for (const std::size_t i : order) {
    const ClosedBox& b = boxes[i];
    tree.insert(static_cast<Id>(i), rank[2 * i], rank[2 * i + 1], b.t.hi, b.t.lo);
  }
  std::vector<std::size_t> label(k);
  for (std::size_t i = 0; i < k; ++i) label[i] = sets.find(i);
  return label;
}

}  // namespace bezier::core
