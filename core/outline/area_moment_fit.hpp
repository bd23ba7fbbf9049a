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

/// Up to four handle pairs (area_moment_handles gives the order).
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
/// quartic in a. Its real roots in [0, kMaxHandle] are found between the zeros of its
/// derivative (found the same way from the zeros of the second derivative, a quadratic),
/// where it is monotone: each stretch with a change of sign holds one, refined by Newton
/// steps kept inside the stretch. Where the quartic comes near zero without crossing it (a
/// zero of its derivative where |q| is within 1e-3 of its largest coefficient), no cubic
/// matches both exactly and that zero of the derivative is a candidate too: its area is
/// exact and its moment nearly so. The pairs are returned with the roots first, then these
/// near roots, each with a >= 0, b >= 0 (a cubic that starts and ends along the tangents of
/// travel) and D not vanishing.
///
/// Precondition: unit tangents, finite area and moment. The result only proposes cubics:
/// the caller measures each against the curve.
[[nodiscard]] HandleCandidates area_moment_handles(core::Point2 t0, core::Point2 t3, double area,
                                                   double moment);

/// The root of the same quartic that Newton's method reaches from the handles of the
/// circular arc with these end tangents (both 1 / (3 cos^2(φ / 4)) chords, φ the angle
/// from t0 to t3), in at most a dozen steps: the cubic nearest an arc, which is the one that
/// fits where O is smooth and turns little; false when the steps leave [0, kMaxHandle], do
/// not settle, or give b < 0. Costs a few evaluations of the quartic, against the search of
/// all its roots.
[[nodiscard]] bool arc_started_handles(core::Point2 t0, core::Point2 t3, double area,
                                       double moment, HandleLengths& out);

/// arc_started_handles for two curves at once (the two sides of a stroke's segment), each
/// answer (the flag and the handles) arc_started_handles' own for that curve: the two Newton
/// walks advance in one loop, so that neither waits on the other's chain of steps.
[[nodiscard]] std::array<bool, 2> arc_started_handles_of_two(
    const std::array<core::Point2, 2>& t0, const std::array<core::Point2, 2>& t3,
    const std::array<double, 2>& area, const std::array<double, 2>& moment,
    std::array<HandleLengths, 2>& out);

/// The largest handle length (in chords) searched: a longer handle makes a cubic that
/// overshoots its chord, not the parallel curve of a piece that turns by less than a half
/// turn.
inline constexpr double kMaxHandle = 3.0;

}  // namespace bezier::outline
