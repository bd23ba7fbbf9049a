#include "core/measure/nearest.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "core/curve/derivative.hpp"
#include "core/curve/evaluate.hpp"
#include "core/bernstein/bernstein1d.hpp"
#include "core/measure/bernstein_product.hpp"
#include "core/measure/interval_roots.hpp"
#include "core/measure/normalised.hpp"

namespace bezier::core {

namespace {

constexpr double kU = bernstein::kU;

struct Candidate {
  double t;
  double distance;
};

template <class P>
double distance_at(const BasicCurve<P>& curve, P target, double t) {
  return length(evaluate(curve, t) - target);
}

/// Newton's method on f = (B - q) · B', each step kept only while it stays in [a, b] and
/// lowers the distance.
template <class P>
Candidate polish(const BasicCurve<P>& curve, P target, double a, double b, double t) {
  Candidate best{t, distance_at(curve, target, t)};
  for (int iteration = 0; iteration < 8; ++iteration) {
    const P offset = evaluate(curve, best.t) - target;
    const auto d = derivatives_at(curve, best.t, 2);
    const double f = dot(offset, d[0]);
    const double slope = dot(d[0], d[0]) + dot(offset, d[1]);
    if (f == 0.0 || !(slope != 0.0)) break;
    const double next = best.t - f / slope;
    if (!(a <= next && next <= b) || next == best.t) break;
    const double distance = distance_at(curve, target, next);
    if (!(distance < best.distance)) break;
    best = {next, distance};
  }
  return best;
}

template <class P>
NearestPoint<P> closest(const BasicCurve<P>& curve, P target, double a, double b) {
  assert(0.0 <= a && a <= b && b <= 1.0);
  std::vector<Candidate> candidates = {{a, distance_at(curve, target, a)},
                                       {b, distance_at(curve, target, b)}};
  if (a < b) {
    std::vector<P> offsets;
    for (const P& p : curve.points()) offsets.push_back(p - target);
    const BasicCurve<P> hodograph = derivative(curve);
    const std::vector<double> f =
        dot_product_polynomial<P>(std::span<const P>(offsets), hodograph.points());
    for (const double t : interval_roots(f, a, b, IntervalEnds::closed).roots)
      candidates.push_back(polish(curve, target, a, b, t));
  }
  double least = candidates.front().distance;
  for (const Candidate& c : candidates) least = std::min(least, c.distance);
  const double coordinate_scale = std::max(scale(curve), max_abs_coordinate(target));
  const double tolerance = std::max(1e-12 * least, 8 * kU * coordinate_scale);

  std::vector<Candidate> tied;
  for (const Candidate& c : candidates) {
    if (c.distance <= least + tolerance) tied.push_back(c);
  }
  std::sort(tied.begin(), tied.end(), [](const Candidate& x, const Candidate& y) { return x.t < y.t; });
  NearestPoint<P> out;
  out.t = tied.front().t;
  out.point = evaluate(curve, out.t);
  out.distance = least;
  double previous = tied.front().t;
  for (std::size_t i = 1; i < tied.size(); ++i) {
    const double t = tied[i].t;
    const double middle = previous + (t - previous) / 2;
    const bool same_minimum =
        t == previous || distance_at(curve, target, middle) <= least + tolerance;
    previous = t;
    if (!same_minimum) out.ties.push_back(t);
  }
  return out;
}

/// The answer for the curve and target scaled together by a power of two (exact), the
/// point and distance scaled back.
template <class P>
NearestPoint<P> scaled_closest(const BasicCurve<P>& curve, P target, double a, double b) {
  const Normalised<P> unit = normalised(curve, max_abs_coordinate(target));
  NearestPoint<P> out = closest(unit.curve, unit.factor * target, a, b);
  out.point = out.point / unit.factor;
  out.distance /= unit.factor;
  return out;
}

}  // namespace

NearestPoint<Point2> nearest(const Curve& curve, Point2 target, double a, double b) {
  return scaled_closest(curve, target, a, b);
}
NearestPoint<Point3> nearest(const Curve3& curve, Point3 target, double a, double b) {
  return scaled_closest(curve, target, a, b);
}

}  // namespace bezier::core
