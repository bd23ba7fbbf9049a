#include "core/path/segment_boxes.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace bezier::path {

namespace {

bool y_ranges_meet(const Box& p, const Box& q) { return p.y_lo <= q.y_hi && q.y_lo <= p.y_hi; }

/// The estimated comparisons of sorting n items: n ceil(log2 n).
std::int64_t sort_work(std::size_t n) {
  return static_cast<std::int64_t>(n) * static_cast<std::int64_t>(std::bit_width(n));
}

/// One sweep over the boxes of one or two sets: each box is compared with the open boxes of
/// the other set, or of its own set when there is one.
struct Sweep {
  struct Entry {
    Box box;
    std::size_t index;
    int set;
  };

  static MeetingBoxes run(std::vector<Entry> entries, int sets, std::int64_t max_work) {
    MeetingBoxes out;
    out.work = sort_work(entries.size());
    if (out.work > max_work) {
      out.complete = false;
      return out;
    }
    std::sort(entries.begin(), entries.end(), [](const Entry& p, const Entry& q) {
      return p.box.x_lo < q.box.x_lo || (p.box.x_lo == q.box.x_lo && p.set < q.set) ||
             (p.box.x_lo == q.box.x_lo && p.set == q.set && p.index < q.index);
    });
    std::vector<Entry> open[2];
    for (const Entry& e : entries) {
      std::vector<Entry>& other = open[sets == 1 ? 0 : 1 - e.set];
      // Boxes that end before this one starts never meet it nor any later one.
      std::erase_if(other, [&](const Entry& o) { return o.box.x_hi < e.box.x_lo; });
      out.work += static_cast<std::int64_t>(other.size()) + 1;
      if (out.work > max_work) {
        out.complete = false;
        break;
      }
      for (const Entry& o : other) {
        if (!y_ranges_meet(e.box, o.box)) continue;
        if (sets == 1) {
          out.pairs.emplace_back(std::min(e.index, o.index), std::max(e.index, o.index));
        } else {
          out.pairs.emplace_back(e.set == 0 ? e.index : o.index, e.set == 0 ? o.index : e.index);
        }
      }
      open[sets == 1 ? 0 : e.set].push_back(e);
    }
    std::sort(out.pairs.begin(), out.pairs.end());
    return out;
  }
};

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
  std::vector<Sweep::Entry> entries;
  entries.reserve(a.size() + b.size());
  for (std::size_t i = 0; i < a.size(); ++i) entries.push_back({a[i], i, 0});
  for (std::size_t j = 0; j < b.size(); ++j) entries.push_back({b[j], j, 1});
  return Sweep::run(std::move(entries), 2, max_work);
}

MeetingBoxes meeting_boxes(std::span<const Box> boxes, std::int64_t max_work) {
  std::vector<Sweep::Entry> entries;
  entries.reserve(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) entries.push_back({boxes[i], i, 0});
  return Sweep::run(std::move(entries), 1, max_work);
}

}  // namespace bezier::path
