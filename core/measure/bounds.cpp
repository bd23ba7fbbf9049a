#include "core/measure/bounds.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "core/bernstein/bernstein1d.hpp"
#include "core/bernstein/exact_casteljau.hpp"
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

// The grid a stretch next to an end is snapped to: a multiple of 2^-32 keeps the exact
// rounds of exact_portion within the double range for every degree the API takes.
constexpr double kStretchGrid = 0x1p-32;

// Whether the root t of x' that the root finder reported next to the end `end` of [a, b]
// is the root x' has at that end: x'(end) = 0 exactly, and x is monotone on a stretch from
// the end to past t (twice as far, at least 2^-32, snapped outward to that grid and clipped
// to [a, b]), so x' keeps one sign there and t is no extreme of x. Both facts are read from
// the exact Bernstein coefficients of x on the stretch (exact_casteljau.hpp): x' is n times
// their differences, so the first difference at the end is zero exactly when x'(end) is,
// and differences of one sign make x' one-signed (the convex hull property). When the
// exact rounds cannot be done (nullopt) the root is kept.
bool is_root_at_end(std::span<const double> values, double end, double t, double a, double b) {
  const double reach = std::max(2 * std::fabs(t - end), kStretchGrid);
  const bool left = end <= t;
  const double far = left ? std::min(b, std::ceil((end + reach) / kStretchGrid) * kStretchGrid)
                          : std::max(a, std::floor((end - reach) / kStretchGrid) * kStretchGrid);
  const auto stretch = left ? exact_portion(values, end, far) : exact_portion(values, far, end);
  if (!stretch) return false;
  const std::size_t n = stretch->size() - 1;
  const Expansion slope_at_end = left ? (*stretch)[1] - (*stretch)[0] : (*stretch)[n] - (*stretch)[n - 1];
  if (slope_at_end.sign() != 0) return false;
  int direction = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const int sign = ((*stretch)[i + 1] - (*stretch)[i]).sign();
    if (sign == 0) continue;
    if (direction != 0 && sign != direction) return false;
    direction = sign;
  }
  return true;
}

// The critical parameters of one axis with the roots of x' at an end of [a, b] left out:
// a root the finder reports next to an end, where x' evaluates within its rounding bound of
// zero (a cluster, often a double root exactly at the end), is checked exactly by
// is_root_at_end and dropped when it is that end's root: the end's value is then the
// extreme, exactly.
SmallArray<double> critical_parameters(std::span<const double> values, std::span<const double> slope,
                                       double a, double b) {
  SmallArray<double> roots = interval_roots(slope, a, b, IntervalEnds::open).roots;
  if (roots.empty()) return roots;
  const double n = static_cast<double>(slope.size() - 1);
  const double flat = 2 * 3.02 * std::max(n, 1.0) * kUnitRoundoff * bernstein::max_abs(slope);
  const auto flat_at = [&](double end) { return std::fabs(bernstein::evaluate(slope, end)) <= flat; };
  std::size_t kept = 0;
  for (std::size_t i = 0; i < roots.size(); ++i) {
    const double t = roots[i];
    const bool first = i == 0, last = i + 1 == roots.size();
    if (first && flat_at(a) && is_root_at_end(values, a, t, a, b)) continue;
    if (last && flat_at(b) && is_root_at_end(values, b, t, a, b)) continue;
    roots[kept++] = t;
  }
  roots.resize(kept, SmallArray<double>::Uninitialized{});
  return roots;
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
    // An end inside (0, 1) is evaluated exactly where exact_value can, and its faces are
    // that value rounded outward (the value itself when it is a double).
    const auto include_end = [&](double t, double v) {
      const auto exact = t == 0.0 || t == 1.0 ? std::nullopt : exact_value(values, t);
      if (!exact) return include(t, v);
      lo = std::min(lo, rounded_down(*exact));
      hi = std::max(hi, rounded_up(*exact));
    };
    include_end(a, axis(start, k));
    include_end(b, axis(end, k));
    if (a < b) {
      Coeffs slope(hodograph.size(), Coeffs::Uninitialized{});
      for (std::size_t i = 0; i < hodograph.size(); ++i) slope[i] = axis(hodograph[i], k);
      out.critical[k] = critical_parameters(values, slope, a, b);
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
