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
/// [lo, hi], in time O(log n + the boxes reported). A box's range [y_lo, y_hi] meets
/// [lo, hi] when y_lo lies in [lo, hi] (found in a map ordered by y_lo), or when it starts
/// below lo and reaches it (y_lo < lo <= y_hi: the ranges that contain the point lo, found
/// in a segment tree over every y a range can start or end at, where each range is stored
/// in the O(log n) nodes that cover it, so that the nodes on the path to lo's leaf hold
/// each range containing lo exactly once). Removal is immediate in the map and lazy in the
/// tree: a removed range is dropped from a node's list when a query next reads that list,
/// which costs each stored copy at most once.
class OpenBoxes {
 public:
  /// `ys`: sorted, without repeats; every y_lo and y_hi of the boxes to insert.
  OpenBoxes(const std::vector<double>& ys, std::size_t ids)
      : ys_(ys), nodes_(4 * std::max<std::size_t>(ys.size(), 1)), where_(ids), open_(ids, false),
        y_lo_(ids, 0.0) {}

  /// Inserts box `id`; returns the work units it cost (one per tree node visited).
  std::int64_t insert(std::size_t id, const Box& box) {
    open_[id] = true;
    y_lo_[id] = box.y_lo;
    where_[id] = by_lo_.emplace(box.y_lo, id);
    std::int64_t visited = 0;
    store(1, 0, ys_.size() - 1, index_of(box.y_lo), index_of(box.y_hi), id, visited);
    return visited;
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
      std::vector<std::size_t>& list = nodes_[node];
      for (std::size_t k = 0; k < list.size();) {
        ++visited;
        const std::size_t id = list[k];
        if (!open_[id]) {
          list[k] = list.back();
          list.pop_back();
          continue;
        }
        if (y_lo_[id] < lo) report(id);
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
  [[nodiscard]] std::size_t index_of(double y) const {
    return static_cast<std::size_t>(std::lower_bound(ys_.begin(), ys_.end(), y) - ys_.begin());
  }

  /// Stores `id` in the nodes that together cover [lo, hi] exactly (node covers [first, last]).
  void store(std::size_t node, std::size_t first, std::size_t last, std::size_t lo, std::size_t hi,
             std::size_t id, std::int64_t& visited) {
    ++visited;
    if (hi < first || last < lo) return;
    if (lo <= first && last <= hi) {
      nodes_[node].push_back(id);
      return;
    }
    const std::size_t middle = first + (last - first) / 2;
    store(2 * node, first, middle, lo, hi, id, visited);
    store(2 * node + 1, middle + 1, last, lo, hi, id, visited);
  }

  std::vector<double> ys_;
  std::vector<std::vector<std::size_t>> nodes_;
  std::multimap<double, std::size_t> by_lo_;
  std::vector<std::multimap<double, std::size_t>::iterator> where_;
  std::vector<bool> open_;
  std::vector<double> y_lo_;
};

struct Entry {
  Box box;
  std::size_t index;
  int set;
};

/// One sweep along x over the boxes of one or two sets: at each box's x_lo, the boxes that
/// end before it are closed, the open boxes of the other set (or of its own set when there
/// is one) that meet its y range are reported with it, and it is opened. Each pair whose
/// boxes meet is reported once, when the second of the two (in the order of x_lo) opens.
MeetingBoxes sweep(std::vector<Entry> entries, int sets, std::int64_t max_work) {
  MeetingBoxes out;
  const std::size_t n = entries.size();
  if (n == 0) return out;
  out.work = 2 * sort_work(n);
  if (out.work > max_work) {
    out.complete = false;
    return out;
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& p, const Entry& q) {
    return std::tie(p.box.x_lo, p.set, p.index) < std::tie(q.box.x_lo, q.set, q.index);
  });
  std::vector<double> ys;
  ys.reserve(2 * n);
  for (const Entry& e : entries) {
    ys.push_back(e.box.y_lo);
    ys.push_back(e.box.y_hi);
  }
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  std::vector<OpenBoxes> open;
  for (int s = 0; s < sets; ++s) open.emplace_back(ys, n);
  // The open boxes by x_hi, the smallest first: closed once the sweep passes it.
  using Closing = std::pair<double, std::size_t>;
  std::priority_queue<Closing, std::vector<Closing>, std::greater<>> closing;
  const std::int64_t log_n = std::bit_width(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Entry& e = entries[k];
    while (!closing.empty() && closing.top().first < e.box.x_lo) {
      const std::size_t id = closing.top().second;
      closing.pop();
      open[static_cast<std::size_t>(entries[id].set)].remove(id);
      out.work += log_n;
    }
    OpenBoxes& others = open[static_cast<std::size_t>(sets == 1 ? 0 : 1 - e.set)];
    out.work += others.query(e.box.y_lo, e.box.y_hi, [&](std::size_t id) {
      // Each pair pays its share of the final sort: log2 of at most N^2 pairs.
      out.work += 2 * log_n;
      const Entry& o = entries[id];
      if (sets == 1) {
        out.pairs.emplace_back(std::min(e.index, o.index), std::max(e.index, o.index));
      } else {
        out.pairs.emplace_back(e.set == 0 ? e.index : o.index, e.set == 0 ? o.index : e.index);
      }
    });
    out.work += open[static_cast<std::size_t>(sets == 1 ? 0 : e.set)].insert(k, e.box) + log_n;
    closing.emplace(e.box.x_hi, k);
    if (out.work > max_work) {
      out.complete = false;
      break;
    }
  }
  std::sort(out.pairs.begin(), out.pairs.end());
  return out;
}

}  // namespace

Box control_box(const core::Curve& segment) noexcept {
  Box box{segment.front().x, segment.front().x, segment.front().y, segment.front().y};
  for (const core::Point2 p : segment.points()) {
    box.x_lo = std::min(box.x_lo, p.x);
    box.x_hi = std::max(box.x_hi, p.x);
    box.y_lo = std::min(box.y_lo, p.y);
    box.y_hi = std::max(box.y_hi, p.y);
  }
  return box;
}

MeetingBoxes meeting_boxes(std::span<const Box> a, std::span<const Box> b,
                           std::int64_t max_work) {
  std::vector<Entry> entries;
  entries.reserve(a.size() + b.size());
  for (std::size_t i = 0; i < a.size(); ++i) entries.push_back({a[i], i, 0});
  for (std::size_t j = 0; j < b.size(); ++j) entries.push_back({b[j], j, 1});
  return sweep(std::move(entries), 2, max_work);
}

MeetingBoxes meeting_boxes(std::span<const Box> boxes, std::int64_t max_work) {
  std::vector<Entry> entries;
  entries.reserve(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) entries.push_back({boxes[i], i, 0});
  return sweep(std::move(entries), 1, max_work);
}

}  // namespace bezier::path
