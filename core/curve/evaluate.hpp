#pragma once

#include <span>
#include <vector>

#include "core/base/curve.hpp"

namespace bezier::core {

// The point evaluators of the kernel, and why each exists. All are de Casteljau's
// algorithm; they differ in what they evaluate and how much accuracy they buy:
//  - evaluate() here: a user's curve (Point2 or Point3), compensated, within one rounding
//    of B(t) at any degree: what the API answers; evaluate_coordinate() one axis of it.
//  - bernstein::evaluate (bernstein/bernstein1d.hpp): one scalar polynomial in doubles, about
//    2 n u of its largest coefficient: the reparametrisations and distance functions the
//    intersection tests compare against tolerances far above that.
//  - evaluate_with_tangent (intersect/working_curve.hpp): a working curve's point and
//    tangent in doubles from one pass (the tangent is n (b_1 - b_0) of the last level):
//    frames, Gauss-Newton and the search, where the tangent is needed with the point.
//  - evaluate_compensated (intersect/compensated_point.hpp): a working curve's exact
//    coordinates (hi + lo) to O(n u^2) with the same tangent: Newton's method where the
//    curves agree to within the rounding of doubles.
//  - evaluate_dd (intersect/working_curve.hpp): the same accuracy in double-double
//    arithmetic throughout, about twice the operations: where a double-double point itself
//    is the result (residuals carried on in double-doubles, overlap ends).
// derivatives_at (derivative.hpp) and polar (polar.hpp) evaluate hodographs and blossoms
// with the same compensated rows as evaluate().

/// B(t) = Σ C(n,i) (1-t)^(n-i) t^i P_i by de Casteljau's algorithm, n rounds of
/// P_i <- (1-t) P_i + t P_{i+1} (Farin, §4.1), compensated (see CasteljauRow): within one
/// rounding of the exact value plus O(n^2 u^2) Σ |P_i| |b_i(t)|, for any degree.
/// Any finite t is allowed; outside [0,1] the polynomial is extrapolated (the bound holds
/// with the same formula, which grows like |2t - 1|^n). Returns P_0 exactly at t = 0 and
/// P_n exactly at t = 1 (every error term is zero there).
[[nodiscard]] Point2 evaluate(const Curve& curve, double t);
[[nodiscard]] Point3 evaluate(const Curve3& curve, double t);

/// One coordinate of B(t): the polynomial with the coefficients `coordinate` (the control
/// points' coordinate on one axis) by the same compensated rounds as evaluate(), with its
/// accuracy, at the cost of one axis instead of all.
[[nodiscard]] double evaluate_coordinate(std::span<const double> coordinate, double t);

/// The parameters of `count` uniform samples: t_i = i / (count - 1), so 0 and 1 are
/// included exactly. count = 1 gives {0}. Precondition: count >= 1.
[[nodiscard]] std::vector<double> uniform_parameters(int count);

/// B(t_i) at each parameter of uniform_parameters(count).
template <class P>
[[nodiscard]] std::vector<P> sample(const BasicCurve<P>& curve, int count) {
  std::vector<P> samples;
  for (const double t : uniform_parameters(count)) samples.push_back(evaluate(curve, t));
  return samples;
}

}  // namespace bezier::core
