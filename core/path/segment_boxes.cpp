#include "core/path/segment_boxes.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <functional>
#include <map>
#include <queue>
#include <tuple>

namespace bezier::path {

namespace {

/// The estimated comparisons of sorting n items: n ceil(log2 n).
std::int64_t sort_work(std::size_t n) {
  return static_cast<std::int64_t>(n) * static_cast<std::int64_t>(std::bit_width(n));
}

/// The boxes open at the sweep's position, by their y ranges: which of them meet a y range
/// [lo, hi], in time O(log n + the boxes reported). A box's range [min.y, max.y] meets
/// [lo, hi] when min.y lies in [lo, hi] (found in a map ordered by min.y), or when it starts
/// below lo and reaches it (min.y < lo <= max.y: the ranges that contain the point lo, found
/// in a segment tree over every y a range can start or end at, where each range is stored
/// in the O(log n) nodes that cover it, so that the nodes on the path to lo's leaf hold
/// each range containing lo exactly once). Removal is immediate in the map and lazy in the
/// tree: a removed range is dropped from a node's list when a query next reads that list,
/// which costs each stored copy at most once. The lists live in one array, laid out before
/// the sweep from the ranges that will be inserted.
class OpenBoxes {
 public:
  /// `ys`: sorted, without repeats; every min.y and max.y of the boxes to insert. `boxes`: the
  /// boxes that will be inserted, by id (the others are never inserted here); the tree's
  /// lists are laid out once for them, so inserting allocates nothing.
  OpenBoxes(const std::vector<double>& ys, const std::vector<const core::Rect*>& boxes)
      : ys_(ys),
        offset_(4 * std::max<std::size_t>(ys.size(), 1) + 1, 0),
        size_(4 * std::max<std::size_t>(ys.size(), 1), 0),
        where_(boxes.size()),
        open_(boxes.size(), false) {
    // offset_[node + 1] counts the node's copies first, then becomes the running sum.
    for (const core::Rect* box : boxes) {
      if (box != nullptr) visit(1, 0, ys_.size() - 1, index_of(box->min.y), index_of(box->max.y), [&](std::size_t node) { ++offset_[node + 1]; });
    }
    for (std::size_t node = 1; node < offset_.size(); ++node) offset_[node] += offset_[node - 1];
    pool_.resize(offset_.back());
  }

  /// Inserts box `id`; returns the work units it cost (one per tree node visited).
  std::int64_t insert(std::size_t id, const core::Rect& box) {
    open_[id] = true;
    where_[id] = by_lo_.emplace(box.min.y, id);
    return visit(1, 0, ys_.size() - 1, index_of(box.min.y), index_of(box.max.y),
                 [&](std::size_t node) { pool_[offset_[node] + size_[node]++] = {id, box.min.y}; });
  }

  void remove(std::size_t id) {
    open_[id] = false;
    by_lo_.erase(where_[id]);
  }

  /// Calls report(id) for every open box whose y range meets [lo, hi] (lo one of `ys`),
  /// once each; returns the work units it cost (entries read and nodes visited).
  template <class Report>
  std::int64_t query(double lo, double hi, const Report& report) {
    std::int64_t visited = 0;
    for (auto it = by_lo_.lower_bound(lo); it != by_lo_.end() && it->first <= hi; ++it) {
      ++visited;
      report(it->second);
    }
    const std::size_t point = index_of(lo);
    std::size_t node = 1, first = 0, last = ys_.size() - 1;
    while (true) {
      Stored* list = pool_.data() + offset_[node];
      for (std::size_t k = 0; k < size_[node];) {
        ++visited;
        if (!open_[list[k].id]) {
          list[k] = list[--size_[node]];
          continue;
        }
        if (list[k].y_lo < lo) report(list[k].id);
        ++k;
      }
      if (first == last) break;
      const std::size_t middle = first + (last - first) / 2;
      node *= 2;
      if (point <= middle) {
        last = middle;
      } else {
        first = middle + 1;
        ++node;
      }
    }
    return visited;
  }

 private:
  struct Stored {
    std::size_t id;
    double y_lo;
  };

  [[nodiscard]] std::size_t index_of(double y) const {
    return static_cast<std::size_t>(std::lower_bound(ys_.begin(), ys_.end(), y) - ys_.begin());
  }

  /// Calls at(node) for the nodes that together cover [lo, hi] exactly (node covers
  /// [first, last]); returns the nodes visited.
  template <class At>
  static std::int64_t visit(std::size_t node, std::size_t first, std::size_t last, std::size_t lo,
                            std::size_t hi, const At& at) {
    if (hi < first || last < lo) return 1;
    if (lo <= first && last <= hi) {
      at(node);
      return 1;
    }
    const std::size_t middle = first + (last - first) / 2;
    return 1 + visit(2 * node, first, middle, lo, hi, at) +
           visit(2 * node + 1, middle + 1, last, lo, hi, at);
  }

  std::vector<double> ys_;
  std::vector<std::size_t> offset_;
  std::vector<std::size_t> size_;
  std::vector<Stored> pool_;
  std::multimap<double, std::size_t> by_lo_;
  std::vector<std::multimap<double, std::size_t>::iterator> where_;
  std::vector<bool> open_;
};

struct Entry {
  core::Rect box;
  std::size_t index;
  int set;
};

/// Stores the pair when the memory budget covers it; false (nothing stored) when not.
bool report_pair(MeetingBoxes& out, int sets, const Entry& e, const Entry& o,
                 core::WorkBudget& budget) {
  if (!budget.charge_memory(kStoredPairBytes)) return false;
  if (sets == 1) {
    out.pairs.emplace_back(std::min(e.index, o.index), std::max(e.index, o.index));
  } else {
    out.pairs.emplace_back(e.set == 0 ? e.index : o.index, e.set == 0 ? o.index : e.index);
  }
  return true;
}

/// Which set's open boxes a box of `set` is compared with.
std::size_t other_set(int sets, int set) { return static_cast<std::size_t>(sets == 1 ? 0 : 1 - set); }

/// The pairs a box is compared with in the plain sweep below: for each box (sorted by min.x),
/// the boxes of the other set whose x ranges hold its min.x. O(N) on the sorted boxes, with
/// each set's max.x sorted.
std::int64_t x_overlapping_pairs(const std::vector<Entry>& entries, int sets) {
  std::vector<double> x_hi[2];
  for (const Entry& e : entries) x_hi[e.set].push_back(e.box.max.x);
  for (auto& v : x_hi) std::sort(v.begin(), v.end());
  std::size_t started[2] = {0, 0}, ended[2] = {0, 0};
  std::int64_t pairs = 0;
  for (const Entry& e : entries) {
    const std::size_t o = other_set(sets, e.set);
    while (ended[o] < x_hi[o].size() && x_hi[o][ended[o]] < e.box.min.x) ++ended[o];
    pairs += static_cast<std::int64_t>(started[o]) - static_cast<std::int64_t>(std::min(ended[o], started[o]));
    ++started[static_cast<std::size_t>(e.set)];
  }
  return pairs;
}

/// Sort and sweep: each box compared with every open box of the other set, O(P) for the P
/// pairs whose x ranges overlap.
void plain_sweep(const std::vector<Entry>& entries, int sets, core::WorkBudget& budget,
                 MeetingBoxes& out) {
  const std::int64_t log_n = std::bit_width(entries.size());
  std::vector<Entry> open[2];
  for (const Entry& e : entries) {
    std::vector<Entry>& other = open[other_set(sets, e.set)];
    // Boxes that end before this one starts never meet it nor any later one.
    std::erase_if(other, [&](const Entry& o) { return o.box.max.x < e.box.min.x; });
    if (!budget.spend(static_cast<std::int64_t>(other.size()) + 1)) return;
    for (const Entry& o : other) {
      if (e.box.min.y <= o.box.max.y && o.box.min.y <= e.box.max.y) {
        // Each pair pays its share of the final sort: log2 of at most N^2 pairs.
        budget.charge(2 * log_n);
        if (!report_pair(out, sets, e, o, budget)) return;
      }
    }
    open[sets == 1 ? 0 : e.set].push_back(e);
  }
}

/// Bentley-Wood: the open boxes in OpenBoxes, each box's query reporting only the boxes it
/// meets. O(N log N + K) for the K pairs that meet.
void tree_sweep(const std::vector<Entry>& entries, int sets, core::WorkBudget& budget,
                MeetingBoxes& out) {
  const std::size_t n = entries.size();
  std::vector<double> ys;
  ys.reserve(2 * n);
  for (const Entry& e : entries) {
    ys.push_back(e.box.min.y);
    ys.push_back(e.box.max.y);
  }
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  std::vector<OpenBoxes> open;
  for (int set = 0; set < sets; ++set) {
    std::vector<const core::Rect*> inserted(n, nullptr);
    for (std::size_t k = 0; k < n; ++k) {
      if (entries[k].set == set) inserted[k] = &entries[k].box;
    }
    open.emplace_back(ys, inserted);
  }
  // The open boxes by max.x, the smallest first: closed once the sweep passes it.
  using Closing = std::pair<double, std::size_t>;
  std::priority_queue<Closing, std::vector<Closing>, std::greater<>> closing;
  const std::int64_t log_n = std::bit_width(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Entry& e = entries[k];
    while (!closing.empty() && closing.top().first < e.box.min.x) {
      const std::size_t id = closing.top().second;
      closing.pop();
      open[static_cast<std::size_t>(sets == 1 ? 0 : entries[id].set)].remove(id);
      budget.charge(log_n);
    }
    bool stored = true;
    budget.charge(open[other_set(sets, e.set)].query(e.box.min.y, e.box.max.y, [&](std::size_t id) {
      // Each pair pays its share of the final sort: log2 of at most N^2 pairs.
      budget.charge(2 * log_n);
      stored = stored && report_pair(out, sets, e, entries[id], budget);
    }));
    if (!stored) return;
    budget.charge(open[static_cast<std::size_t>(sets == 1 ? 0 : e.set)].insert(k, e.box) + log_n);
    closing.emplace(e.box.max.x, k);
    if (!budget.spend(0)) return;
  }
}

/// The tree's setup and updates cost a few times log2 N units per box (the nodes covering
/// its y range, twice, and its query's path); the plain sweep one unit per x-overlapping
/// pair. Below this many x-overlapping pairs per box and log2 N the plain sweep is cheaper,
/// and its cost is then within a constant of N log N.
constexpr std::int64_t kPlainSweepPairsPerBoxAndLog = 8;

/// All pairs of boxes that meet, over one or two sets: the boxes sorted by min.x, then
/// whichever sweep costs less, the plain one when the x-overlapping pairs are at most
/// kPlainSweepPairsPerBoxAndLog N log2 N (so O(N log N) in all), else the tree's.
MeetingBoxes sweep(std::vector<Entry> entries, int sets, core::WorkBudget& budget) {
  MeetingBoxes out;
  const std::size_t n = entries.size();
  if (n == 0) return out;
  if (!budget.spend(3 * sort_work(n))) return out;
  std::sort(entries.begin(), entries.end(), [](const Entry& p, const Entry& q) {
    return std::tie(p.box.min.x, p.set, p.index) < std::tie(q.box.min.x, q.set, q.index);
  });
  const std::int64_t log_n = std::bit_width(n);
  if (x_overlapping_pairs(entries, sets) <=
      kPlainSweepPairsPerBoxAndLog * static_cast<std::int64_t>(n) * log_n) {
    plain_sweep(entries, sets, budget, out);
  } else {
    budget.charge(sort_work(2 * n));
    tree_sweep(entries, sets, budget, out);
  }
  if (budget.exhausted()) return out;
  std::sort(out.pairs.begin(), out.pairs.end());
  return out;
}

}  // namespace

core::Rect control_box(const core::Curve& segment) noexcept {
  return core::bounding_rect(segment.points());
}

MeetingBoxes meeting_boxes(std::span<const core::Rect> a, std::span<const core::Rect> b,
                           core::WorkBudget& budget) {
  std::vector<Entry> entries;
  entries.reserve(a.size() + b.size());
  for (std::size_t i = 0; i < a.size(); ++i) entries.push_back({a[i], i, 0});
  for (std::size_t j = 0; j < b.size(); ++j) entries.push_back({b[j], j, 1});
  return sweep(std::move(entries), 2, budget);
}

MeetingBoxes meeting_boxes(std::span<const core::Rect> boxes, core::WorkBudget& budget) {
  std::vector<Entry> entries;
  entries.reserve(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) entries.push_back({boxes[i], i, 0});
  return sweep(std::move(entries), 1, budget);
}

}  // namespace bezier::path
