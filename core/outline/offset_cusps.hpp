#pragma once

#include <cstdint>
#include <vector>

#include "core/base/curve.hpp"

namespace bezier::outline {

/// The cusps of the parallel curve O(t) = B(t) + d N(t) of a planar Bézier curve of any
/// degree n >= 1 (N the unit left normal, y up: N = (-y', x') / |B'|): the t in [0, 1] where
/// the radius of curvature equals |d| on the side of d, ascending.
///
/// With T = B' / |B'| and the signed curvature κ = cross(B', B'') / |B'|^3, N' = -κ |B'| T, so
/// O'(t) = |B'| (1 - d κ) T: the parallel curve stops and turns back where d κ = 1, that is
/// where d cross(B', B'') = |B'|^3. Squaring gives a polynomial condition: the cusps are the
/// roots of
///   p(t) = d^2 c(t)^2 - s(t)^3,  c = cross(B', B'') (degree 2n - 3), s = |B'|^2 (degree 2n - 2),
/// (degree 6n - 6) where d c(t) > 0 (the other roots of p have d κ = -1, radius |d| on the
/// other side, where the parallel curve is smooth). p is built in Bernstein form from the
/// hodographs' control points (products of Bernstein polynomials:
/// b_{i,m} b_{j,k} = C(m,i) C(k,j) / C(m+k,i+j) b_{i+j,m+k}) and its roots isolated with
/// certainty by bernstein_roots (core/bernstein/roots.hpp); the curve is first scaled by a
/// power of two (exact) so that the sixth powers neither overflow nor underflow. Roots where
/// B' = 0 (s = 0, a cusp of B itself, where the normal turns by a half turn and the parallel
/// curve jumps) are not cusps of the parallel curve and are left out. A root where s^3 is below
/// 1e-12 of the largest coefficient of p cannot be told from such a zero at p's rounding: next
/// to a near-cusp of B (a hairpin, |B'| small but not zero), where s^3 is tiny at the cusps of
/// O too, p's coefficients on [0, 1] are far larger than its values there. Such a piece is
/// halved and p built again on each half from the hodographs' pieces (the values of B' and B''
/// there, rounded as on the whole curve, so p's coefficients shrink with the piece while its
/// values near the root keep their accuracy), until every root is told apart, or the piece is
/// 2^-48 wide, or |B'| stays below 2^-20 of its largest on it (a near-cusp of B, whose parallel
/// curve turns by a half turn where B hardly moves): such a root is then taken as a zero of B',
/// as is any cusp where |B'| is below that floor. A piece where d c <= 0 throughout (to within
/// c's rounding) holds no cusp and is not searched. A double root of p with d c > 0 (a
/// curvature extremum whose radius is exactly |d|, where O' vanishes without turning back) is
/// reported too: O is not smooth there either.
///
/// Each root found is polished by Newton's method on the unsquared condition |B'|^3 = d c,
/// whose two sides keep their accuracy where p's coefficients do not.
///
/// Accuracy: each t within about 1e-12 of a simple root, about the square root of that for a
/// double one. `work`, when given, grows by the operations done (per piece built, its products
/// of Bernstein polynomials and the intervals of its root search, each a portion of p), for
/// the caller's work charge: next to near-zeros of B', where p has clusters of roots, the root
/// search dominates. Precondition: finite coordinates and d.
[[nodiscard]] std::vector<double> offset_cusps(const core::Curve& curve, double d,
                                               std::int64_t* work = nullptr);

}  // namespace bezier::outline
