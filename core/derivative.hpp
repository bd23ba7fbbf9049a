#pragma once

#include <cassert>
#include <vector>

#include "core/curve.hpp"
#include "core/evaluate.hpp"

namespace bezier::core {

/// The hodograph B'(t): the Bézier curve of degree n - 1 with control points
/// P'_i = n (P_{i+1} - P_i), i = 0..n-1 (Farin, §5.3). The derivative of a degree-0
/// curve is the zero curve of degree 0.
template <class P>
[[nodiscard]] BasicCurve<P> derivative(const BasicCurve<P>& curve) {
  const auto pts = curve.points();
  const int n = curve.degree();
  if (n == 0) return BasicCurve<P>({P{}});
  std::vector<P> hodograph;
  hodograph.reserve(static_cast<std::size_t>(n));
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) hodograph.push_back(n * (pts[i + 1] - pts[i]));
  return BasicCurve<P>(std::move(hodograph));
}

/// The k-th derivative as a Bézier curve: the hodograph applied k times (degree
/// max(n - k, 0); identically zero when k > n). k = 0 is the curve itself.
template <class P>
[[nodiscard]] BasicCurve<P> derivative(const BasicCurve<P>& curve, int k) {
  assert(k >= 0);
  BasicCurve<P> result = curve;
  for (int i = 0; i < k; ++i) result = derivative(result);
  return result;
}

/// B'(t), B''(t), ..., B^(k)(t): the first `order` derivatives at t, each evaluated by
/// de Casteljau on its hodograph.
template <class P>
[[nodiscard]] std::vector<P> derivatives_at(const BasicCurve<P>& curve, double t, int order) {
  assert(order >= 0);
  std::vector<P> values;
  values.reserve(static_cast<std::size_t>(order));
  BasicCurve<P> hodograph = curve;
  for (int k = 1; k <= order; ++k) {
    hodograph = derivative(hodograph);
    values.push_back(evaluate(hodograph, t));
  }
  return values;
}

}  // namespace bezier::core
