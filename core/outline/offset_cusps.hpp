#pragma once

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
/// curve jumps) are not cusps of the parallel curve and are left out (s at the root within
/// the rounding of p's coefficients: s^3 below 1e-12 of their largest). A double root of p
/// with d c > 0 (a curvature extremum whose radius is exactly |d|, where O' vanishes without
/// turning back) is reported too: O is not smooth there either.
///
/// Accuracy: each t within about 1e-12 of a simple root (bernstein_roots' refinement),
/// about the square root of that for a double one. Precondition: finite coordinates and d.
[[nodiscard]] std::vector<double> offset_cusps(const core::Curve& curve, double d);

}  // namespace bezier::outline
