#include "core/measure/nearest.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <span>

#include "core/base/multiversion.hpp"
#include "core/bernstein/casteljau_row.hpp"
#include "core/curve/derivative.hpp"
#include "core/curve/evaluate.hpp"
#include "core/measure/bernstein_product.hpp"
#include "core/measure/interval_roots.hpp"
#include "core/measure/normalised.hpp"
#include "core/measure/tuning.hpp"
#include "core/numeric/small_array.hpp"
#include "core/numeric/unit_roundoff.hpp"

namespace bezier::core {

namespace {

/// B(t), B'(t) and B''(t).
template <class P>
struct Jet {
  P point, first, second;
};

/// The Jet from one compensated de Casteljau triangle (CasteljauRow): B(t) is its last
/// entry, bit for bit evaluate()'s; B' is n times the difference of the two entries of the
/// level before and B'' n (n - 1) times the second difference of the three before that
/// (Farin, §5.3), each difference taken on the entries' values and error parts apart, so
/// that close entries lose nothing to cancellation: within a few roundings of the exact
/// derivatives. Newton's method on (B - q) · B' needs all three at each iterate.
template <class P>
Jet<P> jet_of(std::span<const P> points, double t) {
  const double n = static_cast<double>(points.size() - 1);
  CasteljauRow<P> row(points);
  Jet<P> out{};
  while (row.size() > 3) row.casteljau_step(t);
  if (row.size() == 3) {
    const auto &g0 = row.entry(0), &g1 = row.entry(1), &g2 = row.entry(2);
    out.second = (n * (n - 1)) * (((g2.hi - g1.hi) - (g1.hi - g0.hi)) + ((g2.lo - g1.lo) - (g1.lo - g0.lo)));
    row.casteljau_step(t);
  }
  if (row.size() == 2) {
    const auto &e0 = row.entry(0), &e1 = row.entry(1);
    out.first = n * ((e1.hi - e0.hi) + (e1.lo - e0.lo));
    row.casteljau_step(t);
  }
  out.point = row.point(0);
  return out;
}

BEZIER_FMA_CLONES Jet<Point2> jet_at(std::span<const Point2> points, double t) { return jet_of(points, t); }
BEZIER_FMA_CLONES Jet<Point3> jet_at(std::span<const Point3> points, double t) { return jet_of(points, t); }

/// The Bernstein coefficients of f = (B - q) · B' into f[0..2n-1] (degree 2n - 1; f[0] = 0
/// for a point, n = 0): the products (bernstein_product.hpp) of the offsets P_i - q with the
/// hodograph's points, which are derivative()'s (each within one rounding of
/// n (P_{i+1} - P_i)).
template <class P>
void distance_slope_of(std::span<const P> points, P target, double* f) {
  const SmallArray<P> hodograph = hodograph_points(points);
  dot_product_polynomial_into(
      static_cast<int>(points.size()) - 1, static_cast<int>(hodograph.size()) - 1,
      [&](int i) { return points[static_cast<std::size_t>(i)] - target; },
      [&](int j) { return hodograph[static_cast<std::size_t>(j)]; }, f);
}

BEZIER_FMA_CLONES void distance_slope(std::span<const Point2> points, Point2 target, double* f) {
  distance_slope_of(points, target, f);
}
BEZIER_FMA_CLONES void distance_slope(std::span<const Point3> points, Point3 target, double* f) {
  distance_slope_of(points, target, f);
}

/// A candidate parameter and B(t) there.
template <class P>
struct Candidate {
  double t;
  double squared;  // |B(t) - q|^2 from the compensated B(t)
  P point;
};

template <class P>
double squared_length(P v) {
  return dot(v, v);
}

/// B(t) - q in plain doubles, O(n): the Bernstein sum Σ C(n, k) t^k (1 - t)^(n-k) (P_k - q)
/// in Horner-like form, each partial sum times 1 - t before the next term, t^k and C(n, k)
/// carried along (C(n, k) exact up to degree 50, within k roundings beyond). A term rounds
/// at most 4n + 3 times (t^k, the binomial, its product, P_k - q, and per later step a sum,
/// a product and 1 - t's own rounding), so the result is within (4n + 3) u of the
/// coordinate scale: a rough distance, for the screen of the candidates only.
template <class P>
P rough_offset(std::span<const P> points, P target, double t) {
  const std::size_t n = points.size() - 1;
  if (n == 0) return points[0] - target;
  const double s = 1.0 - t;
  double power = 1.0, binomial = 1.0;
  P sum = (points[0] - target) * s;
  for (std::size_t k = 1; k < n; ++k) {
    power *= t;
    binomial = binomial * static_cast<double>(n - k + 1) / static_cast<double>(k);
    sum = (sum + (power * binomial) * (points[k] - target)) * s;
  }
  return sum + (power * t) * (points[n] - target);
}

/// The candidate at an end of [a, b]: at t = 0 or 1 the end control point (what evaluate
/// returns there).
template <class P>
Candidate<P> end_candidate(const BasicCurve<P>& curve, P target, double t) {
  const P point = t == 0.0   ? curve.points().front()
                  : t == 1.0 ? curve.points().back()
                             : evaluate(curve, t);
  return {t, squared_length(point - target), point};
}

/// The candidate at the root t of f, polished by Newton's method on f = (B - q) · B' with
/// f' = |B'|^2 + (B - q) · B'' from the compensated jet, each step kept only while it stays
/// in [a, b] and lowers the distance, or leaves it within a rounding and lowers |f| (near
/// the minimum the distance is flat to rounding, and f, from the compensated jet, still
/// tells the closer parameter).
template <class P>
Candidate<P> polished(std::span<const P> points, P target, double a, double b, double t) {
  Jet<P> jet = jet_at(points, t);
  Candidate<P> best{t, squared_length(jet.point - target), jet.point};
  P point = jet.point;
  for (int iteration = 0; iteration < measure_tuning::kPolishIterations; ++iteration) {
    const P offset = point - target;
    const double f = dot(offset, jet.first);
    const double slope = dot(jet.first, jet.first) + dot(offset, jet.second);
    if (f == 0.0 || !(slope != 0.0)) break;
    const double next = best.t - f / slope;
    if (!(a <= next && next <= b) || next == best.t) break;
    const Jet<P> moved = jet_at(points, next);
    const double squared = squared_length(moved.point - target);
    // At the minimum the distance is flat: within a rounding of it, a smaller |f| is the
    // closer parameter, which the distance no longer tells apart.
    const bool lower = squared < best.squared;
    const bool level_and_closer = squared <= best.squared * (1 + 4 * kUnitRoundoff) &&
                                  std::fabs(dot(moved.point - target, moved.first)) < std::fabs(f);
    if (!lower && !level_and_closer) break;
    best = {next, squared, moved.point};
    point = moved.point;
    jet = moved;
  }
  return best;
}

/// The nearest point, coordinate_scale the largest coordinate of the control points and the
/// target, which the caller has brought into [1/2, 1) (normalised.hpp): the squared
/// distances cannot overflow, and only distances far below the tie tolerance underflow.
template <class P>
NearestPoint<P> closest(const BasicCurve<P>& curve, P target, double a, double b,
                        double coordinate_scale) {
  assert(0.0 <= a && a <= b && b <= 1.0);
  const auto points = curve.points();
  SmallArray<double> roots;
  if (a < b) {
    const std::size_t n = points.size() - 1;
    Coeffs f(std::max<std::size_t>(2 * n, 1), Coeffs::Uninitialized{});
    distance_slope(points, target, f.data());
    // f = D' / 2 for D = |B - q|^2: a minimum of D inside (a, b) is where f rises through
    // zero; where it falls D has a maximum, never the answer.
    roots = interval_roots(f, a, b, IntervalEnds::closed, Crossings::rising).roots;
  }
  // The ends, then the roots that can still be the minimum or tie with it, polished.
  SmallArray<Candidate<P>> candidates(2 + roots.size(), typename SmallArray<Candidate<P>>::Uninitialized{});
  candidates[0] = end_candidate(curve, target, a);
  candidates[1] = end_candidate(curve, target, b);
  std::size_t count = 2;
  if (!roots.empty()) {
    // A root of the computed f is within a rounding-level stretch of the exact one (f's
    // coefficients are within their bound e, about 1e-14 of the scale squared, of the
    // exact ones), and along that stretch D = |B - q|^2 changes by 2 ∫ f, where |f| stays
    // at rounding level: polishing lowers a distance by far less than kPolishMargin of the
    // coordinate scale, and the rough distances (rough_offset) are within a few n u of the
    // scale of the compensated ones, so a root whose rough distance is further than that
    // above the least is neither the minimum nor tied with it.
    SmallArray<double> rough(roots.size(), SmallArray<double>::Uninitialized{});
    double least = std::min(candidates[0].squared, candidates[1].squared);
    for (std::size_t i = 0; i < roots.size(); ++i) {
      rough[i] = squared_length(rough_offset(points, target, roots[i]));
      least = std::min(least, rough[i]);
    }
    const double limit = std::sqrt(least) + measure_tuning::kPolishMargin * coordinate_scale;
    for (std::size_t i = 0; i < roots.size(); ++i) {
      if (rough[i] <= limit * limit) candidates[count++] = polished(points, target, a, b, roots[i]);
    }
  }
  const std::span<Candidate<P>> kept(candidates.data(), count);
  double least_squared = kept.front().squared;
  for (const Candidate<P>& c : kept) least_squared = std::min(least_squared, c.squared);
  // The tie tolerance on the distances, from the least squared one; a candidate's squared
  // distance and its root agree with the distance to within rounding, far below it.
  const double rough_least = std::sqrt(least_squared);
  const double tolerance =
      std::max(kTieRelativeTolerance * rough_least, 8 * kUnitRoundoff * coordinate_scale);
  const double tie_limit = (rough_least + tolerance) * (rough_least + tolerance);
  const auto tied_end = std::partition(kept.begin(), kept.end(), [&](const Candidate<P>& c) {
    return c.squared <= tie_limit;
  });
  std::sort(kept.begin(), tied_end,
            [](const Candidate<P>& x, const Candidate<P>& y) { return x.t < y.t; });
  const std::span<const Candidate<P>> tied(kept.begin(), tied_end);
  NearestPoint<P> out;
  out.t = tied.front().t;
  out.point = tied.front().point;
  // The least distance, hypot(B(t) - q) over the tied candidates.
  out.distance = length(out.point - target);
  for (std::size_t i = 1; i < tied.size(); ++i) out.distance = std::min(out.distance, length(tied[i].point - target));
  double previous = tied.front().t;
  for (std::size_t i = 1; i < tied.size(); ++i) {
    const double t = tied[i].t;
    const double middle = previous + (t - previous) / 2;
    const bool same_minimum =
        t == previous || length(evaluate(curve, middle) - target) <= out.distance + tolerance;
    previous = t;
    if (!same_minimum) out.ties.push_back(t);
  }
  return out;
}

/// The answer for the curve and target scaled together by a power of two (exact), the
/// point and distance scaled back.
template <class P>
NearestPoint<P> scaled_closest(const BasicCurve<P>& curve, P target, double a, double b) {
  const double largest = std::max(scale(curve), max_abs_coordinate(target));
  if (normalising_exponent_of(largest) == 0) return closest(curve, target, a, b, largest);
  const Normalised<P> unit = normalised(curve, max_abs_coordinate(target));
  NearestPoint<P> out = closest(unit.curve, unit.to_unit(target), a, b, unit.to_unit(largest));
  out.point = unit.from_unit(out.point);
  out.distance = unit.from_unit(out.distance);
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
