#pragma once

#include <cstdint>
#include <span>

#include "core/base/point.hpp"

namespace bezier::outline {

/// What check_chord decided about one chord.
struct ChordCheck {
  /// The Hausdorff distance between the curve piece and its chord is at most the tolerance
  /// (certified, see check_chord).
  bool within = false;
  /// A lower bound of h = max over the piece of the distance to the chord (the largest
  /// distance of the curve points the check computed, to rounding).
  double lower = 0.0;
  /// An upper bound of h (certified, see check_chord): within outline_tuning::kChordResolution
  /// times the tolerance of `lower` unless the halvings ran out.
  double upper = 0.0;
  /// Work units spent (about one coordinate update of de Casteljau's algorithm each).
  std::int64_t work = 0;
};

/// Decides whether the chord from B(a) to B(b) stays within `tolerance` of the piece of the
/// Bézier curve B (control points `points`, any degree n >= 1) on [a, b], both ways.
///
/// The bound. Let Q_0..Q_n be the control points of the piece (B on [a, b] reparametrised
/// to [0, 1]; Q_0 = B(a), Q_n = B(b)), S the chord segment [Q_0, Q_n] and
/// h = max_{s in [0,1]} dist(Q(s), S).
///  - Curve to chord: every point of the piece is within h of S, by definition.
///  - Chord to curve: put the chord on the e axis, e(s) = (Q(s) - Q_0) · u with u the unit
///    chord direction, so e(0) = 0 and e(1) = |S|. e is continuous, so for every point p of
///    S (at e = e_p in [0, |S|]) some s has e(s) = e_p; Q(s) projects onto S at p, so
///    |Q(s) - p| = dist(Q(s), S) <= h. (A chord of zero length is the point Q_0 of the
///    curve.) So the Hausdorff distance is at most h, and it is h when the curve does not
///    overshoot the chord's ends.
///  - Bounding h: dist(., S) is a convex function of the point, so on the convex hull of a
///    piece's control points it is at most its largest value at a control point (the convex
///    hull property of Bézier curves): max_i dist(Q_i, S) >= h. This bound exceeds h (twice
///    h for a parabola), so it is refined by branch and bound: the piece is halved by de
///    Casteljau's algorithm where its hull bound is largest, each half bounded by its own
///    control points, until that largest bound is within outline_tuning::kChordResolution
///    times the tolerance of the largest distance of a curve point met (a piece's end), or
///    after outline_tuning::kChordBoundHalvings halvings: [lower, upper] then brackets h.
///    The hull bound of a piece of width w exceeds the curve's largest distance there by
///    O(w^2), so the bracket closes in on h. The chord is `within` when upper is.
///  - Rounding: the pieces come from de Casteljau's algorithm and a change of frame in
///    doubles, within a few n u S of their exact values (S the largest coordinate of
///    `points`); a chord is within only when every bound plus `margin` is within the
///    tolerance, and the caller sizes `margin` for that (flatten.cpp).
///
/// Preconditions: 0 <= a < b <= 1, finite coordinates, tolerance > 0, margin >= 0.
[[nodiscard]] ChordCheck check_chord(std::span<const core::Point2> points, double a, double b,
                                     double tolerance, double margin);

}  // namespace bezier::outline
