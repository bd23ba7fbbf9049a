#pragma once

#include <optional>
#include <span>

#include "core/cubic/predicates.hpp"
#include "core/cubic/cubic_type.hpp"
#include "core/base/curve.hpp"
#include "core/base/point.hpp"

namespace bezier::core {

/// The Stone–DeRose canonical point of a cubic: the image (x, y) of P3 under the affine
/// map that sends P0, P1, P2 to (0,0), (0,1), (1,1) (M. Stone, T. DeRose, "A geometric
/// characterization of parametric cubic curves", ACM TOG 8(3), 1989; Pomax, "A Primer on
/// Bézier Curves", §"Canonical form"). Affine maps preserve inflections, cusps and double
/// points, so (x, y) alone decides the type (see canonical_region()).
///
/// Computed by solving the 2×2 system P3 − P0 = α (P1 − P0) + β (P2 − P0) by Cramer's rule,
/// whose image is (β, α + β): with u = P1 − P0, v = P2 − P0, w = P3 − P0,
///     x = (u × w) / (u × v),   y = ((P1 − P2) × w) / (u × v).
/// The primer's closed formula divides by P1.y − P0.y and fails for a horizontal first
/// leg; this fails only when u × v = 0, i.e. P0, P1, P2 are collinear (decided exactly),
/// and then returns nothing. Also nothing when the point lies beyond the double range.
/// x = 3 and y = 1 (an inflection at t = 1) are reported exactly when they hold exactly.
/// Accuracy: each coordinate within a few ulps of the ratio of the rounded cross products
/// (exactly rounded cross products when the filter in cubic_predicates() was not sure).
[[nodiscard]] std::optional<Point2> canonical_point(std::span<const Point2, 4> p);
/// The same from predicates already computed (their x_num, y_num and d1).
[[nodiscard]] std::optional<Point2> canonical_point(const CubicPredicates& pred);
/// The same for a Curve. Precondition: cubic.degree() == 3.
[[nodiscard]] std::optional<Point2> canonical_point(const Curve& cubic);

/// The type of the cubic whose canonical point is q = (x, y), read off the Stone–DeRose
/// map of regions with the edges of Pomax's primer, each comparison decided exactly in
/// the double coordinates of q:
///   cusp edge        y = (−x² + 2x + 3) / 4, x <= 1                 -> cusp
///   y > 1                                                          -> single_inflection
///   y = 1            an inflection exactly at t = 1: x < 1 double_inflection, x > 1 single
///   between the cusp edge and y = 1, x <= 1                          -> double_inflection
///   below the cusp edge and on or above
///     y = (−x² + 3x) / 3 for x <= 0 (loop closing at t = 0)          -> loop / loop_at_start on it
///     y = (√(3(4x − x²)) − x) / 2 for 0 <= x <= 1 (closing at t = 1) -> loop / loop_at_end on it
///   elsewhere                                                      -> arch
///   q = (3, 0) (then P3 − 3 P2 + 3 P1 − P0 = 0)                      -> quadratic
/// Corners follow CubicType's precedence: (1, 1) (P3 = P2) is a cusp at t = 1, (0, 0)
/// (P3 = P0) is loop_at_start. This is a second, independent derivation of the same
/// classification that classify() decides with the inflection-form predicates; the tests
/// hold the two to agreement. Precondition: finite q.
[[nodiscard]] CubicType canonical_region(Point2 q);

}  // namespace bezier::core
