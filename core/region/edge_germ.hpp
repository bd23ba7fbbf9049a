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
};

/// The germ of `curve` at its start. Derivatives are the compensated ones of
/// core::derivatives_at; a derivative counts as zero when it is exactly zero.
[[nodiscard]] EdgeGerm germ_at_start(const core::Curve& curve);

/// Counter-clockwise angle from germ `from` to germ `to`, in [0, 2 pi): how far `to` lies
/// counter-clockwise of `from` near the vertex. Germs whose tangent angles agree to within
/// kTangentTieAngle are ordered by their turn: a larger turn lies counter-clockwise of a
/// smaller one (it bends to the left of it), giving an angle just above 0 or just below
/// 2 pi; equal germs give 0.
[[nodiscard]] double ccw_angle(const EdgeGerm& from, const EdgeGerm& to);

}  // namespace bezier::region
