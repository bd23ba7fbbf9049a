#pragma once

#include "core/base/curve.hpp"

namespace bezier::region {

/// How a curve leaves its start point, for ordering the edges around a vertex.
struct EdgeGerm {
  /// The angle of the first nonzero derivative B^(k)(0) (atan2, radians in (-pi, pi]).
  double angle = 0.0;
  /// How the curve turns away from that direction: for k = 1 the signed curvature
  /// cross(B', B'') / |B'|^3; otherwise cross(u, B^(j)(0)) / |B^(k)(0)|^(j/k) for the unit
  /// tangent u and the first derivative j > k not parallel to it (the leading term of the
  /// curve's deviation from its tangent, in the same units). Positive: turning left.
  double turn = 0.0;
  /// Whether `turn` is the signed curvature (k = 1 and j = 2, or a curve that does not turn
  /// from its tangent, turn 0): then the curve's point at distance r from the start lies at
  /// the polar angle angle + turn r / 2 + O(r^2) seen from the start.
  bool turn_is_curvature = true;
  /// The distance from the start to the end point: the edge's reach from its vertex.
  double reach = 0.0;
};

/// The germ of `curve` at its start. Derivatives are the compensated ones of
/// core::derivatives_at; a derivative counts as zero when it is exactly zero.
[[nodiscard]] EdgeGerm germ_at_start(const core::Curve& curve);

/// Counter-clockwise angle from germ `from` to germ `to`, in [0, 2 pi): how far `to` lies
/// counter-clockwise of `from` near the vertex. Germs whose tangent angles agree to within
/// kTangentTieAngle are ordered by where the two curves are at the distance r half the
/// shorter reach from the vertex, giving an angle just above 0 (`to` counter-clockwise of
/// `from`) or just below 2 pi; equal germs give 0.
///
/// Why r. Edges of an arrangement meet only at vertices, so two edges leaving a vertex keep
/// their order out to the first vertex along either of them: any radius up to that decides
/// it, and the radius closest to the vertex is not the best one. Tangent angles within
/// kTangentTieAngle may be off by that much (a tangent contact is located to about the square
/// root of the parameter tolerance), so the order is read where the curves are apart by more
/// than that error allows, as far out as the shorter edge reaches (half of it, inside the
/// range where the expansion holds). When both turns are curvatures the offset between the
/// curves seen from the vertex at r is (angle difference) + (curvature difference) r / 2,
/// whose sign is the order: the curvatures decide for curves that touch (tangents equal to
/// within their error and the edges long enough for the curvature term to exceed it), the
/// angles for curves that cross at a small angle and end near the vertex, such as the two
/// short pieces between a near-tangent crossing and the segment ends a few ulps beside it
/// (the curvatures of such pieces are rounding noise, their directions are not). Otherwise
/// (higher-order germs) a larger turn lies counter-clockwise of a smaller one (it bends to
/// the left of it).
[[nodiscard]] double ccw_angle(const EdgeGerm& from, const EdgeGerm& to);

}  // namespace bezier::region
