// Tests of core/outline/loose_curve.hpp: the certified test that a curve's radius of
// curvature exceeds R everywhere and its derivative has no zero.
//
// Independent checks: where the test says loose, the parallel curves at ±R have no cusp
// (offset_cusps, an exact root isolation), B' has no zero (stationary_points), and R |κ(t)| < 1
// at dense samples (κ from derivatives_at); where a sample has R |κ| >= 1, or B' vanishes, the
// test must say no. A circular arc (radius about 1) checks the parts: the whole arc's bound
// proves only R < 1/2, its halves prove R = 0.8, and no R beyond the radius is proved.

#include "core/outline/loose_curve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/curve/derivative.hpp"
#include "core/outline/offset_cusps.hpp"
#include "core/outline/tangent_limits.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::outline {
namespace {

using core::Curve;
using core::Point2;

bool loose(const Curve& curve, double reach) {
  ControlPoints h1, h2;
  hodograph_into(curve.points(), h1);
  hodograph_into(h1, h2);
  return loose_everywhere(h1, h2, reach);
}

/// The largest R |κ(t)| at 2001 uniform t (infinite where B' vanishes at a sample).
double largest_reach_curvature(const Curve& curve, double reach) {
  double largest = 0.0;
  for (int i = 0; i <= 2000; ++i) {
    const auto k = core::derivatives_at(curve, i / 2000.0, 2);
    const double speed = core::length(k[0]);
    if (!(speed > 0.0)) return INFINITY;
    largest = std::max(largest, reach * std::fabs(core::cross(k[0], k[1])) / (speed * speed * speed));
  }
  return largest;
}

TEST(LooseCurve, CircularArcProvedByItsPartsUpToItsRadiusOnly) {
  // A quarter circle of radius 1 (the usual cubic, its radius within 3e-4 of 1).
  constexpr double k = 0.5522847498307936;
  const Curve arc({{1, 0}, {1, k}, {k, 1}, {0, 1}});
  EXPECT_TRUE(loose(arc, 0.4));
  EXPECT_TRUE(loose(arc, 0.8));  // beyond the whole arc's bound (about 1/2): by its parts
  EXPECT_FALSE(loose(arc, 1.01));
  EXPECT_FALSE(loose(arc, 5.0));
  EXPECT_LT(largest_reach_curvature(arc, 0.8), 1.0);
  EXPECT_GT(largest_reach_curvature(arc, 1.01), 1.0);
}

TEST(LooseCurve, ZeroOfTheDerivativeIsNeverLoose) {
  // B'(1/2) = 0 (a cusp of B itself: B' has the control points (3, 3), (-3, 0), (3, -3)),
  // a curve that turns back along a line, and one whose B' vanishes at its start.
  EXPECT_FALSE(loose(Curve({{0, 0}, {1, 1}, {0, 1}, {1, 0}}), 1e-6));
  EXPECT_FALSE(loose(Curve({{0, 0}, {2, 0}, {1, 0}}), 1e-6));
  EXPECT_FALSE(loose(Curve({{0, 0}, {0, 0}, {1, 1}, {2, 0}}), 1e-6));
}

TEST(LooseCurve, LinesAreLooseAtAnyReach) {
  EXPECT_TRUE(loose(Curve({{0, 0}, {3, 1}}), 1e9));
  EXPECT_FALSE(loose(Curve({{1, 1}, {1, 1}}), 1.0));
}

TEST(LooseCurve, RandomCurvesLooseOnlyWhereNoCuspOrZeroExists) {
  test::Mulberry32 rng(31);
  int proved = 0, refused = 0;
  for (int i = 0; i < 400; ++i) {
    std::vector<Point2> points;
    const int degree = 2 + i % 3;
    for (int j = 0; j <= degree; ++j) points.push_back({rng.uniform(-1, 1), rng.uniform(-1, 1)});
    const Curve curve(points);
    for (const double reach : {0.01, 0.05, 0.2}) {
      const double sampled = largest_reach_curvature(curve, reach);
      if (loose(curve, reach)) {
        ++proved;
        EXPECT_LT(sampled, 1.0) << i << " " << reach;
        EXPECT_TRUE(offset_cusps(curve, reach).empty()) << i << " " << reach;
        EXPECT_TRUE(offset_cusps(curve, -reach).empty()) << i << " " << reach;
        EXPECT_TRUE(stationary_points(curve).empty()) << i << " " << reach;
      } else if (sampled >= 1.0) {
        ++refused;
      }
    }
  }
  // Both outcomes occur (the test is neither always nor never true here).
  EXPECT_GT(proved, 100);
  EXPECT_GT(refused, 20);
}

}  // namespace
}  // namespace bezier::outline
