#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "core/base/curve.hpp"

namespace bezier::path {

/// A closed axis-aligned box [x_lo, x_hi] x [y_lo, y_hi].
struct Box {
  double x_lo = 0.0;
  double x_hi = 0.0;
  double y_lo = 0.0;
  double y_hi = 0.0;
};

/// The box of a segment's control points. It contains the segment (a Bézier curve lies in
/// the convex hull of its control points) and is exact: minima and maxima of the inputs,
/// no rounding, so two segments whose boxes are disjoint certainly do not meet.
[[nodiscard]] Box control_box(const core::Curve& segment) noexcept;

/// Pairs of boxes that meet (closed boxes: touching counts), and what finding them cost.
struct MeetingBoxes {
  /// (i, j) pairs, sorted.
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  /// Work units (core/intersect/work_cost.hpp: about one coordinate update each) charged for
  /// the sort and the sweep: one per comparison of the sort's estimated N log2 N and one per
  /// pair of boxes whose x ranges overlap.
  std::int64_t work = 0;
  /// False when the sweep stopped at its work limit: `pairs` may then miss some.
  bool complete = true;
};

/// Every (i, j) with a[i] and b[j] meeting. Sweep along x (sort and sweep): the boxes sorted
/// by x_lo, each box compared with the boxes of the other set still open at its x_lo. Cost
/// O(N log N + P) for N boxes in all, P the pairs whose x ranges overlap (at least the
/// pairs that meet, at most all of them when every box spans the same x range). Stops
/// early (complete = false) once the work exceeds `max_work`.
[[nodiscard]] MeetingBoxes meeting_boxes(std::span<const Box> a, std::span<const Box> b,
                                         std::int64_t max_work);

/// Every (i, j), i < j, with boxes[i] and boxes[j] meeting: the same sweep over one set.
[[nodiscard]] MeetingBoxes meeting_boxes(std::span<const Box> boxes, std::int64_t max_work);

}  // namespace bezier::path
