#include "core/cubic/double_point.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "core/numeric/quadratic_roots.hpp"

namespace bezier::core {

namespace {

// B(t) by de Casteljau on the four points, without the allocation of the general
// evaluate(): this runs inside classify(), whose budget is tens of nanoseconds.
Point2 cubic_point(std::span<const Point2, 4> p, double t) noexcept {
  const Point2 a = lerp(p[0], p[1], t), b = lerp(p[1], p[2], t), c = lerp(p[2], p[3], t);
  const Point2 d = lerp(a, b, t), e = lerp(b, c, t);
  return lerp(d, e, t);
}

// Into [0, 1], and -0 to +0.
double clamp_unit(double t) noexcept {
  return t <= 0.0 ? 0.0 : std::min(t, 1.0);
}

}  // namespace

std::optional<CubicDoublePoint> cubic_double_point(std::span<const Point2, 4> p,
                                                   const CubicPredicates& pred) {
  // disc < 0 implies d1 d3 > 0, so d3 != 0 below.
  if (pred.sign.disc >= 0) return std::nullopt;
  const double d2 = pred.d2, d3 = pred.d3;
  CubicDoublePoint dp;
  // Loop closing exactly at an end: one root is exactly 0 (l0 = d3² s t = 0) or exactly 1
  // (l1 = d3² (1 − s)(1 − t) = 0), the other follows from s + t = −d2 / d3.
  const double sum = -d2 / d3;
  if (pred.sign.l0 == 0 && pred.sign.l1 == 0) {
    dp.t1 = 0.0;
    dp.t2 = 1.0;
  } else if (pred.sign.l0 == 0) {
    dp.t1 = std::min(0.0, sum);
    dp.t2 = std::max(0.0, sum);
  } else if (pred.sign.l1 == 0) {
    dp.t1 = std::min(1.0, sum - 1.0);
    dp.t2 = std::max(1.0, sum - 1.0);
  } else {
    const RootPair r = quadratic_roots(d3, d2, pred.l0 / d3, -3.0 * pred.disc);
    dp.t1 = r.lo;
    dp.t2 = r.hi;
  }
  dp.on_segment = double_point_on_segment(pred.sign);
  if (dp.on_segment) {
    dp.t1 = clamp_unit(dp.t1);
    dp.t2 = clamp_unit(dp.t2);
    // l0 > 0: t1 > 0; l1 > 0: t2 < 1, exactly, even where the rounded root is 0 or 1 (a loop
    // closing within an ulp of an end); so 0 and 1 come only from an exactly closing end.
    if (pred.sign.l0 > 0) dp.t1 = std::max(dp.t1, std::numeric_limits<double>::denorm_min());
    if (pred.sign.l1 > 0) dp.t2 = std::min(dp.t2, std::nextafter(1.0, 0.0));
    // disc < 0: the roots are distinct, t1 < t2 exactly, even where both round (or are
    // clamped) onto one double next to an end; move the one away from that end.
    if (!(dp.t1 < dp.t2)) {
      if (dp.t2 > 0.5) {
        dp.t1 = std::nextafter(dp.t2, 0.0);
      } else {
        dp.t2 = std::nextafter(dp.t1, 1.0);
      }
    }
  }
  // At an exactly closing end the point is that end point, bit for bit.
  if (pred.sign.l0 == 0) {
    dp.point = p[0];
  } else if (pred.sign.l1 == 0) {
    dp.point = p[3];
  } else {
    // Halves first: two points near the largest double would overflow their sum.
    dp.point = 0.5 * cubic_point(p, dp.t1) + 0.5 * cubic_point(p, dp.t2);
  }
  return dp;
}

std::optional<CubicDoublePoint> cubic_double_point(std::span<const Point2, 4> p) {
  return cubic_double_point(p, cubic_predicates(p));
}

std::optional<CubicDoublePoint> cubic_double_point(const Curve& cubic) {
  assert(cubic.degree() == 3);
  return cubic_double_point(std::span<const Point2, 4>(cubic.points().data(), 4));
}

}  // namespace bezier::core
