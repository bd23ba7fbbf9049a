#pragma once

#include <cstdint>
#include <vector>

#include "core/base/curve.hpp"

namespace bezier::core {

/// Distances within this fraction of the least one tie with it (nearest(); below 8 ulps of
/// the coordinates' scale the rounding decides instead): the tie tolerance POST /nearest
/// promises.
inline constexpr double kTieRelativeTolerance = 1e-12;

/// The point of a curve piece nearest to a target.
template <class P>
struct NearestPoint {
  /// The smallest t in [a, b] attaining the minimum distance.
  double t = 0.0;
  /// B(t).
  P point;
  /// The least |B(t) - target| over the candidates: when t ties with a closer candidate,
  /// |B(t) - target| may exceed it by the tie tolerance, and this is the more accurate value
  /// of the minimum.
  double distance = 0.0;
  /// The other t attaining the minimum (to the tie tolerance, see nearest()), increasing;
  /// each a distinct local minimum.
  std::vector<double> ties;
};

/// The global minimum of |B(t) - q| over t in [a, b], ends included.
///
/// Candidates: a, b and every root in [a, b] of f(t) = (B(t) - q) · B'(t) = D'(t) / 2, where
/// D = |B - q|^2 (a minimum of D inside (a, b) is a root of f), except the simple roots
/// where f falls through zero (maxima of D; Crossings::rising). f has degree 2n - 1; its
/// Bernstein coefficients are products of the points P_i - q and of the hodograph's
/// (bernstein_product.hpp). Its roots come from the certified Bernstein root finder
/// (interval_roots): an interval is discarded only when f's coefficients there have one
/// strict sign beyond their rounding bound, so no root is lost except where |f| stays at
/// that bound, where D varies by no more than the bound times the width: such a loss moves
/// the answer by a rounding-level amount, never to another local minimum. Each root whose
/// rough distance (B - q by a Horner-like sum in doubles) is within
/// measure_tuning::kPolishMargin of the coordinate scale of the least is then polished by
/// Newton's method on f with f' = |B'|^2 + (B - q) · B'' from one compensated de Casteljau
/// triangle (kept only while it stays in [a, b] and lowers the distance, or keeps it within
/// a rounding and lowers |f|; polishing moves a
/// distance by a rounding-level amount, so the others are neither the minimum nor tied
/// with it), and the ends and polished roots are compared by their squared distance
/// |B(t) - q|^2 from the compensated B(t) (on the normalised curve, normalised.hpp, where
/// squares neither overflow nor underflow above the tie tolerance); the distance reported
/// is hypot(B(t) - q).
///
/// Ties (as POST /nearest promises in api/openapi.yaml): the candidates within
/// max(kTieRelativeTolerance d_min, 8 u s) of the least distance d_min, s the largest coordinate of the control points and the target (below 8 ulps of
/// the coordinates the distances are rounding, so a target on a self-intersection ties its
/// two parameters). Tied candidates with the distance at their midpoint also within the
/// tolerance are one flat minimum, reported once (its smallest t).
///
/// A curve that is one point (all control points equal): every t attains the distance;
/// t = a is reported and ties is empty.
///
/// Accuracy: the distance within a few ulps of |B(t) - q| at the reported t plus the
/// coordinates' rounding (about u s), so within 1e-13 relative of the true minimum or
/// 8 ulps of s; t within 1e-10 at a well-conditioned (simple) minimum, about u^(1/m) at a
/// minimum of multiplicity m. Precondition: 0 <= a <= b <= 1, finite coordinates.
[[nodiscard]] NearestPoint<Point2> nearest(const Curve& curve, Point2 target, double a, double b);
[[nodiscard]] NearestPoint<Point3> nearest(const Curve3& curve, Point3 target, double a, double b);

/// The work units (core/intersect/work_cost.hpp's unit, about one coordinate update of de
/// Casteljau's algorithm) nearest() is charged for one target on a curve of degree n:
/// isolating and bisecting the roots of a degree 2n - 1 polynomial, each piece and each
/// bisection step O(n^2), and polishing each root; 250 (2n)^2 is an upper estimate of what
/// random curves of degrees 3 to 20 take. A caller checks targets x this against its
/// budget before it starts (nearest() itself is bounded by the degree).
[[nodiscard]] constexpr std::int64_t nearest_work(int degree) noexcept {
  const std::int64_t m = 2 * static_cast<std::int64_t>(degree);
  return 250 * m * m;
}

}  // namespace bezier::core
