#pragma once

#include "core/base/curve.hpp"

namespace bezier::core {

/// The two halves of a curve split at t.
template <class P>
struct Split {
  BasicCurve<P> left;   ///< B on [0, t], reparametrised to [0, 1]
  BasicCurve<P> right;  ///< B on [t, 1], reparametrised to [0, 1]
};

/// Splits B at t by de Casteljau: the left control points are the first points of each
/// level of the triangle, L_k = b_0^k(t), the right ones the last points, R_k = b_k^(n-k)(t)
/// (Farin, "Curves and Surfaces for CAGD", 5th ed., §4.6). The triangle is the compensated
/// one of evaluate() (CasteljauRow), so every new control point is within about one
/// rounding of its exact value, and both halves share the split point L_n = R_0 bit for
/// bit with each other and with evaluate(curve, t): the same steps compute it. Any finite
/// t is allowed (t outside [0,1] gives the extrapolated pieces). For a piece [a, b], see
/// portion() in polar.hpp.
[[nodiscard]] Split<Point2> subdivide(const Curve& curve, double t);
[[nodiscard]] Split<Point3> subdivide(const Curve3& curve, double t);

}  // namespace bezier::core
