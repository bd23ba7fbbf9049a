// core/intersect/refine.hpp: refine_contact converges to crossings built into the curves
// (a point of f chosen exactly, g drawn through it), to a tangency where the curvatures
// differ, and with one parameter free to the other's exact value; an exact root is kept.
#include "core/intersect/refine.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/intersect/kind.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

/// The threshold intersect passes (KindTolerances' default).
constexpr double kTangentSine = KindTolerances{}.tangent_sine;

Contact contact(ParamInterval t, ParamInterval s) {
  Contact c;
  c.t = t;
  c.s = s;
  return c;
}

struct Pair {
  WorkingFrame frame;
  WorkingCurve f, g;
};

Pair working_pair(const Curve& f, const Curve& g) {
  const WorkingFrame frame = working_frame(f, g);
  return {frame, to_working(f, frame), to_working(g, frame)};
}

TEST(Refine, ConvergesToACrossingBuiltIntoTheCurves) {
  // f(1/2) = (P0 + 3 P1 + 3 P2 + P3) / 8 = (3/2, 1/2); g runs from (1, 2) to (5/2, -5/2) and
  // is there at s = 1/3. The curves cross at an angle (f'(1/2) = 3/4 (P3 + P2 - P1 - P0) =
  // (3, -3/2) against g' = (3/2, -9/2)), so Newton's method reaches (1/2, 1/3) to a few ulps.
  const Curve f({{0.0, 0.0}, {1.0, 2.0}, {2.0, -1.0}, {3.0, 1.0}});
  const Curve g({{1.0, 2.0}, {2.5, -2.5}});
  const Pair p = working_pair(f, g);
  const Refinement r = refine_contact(p.f, p.g, contact({0.4, 0.6}, {0.25, 0.45}), false, false, kTangentSine);
  EXPECT_NEAR(r.t, 0.5, 4 * 0x1p-53);
  EXPECT_NEAR(r.s, 1.0 / 3.0, 4 * 0x1p-53);
  EXPECT_FALSE(r.tangency_system);
  EXPECT_GT(r.iterations, 0);
  ASSERT_TRUE(r.f_at_t.has_value());
  ASSERT_TRUE(r.g_at_s.has_value());
  for (const PointAndTangent& at : {*r.f_at_t, *r.g_at_s}) {
    const Point2 point = from_working(at.point, p.frame);
    EXPECT_NEAR(point.x, 1.5, 8 * 0x1p-53);
    EXPECT_NEAR(point.y, 0.5, 8 * 0x1p-53);
  }
}

TEST(Refine, RandomCrossingsThroughAPointOfF) {
  // Control points on the grid of 1/8 in [-4, 4]: f(1/2) is exact in doubles, and g, the
  // segment from a random A to 2 f(1/2) - A, meets it there at s = 1/2. Pairs crossing at a
  // sine below 1/8 are skipped (near-tangencies converge more slowly, not to this bound).
  // Newton's method with double-double residuals ends within a few ulps of (1/2, 1/2).
  test::Mulberry32 rng(21);
  const auto grid = [&] { return std::floor(rng.uniform(-32, 32)) / 8; };
  int crossings = 0;
  for (int trial = 0; trial < 300; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    std::vector<Point2> pts(4);
    for (Point2& q : pts) q = {grid(), grid()};
    const Point2 middle = {(pts[0].x + 3 * pts[1].x + 3 * pts[2].x + pts[3].x) / 8,
                           (pts[0].y + 3 * pts[1].y + 3 * pts[2].y + pts[3].y) / 8};
    const Point2 a = {grid(), grid()};
    const Point2 b = {2 * middle.x - a.x, 2 * middle.y - a.y};
    // f'(1/2) = 3/4 (P3 + P2 - P1 - P0), g' = B - A.
    const Point2 df = {0.75 * (pts[3].x + pts[2].x - pts[1].x - pts[0].x),
                       0.75 * (pts[3].y + pts[2].y - pts[1].y - pts[0].y)};
    const Point2 dg = {b.x - a.x, b.y - a.y};
    if (!(sine_between(df, dg) > 0.125)) continue;
    ++crossings;
    const Pair p = working_pair(Curve(pts), Curve({a, b}));
    const double w = 0x1p-12;
    const Refinement r =
        refine_contact(p.f, p.g, contact({0.5 - w, 0.5 + 2 * w}, {0.5 - 3 * w, 0.5 + w}), false, false, kTangentSine);
    EXPECT_NEAR(r.t, 0.5, 1e-15);
    EXPECT_NEAR(r.s, 0.5, 1e-15);
    EXPECT_FALSE(r.tangency_system);
  }
  EXPECT_GT(crossings, 150);
}

TEST(Refine, ATangencyIsFoundByTheTangencySystem) {
  // The parabola y = x^2 ((-1, 1), (0, -1), (1, 1)) touches the line y = 0 from (-1, 0) to
  // (1, 0) at the origin, t = s = 1/2; the curvatures differ (2 and 0). Newton's method
  // starts off the contact at the centre of the intervals, (0.525, 0.45).
  const Curve f({{-1.0, 1.0}, {0.0, -1.0}, {1.0, 1.0}});
  const Curve g({{-1.0, 0.0}, {1.0, 0.0}});
  const Pair p = working_pair(f, g);
  const Refinement r = refine_contact(p.f, p.g, contact({0.45, 0.6}, {0.3, 0.6}), false, false, kTangentSine);
  EXPECT_TRUE(r.tangency_system);
  EXPECT_NEAR(r.t, 0.5, 1e-15);
  EXPECT_NEAR(r.s, 0.5, 1e-15);
}

TEST(Refine, WithOneParameterFreeOnlyTheOtherIsSolvedFor) {
  // f is the point (3/2, 1/2); g passes through it at s = 1/3 (as above).
  const Curve f({{1.5, 0.5}, {1.5, 0.5}});
  const Curve g({{1.0, 2.0}, {2.5, -2.5}});
  const Pair p = working_pair(f, g);
  const Refinement r = refine_contact(p.f, p.g, contact({0.0, 1.0}, {0.2, 0.5}), true, false, kTangentSine);
  EXPECT_EQ(r.t, 0.0);
  EXPECT_NEAR(r.s, 1.0 / 3.0, 4 * 0x1p-53);
  // The same with the roles exchanged.
  const Pair q = working_pair(g, f);
  const Refinement rq = refine_contact(q.f, q.g, contact({0.2, 0.5}, {0.0, 1.0}), false, true, kTangentSine);
  EXPECT_EQ(rq.s, 0.0);
  EXPECT_NEAR(rq.t, 1.0 / 3.0, 4 * 0x1p-53);
}

TEST(Refine, AnExactRootIsReturnedAsItIs) {
  const Curve f({{0.0, 0.0}, {1.0, 1.0}});
  const Curve g({{1.0, 1.0}, {2.0, 0.0}});
  const Pair p = working_pair(f, g);
  Contact c = contact({1.0 - 0x1p-30, 1.0}, {0.0, 0x1p-30});
  c.exact = true;
  c.exact_root = {1.0, 0.0};
  const Refinement r = refine_contact(p.f, p.g, c, false, false, kTangentSine);
  EXPECT_EQ(r.t, 1.0);
  EXPECT_EQ(r.s, 0.0);
  EXPECT_EQ(r.iterations, 0);
}

TEST(Refine, EstimatesStayInsideTheContactsIntervals) {
  // The crossing (1/2, 1/3) of the first test lies outside these intervals: the estimate is
  // clamped to them.
  const Curve f({{0.0, 0.0}, {1.0, 2.0}, {2.0, -1.0}, {3.0, 1.0}});
  const Curve g({{1.0, 2.0}, {2.5, -2.5}});
  const Pair p = working_pair(f, g);
  const Contact c = contact({0.6, 0.7}, {0.4, 0.45});
  const Refinement r = refine_contact(p.f, p.g, c, false, false, kTangentSine);
  EXPECT_TRUE(c.t.contains(r.t)) << r.t;
  EXPECT_TRUE(c.s.contains(r.s)) << r.s;
}

}  // namespace
}  // namespace bezier::core
