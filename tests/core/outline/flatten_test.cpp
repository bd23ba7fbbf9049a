// Tests of core/outline/flatten.hpp: polylines within a tolerance of a curve, economically.
//
// Everything is checked independently of the kernel's chord bound: vertices against
// evaluate(); the Hausdorff distance both ways by dense samples of the curve (distance to the
// polyline's segments) and by the nearest-point kernel from points of the polyline; counts
// against a greedy polyline and the best uniform step built here with the same dense check
// (a chord is within when its curve piece's samples are within of the chord and the chord's
// samples are within of the piece), and against the closed-form density integral of a
// parabola.

#include "core/outline/flatten.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/curve/evaluate.hpp"
#include "core/measure/nearest.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::outline {
namespace {

using core::Curve;
using core::Point2;

double distance_to_segment(Point2 p, Point2 a, Point2 b) {
  const Point2 ab = b - a;
  const double squared = core::dot(ab, ab);
  const double s = squared > 0 ? std::clamp(core::dot(p - a, ab) / squared, 0.0, 1.0) : 0.0;
  return core::length(p - (a + s * ab));
}

/// The dense check of one chord: the piece's samples to the chord, the chord's to the piece.
double chord_distance(const Curve& curve, double a, double b) {
  const Point2 pa = core::evaluate(curve, a), pb = core::evaluate(curve, b);
  double worst = 0.0;
  constexpr int kCurveSamples = 200, kChordSamples = 12;
  for (int i = 1; i < kCurveSamples; ++i) {
    const double t = a + (b - a) * i / kCurveSamples;
    worst = std::max(worst, distance_to_segment(core::evaluate(curve, t), pa, pb));
  }
  for (int i = 1; i < kChordSamples; ++i) {
    const Point2 p = pa + (static_cast<double>(i) / kChordSamples) * (pb - pa);
    worst = std::max(worst, core::nearest(curve, p, a, b).distance);
  }
  return worst;
}

/// Vertices of the greedy polyline: from each vertex the farthest end (binary search on t)
/// whose chord passes the dense check.
int greedy_vertices(const Curve& curve, double tolerance) {
  int vertices = 1;
  double a = 0.0;
  while (a < 1.0) {
    double b = 1.0;
    if (chord_distance(curve, a, 1.0) > tolerance) {
      double lo = a, hi = 1.0;
      for (int i = 0; i < 40; ++i) {
        const double mid = 0.5 * (lo + hi);
        (chord_distance(curve, a, mid) <= tolerance ? lo : hi) = mid;
      }
      b = lo;
    }
    a = b;
    ++vertices;
  }
  return vertices;
}

/// Whether n equal parameter steps all pass the dense check.
bool uniform_passes(const Curve& curve, double tolerance, int n) {
  for (int j = 0; j < n; ++j) {
    if (chord_distance(curve, static_cast<double>(j) / n, static_cast<double>(j + 1) / n) >
        tolerance)
      return false;
  }
  return true;
}

Flattening flatten_with(const Curve& curve, double tolerance) {
  FlattenOptions options;
  options.tolerance = tolerance;
  options.max_vertices = 100000;
  core::WorkBudget budget;
  return flatten(curve, options, budget);
}

std::vector<Curve> sample_curves() {
  std::vector<Curve> curves;
  test::Mulberry32 rng(31);
  for (int i = 0; i < 40; ++i) {
    std::vector<Point2> p;
    for (int k = 0; k < 4; ++k) p.push_back({rng.uniform(-1, 1), rng.uniform(-1, 1)});
    curves.emplace_back(p);
  }
  for (int i = 0; i < 2; ++i) {
    std::vector<Point2> p;
    for (int k = 0; k < 6; ++k) p.push_back({rng.uniform(-1, 1), rng.uniform(-1, 1)});
    curves.emplace_back(p);
  }
  curves.push_back(Curve({{0, 0}, {1, 1}, {0, 1}, {1, 0}}));   // a loop
  curves.push_back(Curve({{0, 0}, {1, 1}, {0, 1}, {1, 1}}));   // a cusp-like turn
  curves.push_back(Curve({{0, 0}, {2, 2}, {-1, 2}, {1, 0}}));  // a cusp at t = 1/2
  curves.push_back(Curve({{0, 0}, {1, 2}, {2, -2}, {3, 0}}));  // an S with an inflection
  curves.push_back(Curve({{0, 0}, {0.5, 1}, {1, 0}}));         // a parabola
  return curves;
}

TEST(Flatten, VerticesAreCurvePointsInOrderWithTheEnds) {
  for (const Curve& curve : sample_curves()) {
    const Flattening f = flatten_with(curve, 1e-3);
    ASSERT_EQ(f.status, FlattenStatus::ok);
    ASSERT_EQ(f.polylines.size(), 1u);
    const auto& line = f.polylines[0];
    ASSERT_GE(line.size(), 2u);
    EXPECT_EQ(line.front().t, 0.0);
    EXPECT_EQ(line.back().t, 1.0);
    EXPECT_EQ(line.front().point, curve.front());
    EXPECT_EQ(line.back().point, curve.back());
    EXPECT_EQ(f.count, line.size());
    for (std::size_t i = 0; i < line.size(); ++i) {
      EXPECT_EQ(line[i].segment, 0u);
      EXPECT_EQ(line[i].point, core::evaluate(curve, line[i].t));
      if (i > 0) {
        EXPECT_LT(line[i - 1].t, line[i].t);
      }
    }
  }
}

TEST(Flatten, HausdorffDistanceWithinToleranceBothWays) {
  for (const Curve& curve : sample_curves()) {
    for (const double tolerance : {1e-2, 1e-3, 1e-5}) {
      const Flattening f = flatten_with(curve, tolerance);
      ASSERT_EQ(f.status, FlattenStatus::ok);
      const auto& line = f.polylines[0];
      const double allowed = tolerance * (1 + 1e-9);
      // Curve to polyline: samples of every chord's piece, distance to the nearest segment.
      for (std::size_t j = 1; j < line.size(); ++j) {
        for (int i = 0; i <= 64; ++i) {
          const double t = line[j - 1].t + (line[j].t - line[j - 1].t) * i / 64;
          const Point2 p = core::evaluate(curve, t);
          double d = HUGE_VAL;
          for (std::size_t k = 1; k < line.size(); ++k)
            d = std::min(d, distance_to_segment(p, line[k - 1].point, line[k].point));
          EXPECT_LE(d, allowed) << "t " << t << " tolerance " << tolerance;
        }
      }
      // Polyline to curve: points of every chord, nearest point of the whole curve.
      for (std::size_t j = 1; j < line.size(); ++j) {
        for (int i = 1; i < 8; ++i) {
          const Point2 p = line[j - 1].point + (i / 8.0) * (line[j].point - line[j - 1].point);
          EXPECT_LE(core::nearest(curve, p, 0, 1).distance, allowed)
              << "chord " << j << " tolerance " << tolerance;
        }
      }
    }
  }
}

TEST(Flatten, AtMostATenthMoreThanGreedyAndNoMoreThanUniform) {
  for (const Curve& curve : sample_curves()) {
    for (const double tolerance : {3e-2, 1e-2, 1e-3, 1e-4}) {
      const Flattening f = flatten_with(curve, tolerance);
      ASSERT_EQ(f.status, FlattenStatus::ok);
      const auto ours = static_cast<int>(f.count);
      const int greedy = greedy_vertices(curve, tolerance);
      EXPECT_LE(ours, static_cast<int>(std::floor(1.1 * greedy)))
          << "greedy " << greedy << " tolerance " << tolerance << " first point "
          << curve.front().x;
      // No uniform step with fewer chords passes.
      for (int n = 1; n < ours - 1; ++n)
        EXPECT_FALSE(uniform_passes(curve, tolerance, n)) << n << " uniform chords, ours " << ours;
    }
  }
}

TEST(Flatten, PowerOfTwoScalingAndTranslationKeepTheParameters) {
  const Curve curve({{0, 0}, {1, 2}, {2, -2}, {3, 0}});
  const Flattening f = flatten_with(curve, 1e-3);
  for (const double s : {0x1p-20, 0x1p20}) {
    std::vector<Point2> moved;
    for (const Point2 p : curve.points()) moved.push_back(s * p);
    const Flattening g = flatten_with(Curve(moved), s * 1e-3);
    ASSERT_EQ(g.count, f.count) << s;
    for (std::size_t i = 0; i < f.count; ++i) EXPECT_EQ(g.polylines[0][i].t, f.polylines[0][i].t);
  }
  std::vector<Point2> shifted;
  for (const Point2 p : curve.points()) shifted.push_back(p + Point2{1000, -1000});
  const Flattening g = flatten_with(Curve(shifted), 1e-3);
  // Translation changes the rounding of the control points, so only the count is compared.
  EXPECT_LE(g.count, f.count + 1);
  EXPECT_GE(g.count + 1, f.count);
}

TEST(Flatten, AtTheEndsOfTheDoubleRange) {
  // Differences of these coordinates overflow (3 * 2^1023) or are subnormal: the kernel works
  // on the curve scaled by a power of two, so the parameters are the unit curve's.
  const Curve unit({{-1.5, 0}, {1.5, 1}, {0, -1.5}, {1, 1}});
  const Flattening f = flatten_with(unit, 0x1p-10);  // a power of two: exact when scaled
  ASSERT_EQ(f.status, FlattenStatus::ok);
  ASSERT_GT(f.count, 2u);
  for (const double s : {0x1p1023, 0x1p-1060}) {
    std::vector<Point2> moved;
    for (const Point2 p : unit.points()) moved.push_back(s * p);
    const Flattening g = flatten_with(Curve(moved), s * 0x1p-10);
    ASSERT_EQ(g.status, FlattenStatus::ok);
    ASSERT_EQ(g.count, f.count) << s;
    for (std::size_t i = 0; i < f.count; ++i) EXPECT_EQ(g.polylines[0][i].t, f.polylines[0][i].t);
  }
}

TEST(Flatten, LinesAndPointsGiveTwoVertices) {
  for (const Curve& line :
       {Curve({{0, 0}, {3, 1}}), Curve({{0, 0}, {1, 1.0 / 3}, {2, 2.0 / 3}, {3, 1}}),
        Curve({{2, 2}, {2, 2}, {2, 2}})}) {
    const Flattening f = flatten_with(line, 1e-6);
    ASSERT_EQ(f.status, FlattenStatus::ok);
    EXPECT_EQ(f.count, 2u);
  }
}

TEST(Flatten, CollinearCurveThatTurnsBackKeepsItsFarthestPoint) {
  // x(t) = 4t - 3t^2 on the x axis: out to x = 4/3 at t = 2/3, back to 1.
  const Curve fold({{0, 0}, {2, 0}, {1, 0}});
  const double tolerance = 1e-4;
  const Flattening f = flatten_with(fold, tolerance);
  ASSERT_EQ(f.status, FlattenStatus::ok);
  double farthest = 0.0;
  for (const PolylineVertex& v : f.polylines[0]) farthest = std::max(farthest, v.point.x);
  EXPECT_GE(farthest, 4.0 / 3.0 - tolerance);
  EXPECT_LE(farthest, 4.0 / 3.0);
}

TEST(Flatten, ParabolaCountMatchesTheDensityIntegral) {
  // B(t) = (t, a t^2) from (0,0),(1/2,0),(1,a): B' = (1, 2at), B'' = (0, 2a), so
  // |B''_⊥| = 2a / sqrt(1 + 4a^2 t^2) and the optimal chord count as ε -> 0 is
  // ∫_0^1 sqrt(|B''_⊥| / (8ε)) dt = sqrt(2a) / (2a sqrt(8ε)) ∫_0^{2a} (1 + u^2)^(-1/4) du.
  // The chord of a parabola over a step is parallel to the tangent at the step's middle and
  // stands off by exactly |B''_⊥(middle)| Δ^2 / 8, so the greedy count is this integral's
  // midpoint sum, within a chord or two of it.
  const double a = 2.0;
  const Curve parabola({{0, 0}, {0.5, 0}, {1, a}});
  // Simpson's rule on 20000 intervals for the smooth integrand (1 + u^2)^(-1/4).
  const int m = 20000;
  const double upper = 2 * a, h = upper / m;
  double integral = 0.0;
  for (int i = 0; i <= m; ++i) {
    const double weight = (i == 0 || i == m) ? 1 : (i % 2 ? 4 : 2);
    integral += weight * std::pow(1 + (i * h) * (i * h), -0.25);
  }
  integral *= h / 3;
  for (const double tolerance : {1e-4, 1e-6}) {
    const double optimal = std::sqrt(2 * a) / (2 * a) * integral / std::sqrt(8 * tolerance);
    const Flattening f = flatten_with(parabola, tolerance);
    ASSERT_EQ(f.status, FlattenStatus::ok);
    const double chords = static_cast<double>(f.count) - 1;
    EXPECT_GE(chords, std::floor(optimal) - 1) << tolerance;
    EXPECT_LE(chords, std::ceil(1.01 * optimal) + 1) << tolerance;
  }
}

TEST(Flatten, PathHasOnePolylinePerSubpathWithEverySegmentsEnds) {
  path::Path p;
  p.segments.push_back(Curve({{0, 0}, {1, 2}, {2, 0}}));
  p.segments.push_back(Curve({{2, 0}, {3, 0}}));
  p.segments.push_back(Curve({{3, 0}, {0, 0}}));
  p.segments.push_back(Curve({{5, 5}, {6, 7}, {7, 4}, {8, 5}}));
  p.subpaths.push_back({0, 3, true});
  p.subpaths.push_back({3, 1, false});
  FlattenOptions options;
  options.tolerance = 1e-3;
  core::WorkBudget budget;
  const Flattening f = flatten(p, options, budget);
  ASSERT_EQ(f.status, FlattenStatus::ok);
  ASSERT_EQ(f.polylines.size(), 2u);
  const auto& first = f.polylines[0];
  EXPECT_EQ(first.front().segment, 0u);
  EXPECT_EQ(first.front().t, 0.0);
  EXPECT_EQ(first.back().segment, 2u);
  EXPECT_EQ(first.back().t, 1.0);
  EXPECT_EQ(first.back().point, first.front().point);  // closed
  // The joints: segment 0 at t = 1 then segment 1's end (a line has no inner vertex).
  int joints = 0;
  for (std::size_t i = 0; i < first.size(); ++i) {
    if (first[i].t == 1.0) ++joints;
    EXPECT_EQ(first[i].point, core::evaluate(p.segments[first[i].segment], first[i].t));
    if (i > 0) {
      EXPECT_TRUE(first[i - 1].segment < first[i].segment ||
                  (first[i - 1].segment == first[i].segment && first[i - 1].t < first[i].t));
      EXPECT_NE(first[i].t, 0.0);  // a joint is listed once, as the earlier segment's end
    }
  }
  EXPECT_EQ(joints, 3);
  EXPECT_EQ(f.polylines[1].front().segment, 3u);
  EXPECT_EQ(f.count, first.size() + f.polylines[1].size());
}

TEST(Flatten, RefusesBeforeBuildingWhenTheEstimateIsBeyondTheLimit) {
  const Curve curve({{0, 0}, {1, 2}, {2, -2}, {3, 0}});
  FlattenOptions options;
  options.tolerance = 1e-8;
  options.max_vertices = 100;
  core::WorkBudget budget;
  const Flattening f = flatten(curve, options, budget);
  EXPECT_EQ(f.status, FlattenStatus::too_many_vertices);
  EXPECT_TRUE(f.polylines.empty());
  EXPECT_GT(f.estimated_count, 100.0);
  // The estimate is the density integral: the certified count is not far from it.
  options.max_vertices = 1000000;
  const Flattening built = flatten(curve, options, budget);
  ASSERT_EQ(built.status, FlattenStatus::ok);
  EXPECT_GE(static_cast<double>(built.count), 0.9 * f.estimated_count);
  EXPECT_LE(static_cast<double>(built.count), 1.1 * f.estimated_count);
}

TEST(Flatten, WorkCapIsReported) {
  const Curve curve({{0, 0}, {1, 2}, {2, -2}, {3, 0}});
  FlattenOptions options;
  options.tolerance = 1e-6;
  core::WorkBudget budget(1000);
  const Flattening f = flatten(curve, options, budget);
  EXPECT_TRUE(budget.exhausted());
  EXPECT_TRUE(f.polylines.empty());
}

TEST(Flatten, WhatItSpentIsEnoughAndOneUnitLessIsNot) {
  // The march's choices depend on the chord checks alone, never on the budget, so a budget
  // of exactly what an unlimited run spent gives the same polylines, and one unit less
  // runs out at the last charge.
  path::Path p;
  p.segments.push_back(Curve({{0, 0}, {1, 2}, {2, -2}, {3, 0}}));
  p.segments.push_back(Curve({{3, 0}, {4, 3}, {5, 0}}));
  p.subpaths.push_back({0, 2, false});
  FlattenOptions options;
  options.tolerance = 1e-4;
  core::WorkBudget unlimited;
  const Flattening reference = flatten(p, options, unlimited);
  ASSERT_FALSE(unlimited.exhausted());
  ASSERT_GT(unlimited.spent(), 0);

  core::WorkBudget exact(unlimited.spent());
  const Flattening again = flatten(p, options, exact);
  EXPECT_FALSE(exact.exhausted());
  EXPECT_EQ(exact.spent(), unlimited.spent());
  EXPECT_EQ(again.count, reference.count);

  core::WorkBudget short_by_one(unlimited.spent() - 1);
  const Flattening refused = flatten(p, options, short_by_one);
  EXPECT_TRUE(short_by_one.exhausted());
  EXPECT_TRUE(refused.polylines.empty());
}

}  // namespace
}  // namespace bezier::outline
