#pragma once

#include <array>
#include <optional>
#include <span>

#include "core/cubic/double_point.hpp"
#include "core/cubic/cubic_type.hpp"
#include "core/base/curve.hpp"
#include "core/base/point.hpp"

namespace bezier::core {

/// At most two parameters in increasing order (a cubic has at most two inflections).
struct Inflections {
  std::array<double, 2> t{};
  int count = 0;

  [[nodiscard]] std::span<const double> values() const noexcept {
    return {t.data(), static_cast<std::size_t>(count)};
  }
};

/// Everything classify() finds out about a cubic segment.
struct CubicClassification {
  /// The type on [0,1], with the conventions of CubicType (cubic_type.hpp).
  CubicType type = CubicType::point;
  /// The class of the unbounded curve (see LoopBlinnClass).
  LoopBlinnClass loop_blinn = LoopBlinnClass::point;
  /// The Stone–DeRose canonical point; nothing when P0, P1, P2 are collinear.
  std::optional<Point2> canonical_point;
  /// Roots of B'(t) × B''(t) in [0,1], increasing; a cusp is not an inflection. Empty for
  /// points, lines and quadratics (where B' × B'' vanishes identically or nowhere).
  Inflections inflections;
  /// The t in [0,1] with B'(t) = 0, when type is cusp; exactly 0 when P0 = P1 and exactly
  /// 1 when P2 = P3.
  std::optional<double> cusp;
  /// The loop's double point, when type is loop, loop_at_start or loop_at_end
  /// (0 <= t1 < t2 <= 1, on_segment true; t1 exactly 0 for loop_at_start, t2 exactly 1
  /// for loop_at_end).
  std::optional<CubicDoublePoint> self_intersection;
  /// Whether every boundary decision was certainly exact (CubicPredicates::exact: true
  /// unless the nonzero coordinates span more than about 2^400).
  bool exact = true;
};

/// Classifies the cubic Bézier segment p[0..3] on t in [0,1].
///
/// Direct math, decided exactly (the precedence of CubicType, top to bottom):
///   - point: all control points equal; line: d1 = d2 = d3 = 0, i.e. all collinear;
///     quadratic: d2 = d3 = 0 and d1 != 0, i.e. c = P3 − 3 P2 + 3 P1 − P0 = 0
///     (d1, d2, d3: the inflection polynomial I(t) = d1 + d2 t + d3 t² ∝ B' × B'',
///     see cubic_predicates.hpp).
///   - cusp: B'(t) = 0 makes t a double root of I, so disc = d2² − 4 d1 d3 = 0 and
///     t = −d2 / (2 d3); it counts when 0 <= t <= 1 (d2 d3 <= 0, (d2 + 2 d3) d3 >= 0).
///   - loop: disc < 0 and both roots of the double-point quadratic in [0,1]
///     (cubic_double_point()); t1 = 0 exactly when l0 = 0, t2 = 1 exactly when l1 = 0.
///   - otherwise the roots of I in [0,1] (for disc > 0; none for disc <= 0, where I has
///     no simple real root), counted from the exact signs of I(0) = d1, I(1) = d1 + d2 + d3
///     and the vertex position: 2 double_inflection, 1 single_inflection, 0 arch.
/// Every decision is the sign of a polynomial in the input coordinates (degree 2 or 4),
/// computed with a floating-point filter and exact expansion arithmetic behind it, so a
/// cubic exactly on an edge (e.g. an edge point of the canonical map mapped back by an
/// affine map with dyadic entries) gets the edge's type, never a neighbour's by rounding.
/// In canonical coordinates these polynomials are the Stone–DeRose edges (the table in
/// cubic_predicates.hpp), and canonical_region() reads the same answer off the plane.
///
/// Degenerate input has real answers: P0, P1, P2 collinear (no canonical map) is
/// classified directly from the same predicates; P0 = P1 is a cusp at t = 0 (closed
/// interval); P1 = P2 makes B'' parallel to B' at both ends, so I(0) = I(1) = 0 with simple
/// roots: inflections at exactly t = 0 and t = 1, double_inflection; P0 = P3 (closed) is
/// loop_at_start with t = (0, 1).
///
/// Invariant under affine maps (reflections included), exactly for exact images; under
/// reversal (t -> 1 − t) the type is the same with loop_at_start and loop_at_end swapped
/// (except for a closed cubic, loop_at_start both ways) and parameters reflected. No iteration:
/// constant time (tens of nanoseconds on the filter path, a few microseconds when an exact
/// evaluation is needed). Precondition: finite coordinates.
[[nodiscard]] CubicClassification classify(std::span<const Point2, 4> p);

/// The same for a Curve. Precondition: cubic.degree() == 3.
[[nodiscard]] CubicClassification classify(const Curve& cubic);

}  // namespace bezier::core
