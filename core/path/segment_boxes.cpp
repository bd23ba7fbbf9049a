#include "core/path/segment_boxes.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <queue>
#include <tuple>

#include "core/base/sort_by_key.hpp"

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

/// The pair of two entries as reported: (lower index, higher index) over one set, (index in
/// the first set, index in the second) over two.
std::pair<std::size_t, std::size_t> oriented_pair(int sets, const Entry& e, const Entry& o) {
  if (sets == 1) return {std::min(e.index, o.index), std::max(e.index, o.index)};
  return {e.set == 0 ? e.index : o.index, e.set == 0 ? o.index : e.index};
}

/// Stores the pair when the memory budget covers it; false (nothing stored) when not.
bool report_pair(MeetingBoxes& out, int sets, const Entry& e, const Entry& o,
                 core::WorkBudget& budget) {
  if (!budget.charge_memory(kStoredPairBytes)) return false;
  out.pairs.push_back(oriented_pair(sets, e, o));
  return true;
}

/// Which set's open boxes a box of `set` is compared with.
std::size_t other_set(int sets, int set) { return static_cast<std::size_t>(sets == 1 ? 0 : 1 - set); }

/// An open box of the plain sweep: what its tests read, and where its entry is.
struct OpenEntry {
  double max_x;
  double min_y;
  double max_y;
  std::size_t entry;
};

/// What the plain sweep found before anything is charged: the open boxes of the other set
/// compared with, and the pairs found, in all and (when asked for) per box in sweep order,
/// the pair count up to and including each box's own; the pairs themselves, up to a number
/// that the memory budget can certainly not pass.
struct PlainFindings {
  std::int64_t compared_total = 0;
  std::size_t pair_count = 0;
  std::vector<std::size_t> compared;
  std::vector<std::size_t> pairs_end;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
};

/// Sort and sweep: each box compared with every open box of the other set, O(P) for the P
/// pairs whose x ranges overlap. Each box first drops the open boxes that end before it
/// starts (they never meet it nor any later one) while it notes the ones it meets, in one
/// pass. The open boxes it is compared with are exactly the boxes of the other set before
/// it in the order whose x ranges hold its min.x, so their count summed over the boxes is
/// the number of x-overlapping pairs: nullopt (nothing charged) as soon as that passes
/// `most_compared`. Only the first `most_kept` pairs are kept (the memory budget refuses
/// the later ones), so what it holds uncharged stays within that budget. The counts per box
/// are kept only `per_box`.
std::optional<PlainFindings> plain_sweep_findings(const std::vector<Entry>& entries, int sets,
                                                  std::int64_t most_compared,
                                                  std::size_t most_kept, bool per_box) {
  PlainFindings found;
  if (per_box) {
    found.compared.resize(entries.size());
    found.pairs_end.resize(entries.size());
  }
  // Boxes that follow each other along a path meet, so there are usually a little more pairs
  // than boxes: room for that many (never more than may be kept) from the start.
  found.pairs.reserve(std::min(entries.size() + entries.size() / 4 + 8, most_kept));
  // The open boxes of each set: the first open_count[set] entries of open[set] (the vector
  // only grows; the dropped boxes' places are reused).
  std::vector<OpenEntry> open[2];
  std::size_t open_count[2] = {0, 0};
  // Few boxes are open at once along a path; room for a few dozen saves the first growths.
  for (int set = 0; set < sets; ++set) {
    open[set].reserve(std::min<std::size_t>(entries.size(), 32));
  }
  std::int64_t compared = 0;
  std::size_t pairs = 0;
  for (std::size_t k = 0; k < entries.size(); ++k) {
    const Entry& e = entries[k];
    const std::size_t other = other_set(sets, e.set);
    // A dropped box takes the last open box's place (no order is kept among the open boxes:
    // the pairs are sorted at the end, and when the memory budget cuts the list short the
    // sweep's pairs are not used at all). Walked through a pointer and a count held here
    // (storing a pair leaves the list alone).
    OpenEntry* const list = open[other].data();
    std::size_t kept = open_count[other];
    for (std::size_t l = 0; l < kept;) {
      if (list[l].max_x < e.box.min.x) {
        list[l] = list[--kept];
        continue;
      }
      if (e.box.min.y <= list[l].max_y && list[l].min_y <= e.box.max.y && pairs++ < most_kept) {
        found.pairs.push_back(oriented_pair(sets, e, entries[list[l].entry]));
      }
      ++l;
    }
    open_count[other] = kept;
    compared += static_cast<std::int64_t>(kept);
    if (compared > most_compared) return std::nullopt;
    if (per_box) {
      found.compared[k] = kept;
      found.pairs_end[k] = pairs;
    }
    const std::size_t mine = sets == 1 ? 0 : static_cast<std::size_t>(e.set);
    const OpenEntry opened{e.box.max.x, e.box.min.y, e.box.max.y, k};
    if (open_count[mine] < open[mine].size()) {
      open[mine][open_count[mine]] = opened;
    } else {
      open[mine].push_back(opened);
    }
    ++open_count[mine];
  }
  found.compared_total = compared;
  found.pair_count = pairs;
  return found;
}

/// The plain sweep's charges, box by box in sweep order, as it goes: one unit per open box
/// compared and one for the box itself (judged before the box's pairs are stored), and per
/// pair its share of the final sort (log2 of at most N^2 pairs) and its memory, before it is
/// stored. Stores the pairs found up to where the budget ran out.
void charge_plain_sweep(PlainFindings&& found, std::size_t n, core::WorkBudget& budget,
                        MeetingBoxes& out) {
  const std::int64_t log_n = std::bit_width(n);
  std::size_t stored = 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (!budget.spend(static_cast<std::int64_t>(found.compared[k]) + 1)) break;
    for (; stored < found.pairs_end[k]; ++stored) {
      budget.charge(2 * log_n);
      if (!budget.charge_memory(kStoredPairBytes)) break;
    }
    if (stored < found.pairs_end[k]) break;
  }
  found.pairs.resize(stored);
  out.pairs = std::move(found.pairs);
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

/// The pairs sorted: by the first index into buckets (counting sort, O(N + P)), each bucket
/// by the second index (insertion sort: a box meets few others). The same order as
/// std::sort, the pairs being distinct.
void sort_pairs(std::vector<std::pair<std::size_t, std::size_t>>& pairs, std::size_t n) {
  std::vector<std::size_t> bucket_start(n + 1, 0);
  for (const auto& p : pairs) ++bucket_start[p.first + 1];
  for (std::size_t i = 0; i < n; ++i) bucket_start[i + 1] += bucket_start[i];
  std::vector<std::pair<std::size_t, std::size_t>> sorted(pairs.size());
  std::vector<std::size_t> next(bucket_start.begin(), bucket_start.end() - 1);
  for (const auto& p : pairs) sorted[next[p.first]++] = p;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = bucket_start[i] + 1; k < bucket_start[i + 1]; ++k) {
      const auto p = sorted[k];
      std::size_t m = k;
      for (; m > bucket_start[i] && p.second < sorted[m - 1].second; --m) sorted[m] = sorted[m - 1];
      sorted[m] = p;
    }
  }
  pairs = std::move(sorted);
}

/// All pairs of boxes that meet, over one or two sets: the boxes sorted by min.x, then
/// whichever sweep costs less, the plain one when the x-overlapping pairs are at most
/// kPlainSweepPairsPerBoxAndLog N log2 N (so O(N log N) in all), else the tree's. The plain
/// sweep runs first, counting them, and stops (nothing charged) once they pass that bound.
/// The boxes of `a` (set 0) and then of `b` (set 1, empty for one set), each position k of
/// that list (a's boxes at 0 .. |a| - 1, b's after) an entry.
MeetingBoxes sweep(std::span<const core::Rect> a, std::span<const core::Rect> b, int sets,
                   core::WorkBudget& budget) {
  MeetingBoxes out;
  const std::size_t n = a.size() + b.size();
  if (n == 0) return out;
  if (!budget.spend(3 * sort_work(n))) return out;
  // Filled field by field: an Entry built whole and then copied is read back by the
  // compiler in wide pieces across the narrower stores just made (a store-buffer stall on
  // every entry).
  const auto fill_entry = [&](Entry& entry, std::size_t k) {
    const bool in_a = k < a.size();
    entry.box = in_a ? a[k] : b[k - a.size()];
    entry.index = in_a ? k : k - a.size();
    entry.set = in_a ? 0 : 1;
  };
  // Sorted by (min.x, set, index): the positions come in (set, index) order, so they break
  // ties in min.x; sorting small keys and gathering once moves less.
  std::vector<std::pair<double, std::size_t>> keys(n);
  for (std::size_t k = 0; k < a.size(); ++k) keys[k] = {a[k].min.x, k};
  for (std::size_t k = 0; k < b.size(); ++k) keys[a.size() + k] = {b[k].min.x, a.size() + k};
  core::sort_by_key_then_index(keys);
  std::vector<Entry> entries(n);
  std::size_t first_indices = 0;  // the first index of a pair is below this
  for (std::size_t k = 0; k < n; ++k) {
    fill_entry(entries[k], keys[k].second);
    if (entries[k].set == 0) first_indices = std::max(first_indices, entries[k].index + 1);
  }
  const std::int64_t log_n = std::bit_width(n);
  // The pairs a plain sweep can store: the memory budget refuses the one after these.
  const std::size_t most_kept = static_cast<std::size_t>(
      std::max<std::int64_t>(budget.memory_limit() - budget.memory(), 0) / kStoredPairBytes);
  const std::int64_t most_compared =
      kPlainSweepPairsPerBoxAndLog * static_cast<std::int64_t>(n) * log_n;
  if (auto found = plain_sweep_findings(entries, sets, most_compared, most_kept, false)) {
    // What charge_plain_sweep charges box by box, summed: when the budget covers the sum,
    // no charge on the way passes a limit (they only add), so charging the sums at once
    // leaves the budget as charging them in turn would, with every pair stored. Otherwise
    // the sweep runs again (the same findings) with its counts per box, charged in turn.
    const std::int64_t work = found->compared_total + static_cast<std::int64_t>(n) +
                              static_cast<std::int64_t>(found->pair_count) * 2 * log_n;
    const std::int64_t memory = static_cast<std::int64_t>(found->pair_count) * kStoredPairBytes;
    if (found->pair_count <= most_kept && work <= budget.remaining() &&
        memory <= budget.memory_limit() - budget.memory()) {
      budget.charge(work);
      (void)budget.charge_memory(memory);
      out.pairs = std::move(found->pairs);
    } else {
      auto per_box = plain_sweep_findings(entries, sets, most_compared, most_kept, true);
      charge_plain_sweep(std::move(*per_box), n, budget, out);
    }
  } else {
    budget.charge(sort_work(2 * n));
    tree_sweep(entries, sets, budget, out);
  }
  if (budget.exhausted()) return out;
  sort_pairs(out.pairs, first_indices);
  return out;
}

}  // namespace

core::Rect control_box(const core::Curve& segment) noexcept {
  const std::span<const core::Point2> points = segment.points();
  // A cubic's four points with a fixed extent (the loop unrolls): the same faces, as
  // including P_0 in the box {P_0, P_0} leaves it as it is.
  if (points.size() == 4) {
    core::Rect box{points[0], points[0]};
    for (std::size_t k = 1; k < 4; ++k) box = box.including(points[k]);
    return box;
  }
  return core::bounding_rect(points);
}

MeetingBoxes meeting_boxes(std::span<const core::Rect> a, std::span<const core::Rect> b,
                           core::WorkBudget& budget) {
  return sweep(a, b, 2, budget);
}

MeetingBoxes meeting_boxes(std::span<const core::Rect> boxes, core::WorkBudget& budget) {
  return sweep(boxes, {}, 1, budget);
}

}  // namespace bezier::path
