#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/base/point.hpp"
#include "core/base/work_budget.hpp"
#include "core/region/region.hpp"

namespace bezier::region {

/// Where a target lies w.r.t. a region's boundary.
struct Winding {
  /// The target is within the boundary band of the path: at distance <= 8 u s from it,
  /// u = 2^-53 and s the coordinates' scale (the largest |coordinate| of the region's
  /// control points and of the target). Then `winding` is 0 and means nothing.
  bool boundary = false;
  /// The winding number of the path around the target (when !boundary): the number of
  /// times the path turns counter-clockwise around it (with y up; clockwise on an SVG
  /// screen, whose y points down), exact.
  long winding = 0;
};

/// Whether the region holds the target: on its boundary, or filled by its winding number.
[[nodiscard]] inline bool inside(const Winding& w, FillRule rule) noexcept {
  return w.boundary || fills(rule, w.winding);
}

/// A region prepared for winding numbers: its path scaled by a power of two (exact) to
/// coordinates below 2 in magnitude, and each segment's box, shared by every target.
///
/// The winding number is decided exactly. For each segment whose box is farther than the
/// band from the target (in one coordinate) its contribution to the crossings of the ray
/// from the target towards +x comes from its end points alone. Each other segment is
/// subdivided at t = 1/2 in double-double arithmetic, with a bound on the pieces' rounding
/// error, until every piece is settled:
///   - its control points, widened by their error bound, lie strictly on one side of the
///     target's horizontal or vertical line: the convex hull of the exact piece misses the
///     target, so the piece can be replaced by its chord without changing the winding
///     number (the straight-line homotopy between the two stays in the hull); the chords
///     form a closed polygon through the computed subdivision points (shared exactly by
///     neighbouring pieces), whose crossings of the ray follow from exact comparisons of
///     the chords' end points with the target's y (the half-open rule: an end point at the
///     target's y counts as below, so a ray through a vertex or along a horizontal edge
///     counts once or not at all, as the path passes or turns back);
///   - and it is farther than the band from the target: its widened hull is beyond the
///     band in one coordinate, or on the far side of the line at distance band from the
///     target perpendicular to the direction to the nearest point of its chord (one of the
///     pieces' ancestors may have shown this for it).
/// A piece end point within the band (with its error bound) makes the answer `boundary`.
/// So a `winding` is certified whenever reported, and `boundary` means the target is within
/// the band of the exact path, except where it lies within about 2^-80 s of the band's edge
/// (region_tuning::kMaxDepth), where neither can be shown and `boundary` is reported: a
/// target one ulp of s outside the band gets its winding number.
///
/// Work: each segment costs region_tuning::kBoxTestCost per target, each double-double
/// piece kCompensatedFactor (n + 1)^2 (core/intersect/work_cost.hpp); near the path a
/// target takes about log2(1 / (distance to the band's edge)) levels of a few pieces.
class RegionWinding {
 public:
  explicit RegionWinding(const Region& region);

  /// The winding of the region's path around `target` (finite), charging its work to
  /// `budget` (the targets of one request share it); nullopt when it ran out first
  /// (budget.exhausted()).
  [[nodiscard]] std::optional<Winding> at(core::Point2 target, core::WorkBudget& budget) const;

 private:
  struct Box {
    double x_min, x_max, y_min, y_max;
  };
  /// The control points of every segment, scaled, one after another: segment k's are
  /// points_[offsets_[k] .. offsets_[k + 1]).
  std::vector<core::Point2> points_;
  std::vector<std::size_t> offsets_;
  std::vector<Box> boxes_;
  /// The region's scale (largest |coordinate|) after scaling: in [1, 2), or 0 when the
  /// region is empty or every control point is the origin.
  double scale_ = 0.0;
  /// The exponent e of the scaling by 2^-e.
  int exponent_ = 0;
};

/// RegionWinding(region).at(target, work) for one target: nullopt when more than
/// `max_work` units would be spent.
[[nodiscard]] std::optional<Winding> winding(const Region& region, core::Point2 target,
                                             std::int64_t max_work);

}  // namespace bezier::region
