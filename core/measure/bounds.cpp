#include "core/measure/bounds.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "core/bernstein/bernstein1d.hpp"
#include "core/curve/derivative.hpp"
#include "core/curve/evaluate.hpp"
#include "core/measure/axis.hpp"
#include "core/measure/interval_roots.hpp"
#include "core/measure/normalised.hpp"
#include "core/numeric/outward.hpp"
#include "core/numeric/unit_roundoff.hpp"

namespace bezier::core {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

template <class P>
Coeffs coordinate(std::span<const P> points, std::size_t k) {
  Coeffs c(points.size(), Coeffs::Uninitialized{});
  for (std::size_t i = 0; i < points.size(); ++i) c[i] = axis(points[i], k);
  return c;
}

template <class P>
Bounds<P> box(const BasicCurve<P>& curve, double a, double b) {
  assert(0.0 <= a && a <= b && b <= 1.0);
  constexpr std::size_t kAxes = Bounds<P>::kAxes;
  Bounds<P> out;
  // At 0 and 1 the curve is its end control point (evaluate would return it too).
  const P start = a == 0.0 ? curve.points().front() : evaluate(curve, a);
  const P end = b == 1.0 ? curve.points().back() : evaluate(curve, b);
  const SmallArray<P> hodograph = hodograph_points(curve.points());
  const double n = curve.degree();
  for (std::size_t k = 0; k < kAxes; ++k) {
    // The compensated evaluation's second-order term, with room for its constant.
    const Coeffs values = coordinate(curve.points(), k);
    const double evaluation_error = 2 * (n + 1) * (n + 1) * kUnitRoundoff * kUnitRoundoff * bernstein::max_abs(values);
    // A coordinate at t = 0 or 1 is a control point's, exact; elsewhere it is moved outward
    // by the evaluation's bound and one more rounding.
    double lo = kInfinity, hi = -kInfinity;
    const auto include = [&](double t, double v) {
      const bool exact = t == 0.0 || t == 1.0;
      lo = std::min(lo, exact ? v : next_down(v - evaluation_error));
      hi = std::max(hi, exact ? v : next_up(v + evaluation_error));
    };
    include(a, axis(start, k));
    include(b, axis(end, k));
    if (a < b) {
      Coeffs slope(hodograph.size(), Coeffs::Uninitialized{});
      for (std::size_t i = 0; i < hodograph.size(); ++i) slope[i] = axis(hodograph[i], k);
      out.critical[k] = interval_roots(slope, a, b, IntervalEnds::open).roots;
      for (const double t : out.critical[k]) include(t, evaluate_coordinate(values, t));
    }
    axis(out.min, k) = lo;
    axis(out.max, k) = hi;
  }
  return out;
}

/// The box of the normalised curve, scaled back (exactly: powers of two).
template <class P>
Bounds<P> scaled_box(const BasicCurve<P>& curve, double a, double b) {
  if (normalising_exponent(curve) == 0) return box(curve, a, b);
  const Normalised<P> unit = normalised(curve);
  Bounds<P> out = box(unit.curve, a, b);
  // Scaling back is exact unless a face lands among the subnormals (a curve whose largest
  // coordinate is subnormal or nearly so), where it rounds once: a face rounded inward is
  // moved out by one step, so the box still contains the curve. Scaling the rounded face
  // up again is exact, which tells the direction.
  for (std::size_t k = 0; k < Bounds<P>::kAxes; ++k) {
    const double lo = unit.from_unit(axis(out.min, k));
    const double hi = unit.from_unit(axis(out.max, k));
    axis(out.min, k) = unit.to_unit(lo) > axis(out.min, k) ? next_down(lo) : lo;
    axis(out.max, k) = unit.to_unit(hi) < axis(out.max, k) ? next_up(hi) : hi;
  }
  return out;
}

}  // namespace

Bounds<Point2> bounds(const Curve& curve, double a, double b) { return scaled_box(curve, a, b); }
Bounds<Point3> bounds(const Curve3& curve, double a, double b) { return scaled_box(curve, a, b); }

}  // namespace bezier::core
