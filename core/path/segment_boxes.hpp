#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "core/base/curve.hpp"
#include "core/base/rect.hpp"
#include "core/base/work_budget.hpp"

namespace bezier::path {

/// The box of a segment's control points. It contains the segment (a Bézier curve lies in
/// the convex hull of its control points) and is exact: minima and maxima of the inputs,
/// no rounding, so two segments whose boxes are disjoint certainly do not meet.
[[nodiscard]] core::Rect control_box(const core::Curve& segment) noexcept;

/// Pairs of boxes that meet (closed boxes: touching counts, core::Rect::intersects).
struct MeetingBoxes {
  /// (i, j) pairs, sorted (unsorted, and maybe not all, when the budget ran out).
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
};

/// The memory a stored pair is charged (core::WorkBudget::charge_memory), in bytes.
inline constexpr std::int64_t kStoredPairBytes =
    static_cast<std::int64_t>(sizeof(std::pair<std::size_t, std::size_t>));

/// Every (i, j) with a[i] and b[j] meeting. The boxes are sorted by min.x and swept along x:
/// at each box, the boxes that end before it are closed, the open boxes of the other set
/// that meet it are reported, and it is opened. When few pairs overlap in x (at most
/// 8 N log2 N), each box is compared with every open box of the other set (this sweep runs
/// first, counting those pairs, and is abandoned uncharged once they pass the bound, after
/// O(N log N) comparisons); otherwise the open boxes are held by min.y in a map and by their y ranges in a
/// segment tree, so that a box's query reads only the boxes it meets (Bentley & Wood, "An
/// optimal worst case algorithm for reporting intersections of rectangles", IEEE Trans.
/// Computers C-29, 1980). Cost O(N log N + K) for N boxes in all and K pairs that meet.
///
/// Charged to `budget` in work units (core/intersect/work_cost.hpp: about one coordinate
/// update each): the sorts by their estimated comparisons (the pairs' sort, a bucket sort
/// by the first index, as each pair is found), one per pair of boxes compared in the plain
/// sweep (and one per box), charged box by box in sweep order once the plain sweep is
/// chosen, and in the tree's each
/// insertion, removal and query by the nodes and entries it reads; and in memory,
/// kStoredPairBytes per pair as it is found, before it is stored. Stops early, the budget
/// exhausted, once the work passes its limit or a pair would pass the memory limit.
[[nodiscard]] MeetingBoxes meeting_boxes(std::span<const core::Rect> a,
                                         std::span<const core::Rect> b, core::WorkBudget& budget);

/// Every (i, j), i < j, with boxes[i] and boxes[j] meeting: the same sweep over one set.
[[nodiscard]] MeetingBoxes meeting_boxes(std::span<const core::Rect> boxes,
                                         core::WorkBudget& budget);

}  // namespace bezier::path
