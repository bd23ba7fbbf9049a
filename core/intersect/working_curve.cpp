#include "core/intersect/working_curve.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

#include "core/bernstein/bernstein1d.hpp"
#include "core/numeric/lerp_error_bound.hpp"
#include "core/numeric/min_max.hpp"
#include "core/numeric/fixed_extent.hpp"
#include "core/base/multiversion.hpp"
#include "core/numeric/power_of_two.hpp"
#include "core/numeric/unit_roundoff.hpp"

namespace bezier::core {

namespace {

/// The exponent of the smallest subnormal double, 2^-1074.
constexpr int kSmallestExponent = -1074;

/// The multiple of `grid` nearest to x, or the one next to it towards zero when the nearest
/// is beyond the largest double (x within half a grid step of it:
/// WorkingCurve.CoordinatesNextToTheLargestDouble).
double grid_point(double x, double grid) noexcept {
  // From 2^53 grid steps on, x's ulp is a multiple of the grid, and so is x; x / grid may
  // then even overflow (a curve 2^-1030 tall at x = -7 would give an infinite origin and
  // overflow the frame's exponent: WorkingCurve.ATinyCurveFarFromTheOriginHasAFiniteFrame).
  if (!(std::fabs(x) < grid * 0x1p53)) return x;
  const double nearest = std::nearbyint(x / grid) * grid;
  return std::isfinite(nearest) ? nearest : std::trunc(x / grid) * grid;
}

/// max(|p.x|, |p.y|) as max_abs_coordinate (std::fmax), without the library call: the
/// same value, NaN included (fmax returns the other argument).
double largest_coordinate(Point2 p) noexcept {
  const double a = std::fabs(p.x), b = std::fabs(p.y);
  return b > a || a != a ? b : a;
}

/// hi + lo as double-doubles: built where needed (compensated pieces, Newton residuals)
/// rather than held by every working curve, which most pairs never ask for.
SmallArray<dd::Real> exact_coordinates(const Coeffs& hi, const Coeffs& lo) {
  SmallArray<dd::Real> out(hi.size(), SmallArray<dd::Real>::Uninitialized{});
  for (std::size_t i = 0; i < hi.size(); ++i) out[i] = {hi[i], lo[i]};
  return out;
}

}  // namespace

WorkingFrame working_frame(const Curve& f, const Curve& g) {
  Point2 lo = f.front(), hi = f.front();
  for (const Curve* c : {&f, &g}) {
    for (const Point2 p : c->points()) {
      lo = {min2(lo.x, p.x), min2(lo.y, p.y)};
      hi = {max2(hi.x, p.x), max2(hi.y, p.y)};
    }
  }
  // Halves first: lo + hi may overflow.
  const Point2 center = {lo.x / 2 + hi.x / 2, lo.y / 2 + hi.y / 2};
  const double extent = max2(hi.x / 2 - lo.x / 2, hi.y / 2 - lo.y / 2);
  WorkingFrame frame;
  if (!(extent > 0.0)) {
    frame.origin = f.front();  // every control point of both curves is this point
    return frame;
  }
  // A grid of a sixteenth of the extent: the origin has few significant bits, so inputs on
  // any finer grid subtract from it exactly, and translating the inputs by a multiple of
  // the grid translates the origin by the same amount. (Never finer than the smallest
  // subnormal: a grid of 0 would make the origin NaN,
  // WorkingCurve.SegmentFourSubnormalStepsLong.)
  const double grid = power_of_two(std::max(exponent_of(extent) - 4, kSmallestExponent));
  frame.origin = {grid_point(center.x, grid), grid_point(center.y, grid)};
  double m = 0.0;
  for (const Curve* c : {&f, &g}) {
    for (const Point2 p : c->points()) m = max2(m, largest_coordinate(p - frame.origin));
  }
  // 2^-(e + 1) with 2^e <= m (m is finite and nonzero: the origin lies within a grid step
  // of the centre, and some coordinate differs from it by at least half the extent).
  frame.exponent = -(exponent_of(m) + 1);
  return frame;
}

namespace {

/// The body of to_working for E control points (with_fixed_extent: unrolled for the low
/// degrees), into w's arrays, already sized.
template <std::size_t E>
void fill_working(std::span<const Point2, E> points, WorkingFrame frame, WorkingCurve& w) noexcept {
  const PowerOfTwo scale(frame.exponent);
  double* const x_hi = w.x.data();
  double* const y_hi = w.y.data();
  double* const x_lo = w.x_lo.data();
  double* const y_lo = w.y_lo.data();
  double magnitude = 0.0, frame_error = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const TwoTerm<double> x = two_sum(points[i].x, -frame.origin.x);
    const TwoTerm<double> y = two_sum(points[i].y, -frame.origin.y);
    x_hi[i] = scale.times(x.hi);
    y_hi[i] = scale.times(y.hi);
    x_lo[i] = scale.times(x.lo);
    y_lo[i] = scale.times(y.lo);
    magnitude = max2(magnitude, max2(std::fabs(x_hi[i]), std::fabs(y_hi[i])));
    frame_error =
        max2(frame_error, max2(std::fabs(x_lo[i]), std::fabs(y_lo[i])));
  }
  bool is_point = true;
  for (std::size_t i = 1; i < points.size(); ++i) {
    is_point = is_point && x_hi[i] == x_hi[0] && y_hi[i] == y_hi[0] && x_lo[i] == x_lo[0] &&
               y_lo[i] == y_lo[0];
  }
  w.magnitude = magnitude;
  w.frame_error = frame_error;
  w.is_point = is_point;
}

}  // namespace

WorkingCurve to_working(const Curve& curve, WorkingFrame frame) {
  const std::span<const Point2> points = curve.points();
  const std::size_t count = points.size();
  // Default-initialised, then sized with the entries unset (every one is written below):
  // brace-initialising the aggregate made GCC zero all of its inline storage first, about
  // 900 bytes per curve.
  WorkingCurve w;
  w.degree = curve.degree();
  for (Coeffs* c : {&w.x, &w.y, &w.x_lo, &w.y_lo}) c->resize(count, Coeffs::Uninitialized{});
  with_fixed_extent(count, [&](auto e) {
    fill_working(std::span<const Point2, decltype(e)::value>(points.data(), count), frame, w);
  });
  return w;
}

Piece fast_piece(const WorkingCurve& f, double a, double b) {
  Piece p;
  fast_piece_into(f, a, b, p);
  return p;
}

BEZIER_FMA_CLONES void fast_piece_into(const WorkingCurve& f, double a, double b, Piece& out) {
  const std::size_t count = f.x.size();
  if (out.x.size() != count) {
    out.x = Coeffs(count, Coeffs::Uninitialized{});
    out.y = Coeffs(count, Coeffs::Uninitialized{});
  }
  bernstein::portion_into<double>(f.x, a, b, out.x.data());
  bernstein::portion_into<double>(f.y, a, b, out.y.data());
  out.error = f.frame_error + lerp_levels_error_bound(f.degree, f.magnitude);
}

BEZIER_FMA_CLONES Piece compensated_piece(const WorkingCurve& f, double a, double b, Point2 center) {
  const SmallArray<dd::Real> x_exact = exact_coordinates(f.x, f.x_lo);
  const SmallArray<dd::Real> y_exact = exact_coordinates(f.y, f.y_lo);
  const SmallArray<dd::Real> xs = bernstein::portion<dd::Real>(x_exact, a, b);
  const SmallArray<dd::Real> ys = bernstein::portion<dd::Real>(y_exact, a, b);
  Piece p;
  p.x.resize(xs.size());
  p.y.resize(ys.size());
  double local = 0.0;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    p.x[i] = dd::to_double(dd::sub(xs[i], dd::from(center.x)));
    p.y[i] = dd::to_double(dd::sub(ys[i], dd::from(center.y)));
    local = max2(local, max2(std::fabs(p.x[i]), std::fabs(p.y[i])));
  }
  p.error = 1.01 * kUnitRoundoff * local + (12.0 * f.degree + 4.0) * kUnitRoundoff * kUnitRoundoff * f.magnitude + 0x1p-1000;
  return p;
}

PointDD evaluate_dd(const WorkingCurve& f, double t) {
  SmallArray<dd::Real> xs = exact_coordinates(f.x, f.x_lo), ys = exact_coordinates(f.y, f.y_lo);
  for (std::size_t level = xs.size() - 1; level > 0; --level) {
    for (std::size_t k = 0; k < level; ++k) {
      xs[k] = dd::lerp(xs[k], xs[k + 1], t);
      ys[k] = dd::lerp(ys[k], ys[k + 1], t);
    }
  }
  return {xs[0], ys[0]};
}

namespace {

/// de Casteljau down to the last level in the buffers xs, ys (overwritten), for
/// evaluate_with_tangent.
inline PointAndTangent point_and_tangent_in(double* xs, double* ys, std::size_t n,
                                            double t) noexcept {
  for (std::size_t level = n; level > 1; --level) {
    for (std::size_t k = 0; k < level; ++k) {
      xs[k] = bernstein::lerp(xs[k], xs[k + 1], t);
      ys[k] = bernstein::lerp(ys[k], ys[k + 1], t);
    }
  }
  const double dn = static_cast<double>(n);
  return {{bernstein::lerp(xs[0], xs[1], t), bernstein::lerp(ys[0], ys[1], t)},
          {dn * (xs[1] - xs[0]), dn * (ys[1] - ys[0])}};
}

}  // namespace

PointAndTangent evaluate_with_tangent(const WorkingCurve& f, double t) {
  const std::size_t n = f.x.size() - 1;
  if (n == 0) return {{f.x[0], f.y[0]}, {0.0, 0.0}};
  // Called at every contact and in every refinement step: plain stack buffers for the
  // degrees a piece holds inline, no copies of whole SmallArrays; of a size fixed at
  // compile time for degrees 1 to 3 (the loops unroll).
  const std::optional<PointAndTangent> fixed =
      with_fixed_extent(n + 1, [&](auto e) -> std::optional<PointAndTangent> {
        constexpr std::size_t E = decltype(e)::value;
        if constexpr (E == std::dynamic_extent) {
          return std::nullopt;
        } else {
          // The shared level-by-level de Casteljau (no in-place buffer: see its comment).
          const auto x = bernstein::last_casteljau_level(fixed_span<E>(f.x.data(), E), t);
          const auto y = bernstein::last_casteljau_level(fixed_span<E>(f.y.data(), E), t);
          const double dn = static_cast<double>(E - 1);
          return PointAndTangent{{bernstein::lerp(x[0], x[1], t), bernstein::lerp(y[0], y[1], t)},
                                 {dn * (x[1] - x[0]), dn * (y[1] - y[0])}};
        }
      });
  if (fixed) return *fixed;
  if (n + 1 <= Coeffs::kInline) {
    double xs[Coeffs::kInline], ys[Coeffs::kInline];
    std::copy(f.x.begin(), f.x.end(), xs);
    std::copy(f.y.begin(), f.y.end(), ys);
    return point_and_tangent_in(xs, ys, n, t);
  }
  Coeffs xs(std::span<const double>(f.x)), ys(std::span<const double>(f.y));
  return point_and_tangent_in(xs.data(), ys.data(), n, t);
}

Point2 second_derivative(const WorkingCurve& f, double t) {
  const std::size_t n = f.x.size() - 1;
  if (n < 2) return {0.0, 0.0};
  Coeffs xs(n - 1), ys(n - 1);
  const double factor = static_cast<double>(n) * static_cast<double>(n - 1);
  for (std::size_t i = 0; i + 2 <= n; ++i) {
    xs[i] = factor * ((f.x[i + 2] - f.x[i + 1]) - (f.x[i + 1] - f.x[i]));
    ys[i] = factor * ((f.y[i + 2] - f.y[i + 1]) - (f.y[i + 1] - f.y[i]));
  }
  return {bernstein::evaluate(xs, t), bernstein::evaluate(ys, t)};
}

Point2 from_working(Point2 p, WorkingFrame frame) noexcept {
  const PowerOfTwo unscale(-frame.exponent);
  return {unscale.times(p.x) + frame.origin.x, unscale.times(p.y) + frame.origin.y};
}

}  // namespace bezier::core
