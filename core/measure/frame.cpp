#include "core/measure/frame.hpp"

#include <cmath>
#include <vector>

#include "core/curve/derivative.hpp"
#include "core/bernstein/bernstein1d.hpp"
#include "core/measure/normalised.hpp"
#include "core/numeric/unit_roundoff.hpp"

namespace bezier::core {

namespace {

/// Largest |P^(k)_i| over the control points of the k-th hodograph: a bound on |B^(k)(t)|
/// on [0, 1] by the convex hull property (per coordinate; the length adds at most a factor
/// sqrt(3), absorbed in the threshold's constant).
template <class P>
double hodograph_bound(const BasicCurve<P>& curve, int k) {
  return scale(derivative(curve, k));
}

/// |B'| below which B'(t) is numerically zero (see frame.hpp).
template <class P>
double stationary_threshold(const BasicCurve<P>& curve) {
  return 16 * kUnitRoundoff * (hodograph_bound(curve, 1) + hodograph_bound(curve, 2));
}

std::optional<Frame<Point2>> unit_frame(const Curve& curve, double t) {
  const std::vector<Point2> d = derivatives_at(curve, t, 2);
  const double speed = length(d[0]);
  if (!(speed > stationary_threshold(curve))) return std::nullopt;
  const Point2 tangent = d[0] / speed;
  Frame<Point2> f;
  f.tangent = tangent;
  // 0 - y, not -y: a horizontal tangent's normal is (0, ±1), not (-0, 1).
  f.normal = Point2{0.0 - tangent.y, tangent.x};
  f.curvature = cross(d[0], d[1]) / (speed * speed * speed);
  return f;
}

std::optional<Frame<Point3>> unit_frame(const Curve3& curve, double t) {
  const std::vector<Point3> d = derivatives_at(curve, t, 2);
  const double speed = length(d[0]);
  if (!(speed > stationary_threshold(curve))) return std::nullopt;
  Frame<Point3> f;
  f.tangent = d[0] / speed;
  const Point3 binormal_direction = cross(d[0], d[1]);
  const double bend = length(binormal_direction);
  f.curvature = bend / (speed * speed * speed);
  // Each component of B' × B'' rounds with an error up to about 2 u |B'| |B''|: below a few
  // times that the osculating plane is rounding noise.
  if (bend > 8 * kUnitRoundoff * speed * length(d[1])) {
    const Point3 normal_direction = cross(binormal_direction, d[0]);  // (B' × B'') × B'
    const double size = length(normal_direction);
    if (size > 0.0) f.normal = normal_direction / size;
  }
  return f;
}

/// The frame of the normalised curve (tangent and normal are scale-free; the curvature of
/// 2^e B is the curvature of B over 2^e).
template <class P>
std::optional<Frame<P>> scaled_frame(const BasicCurve<P>& curve, double t) {
  const Normalised<P> unit = normalised(curve);
  auto f = unit_frame(unit.curve, t);
  if (f) f->curvature = unit.to_unit(f->curvature);
  return f;
}

}  // namespace

std::optional<Frame<Point2>> frame(const Curve& curve, double t) { return scaled_frame(curve, t); }
std::optional<Frame<Point3>> frame(const Curve3& curve, double t) { return scaled_frame(curve, t); }

}  // namespace bezier::core
