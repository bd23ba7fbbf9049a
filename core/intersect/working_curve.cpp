#include "core/intersect/working_curve.hpp"

#include <algorithm>
#include <cmath>

#include "core/intersect/bernstein1d.hpp"

namespace bezier::core {

namespace {

constexpr double kU = bernstein::kU;
/// The exponent of the smallest subnormal double, 2^-1074.
constexpr int kSmallestExponent = -1074;

/// The multiple of `grid` nearest to x, or the one next to it towards zero when the nearest
/// is beyond the largest double (x within half a grid step of it, finding F13).
double grid_point(double x, double grid) noexcept {
  const double nearest = std::nearbyint(x / grid) * grid;
  return std::isfinite(nearest) ? nearest : std::trunc(x / grid) * grid;
}

/// Multiplication by 2^e as two factors (2^e itself may be beyond the double range): exact
/// whenever the result is a normal double.
struct PowerOfTwo {
  double first, second;
  explicit PowerOfTwo(int e) noexcept
      : first(std::ldexp(1.0, e / 2)), second(std::ldexp(1.0, e - e / 2)) {}
  [[nodiscard]] double times(double x) const noexcept { return x * first * second; }
};

}  // namespace

WorkingFrame working_frame(const Curve& f, const Curve& g) {
  Point2 lo = f.front(), hi = f.front();
  for (const Curve* c : {&f, &g}) {
    for (const Point2 p : c->points()) {
      lo = {bernstein::min2(lo.x, p.x), bernstein::min2(lo.y, p.y)};
      hi = {bernstein::max2(hi.x, p.x), bernstein::max2(hi.y, p.y)};
    }
  }
  // Halves first: lo + hi may overflow.
  const Point2 center = {lo.x / 2 + hi.x / 2, lo.y / 2 + hi.y / 2};
  const double extent = bernstein::max2(hi.x / 2 - lo.x / 2, hi.y / 2 - lo.y / 2);
  WorkingFrame frame;
  if (!(extent > 0.0)) {
    frame.origin = f.front();  // every control point of both curves is this point
    return frame;
  }
  // A grid of a sixteenth of the extent: the origin has few significant bits, so inputs on
  // any finer grid subtract from it exactly, and translating the inputs by a multiple of
  // the grid translates the origin by the same amount. (Never finer than the smallest
  // subnormal: a grid of 0 would make the origin NaN, finding F5b.)
  const double grid = std::ldexp(1.0, std::max(std::ilogb(extent) - 4, kSmallestExponent));
  frame.origin = {grid_point(center.x, grid), grid_point(center.y, grid)};
  double m = 0.0;
  for (const Curve* c : {&f, &g}) {
    for (const Point2 p : c->points()) m = bernstein::max2(m, max_abs_coordinate(p - frame.origin));
  }
  // 2^-(e + 1) with 2^e <= m (m is finite and nonzero: the origin lies within a grid step
  // of the centre, and some coordinate differs from it by at least half the extent).
  frame.exponent = -(std::ilogb(m) + 1);
  return frame;
}

WorkingCurve to_working(const Curve& curve, WorkingFrame frame) {
  WorkingCurve w;
  w.degree = curve.degree();
  const std::size_t count = curve.points().size();
  w.x.resize(count);
  w.y.resize(count);
  w.x_lo.resize(count);
  w.y_lo.resize(count);
  w.x_dd.resize(count);
  w.y_dd.resize(count);
  const PowerOfTwo scale(frame.exponent);
  for (std::size_t i = 0; i < count; ++i) {
    const Point2 p = curve.points()[i];
    const TwoTerm<double> x = two_sum(p.x, -frame.origin.x);
    const TwoTerm<double> y = two_sum(p.y, -frame.origin.y);
    w.x[i] = scale.times(x.hi);
    w.y[i] = scale.times(y.hi);
    w.x_lo[i] = scale.times(x.lo);
    w.y_lo[i] = scale.times(y.lo);
    w.x_dd[i] = {w.x[i], w.x_lo[i]};
    w.y_dd[i] = {w.y[i], w.y_lo[i]};
    w.magnitude =
        bernstein::max2(w.magnitude, bernstein::max2(std::fabs(w.x[i]), std::fabs(w.y[i])));
    w.frame_error =
        bernstein::max2(w.frame_error, bernstein::max2(std::fabs(w.x_lo[i]), std::fabs(w.y_lo[i])));
  }
  w.is_point = true;
  for (std::size_t i = 1; i < w.x.size(); ++i) {
    w.is_point = w.is_point && w.x[i] == w.x[0] && w.y[i] == w.y[0] && w.x_lo[i] == w.x_lo[0] &&
                 w.y_lo[i] == w.y_lo[0];
  }
  return w;
}

Piece fast_piece(const WorkingCurve& f, double a, double b) {
  Piece p;
  fast_piece_into(f, a, b, p);
  return p;
}

void fast_piece_into(const WorkingCurve& f, double a, double b, Piece& out) {
  const std::size_t count = f.x.size();
  if (out.x.size() != count) {
    out.x = Coeffs(count, Coeffs::Uninitialized{});
    out.y = Coeffs(count, Coeffs::Uninitialized{});
  }
  bernstein::portion_into<double>(f.x, a, b, out.x.data());
  bernstein::portion_into<double>(f.y, a, b, out.y.data());
  out.error = f.frame_error + 3.02 * f.degree * kU * f.magnitude + 0x1p-1000;
}

Piece compensated_piece(const WorkingCurve& f, double a, double b, Point2 center) {
  const SmallArray<dd::Real> xs = bernstein::portion<dd::Real>(f.x_dd, a, b);
  const SmallArray<dd::Real> ys = bernstein::portion<dd::Real>(f.y_dd, a, b);
  Piece p;
  p.x.resize(xs.size());
  p.y.resize(ys.size());
  double local = 0.0;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    p.x[i] = dd::to_double(dd::sub(xs[i], dd::from(center.x)));
    p.y[i] = dd::to_double(dd::sub(ys[i], dd::from(center.y)));
    local = bernstein::max2(local, bernstein::max2(std::fabs(p.x[i]), std::fabs(p.y[i])));
  }
  p.error = 1.01 * kU * local + (12.0 * f.degree + 4.0) * kU * kU * f.magnitude + 0x1p-1000;
  return p;
}

PointDD evaluate_dd(const WorkingCurve& f, double t) {
  SmallArray<dd::Real> xs(std::span<const dd::Real>(f.x_dd)), ys(std::span<const dd::Real>(f.y_dd));
  for (std::size_t level = xs.size() - 1; level > 0; --level) {
    for (std::size_t k = 0; k < level; ++k) {
      xs[k] = dd::lerp(xs[k], xs[k + 1], t);
      ys[k] = dd::lerp(ys[k], ys[k + 1], t);
    }
  }
  return {xs[0], ys[0]};
}

PointAndTangent evaluate_with_tangent(const WorkingCurve& f, double t) {
  const std::size_t n = f.x.size() - 1;
  if (n == 0) return {{f.x[0], f.y[0]}, {0.0, 0.0}};
  Coeffs xs(std::span<const double>(f.x)), ys(std::span<const double>(f.y));
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
