#pragma once

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <initializer_list>
#include <span>
#include <utility>
#include <vector>

#include "core/base/point.hpp"
#include "core/base/small_vector.hpp"

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
  /// The control points of a curve of degree below kInlinePoints (lines, quadratics,
  /// cubics) are stored in the curve itself, without a heap allocation.
  static constexpr std::size_t kInlinePoints = 4;
  using Points = SmallVector<P, kInlinePoints>;

  /// From a std::vector, whose storage is kept when the points do not fit inline.
  explicit BasicCurve(std::vector<P> points) noexcept : points_(std::move(points)) {
    assert(!points_.empty());
  }
  explicit BasicCurve(Points points) noexcept : points_(std::move(points)) { assert(!points_.empty()); }
  explicit BasicCurve(std::span<const P> points) : points_(points) { assert(!points_.empty()); }
  explicit BasicCurve(std::initializer_list<P> points) : points_(points) { assert(!points_.empty()); }

  /// n, the degree: one less than the number of control points.
  [[nodiscard]] int degree() const noexcept { return static_cast<int>(points_.size()) - 1; }
  /// A view of the curve's own control points: valid while the curve is neither destroyed
  /// nor moved (a curve of degree at most 3 carries its points with it when it moves, so a
  /// view taken before a vector<Curve> grows does not see them after).
  [[nodiscard]] std::span<const P> points() const noexcept { return points_.span(); }
  [[nodiscard]] const P& operator[](int i) const noexcept { return points_[static_cast<std::size_t>(i)]; }
  [[nodiscard]] const P& front() const noexcept { return points_.front(); }
  [[nodiscard]] const P& back() const noexcept { return points_.back(); }

  /// The control points, taken out of a curve that is not used again (a curve edited or
  /// reversed without copying its points when they are on the heap).
  [[nodiscard]] std::vector<P> take_points() && { return std::move(points_).take_vector(); }
  /// The same, as a Points sequence: no allocation for any degree.
  [[nodiscard]] Points take_point_sequence() && noexcept { return std::move(points_); }

  friend bool operator==(const BasicCurve&, const BasicCurve&) = default;

 private:
  Points points_;
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
  typename BasicCurve<P>::Points points(curve.points());
  std::reverse(points.begin(), points.end());
  return BasicCurve<P>(std::move(points));
}

/// The same, reusing the storage of a curve that is not used again.
template <class P>
[[nodiscard]] BasicCurve<P> reversed(BasicCurve<P>&& curve) {
  typename BasicCurve<P>::Points points = std::move(curve).take_point_sequence();
  std::reverse(points.begin(), points.end());
  return BasicCurve<P>(std::move(points));
}

}  // namespace bezier::core
