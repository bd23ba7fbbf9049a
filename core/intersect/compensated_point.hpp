#pragma once

#include "core/numeric/double_double.hpp"
#include "core/intersect/working_curve.hpp"

namespace bezier::core {

/// f(t) as a double-double and f'(t) in doubles, for Newton's method on f(t) - g(s).
struct CompensatedPoint {
  dd::Real x, y;
  Point2 tangent;
};

/// Compensated de Casteljau (H. Jiang, S. Li, L. Cheng, F. Su, "Accurate evaluation of a
/// polynomial and its derivative in Bernstein form", Comput. Math. Appl. 60, 2010) on the
/// exact working curve hi + lo: each level's values are the plain de Casteljau's, and the
/// rounding errors of its products and sums (error-free transformations) plus the lo parts
/// are carried through the same levels in a second, double row. The point is hi + that
/// correction, accurate to O(n u^2 magnitude) like evaluate_dd, in about half its
/// operations; the tangent n (b_1 - b_0) of the hi row is exactly evaluate_with_tangent's.
/// Precondition: t in [0, 1], degree >= 1.
[[nodiscard]] CompensatedPoint evaluate_compensated(const WorkingCurve& f, double t);

}  // namespace bezier::core
