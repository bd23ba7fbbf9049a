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
#include "core/numeric/small_array.hpp"
#include "core/numeric/unit_roundoff.hpp"

namespace bezier::core {

namespace {

template <class P>
struct Candidate {
  double t;
  double distance;
  P point;  // B(t)
};

template <class P>
Candidate<P> candidate_at(const BasicCurve<P>& curve, P target, double t) {
  const P point = evaluate(curve, t);
  return {t, length(point - target), point};
}

/// The candidate at an end of [a, b]: at t = 0 or 1 the end control point (what evaluate
/// returns there).
template <class P>
Candidate<P> end_candidate(const BasicCurve<P>& curve, P target, double t) {
  if (t != 0.0 && t != 1.0) return candidate_at(curve, target, t);
  const P point = t == 0.0 ? curve.points().front() : curve.points().back();
  return {t, length(point - target), point};
}

template <class P>
double distance_at(const BasicCurve<P>& curve, P target, double t) {
  return length(evaluate(curve, t) - target);
}

/// Newton's method on f = (B - q) · B', each step kept only while it stays in [a, b] and
/// lowers the distance.
template <class P>
Candidate<P> polish(const BasicCurve<P>& curve, P target, double a, double b, Candidate<P> best) {
  for (int iteration = 0; iteration < 8; ++iteration) {
    const P offset = best.point - target;
    const auto d = derivatives_at(curve, best.t, 2);
    const double f = dot(offset, d[0]);
    const double slope = dot(d[0], d[0]) + dot(offset, d[1]);
    if (f == 0.0 || !(slope != 0.0)) break;
    const double next = best.t - f / slope;
    if (!(a <= next && next <= b) || next == best.t) break;
    const Candidate<P> moved = candidate_at(curve, target, next);
    if (!(moved.distance < best.distance)) break;
    best = moved;
  }
  return best;
}

template <class P>
NearestPoint<P> closest(const BasicCurve<P>& curve, P target, double a, double b) {
  assert(0.0 <= a && a <= b && b <= 1.0);
  std::vector<Candidate<P>> candidates = {end_candidate(curve, target, a),
                                          end_candidate(curve, target, b)};
  if (a < b) {
    const auto points = curve.points();
    SmallArray<P> offsets(points.size(), typename SmallArray<P>::Uninitialized{});
    for (std::size_t i = 0; i < points.size(); ++i) offsets[i] = points[i] - target;
    const BasicCurve<P> hodograph = derivative(curve);
    const std::vector<double> f = dot_product_polynomial<P>(offsets, hodograph.points());
    // f = D' / 2 for D = |B - q|^2: a minimum of D inside (a, b) is where f rises through
    // zero; where it falls D has a maximum, never the answer.
    for (const double t : interval_roots(f, a, b, IntervalEnds::closed, Crossings::rising).roots)
      candidates.push_back(candidate_at(curve, target, t));
  }
  const double coordinate_scale = std::max(scale(curve), max_abs_coordinate(target));
  // Only the candidates near the least distance are polished. A root of the computed f is
  // within a rounding-level stretch of the exact one (f's coefficients are within their
  // bound e, about 1e-14 of the scale squared, of the exact ones), and along that stretch
  // D = |B - q|^2 changes by 2 ∫ f, where |f| stays at rounding level: polishing lowers a
  // distance by far less than 1e-6 of the coordinate scale, so a candidate further than
  // that above the least is neither the minimum nor tied with it.
  double rough_least = candidates.front().distance;
  for (const Candidate<P>& c : candidates) rough_least = std::min(rough_least, c.distance);
  const double polish_margin = 1e-6 * coordinate_scale;
  for (std::size_t i = 2; i < candidates.size(); ++i) {
    if (candidates[i].distance <= rough_least + polish_margin)
      candidates[i] = polish(curve, target, a, b, candidates[i]);
  }
  double least = candidates.front().distance;
  for (const Candidate<P>& c : candidates) least = std::min(least, c.distance);
  const double tolerance = std::max(1e-12 * least, 8 * kUnitRoundoff * coordinate_scale);

  std::vector<Candidate<P>> tied;
  for (const Candidate<P>& c : candidates) {
    if (c.distance <= least + tolerance) tied.push_back(c);
  }
  std::sort(tied.begin(), tied.end(),
            [](const Candidate<P>& x, const Candidate<P>& y) { return x.t < y.t; });
  NearestPoint<P> out;
  out.t = tied.front().t;
  out.point = tied.front().point;
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
  if (normalising_factor(curve, max_abs_coordinate(target)) == 1.0) return closest(curve, target, a, b);
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
