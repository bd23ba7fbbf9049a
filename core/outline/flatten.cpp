#include "core/outline/flatten.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <utility>

#include "core/curve/evaluate.hpp"
#include "core/numeric/power_of_two.hpp"
#include "core/outline/chord_error.hpp"
#include "core/outline/tuning.hpp"

namespace bezier::outline {

namespace {

using core::Point2;

/// The point of the curve with control points `q` at t by de Casteljau's algorithm in
/// doubles (the density only steers the placement, so plain rounding is enough).
Point2 plain_point(std::vector<Point2> q, double t) {
  for (std::size_t k = q.size() - 1; k > 0; --k)
    for (std::size_t i = 0; i < k; ++i) q[i] = core::lerp(q[i], q[i + 1], t);
  return q.front();
}

/// The hodograph's control points n (P_{i+1} - P_i).
std::vector<Point2> hodograph(const std::vector<Point2>& p) {
  const double n = static_cast<double>(p.size() - 1);
  std::vector<Point2> h;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) h.push_back(n * (p[i + 1] - p[i]));
  return h;
}

/// The cumulative flattening integral F at the cell boundaries k / M, k = 0..M
/// (flatten.hpp): midpoint rule on sqrt(|B''_⊥|), B''_⊥ = cross(B' / |B'|, B'').
struct DensityTable {
  std::vector<double> cumulative;
  std::int64_t work = 0;
};

DensityTable density_table(const core::Curve& curve) {
  const std::vector<Point2> p(curve.points().begin(), curve.points().end());
  const int n = curve.degree();
  DensityTable table;
  table.cumulative.push_back(0.0);
  if (n < 2) {
    table.cumulative.push_back(0.0);  // a line: one cell of no density
    return table;
  }
  const std::vector<Point2> first = hodograph(p);
  const std::vector<Point2> second = hodograph(first);
  const int cells = outline_tuning::kDensityCellsPerDegree * n;
  double total = 0.0;
  for (int k = 0; k < cells; ++k) {
    const double t = (k + 0.5) / cells;
    const Point2 velocity = plain_point(first, t);
    const Point2 acceleration = plain_point(second, t);
    const double speed = core::length(velocity);
    // Where B' = 0 (a cusp) the density is its limit, which is finite; the cell's middle
    // lands exactly on it only by accident, and one cell's value steers placement only.
    const double across =
        speed > 0.0 ? std::fabs(core::cross(velocity / speed, acceleration)) : 0.0;
    total += std::sqrt(across) / cells;
    table.cumulative.push_back(total);
  }
  table.work = static_cast<std::int64_t>(cells) * static_cast<std::int64_t>(n) * (n + 1) * 2;
  return table;
}

/// The t with F(t) = target, F piecewise linear between the table's cell boundaries.
double parameter_of(const std::vector<double>& cumulative, double target) {
  const auto cells = static_cast<double>(cumulative.size() - 1);
  const auto upper = std::upper_bound(cumulative.begin(), cumulative.end(), target);
  if (upper == cumulative.end()) return 1.0;
  const auto k = static_cast<std::size_t>(upper - cumulative.begin()) - 1;
  const double rise = cumulative[k + 1] - cumulative[k];
  const double fraction = rise > 0.0 ? (target - cumulative[k]) / rise : 0.0;
  return std::min(1.0, (static_cast<double>(k) + fraction) / cells);
}

/// A curve scaled by a power of two (exact) so that its largest coordinate is in [1, 2), and
/// the tolerance scaled alike: the parameters are then those of the curve itself, and the
/// differences, hodographs and lengths of the kernels neither overflow nor underflow at the
/// ends of the double range.
struct Normalised {
  core::Curve curve;
  double tolerance = 0.0;
};

Normalised normalised(const core::Curve& curve, double tolerance) {
  const double s = core::scale(curve);
  if (s == 0.0) return {curve, tolerance};
  const int e = -core::exponent_of(s);
  const core::PowerOfTwo factor(e);
  return {core::Curve(core::scaled_by_power_of_two(curve.points(), e)), factor.times(tolerance)};
}

double rounding_margin(const core::Curve& curve) {
  return outline_tuning::kRoundingMarginUnits * curve.degree() *
         std::numeric_limits<double>::epsilon() * core::scale(curve);
}

}  // namespace

ChordEstimate estimate_chords(const core::Curve& curve, double tolerance) {
  const Normalised scaled = normalised(curve, tolerance);
  const DensityTable table = density_table(scaled.curve);
  return {table.cumulative.back() / std::sqrt(8.0 * scaled.tolerance), table.work};
}

namespace {

/// The march of flatten_parameters on a curve whose density table is known.
std::vector<double> march(const core::Curve& curve, const DensityTable& table, double tolerance,
                          core::WorkBudget& budget) {
  assert(curve.degree() >= 1 && tolerance > 0.0);
  const double root = std::sqrt(8.0 * tolerance);
  const double total = table.cumulative.back();
  const double margin = rounding_margin(curve);
  const double slack = outline_tuning::kChordSlack;
  const std::span<const Point2> points = curve.points();
  const auto F = [&](double t) {
    const double cells = static_cast<double>(table.cumulative.size() - 1);
    const double x = t * cells;
    const auto k = std::min(static_cast<std::size_t>(x), table.cumulative.size() - 2);
    return table.cumulative[k] +
           (x - static_cast<double>(k)) * (table.cumulative[k + 1] - table.cumulative[k]);
  };

  std::vector<double> vertices{0.0};
  while (vertices.back() < 1.0) {
    const double a = vertices.back();
    // The first try: the rest of the integral spread evenly over the chords it needs.
    const double rest = std::max(0.0, total - F(a));
    const double chords_left = std::max(1.0, std::ceil(rest / root));
    double b = chords_left <= 1.0 ? 1.0 : parameter_of(table.cumulative, F(a) + rest / chords_left);
    if (!(b > a)) b = std::min(1.0, a + (1.0 - a) / chords_left);
    // The bracket: lo the farthest certified end (a when none yet) with its distance, hi the
    // nearest end found too far (none yet: above 1) with its distance.
    double lo = a, lo_distance = 0.0;
    double hi = 2.0, hi_distance = 0.0;
    int probes = 0;
    int bracketed_tries = 0;
    for (;;) {
      const ChordCheck check = check_chord(points, a, b, tolerance, margin);
      if (!budget.spend(check.work)) return {};
      if (check.within && b > lo) {
        lo = b;
        lo_distance = check.upper;
        // A failure below a farther certified end says nothing about what lies beyond it.
        if (hi < lo) hi = 2.0;
      } else if (!check.within && b < hi && b > lo) {
        hi = b;
        hi_distance = check.upper;
      }
      if (lo > a && (lo == 1.0 || lo_distance >= (1.0 - slack) * tolerance)) {
        // Long enough. Past an inflection the distance can fall again as the chord turns
        // with the curve (it need not grow with the step): longer chords are tried first,
        // each kProbeFactor times the step of the one before; one that is certified becomes
        // lo, and the march goes on from it.
        if (probes >= outline_tuning::kProbes) break;
        b = std::min(1.0, a + (lo - a) * std::pow(outline_tuning::kProbeFactor, probes + 1));
        ++probes;
        if (!(b > lo)) break;
        continue;
      }
      // The tries are counted once the longest chord is bracketed; growing (nothing too far
      // yet) at least doubles the step each try, so it ends within log2(1 / step) tries.
      if (hi <= 1.0 && ++bracketed_tries >= outline_tuning::kMarchTries && lo > a) break;
      double next = 0.0;
      if (hi > 1.0) {
        // Nothing too far yet: the square law from lo, aimed a quarter of the slack short of
        // the tolerance, the step growing between 2 and 4 times.
        const double distance = std::max(lo_distance, 1e-3 * tolerance);
        next = std::min(
            1.0, a + (lo - a) * std::clamp(std::sqrt(tolerance / distance) * (1.0 - 0.25 * slack),
                                           2.0, 4.0));
      } else if (lo > a) {
        // Between a certified end and one too far: the secant of the distance through both,
        // aimed at half the slack below the tolerance, kept inside the bracket; every other
        // try halves the bracket instead, so a distance that jumps (a sharp turn just past
        // lo) cannot hold the secant to small steps.
        const double target = (1.0 - 0.5 * slack) * tolerance;
        const double rise = hi_distance - lo_distance;
        const double w =
            rise > 0.0 && bracketed_tries % 2 == 1 ? (target - lo_distance) / rise : 0.5;
        next = lo + (hi - lo) * std::clamp(w, 0.05, 0.95);
      } else {
        // Only too far so far: the square law down from hi (halving where the check could
        // not decide, its distance then being about the tolerance).
        const double shrink =
            hi_distance > tolerance
                ? std::min(0.9, std::sqrt(tolerance / hi_distance) * (1.0 - 0.25 * slack))
                : 0.5;
        next = a + (hi - a) * shrink;
      }
      if (!(next > lo) || !(next < hi) || next == b) {
        if (lo > a) break;
        // No double strictly between a and the chord's end: the tolerance is below the
        // rounding the precondition excludes; report it as the budget's end.
        budget.exhaust();
        return {};
      }
      b = next;
    }
    vertices.push_back(lo);
  }
  return vertices;
}

}  // namespace

std::vector<double> flatten_parameters(const core::Curve& curve, double tolerance,
                                       core::WorkBudget& budget) {
  const Normalised scaled = normalised(curve, tolerance);
  const DensityTable table = density_table(scaled.curve);
  if (!budget.spend(table.work)) return {};
  return march(scaled.curve, table, scaled.tolerance, budget);
}

Flattening flatten(const core::Curve& curve, const FlattenOptions& options,
                   core::WorkBudget& budget) {
  path::Path single;
  single.segments.push_back(curve);
  single.subpaths.push_back({0, 1, curve.front() == curve.back() && curve.degree() >= 1});
  return flatten(single, options, budget);
}

Flattening flatten(const path::Path& path, const FlattenOptions& options,
                   core::WorkBudget& budget) {
  Flattening result;
  double estimate = static_cast<double>(path.subpaths.size());
  std::vector<Normalised> scaled;
  std::vector<DensityTable> tables;
  scaled.reserve(path.segments.size());
  tables.reserve(path.segments.size());
  for (const core::Curve& segment : path.segments) {
    scaled.push_back(normalised(segment, options.tolerance));
    tables.push_back(density_table(scaled.back().curve));
    const double root = std::sqrt(8.0 * scaled.back().tolerance);
    estimate += std::max(1.0, std::ceil(tables.back().cumulative.back() / root));
    if (!budget.spend(tables.back().work)) return result;
  }
  result.estimated_count = estimate;
  if (estimate > static_cast<double>(options.max_vertices)) {
    result.status = FlattenStatus::too_many_vertices;
    return result;
  }

  for (const path::Subpath& subpath : path.subpaths) {
    std::vector<PolylineVertex> polyline;
    for (std::size_t k = subpath.first_segment; k < subpath.first_segment + subpath.segment_count;
         ++k) {
      const core::Curve& segment = path.segments[k];
      const std::vector<double> parameters =
          march(scaled[k].curve, tables[k], scaled[k].tolerance, budget);
      if (budget.exhausted()) {
        result.polylines.clear();
        return result;
      }
      // A segment after the first starts at the previous one's end: that vertex is listed.
      const std::size_t first = k == subpath.first_segment ? 0 : 1;
      for (std::size_t j = first; j < parameters.size(); ++j) {
        const double t = parameters[j];
        polyline.push_back({k, t, core::evaluate(segment, t)});
      }
      result.count += parameters.size() - first;
      if (result.count > options.max_vertices) {
        result.status = FlattenStatus::too_many_vertices;
        result.polylines.clear();
        return result;
      }
    }
    result.polylines.push_back(std::move(polyline));
  }
  return result;
}

}  // namespace bezier::outline
