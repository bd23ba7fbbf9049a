#pragma once

#include <array>
#include <cstddef>

#include "core/base/point.hpp"

namespace bezier::outline {

/// The handle lengths of a cubic with given ends and end tangents, in units of its chord.
struct HandleLengths {
  double start = 0.0;
  double end = 0.0;
};

/// Up to four handle pairs, in increasing order of `start`.
struct HandleCandidates {
  std::array<HandleLengths, 4> pairs{};
  std::size_t count = 0;
};

/// The cubics that match a curve's signed area and first moment (R. Levien, "Parallel
/// curves of cubic Béziers", 2022): in the chord frame, where the curve runs from (0, 0) to
/// (1, 0), the cubic C with control points (0, 0), a t0, (1, 0) - b t3, (1, 0) (t0, t3 the
/// unit tangents of travel at the ends) whose area A = ∫ y dx and moment M = ∫ x y dx
/// equal the given ones. Matching the ends, the end tangents, the area and the moment
/// makes C agree with a smooth curve to the sixth order in its length (the order of the
/// geometric Hermite cubic, de Boor, Höllig and Sabin, CAGD 4, 1987), against the fourth of
/// a fit by end tangents alone.
///
/// For this C (Bernstein integrals, expanded exactly):
///   A = 3/10 s0 a - 3/10 s3 b - 3/20 k a b,
///   M = 17/140 s0 a - 5/28 s3 b + 3/56 c0 s0 a^2 + 3/56 c3 s3 b^2
///       + (9/280 c0 s3 - 33/280 s0 c3) a b - 9/280 c0 k a^2 b + 9/280 c3 k a b^2,
/// with t0 = (c0, s0), t3 = (c3, s3), k = s0 c3 - c0 s3. The area is linear in b:
/// b = N(a) / D(a), N = 2 s0 a - 20/3 A, D = 2 s3 + k a; then D^2 (M(a, b(a)) - M) is a
/// quartic in a, whose real roots in [0, kMaxHandle] are found where its sign changes
/// between the ends of equal cells of that range, each refined by Newton steps kept inside
/// its cell (two roots in one cell, with no change of sign between them, are not found: a
/// near-double root, where the cubic is not well determined anyway). Only the pairs with a >= 0, b >= 0 (a cubic that starts and ends along the
/// tangents of travel) and |D| not vanishing are returned.
///
/// Precondition: unit tangents, finite area and moment. The result only proposes cubics:
/// the caller measures each against the curve.
[[nodiscard]] HandleCandidates area_moment_handles(core::Point2 t0, core::Point2 t3, double area,
                                                   double moment);

/// The largest handle length (in chords) searched: a longer handle makes a cubic that
/// overshoots its chord, not the parallel curve of a piece that turns by less than a half
/// turn.
inline constexpr double kMaxHandle = 3.0;

}  // namespace bezier::outline
