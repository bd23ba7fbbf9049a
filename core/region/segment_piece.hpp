#pragma once

#include <algorithm>
#include <span>
#include <utility>

#include "core/base/curve.hpp"
#include "core/curve/polar.hpp"

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
  const auto has_zero = [](core::Point2 p) { return p.x == 0.0 || p.y == 0.0; };
  // A cubic's four points tested at once (no early exit to branch on); other degrees in turn.
  if (points.size() == 4) {
    return !(has_zero(points[0]) | has_zero(points[1]) | has_zero(points[2]) | has_zero(points[3]));
  }
  return std::none_of(points.begin(), points.end(), has_zero);
}

[[nodiscard]] inline core::Curve segment_piece(const core::Curve& segment, double t0, double t1) {
  if (segment_piece_is_segment(segment, t0, t1)) return segment;
  return core::portion(segment, t0, t1);
}

/// segment_piece of a segment the caller no longer needs: the segment itself is moved into
/// the result when it is the piece, and left unchanged otherwise.
[[nodiscard]] inline core::Curve segment_piece(core::Curve&& segment, double t0, double t1) {
  if (segment_piece_is_segment(segment, t0, t1)) return std::move(segment);
  return core::portion(segment, t0, t1);
}

}  // namespace bezier::region
