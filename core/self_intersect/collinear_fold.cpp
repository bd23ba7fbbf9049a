#include "core/self_intersect/collinear_fold.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "core/self_intersect/tuning.hpp"
#include "core/self_intersect/work_cost.hpp"

namespace bezier::core {

namespace {

/// Σ c_i b_i(t) by de Casteljau.
double bernstein_value(std::span<const double> c, double t) {
  std::vector<double> w(c.begin(), c.end());
  for (std::size_t level = w.size() - 1; level > 0; --level) {
    for (std::size_t i = 0; i < level; ++i) w[i] = (1.0 - t) * w[i] + t * w[i + 1];
  }
  return w[0];
}

int sign_of(double v) {
  return v > 0.0 ? 1 : (v < 0.0 ? -1 : 0);
}

/// An interval on which x' has one sign (all Bernstein coefficients of that sign).
struct SignRun {
  double lo;
  double hi;
  int sign;
};

/// Bisection for a sign change of f between lo (sign s_lo) and hi: stops when the midpoint
/// is no longer strictly inside (adjacent doubles) or f vanishes.
template <class F>
double bisect(F f, double lo, double hi, int s_lo) {
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (!(lo < mid && mid < hi)) break;
    const int s = sign_of(f(mid));
    if (s == 0) return mid;
    (s == s_lo ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

/// collinear_frame over a span of any extent (fixed for a cubic: the loops unroll).
template <std::size_t Extent>
std::optional<CollinearFrame> frame_of(std::span<const Point2, Extent> points, double dist_tol) {
  assert(!points.empty());
  const Point2 origin = points[0];
  Point2 direction{};
  double farthest2 = 0.0;  // squared distances: this runs before every search
  // P_0 itself is left out of both passes: for finite coordinates P_0 - origin is exactly
  // zero, never the farthest, and its cross product 0 is within any bound another point
  // is within (and there is another point once farthest2 > 0).
  for (const Point2 p : points.template subspan<1>()) {
    const Point2 r = p - origin;
    const double d2 = dot(r, r);
    if (d2 > farthest2) {
      farthest2 = d2;
      direction = r;
    }
  }
  if (farthest2 == 0.0) return CollinearFrame{origin, {}};
  // |cross| / |direction| <= dist_tol; sqrt rather than hypot: the caller normalises.
  const double bound = dist_tol * std::sqrt(farthest2);
  for (const Point2 p : points.template subspan<1>()) {
    if (!(std::fabs(cross(p - origin, direction)) <= bound)) return std::nullopt;
  }
  return CollinearFrame{origin, direction};
}

}  // namespace

std::optional<CollinearFrame> collinear_frame(std::span<const Point2> points, double dist_tol) {
  return frame_of(points, dist_tol);
}

std::optional<CollinearFrame> collinear_frame(std::span<const Point2, 4> points, double dist_tol) {
  return frame_of(points, dist_tol);
}

namespace {

/// The curve along its line: x_i = (P_i - origin)·direction / |direction|^2, and the
/// coefficients of x' up to the factor n, x_{i+1} - x_i (same signs, same roots).
struct LineCoordinates {
  std::vector<double> x;
  std::vector<double> dx;
};

LineCoordinates line_coordinates(std::span<const Point2> points, const CollinearFrame& frame,
                                 double len2) {
  LineCoordinates out;
  for (const Point2 p : points) out.x.push_back(dot(p - frame.origin, frame.direction) / len2);
  for (std::size_t i = 0; i + 1 < out.x.size(); ++i) out.dx.push_back(out.x[i + 1] - out.x[i]);
  return out;
}

/// The sign runs of x' from left to right: subdivision of its Bernstein coefficients,
/// depth-first and left half first, until they share a sign; intervals narrower than
/// kNarrowestSignRun with mixed signs hold a root of x' and are left out. Each step is
/// charged collinear_fold_step_cost(n) to `budget`; nullopt, the budget exhausted, when a
/// step does not fit in what is left.
std::optional<std::vector<SignRun>> sign_runs(const std::vector<double>& dx, WorkBudget& budget) {
  struct Pending {
    double lo, hi;
    std::vector<double> c;
  };
  const std::int64_t step_cost = collinear_fold_step_cost(static_cast<int>(dx.size()));
  std::vector<Pending> stack{{0.0, 1.0, dx}};
  std::vector<SignRun> runs;
  while (!stack.empty()) {
    if (!budget.reserve(step_cost)) return std::nullopt;
    budget.charge(step_cost);
    Pending node = std::move(stack.back());
    stack.pop_back();
    const bool positive =
        std::all_of(node.c.begin(), node.c.end(), [](double v) { return v > 0.0; });
    const bool negative =
        std::all_of(node.c.begin(), node.c.end(), [](double v) { return v < 0.0; });
    if (positive || negative) {
      runs.push_back({node.lo, node.hi, positive ? 1 : -1});
      continue;
    }
    // Narrower than that: a root of x' lies in it.
    if (node.hi - node.lo <= self_intersect_tuning::kNarrowestSignRun) continue;
    // Split the coefficients at 1/2: left gets the first entries of each round, the
    // working row ends as the right half.
    std::vector<double> left(node.c.size());
    std::vector<double> right = node.c;
    left[0] = right[0];
    for (std::size_t k = 1; k < right.size(); ++k) {
      for (std::size_t i = 0; i + k < right.size(); ++i)
        right[i] = 0.5 * right[i] + 0.5 * right[i + 1];
      left[k] = right[0];
    }
    const double mid = 0.5 * (node.lo + node.hi);
    stack.push_back({mid, node.hi, std::move(right)});
    stack.push_back({node.lo, mid, std::move(left)});
  }
  return runs;
}

/// The monotone pieces of x: bounds[k] to bounds[k + 1] (bounds from 0 to 1) with the sign
/// signs[k] of x' on it. A turning point lies where consecutive runs change sign, located by
/// bisection on x' in the gap between them; runs of one sign either side of a gap (a root of
/// even multiplicity) do not turn the curve.
struct MonotonePieces {
  std::vector<double> bounds;
  std::vector<int> signs;
};

MonotonePieces monotone_pieces(const std::vector<SignRun>& runs, const std::vector<double>& dx) {
  const auto dx_at = [&](double t) { return bernstein_value(dx, t); };
  MonotonePieces out;
  out.bounds.push_back(0.0);
  for (std::size_t r = 0; r < runs.size(); ++r) {
    if (out.signs.empty()) {
      out.signs.push_back(runs[r].sign);
    } else if (runs[r].sign != out.signs.back()) {
      out.bounds.push_back(bisect(dx_at, runs[r - 1].hi, runs[r].lo, out.signs.back()));
      out.signs.push_back(runs[r].sign);
    }
  }
  out.bounds.push_back(1.0);
  return out;
}

/// Every two monotone pieces whose ranges of x overlap by more than x_tol: the preimages of
/// the common range on each (bisection on x), sorted by t then s.
std::vector<Overlap> retraced_pieces(const MonotonePieces& pieces, const std::vector<double>& x,
                                     double x_tol) {
  const auto x_at = [&](double t) { return bernstein_value(x, t); };
  const std::vector<double>& bounds = pieces.bounds;
  std::vector<double> values;
  for (const double t : bounds) values.push_back(x_at(t));
  const auto preimage = [&](std::size_t k, double value) {
    const double lo = bounds[k], hi = bounds[k + 1];
    if (value == values[k]) return lo;
    if (value == values[k + 1]) return hi;
    const int s_lo = sign_of(values[k] - value);
    return bisect([&](double t) { return x_at(t) - value; }, lo, hi, s_lo);
  };
  std::vector<Overlap> overlaps;
  const std::size_t count = pieces.signs.size();
  for (std::size_t p = 0; p + 1 < count; ++p) {
    for (std::size_t q = p + 1; q < count; ++q) {
      const double lo =
          std::max(std::min(values[p], values[p + 1]), std::min(values[q], values[q + 1]));
      const double hi =
          std::min(std::max(values[p], values[p + 1]), std::max(values[q], values[q + 1]));
      if (!(hi - lo > x_tol)) continue;
      const double t1 = preimage(p, lo), t2 = preimage(p, hi);
      const double s1 = preimage(q, lo), s2 = preimage(q, hi);
      overlaps.push_back(
          {{std::min(t1, t2), std::max(t1, t2)}, {std::min(s1, s2), std::max(s1, s2)}});
    }
  }
  std::sort(overlaps.begin(), overlaps.end(), [](const Overlap& a, const Overlap& b) {
    return a.t_interval.lo != b.t_interval.lo ? a.t_interval.lo < b.t_interval.lo
                                              : a.s_interval.lo < b.s_interval.lo;
  });
  return overlaps;
}

}  // namespace

std::vector<Overlap> collinear_self_overlaps(std::span<const Point2> points,
                                             const CollinearFrame& frame, double dist_tol,
                                             WorkBudget& budget) {
  const double len2 = dot(frame.direction, frame.direction);
  if (len2 == 0.0) return {{{0.0, 1.0}, {0.0, 1.0}}};
  const LineCoordinates line = line_coordinates(points, frame, len2);
  const std::optional<std::vector<SignRun>> runs = sign_runs(line.dx, budget);
  if (!runs) return {};
  const MonotonePieces pieces = monotone_pieces(*runs, line.dx);
  if (pieces.signs.size() < 2) return {};  // monotone: no self-intersection at all
  return retraced_pieces(pieces, line.x, dist_tol / std::sqrt(len2));
}

}  // namespace bezier::core
