#pragma once

#include <cmath>
#include <numbers>

namespace bezier::outline {

/// A bound of |d N''| on a piece of a curve, from bounds of its direction field Q (B' itself,
/// or B' with factors t^i (1 - t)^j divided out, offset.hpp) on the piece: |Q| >= w > 0,
/// |Q'| <= W2, |Q''| <= W3 (the largest control points of Q's hodographs and the least
/// projection of Q's control points on one direction: convex hulls).
///
/// With T = Q / |Q|, N its left normal and the turning rate ω = cross(Q, Q') / |Q|^2,
/// T' = ω N and N' = -ω T, so N'' = -ω' T - ω^2 N and |N''| <= |ω'| + ω^2, where
///   ω  = |Q'| sin θ / |Q|,
///   ω' = cross(Q, Q'') / |Q|^2 - 2 cross(Q, Q') (Q · Q') / |Q|^4,
///   |ω'| <= |Q''| / |Q| + |Q'|^2 |sin 2θ| / |Q|^2,
/// θ the angle from Q to Q'. Since sin^2 θ + |sin 2θ| = 1/2 - cos(2θ)/2 + |sin 2θ| <=
/// 1/2 + sqrt(1/4 + 1) = φ (the golden ratio),
///   |d N''| <= |d| (W3 / w + φ (W2 / w)^2).
/// The few roundings of this expression are relative errors of a few units in the last place
/// of a term the caller keeps within the tolerance: far inside offset.hpp's rounding margin.
[[nodiscard]] inline double normal_second_bound(double W2, double W3, double w, double d) {
  const double bend = W2 / w;
  return std::fabs(d) * (W3 / w + std::numbers::phi * bend * bend);
}

}  // namespace bezier::outline
