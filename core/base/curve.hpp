#pragma once

#include <algorithm>
#include <cassert>
#include <span>
#include <utility>
#include <vector>

#include "core/base/point.hpp"

namespace bezier::core {

/// A Bézier curve B(t) = Σ_{i=0..n} C(n,i) (1-t)^(n-i) t^i P_i of run-time degree n,
/// given by its n + 1 control points. Degree 0 (a single point) is allowed because it
/// is what the n-th hodograph of a degree-n curve is; the API asks for n >= 1.
///
/// Invariant: at least one control point. Coordinates are expected to be finite
/// (api/ validates that); the kernel asserts it where it matters.
template <class P>
class BasicCurve {
 public:
  using Point = P;

  explicit BasicCurve(std::vector<P> points) : points_(std::move(points)) {
    assert(!points_.empty());
  }

  /// n, the degree: one less than the number of control points.
  [[nodiscard]] int degree() const noexcept { return static_cast<int>(points_.size()) - 1; }
  [[nodiscard]] std::span<const P> points() const noexcept { return points_; }
  [[nodiscard]] const P& operator[](int i) const noexcept { return points_[static_cast<std::size_t>(i)]; }
  [[nodiscard]] const P& front() const noexcept { return points_.front(); }
  [[nodiscard]] const P& back() const noexcept { return points_.back(); }

  /// The control points, taken out of a curve that is not used again (a curve edited or
  /// reversed without copying its points).
  [[nodiscard]] std::vector<P> take_points() && noexcept { return std::move(points_); }

  friend bool operator==(const BasicCurve&, const BasicCurve&) = default;

 private:
  std::vector<P> points_;
};

/// A planar curve: what every capability of the kernel takes.
using Curve = BasicCurve<Point2>;
/// A space curve: evaluation, subdivision and polars also work in 3-D.
using Curve3 = BasicCurve<Point3>;

/// Largest absolute control-point coordinate: the geometric scale of the curve. Since
/// the curve lies in the convex hull of its control points, |B(t)| <= scale for t in [0,1].
template <class P>
[[nodiscard]] double scale(const BasicCurve<P>& curve) noexcept {
  double s = 0.0;
  for (const P& p : curve.points()) s = std::fmax(s, max_abs_coordinate(p));
  return s;
}

/// Every control point equal to the first, bit for bit as Point2's == compares (+0 == -0,
/// a NaN coordinate never equal): the curve is one point, B(t) = P_0 for every t, with
/// zero length and no tangent. A curve of degree 0 is one.
template <class P>
[[nodiscard]] bool is_point(const BasicCurve<P>& curve) noexcept {
  for (const P& p : curve.points()) {
    if (!(p == curve.front())) return false;
  }
  return true;
}

/// The same curve traversed backwards: R(t) = B(1 - t), control points reversed.
template <class P>
[[nodiscard]] BasicCurve<P> reversed(const BasicCurve<P>& curve) {
  const auto pts = curve.points();
  return BasicCurve<P>(std::vector<P>(pts.rbegin(), pts.rend()));
}

/// The same, reusing the storage of a curve that is not used again.
template <class P>
[[nodiscard]] BasicCurve<P> reversed(BasicCurve<P>&& curve) {
  std::vector<P> points = std::move(curve).take_points();
  std::reverse(points.begin(), points.end());
  return BasicCurve<P>(std::move(points));
}

}  // namespace bezier::core
