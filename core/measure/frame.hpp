#pragma once

#include <optional>

#include "core/base/curve.hpp"

namespace bezier::core {

/// The Frenet frame of a curve at one parameter.
template <class P>
struct Frame {
  /// B'(t) / |B'(t)|.
  P tangent;
  /// 2-D: the tangent turned +90° (counter-clockwise), always present. 3-D: the principal
  /// normal (B' × B'') × B' / |(B' × B'') × B'|, toward the centre of curvature; nullopt where
  /// B' × B'' vanishes to within its rounding (a straight piece, an inflection), since the
  /// osculating plane, and so the normal, is undefined there.
  std::optional<P> normal;
  /// 2-D: signed, (x'y'' - y'x'') / |B'|^3, positive where the curve turns counter-clockwise.
  /// 3-D: |B' × B''| / |B'|^3 (>= 0).
  double curvature = 0.0;
};

/// The frame of B at t, or nullopt where B'(t) = 0 (a cusp, a degenerate end with
/// P_1 = P_0, a curve that is one point).
///
/// B'(t) and B''(t) come from derivatives_at (within one rounding of their exact values plus
/// O(n^2 u^2) times their condition scales), so the tangent is accurate to a few ulps and the
/// curvature to a few ulps times the conditioning of x'y'' - y'x'' (cancellation where the
/// curve is nearly straight).
///
/// "B'(t) = 0" is numerical: |B'(t)| <= 16 u (M_1 + M_2), where M_k = max_i |P^(k)_i| bounds
/// |B^(k)| on [0, 1] (convex hull of the k-th hodograph). The parameter t is a double, known
/// to within u, and moving t by u moves B' by up to M_2 u; a B' below a few times that (plus
/// the rounding of the hodograph, M_1 u) has no direction the input determines. Both terms
/// scale with the curve, so the test is invariant under uniform scaling and translation.
/// Any finite t (outside [0, 1] the bound M_k is the hull's, a little optimistic).
[[nodiscard]] std::optional<Frame<Point2>> frame(const Curve& curve, double t);
[[nodiscard]] std::optional<Frame<Point3>> frame(const Curve3& curve, double t);

}  // namespace bezier::core
