#pragma once
// What the peers' region answers are checked against (tests/bench/lib2geom/region_cases.cpp,
// tests/bench/peers/): for a pair of operands and an operation, our certified result's area,
// and points at which membership in the result is decided by definition, op(in a, in b),
// from our certified winding numbers of the operands (core/region/winding.hpp), not from our
// boolean result.
//
// Sample points: a 40 x 40 grid over the operands' box widened by 5 % on each side, moved
// off the grid's symmetry (fractions 0.3183 and 0.5772 of a cell), keeping only the points
// farther than kClearance of the box's diagonal from both boundaries (so that a float32
// peer's rounding cannot move a boundary across a point). The distance is to the polylines
// through 257 points of each segment (the sagitta of those chords is far below kClearance).
//
// Area: a peer's result area (Green's theorem on its curves) differs from ours when
// |area - ours| > kAreaTolerance of the box's area.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/base/curve.hpp"
#include "core/curve/evaluate.hpp"
#include "core/region/boolean.hpp"
#include "core/region/winding.hpp"

namespace bezier::bench {

inline constexpr double kClearance = 1e-3;
inline constexpr double kAreaTolerance = 1e-6;
inline constexpr std::int64_t kTruthWork = 1000000000;

inline constexpr region::BooleanOperation kCaseOperations[] = {
    region::BooleanOperation::union_, region::BooleanOperation::intersection,
    region::BooleanOperation::difference, region::BooleanOperation::xor_};

inline const char* operation_name(region::BooleanOperation op) {
  switch (op) {
    case region::BooleanOperation::union_: return "union";
    case region::BooleanOperation::intersection: return "intersection";
    case region::BooleanOperation::difference: return "difference";
    case region::BooleanOperation::xor_: return "xor";
    case region::BooleanOperation::simplify: return "simplify";
  }
  return "?";
}

struct Box {
  double x_min = INFINITY, y_min = INFINITY, x_max = -INFINITY, y_max = -INFINITY;
  void add(core::Point2 p) {
    x_min = std::min(x_min, p.x), x_max = std::max(x_max, p.x);
    y_min = std::min(y_min, p.y), y_max = std::max(y_max, p.y);
  }
  [[nodiscard]] double diagonal() const { return std::hypot(x_max - x_min, y_max - y_min); }
  [[nodiscard]] double area() const { return (x_max - x_min) * (y_max - y_min); }
};

struct SamplePoint {
  core::Point2 p;
  bool in_a = false, in_b = false;
};

struct CaseTruth {
  Box box;
  std::vector<SamplePoint> points;
  /// Our result's area and status per kCaseOperations entry.
  std::vector<double> areas;
  std::vector<region::BooleanStatus> statuses;
};

/// Squared distance from p to the segment [a, b].
inline double segment_distance2(core::Point2 p, core::Point2 a, core::Point2 b) {
  const core::Point2 d = b - a, w = p - a;
  const double len2 = d.x * d.x + d.y * d.y;
  double t = len2 > 0 ? (w.x * d.x + w.y * d.y) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const core::Point2 e = w - t * d;
  return e.x * e.x + e.y * e.y;
}

inline CaseTruth case_truth(const region::Region& a, const region::Region& b) {
  CaseTruth truth;
  std::vector<std::pair<core::Point2, core::Point2>> chords;
  for (const region::Region* r : {&a, &b}) {
    for (const core::Curve& c : r->path.segments) {
      core::Point2 prev = core::evaluate(c, 0.0);
      truth.box.add(prev);
      for (const core::Point2 q : c.points()) truth.box.add(q);
      for (int k = 1; k <= 256; ++k) {
        const core::Point2 next = core::evaluate(c, k / 256.0);
        chords.emplace_back(prev, next);
        prev = next;
      }
    }
  }
  Box grid = truth.box;
  const double wx = grid.x_max - grid.x_min, wy = grid.y_max - grid.y_min;
  grid.x_min -= 0.05 * wx, grid.x_max += 0.05 * wx, grid.y_min -= 0.05 * wy, grid.y_max += 0.05 * wy;
  const double clearance = kClearance * truth.box.diagonal();
  const region::RegionWinding wa(a), wb(b);
  for (int i = 0; i < 40; ++i) {
    for (int j = 0; j < 40; ++j) {
      const core::Point2 p{grid.x_min + (grid.x_max - grid.x_min) * (i + 0.3183) / 40,
                           grid.y_min + (grid.y_max - grid.y_min) * (j + 0.5772) / 40};
      double nearest = INFINITY;
      for (const auto& [s, e] : chords) nearest = std::min(nearest, segment_distance2(p, s, e));
      if (nearest <= clearance * clearance) continue;
      bezier::core::WorkBudget work(kTruthWork);
      const auto in_a = wa.at(p, work);
      work = bezier::core::WorkBudget(kTruthWork);
      const auto in_b = wb.at(p, work);
      if (!in_a || !in_b || in_a->boundary || in_b->boundary) continue;
      truth.points.push_back(
          {p, region::fills(a.fill_rule, in_a->winding), region::fills(b.fill_rule, in_b->winding)});
    }
  }
  for (const region::BooleanOperation op : kCaseOperations) {
    const region::BooleanResult r = region::boolean_operation(op, a, b, kTruthWork);
    truth.areas.push_back(r.area);
    truth.statuses.push_back(r.status);
  }
  return truth;
}

/// The signed area of a Bézier curve of any degree under Green's theorem,
/// (1/2) ∫ (x y' - y x') dt, from its control points in closed form:
/// ∫ B_i^n B_j^(n-1) dt = C(n, i) C(n-1, j) / (2n C(2n-1, i+j)).
template <class Points>
double green_area(const Points& p) {
  const int n = static_cast<int>(p.size()) - 1;
  if (n < 1) return 0.0;
  const auto binomial = [](int m, int k) {
    double r = 1;
    for (int q = 1; q <= k; ++q) r = r * (m - k + q) / q;
    return r;
  };
  double sum = 0;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j < n; ++j) {
      const double w = binomial(n, i) * binomial(n - 1, j) / (2.0 * n * binomial(2 * n - 1, i + j));
      const double dx = p[j + 1].x - p[j].x, dy = p[j + 1].y - p[j].y;
      sum += w * n * (p[i].x * dy - p[i].y * dx);
    }
  }
  return 0.5 * sum;
}

}  // namespace bezier::bench
