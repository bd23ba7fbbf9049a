#include "core/self_intersect/collinear_fold.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "core/self_intersect/tuning.hpp"

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

}  // namespace

std::optional<CollinearFrame> collinear_frame(std::span<const Point2> points, double dist_tol) {
  assert(!points.empty());
  const Point2 origin = points[0];
  Point2 direction{};
  double farthest2 = 0.0;  // squared distances: this runs before every search
  for (const Point2 p : points) {
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
  for (const Point2 p : points) {
    if (!(std::fabs(cross(p - origin, direction)) <= bound)) return std::nullopt;
  }
  return CollinearFrame{origin, direction};
}

CollinearOverlaps collinear_self_overlaps(std::span<const Point2> points,
                                          const CollinearFrame& frame, double dist_tol,
                                          std::int64_t max_work) {
  CollinearOverlaps out;
  const double len2 = dot(frame.direction, frame.direction);
  if (len2 == 0.0) {
    out.overlaps.push_back({{0.0, 1.0}, {0.0, 1.0}});
    return out;
  }
  std::vector<double> x;
  for (const Point2 p : points) x.push_back(dot(p - frame.origin, frame.direction) / len2);
  std::vector<double> dx;
  for (std::size_t i = 0; i + 1 < x.size(); ++i) dx.push_back(x[i + 1] - x[i]);
  const auto x_at = [&](double t) { return bernstein_value(x, t); };
  const auto dx_at = [&](double t) { return bernstein_value(dx, t); };

  // Sign runs of x' from left to right: depth-first, left half first.
  struct Pending {
    double lo, hi;
    std::vector<double> c;
  };
  std::vector<Pending> stack{{0.0, 1.0, dx}};
  std::vector<SignRun> runs;
  while (!stack.empty()) {
    if (out.work >= max_work) {
      out.work_cap_reached = true;
      return out;
    }
    ++out.work;
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

  // Turning points: where consecutive runs change sign.
  std::vector<double> bounds{0.0};
  std::vector<int> signs;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    if (signs.empty()) {
      signs.push_back(runs[r].sign);
    } else if (runs[r].sign != signs.back()) {
      bounds.push_back(bisect(dx_at, runs[r - 1].hi, runs[r].lo, signs.back()));
      signs.push_back(runs[r].sign);
    }
  }
  bounds.push_back(1.0);
  if (signs.size() < 2) return out;  // monotone: no self-intersection at all

  // Monotone pieces [bounds_k, bounds_k+1]; preimage of a value by bisection.
  std::vector<double> values;
  for (const double t : bounds) values.push_back(x_at(t));
  const auto preimage = [&](std::size_t k, double value) {
    const double lo = bounds[k], hi = bounds[k + 1];
    if (value == values[k]) return lo;
    if (value == values[k + 1]) return hi;
    const int s_lo = sign_of(values[k] - value);
    return bisect([&](double t) { return x_at(t) - value; }, lo, hi, s_lo);
  };
  const double x_tol = dist_tol / std::sqrt(len2);
  for (std::size_t p = 0; p + 1 < signs.size(); ++p) {
    for (std::size_t q = p + 1; q < signs.size(); ++q) {
      const double lo =
          std::max(std::min(values[p], values[p + 1]), std::min(values[q], values[q + 1]));
      const double hi =
          std::min(std::max(values[p], values[p + 1]), std::max(values[q], values[q + 1]));
      if (!(hi - lo > x_tol)) continue;
      const double t1 = preimage(p, lo), t2 = preimage(p, hi);
      const double s1 = preimage(q, lo), s2 = preimage(q, hi);
      out.overlaps.push_back(
          {{std::min(t1, t2), std::max(t1, t2)}, {std::min(s1, s2), std::max(s1, s2)}});
    }
  }
  std::sort(out.overlaps.begin(), out.overlaps.end(),
            [](const Overlap& a, const Overlap& b) {
              return a.t_interval.lo != b.t_interval.lo ? a.t_interval.lo < b.t_interval.lo
                                                        : a.s_interval.lo < b.s_interval.lo;
            });
  return out;
}

}  // namespace bezier::core
