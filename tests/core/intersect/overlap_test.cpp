// Overlaps (overlap.hpp): what is one and what is not, in both orders of the curves.
// Expected answers follow from closed forms and exact rationals.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "core/base/curve.hpp"
#include "core/curve/evaluate.hpp"
#include "core/intersect/intersect.hpp"
#include "tests/support/exact.hpp"
#include "tests/support/intersection_checks.hpp"

namespace bezier::core {
namespace {

using test::covered;
using test::exact_point;
using test::expect_intersection_contract;
using test::expect_no_common_point;
using test::expect_one_exact_end_root;
using test::for_every_option;
using test::on_parabola;
using test::RationalPoint;

// The curve g starts on the segment f, at
// x = 0x1.3p-23, and leaves it at an angle of 2^-22 (g's slope 2^-19 / (8 + 0x1.3p-23)). A
// direction tolerance coarser than that angle would call the start an overlap in one order
// and a crossing in the other. Two distinct lines cross once: at f(t) = g(0), t = 0x1.3p-29
// exactly, transversally, in both orders.
TEST(Overlap, SwappingTheCurvesGivesTheSameKindOfAnswer) {
  const Curve f({{0.0, 0.0}, {64.0, 0.0}});
  const Curve g({{0x1.3p-23, 0.0}, {-8.0, 0x1p-19}});
  IntersectOptions options;
  options.tolerance = 0x1.0624dd2f1a9fcp-10;
  options.method = IntersectMethod::bezier_clipping;
  options.fat_curve_degree = 3;
  for (const bool swapped : {false, true}) {
    const IntersectionResult r = swapped ? intersect(g, f, options) : intersect(f, g, options);
    ASSERT_EQ(r.status, IntersectStatus::ok);
    EXPECT_TRUE(r.overlaps.empty());
    ASSERT_EQ(r.intersections.size(), 1u);
    EXPECT_TRUE(swapped ? covered(r, 0.0, 0x1.3p-29) : covered(r, 0x1.3p-29, 0.0));
    EXPECT_EQ(r.intersections[0].kind, IntersectionKind::transversal);
    EXPECT_TRUE(r.intersections[0].resolved);
    expect_intersection_contract(r, options.tolerance);
  }
}

// The curve g(s) = 0x1.80200021p-2 (1 - s)^3
// is within the overlap tolerance of a point for s near 1, so "g on [0.99992, 1] = f at t = 0"
// passed the overlap verification in one order: an overlap of width 0 in t; nothing in the
// other. The only root is the exact end root f(0) = g(1).
TEST(Overlap, FlatEndIsNoOverlapOfWidthZero) {
  const Curve f({{0.0, 0.0}, {-0x1.cp+2, 0x1p+2}, {-0x1p+2, 0x1p+3}, {-0x1p+26, 0x1p-29}});
  const Curve g({{0x1.80200021p-2, 0.0}, {0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}});
  IntersectOptions options;
  options.tolerance = 0x1.12e0be826d695p-30;
  for (const bool swapped : {false, true}) {
    const IntersectionResult r = swapped ? intersect(g, f, options) : intersect(f, g, options);
    ASSERT_EQ(r.status, IntersectStatus::ok);
    EXPECT_TRUE(r.overlaps.empty());
    ASSERT_EQ(r.intersections.size(), 1u);
    EXPECT_TRUE(swapped ? covered(r, 1.0, 0.0) : covered(r, 0.0, 1.0));
  }
}

TEST(Overlap, ACurveTheSizeOfAnotherCurvesRoundingIsNoOverlap) {
  // g runs from (1, 0) to (0, 0) along the x axis as (1 - s)^4 (an improper curve: it
  // factors through (1 - s)^2); f starts at (0, 0) and reaches 2^27. Near its start f
  // stays within 2^-40 of the frame (f's size) of g for t up to 9e-5, but it leaves at
  // the angle of (-1, -1/2) to g's direction: no overlap. The overlap tolerance taken
  // relative to the frame alone let g, 2^-27 of it, pass in one order.
  const Curve f(
      {{0x0p+0, 0x0p+0}, {-0x1.ff006bfc6cp-1, -0x1.ff006bfc6cp-2}, {0x1p+27, 0x1.555555554554p+9}});
  const Curve g({{1.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}});
  const IntersectionResult a = intersect(f, g), b = intersect(g, f);
  EXPECT_TRUE(a.overlaps.empty());
  EXPECT_TRUE(b.overlaps.empty());
  EXPECT_EQ(a.status, b.status);
}

TEST(Overlap, ACurveComingWithin2eMinus9OfAnotherDoesNotMeetIt) {
  // f = (2^-9 t (1 - t), 139264 (1 - t)^2) has x >= 0 on [0, 1], zero only at its ends
  // (0, 139264) and (0, 0). g lies on x = 0 with y = a (1 - s)^2 + c s^2, a = 0x1.fap-30,
  // c = 0x1.8ffep-14, never below a c / (a + c) > 0: it misses both of f's ends, so the
  // curves do not meet. With the frame's tolerance (f's size, 2^17) both orders answered
  // two overlaps.
  const Curve f({{0.0, 0x1.1p+17}, {0x1p-10, 0.0}, {0.0, 0.0}});
  const Curve g({{0.0, 0x1.fap-30}, {0.0, 0.0}, {0.0, 0x1.8ffep-14}});
  for (const bool swapped : {false, true}) {
    const IntersectionResult r = swapped ? intersect(g, f) : intersect(f, g);
    EXPECT_EQ(r.status, IntersectStatus::ok);
    EXPECT_TRUE(r.overlaps.empty()) << "swapped " << swapped;
    EXPECT_TRUE(r.intersections.empty()) << "swapped " << swapped;
  }
}

TEST(Overlap, AnOverlapReachesTheEndPointTheCurvesShare) {
  // Two quartics with the same first four control points, the last one's y differing by
  // 2^-38 (1e-13 of their size): one overlap of the whole curves, to within the tolerance.
  // They start at (0, 0) bit for bit, so the answer must contain (0, 0); an overlap end pinned
  // by Newton's method alone can stop just short of it, and the exact end root must then
  // not be dropped as lying on the overlap.
  std::vector<Point2> points = {{0x0p+0, 0x0p+0},
                                {0x0p+0, 0x1.801090201027fp-31},
                                {-0x1p+0, 0x1.801090201027fp-31},
                                {-0x1.cp+2, -0x1.f6p+7},
                                {-0x1.8p+2, 0x1.1010704010204p+4}};
  const Curve f(points);
  points[4].y = 0x1.1010704010606p+4;
  const Curve g(points);
  for (const bool swapped : {false, true}) {
    const IntersectionResult r = swapped ? intersect(g, f) : intersect(f, g);
    ASSERT_EQ(r.status, IntersectStatus::ok);
    ASSERT_EQ(r.overlaps.size(), 1u) << "swapped " << swapped;
    EXPECT_TRUE(r.intersections.empty()) << "swapped " << swapped;
    EXPECT_TRUE(covered(r, 0.0, 0.0)) << "swapped " << swapped;
  }
}

TEST(Overlap, AnOverlapWithinRoundingOfAPointHidesNoCrossing) {
  // f starts at the origin, g at (0, 2.08e-8): f's third control point (1.04e9, 30464) sets
  // the working scale, next to which both starts are within rounding of the origin, and both
  // orders report that as an overlap (f on [0, 9.5e-10] with g on [0, 5.4e-6]). f crosses g's
  // parabola between t_lo and t_hi (a sign change of its implicit equation at f's exact
  // points). There f's x is positive and below 32, and f's y below g's first point y0: on g,
  // x = 32 s^2 and y = y0 (1 - s)^2, so the crossing has 0 < s < 1 (about 0.0047). An
  // overlap's map verified only on tiny pieces must not be taken to hold on the whole
  // square, or it hides that crossing in the order (g, f). Subdivision runs into the work
  // cap in both orders: halving cannot separate the two starts, within rounding of each
  // other, outside the overlap's own box.
  using bezier::test::Rational;
  const Curve f({{0x0p+0, 0x0p+0}, {-0x1.fc03ff92e794p-1, 0x1.6540001p-26},
                 {0x1.f0000ed34f583p+29, 0x1.dcp+14}});
  const Curve g({{0x0p+0, 0x1.6540000fffffep-26}, {0x0p+0, 0x0p+0}, {0x1.ffffff8084p+4, 0x0p+0}});
  const double t_lo = 8.2e-7, t_hi = 8.25e-7;
  ASSERT_LT(on_parabola(g, exact_point(f, t_lo)).sign() * on_parabola(g, exact_point(f, t_hi)).sign(),
            0);
  for (const double t : {t_lo, t_hi}) {
    const RationalPoint p = exact_point(f, t);
    ASSERT_GT(p[0], Rational(0));
    ASSERT_LT(p[0], Rational(32));
    ASSERT_LT(p[1], Rational(g[0].y));
  }
  for_every_option(f, g, 0x1.19799812dea11p-40,
                   [&](const IntersectionResult& r, const IntersectOptions& options, bool swapped) {
                     // A capped search (subdivision) may say nothing; an answer must hold the
                     // crossing.
                     if (options.method == IntersectMethod::subdivision &&
                         r.status == IntersectStatus::work_cap_reached) {
                       return;
                     }
                     ASSERT_EQ(r.status, IntersectStatus::ok);
                     bool crossing = false;
                     for (const Intersection& x : r.intersections) {
                       const ParamInterval t = swapped ? x.s_interval : x.t_interval;
                       crossing = crossing || (t.lo <= t_hi && t_lo <= t.hi);
                     }
                     EXPECT_TRUE(crossing);
                     expect_intersection_contract(r, options.tolerance);
                   });
}

TEST(Overlap, TwoEndsWithinRoundingOfEachOtherAreNoOverlap) {
  // f, 5e7 tall, ends at (a, a), a = 0x1.d9d9d9d9d9dap-3; g, 0.03 long, ends 3e-9 from there.
  // Next to f's scale both end pieces are within rounding of a point, and the order (f, g)
  // reported them as an overlap, the order (g, f) not. Two parabolas share at most four
  // points unless they are the same conic, and g's ends are off f's (the sign of f's implicit
  // equation, in rationals): there is no overlap. Both orders must say so and report the
  // same crossings, mirrored.
  using bezier::test::Rational;
  const double a = 0x1.d9d9d9d9d9dap-3;
  const Curve f({{0.0, -0x1.8p+25}, {0.0, 0x1.d9d5f639d9dap-3}, {a, a}});
  const Curve g({{0x1.d9d9d9d999dap-3, 0x1.99d9d9d9d9dap-3},
                 {0x1.d9d9d9d9d9dap-3, 0x1.d9d9d9d9d606p-3},
                 {0x1.d9d9d14p-3, 0x1.d9d9d0104011p-3}});
  ASSERT_NE(on_parabola(f, exact_point(g, 0.0)).sign(), 0);
  ASSERT_NE(on_parabola(f, exact_point(g, 1.0)).sign(), 0);
  for (const IntersectMethod method : {IntersectMethod::hybrid, IntersectMethod::bezier_clipping}) {
    IntersectOptions options;
    options.method = method;
    options.fat_curve_degree = 2;
    const IntersectionResult r = intersect(f, g, options), w = intersect(g, f, options);
    ASSERT_EQ(r.status, IntersectStatus::ok);
    ASSERT_EQ(w.status, IntersectStatus::ok);
    EXPECT_TRUE(r.overlaps.empty());
    EXPECT_TRUE(w.overlaps.empty());
    ASSERT_EQ(r.intersections.size(), w.intersections.size());
    for (const Intersection& x : r.intersections) {
      bool mirrored = false;
      for (const Intersection& y : w.intersections) {
        mirrored =
            mirrored || (x.t_interval.lo <= y.s_interval.hi && y.s_interval.lo <= x.t_interval.hi &&
                         x.s_interval.lo <= y.t_interval.hi && y.t_interval.lo <= x.s_interval.hi);
      }
      EXPECT_TRUE(mirrored) << "method " << static_cast<int>(method) << " t " << x.t;
    }
    expect_intersection_contract(r, options.tolerance);
    expect_intersection_contract(w, options.tolerance);
  }
}

}  // namespace
}  // namespace bezier::core
