#pragma once

#include <algorithm>
#include <optional>
#include <span>
#include <utility>

#include "core/base/curve.hpp"
#include "core/curve/polar.hpp"
#include "core/curve/subdivide.hpp"

namespace bezier::region {

/// core::portion(segment, t0, t1), bit for bit, without its arithmetic when the piece is the
/// whole segment (t0 = 0, t1 = 1) and no control-point coordinate is zero.
///
/// Why that is the segment itself. portion's control point i is the blossom
/// b(0^(n-i), 1^i), computed by de Casteljau rounds (core/bernstein/casteljau_row.hpp) with
/// parameters 0 and 1 only. A round with parameter 0 gives each entry (1 - 0) a + 0 b, one
/// with parameter 1 gives 0 a + 1 b: the error-free products by 1 and 0 and the two-sum of a
/// value and a zero are exact with zero error parts, so every entry stays an input coordinate
/// with error part zero, and the point, value plus error part, is that coordinate. The one
/// exception is the sign of a zero (-0 + 0 = +0): a segment with a zero coordinate takes
/// core::portion. Checked against core::portion in tests/core/region/segment_piece_test.cpp.
[[nodiscard]] inline bool segment_piece_is_segment(const core::Curve& segment, double t0,
                                                   double t1) {
  if (!(t0 == 0.0 && t1 == 1.0)) return false;
  const std::span<const core::Point2> points = segment.points();
  // (An int, so that the four tests below combine with | without a warning for | on bool.)
  const auto has_zero = [](core::Point2 p) -> int { return p.x == 0.0 || p.y == 0.0; };
  // A cubic's four points tested at once (no early exit to branch on); other degrees in turn.
  if (points.size() == 4) {
    return (has_zero(points[0]) | has_zero(points[1]) | has_zero(points[2]) |
            has_zero(points[3])) == 0;
  }
  return std::none_of(points.begin(), points.end(), has_zero);
}

/// Whether no control-point coordinate of the curve is zero (of either sign).
[[nodiscard]] inline bool without_zero_coordinate(const core::Curve& curve) {
  return std::none_of(curve.points().begin(), curve.points().end(),
                      [](core::Point2 p) { return p.x == 0.0 || p.y == 0.0; });
}

/// core::portion(segment, t0, t1) of an end piece (t0 = 0 or t1 = 1) as the matching half of
/// core::subdivide(segment, t1 or t0), bit for bit, where that is shown; nullopt otherwise.
///
/// Why. portion's control point i is n - i de Casteljau rounds with t0 on the whole row, then
/// i rounds with t1, entry 0 (core/curve/polar.cpp), each round the compensated step of
/// core/bernstein/casteljau_row.hpp (entries: value hi, error part lo); subdivide's left
/// point i is entry 0 after i rounds with t, its right point i entry i after n - i rounds.
///  - t0 = 0: a round with 0 has 1 - 0 = 1 + 0 exactly (two_sum), two_product(1, hi) = (hi, +0),
///    two_product(0, hi') a zero with error +0, two_sum(hi, zero) = (hi, +0) when hi != 0, so
///    the step's local error is +0 and the entry stays (hi, lo) (lo = +0 for an input point).
///    With no zero coordinate in the segment, the rounds with 0 leave the control points as
///    given, and the i rounds with t1 then do subdivide's arithmetic on the same entries:
///    the left half of subdivide(segment, t1).
///  - t1 = 1: a round with 1 has 1 - 1 = 0 + 0, and by the same products and sums moves
///    entry j + 1 = (hi, lo) to place j unchanged when hi != 0 (lo only loses a zero's sign);
///    when hi = 0 the new hi is a zero and lo is kept as long as it is not zero. So point 0
///    after i such rounds, hi + lo, is subdivide's right point i whenever that point has no
///    zero coordinate (then hi or lo is not zero); the rounds with t0 before are the same.
/// Checked against core::portion in tests/core/region/segment_piece_test.cpp. Where a
/// coordinate is zero the piece is left to core::portion.
[[nodiscard]] inline std::optional<core::Curve> end_piece_by_halving(const core::Curve& segment,
                                                                     double t0, double t1) {
  if (t0 == 0.0 && t1 != 1.0) {
    if (!without_zero_coordinate(segment)) return std::nullopt;
    return std::move(core::subdivide(segment, t1).left);
  }
  if (t1 == 1.0 && t0 != 0.0) {
    core::Split<core::Point2> halves = core::subdivide(segment, t0);
    if (!without_zero_coordinate(halves.right)) return std::nullopt;
    return std::move(halves.right);
  }
  return std::nullopt;
}

[[nodiscard]] inline core::Curve segment_piece(const core::Curve& segment, double t0, double t1) {
  if (segment_piece_is_segment(segment, t0, t1)) return segment;
  if (auto half = end_piece_by_halving(segment, t0, t1)) return std::move(*half);
  return core::portion(segment, t0, t1);
}

/// segment_piece(segment, 0, t) and segment_piece(segment, t, 1) for 0 < t < 1, the same
/// bits, from one core::subdivide where end_piece_by_halving would take its halves.
[[nodiscard]] inline std::pair<core::Curve, core::Curve> segment_pieces_at(
    const core::Curve& segment, double t) {
  core::Split<core::Point2> halves = core::subdivide(segment, t);
  core::Curve before = without_zero_coordinate(segment) ? std::move(halves.left)
                                                        : core::portion(segment, 0.0, t);
  core::Curve after = without_zero_coordinate(halves.right) ? std::move(halves.right)
                                                            : core::portion(segment, t, 1.0);
  return {std::move(before), std::move(after)};
}

/// segment_piece of a segment the caller no longer needs: the segment itself is moved into
/// the result when it is the piece, and left unchanged otherwise.
[[nodiscard]] inline core::Curve segment_piece(core::Curve&& segment, double t0, double t1) {
  if (segment_piece_is_segment(segment, t0, t1)) return std::move(segment);
  if (auto half = end_piece_by_halving(segment, t0, t1)) return std::move(*half);
  return core::portion(segment, t0, t1);
}

}  // namespace bezier::region
