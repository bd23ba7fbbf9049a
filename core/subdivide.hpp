#pragma once

#include <vector>

#include "core/curve.hpp"

namespace bezier::core {

/// The two halves of a curve split at t.
template <class P>
struct Split {
  BasicCurve<P> left;   ///< B on [0, t], reparametrised to [0, 1]
  BasicCurve<P> right;  ///< B on [t, 1], reparametrised to [0, 1]
};

/// Splits B at t by de Casteljau: the left control points are the first points of each
/// level of the triangle, the right ones the last points, read backwards (Farin, §4.6).
/// Both halves share the split point bit for bit, and it is the same value evaluate()
/// returns, because the same lerp sequence computes it. Any finite t is allowed
/// (t outside [0,1] gives the extrapolated pieces). For a piece [a, b], see portion() in
/// polar.hpp.
template <class P>
[[nodiscard]] Split<P> subdivide(const BasicCurve<P>& curve, double t) {
  std::vector<P> work(curve.points().begin(), curve.points().end());
  const std::size_t n = work.size() - 1;
  std::vector<P> left(n + 1);
  std::vector<P> right(n + 1);
  left[0] = work[0];
  right[n] = work[n];
  for (std::size_t level = n; level > 0; --level) {
    for (std::size_t i = 0; i < level; ++i) work[i] = lerp(work[i], work[i + 1], t);
    left[n - level + 1] = work[0];
    right[level - 1] = work[level - 1];
  }
  return {BasicCurve<P>(std::move(left)), BasicCurve<P>(std::move(right))};
}

}  // namespace bezier::core
