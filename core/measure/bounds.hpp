#pragma once

#include <array>

#include "core/base/curve.hpp"
#include "core/numeric/small_array.hpp"

namespace bezier::core {

/// The tight axis-aligned box of a curve piece and where its coordinates turn.
template <class P>
struct Bounds {
  static constexpr std::size_t kAxes = sizeof(P) / sizeof(double);
  /// Lower and upper faces: every point of B on [a, b] lies in [min, max] (certainly, see
  /// bounds()), and each face is within 2 ulps of the exact extreme.
  P min;
  P max;
  /// Per axis, increasing: the t in (a, b) where that coordinate's derivative vanishes,
  /// each root once (a double root once).
  std::array<SmallArray<double>, kAxes> critical;
};

/// The box of B on [a, b]: per axis, the extreme coordinate is attained at a or b or at a
/// root of that coordinate of B' in (a, b). The roots come from the certified Bernstein
/// root finder on the hodograph's coordinate (interval_roots: none lost, a simple root to
/// full precision; derivative() gives the hodograph within one rounding per point). Each
/// candidate coordinate is evaluated by the compensated de Casteljau (evaluate: within one
/// rounding plus gamma n^2 u^2 Σ|P_i| b_i(t), bounded here by n^2 u^2 max|P_i|).
///
/// Error: at a simple root t* of x' a computed t within δ of it changes x by about
/// |x''| δ^2 / 2, far below an ulp; at a root of higher multiplicity the finder leaves t
/// where |x'| is within its rounding bound e over the whole stretch to t*, so x moves by at
/// most e |t - t*|, also below an ulp of the curve's scale for the degrees the API takes.
/// Each face is then moved outward by the evaluation's bound and rounded outward once more
/// (next_up, next_down), except a face attained at t = 0 or 1, which is a control point's
/// coordinate and exact: the box contains the curve, and a face is at most 2 ulps (of its value,
/// or of n^2 u max|P_i| where the extreme is near zero against the control points) beyond
/// the exact extreme.
///
/// Precondition: 0 <= a <= b <= 1, finite control points. a = b gives the point's box.
[[nodiscard]] Bounds<Point2> bounds(const Curve& curve, double a, double b);
[[nodiscard]] Bounds<Point3> bounds(const Curve3& curve, double a, double b);

}  // namespace bezier::core
