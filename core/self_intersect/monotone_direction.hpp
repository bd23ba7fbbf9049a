#pragma once

#include <span>

#include "core/base/point.hpp"

namespace bezier::core {

/// Whether the curve with control points p[0..n] (n >= 1) is certainly strictly monotone
/// along some direction d, hence injective on [0, 1]: no self-intersection, no retraced
/// piece, no cusp. True is an answer; false means "not shown".
///
/// Why it is exact. The hodograph B'(t) = n sum_{i<n} b_{i,n-1}(t) (P_{i+1} - P_i) is a
/// combination of the difference vectors h_i = P_{i+1} - P_i with Bernstein weights that
/// are nonnegative and sum to 1 on [0, 1]. If d . h_i > 0 for every i, then d . B'(t) > 0
/// on [0, 1], so t -> d . B(t) is strictly increasing and B(t) = B(s) forces t = s (the
/// classical half-plane criterion for loop-free pieces: Sederberg & Meyers, "Loop detection
/// in surface patch intersections", CAGD 5(2), 1988). Each sign d . h_i is decided by
/// core::bounded_projection (core/numeric/bounded_projection.hpp), whose error bound covers
/// the rounding of the differences and of the projection and fails on overflow or NaN; d
/// itself is any pair of doubles, taken as exact, so the way it is computed needs no bound.
///
/// The directions tried: the chord P_n - P_0 (within 90 degrees of every h_i when the curve
/// turns by less than about a right angle), then the sum of the unit vectors along h_0 and
/// h_{n-1} (the bisector of the end tangents, for curves that turn more, up to nearly a
/// half turn). A zero h_i (a repeated control point: a cusp at an end, or a degenerate
/// hodograph) has no positive projection, and the answer is false.
/// Cost: O(n) for each direction, no allocation.
[[nodiscard]] bool certainly_monotone(std::span<const Point2> p) noexcept;

/// The same for a cubic's four control points (the same tests in the same order).
[[nodiscard]] bool certainly_monotone(std::span<const Point2, 4> p) noexcept;

}  // namespace bezier::core
