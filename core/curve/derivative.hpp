#pragma once

#include <span>
#include <vector>

#include "core/base/curve.hpp"
#include "core/bernstein/casteljau_row.hpp"
#include "core/numeric/small_array.hpp"

namespace bezier::core {

/// The k-th derivative as a Bézier curve: the hodograph applied k times, P'_i = n (P_{i+1}
/// - P_i), i = 0..n-1 (Farin, "Curves and Surfaces for CAGD", 5th ed., §5.3); degree
/// max(n - k, 0), identically zero when k > n; k = 0 is the curve itself. The k rounds
/// carry their rounding errors (CasteljauRow::hodograph_step) and each control point is
/// rounded once at the end, so it is the exact k-th hodograph point to within about one
/// rounding, even where differences of close control points cancel.
[[nodiscard]] Curve derivative(const Curve& curve, int k);
[[nodiscard]] Curve3 derivative(const Curve3& curve, int k);

/// The hodograph B'(t) as a curve of degree n - 1 (see derivative(curve, k)). The
/// derivative of a degree-0 curve is the zero curve of degree 0.
template <class P>
[[nodiscard]] BasicCurve<P> derivative(const BasicCurve<P>& curve) {
  return derivative(curve, 1);
}

/// The hodograph's points, the same values as derivative(curve).points(), in an inline
/// store: for the kernels that only read them (no curve to allocate per call).
template <class P>
[[nodiscard]] SmallArray<P> hodograph_points(std::span<const P> points) {
  CasteljauRow<P> row(points);
  row.hodograph_step();
  SmallArray<P> out(row.size(), typename SmallArray<P>::Uninitialized{});
  for (std::size_t i = 0; i < row.size(); ++i) out[i] = row.point(i);
  return out;
}

/// B'(t), B''(t), ..., B^(order)(t): the first `order` derivatives at t. Each is the
/// compensated de Casteljau evaluation of the k-th hodograph whose control points are
/// kept unrounded (value + error), so B^(k)(t) is within one rounding of the exact value
/// plus O((n + k)^2 u^2) times its condition scale
///   S_k(t) = n!/(n-k)! Σ_i (Σ_j C(k,j) |P_{i+j}|) |b_{i,n-k}(t)|.
/// This is more accurate than evaluate(derivative(curve, k), t), which rounds the hodograph
/// points first (an extra error of about u Σ |P^(k)_i| |b_{i,n-k}(t)|).
/// Any finite t. Precondition: order >= 0. O(order n^2).
[[nodiscard]] std::vector<Point2> derivatives_at(const Curve& curve, double t, int order);
[[nodiscard]] std::vector<Point3> derivatives_at(const Curve3& curve, double t, int order);

}  // namespace bezier::core
