#pragma once

#include <optional>
#include <span>

#include "core/cubic/predicates.hpp"
#include "core/base/curve.hpp"
#include "core/base/point.hpp"

namespace bezier::core {

/// The double point of a planar cubic: the parameters t1 < t2 with B(t1) = B(t2), and the
/// point. A cubic curve that is not a line, quadratic or cusp has exactly one (possibly
/// with complex parameters), so this closed form is the cubic fast path of
/// self-intersection: no subdivision, no iteration, and exact decisions on the boundaries.
struct CubicDoublePoint {
  /// t1 < t2 exactly; the rounded values keep t1 <= t2 (equal only for a loop narrower
  /// than the spacing of doubles). On the whole real line (outside [0,1] when the loop is).
  double t1 = 0.0;
  double t2 = 0.0;
  Point2 point;  ///< B(t1) = B(t2)
  /// Decided exactly: 0 <= t1 < t2 <= 1, i.e. the loop lies on the curve segment. When it
  /// holds, t1 and t2 are clamped into [0,1], t1 is exactly 0 when the loop closes at the
  /// start (then point = P0 exactly) and t2 exactly 1 when it closes at the end
  /// (point = P3); otherwise both are strictly inside (0, 1), also where the rounded root
  /// would be 0 or 1.
  bool on_segment = false;
};

/// Whether the double point exists (disc < 0) and both parameters lie in [0,1], from the
/// exact signs alone: l0 = d3² t1 t2 >= 0, l1 = d3² (1 − t1)(1 − t2) >= 0 and the midpoint
/// −d2 / (2 d3) in [0,1] (d2 d3 <= 0, (d2 + 2 d3) d3 >= 0). Lets a caller skip the roots
/// when the loop is off the segment.
[[nodiscard]] constexpr bool double_point_on_segment(const CubicSigns& s) noexcept {
  return s.disc < 0 && s.l0 >= 0 && s.l1 >= 0 && s.d2 * s.d3 <= 0 && s.d2_plus_2d3 * s.d3 >= 0;
}

/// The double point of the cubic with control points p[0..3], over all real t.
///
/// Derivation (with a, b, c, d1, d2, d3 as in cubic_predicates.hpp): B(s) = B(t), s != t,
/// divided by s − t is 3a + 3b (s + t) + c (s² + st + t²) = 0. Its cross products with c and
/// with b give s + t = −d2 / d3 and s² + st + t² = 3 d1 / d3, so st = (d2² − 3 d1 d3) / d3²
/// and s, t are the roots of d3 z² + d2 z + l0 / d3, z = (−d2 ± √(−3 disc)) / (2 d3),
/// computed in the cancellation-free form (core/numeric/quadratic_roots.hpp). They are real and
/// distinct exactly when disc = d2² − 4 d1 d3 < 0, Loop and Blinn's loop class; the
/// decision is exact. (Stone & DeRose 1989 and Loop & Blinn 2005 derive the same curve.)
///
/// Returns nothing when disc >= 0: a serpentine's double point has complex conjugate
/// parameters (an isolated point, not on the real curve), at disc = 0 the two parameters
/// meet in a cusp, and lines (collinear control points; these can overlap themselves along
/// whole intervals), quadratics (P3 − 3P2 + 3P1 − P0 = 0) and points have no isolated
/// double point. A closed cubic (P0 = P3, not a line) returns (0, 1): the trivial pair of
/// a closed curve, which self-intersection listings leave out.
///
/// Accuracy: the parameters are as accurate as the data allow (the roots of a quadratic
/// with coefficients accurate to a few ulps of their scale); the point is the mean of
/// B(t1) and B(t2), each by de Casteljau. Invariant under translation, uniform scaling
/// and reversal (t -> 1 − t swaps and reflects t1, t2) up to rounding.
/// Precondition: finite coordinates.
[[nodiscard]] std::optional<CubicDoublePoint> cubic_double_point(std::span<const Point2, 4> p);

/// The same from predicates already computed for p (see cubic_predicates()).
[[nodiscard]] std::optional<CubicDoublePoint> cubic_double_point(std::span<const Point2, 4> p,
                                                                 const CubicPredicates& pred);

/// The same for a Curve. Precondition: cubic.degree() == 3.
[[nodiscard]] std::optional<CubicDoublePoint> cubic_double_point(const Curve& cubic);

}  // namespace bezier::core
