// Pairs taken the collinear way (collinear.hpp): curves on one line to within the frame's
// tolerance, tiny curves on a long one, flat ends. Expected values are exact roots and
// closed forms.

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

// Here f starts exactly where g ends; g is 2^-29 long and f 2^24, so g
// is within the working frame's line tolerance of f's line and of a point, and the pair goes the
// collinear way. g(s) = (0x1.d4p-30 (1 - s)^2, 0) meets the line x = 0 of f only at s = 1: the
// one intersection is f(0) = g(1) = (0, 0), equal bit for bit. g's positions along f's line were
// all 0, its derivative's roots a cut at s = 1/2, and the two halves gave two contacts that are
// not intersections ((0, 0) and (0, 1/2)) and not the root. The answer: one contact, estimated at the
// exact root, in both orders.
TEST(Collinear, EndPointRootOfATinyCurveIsReported) {
  const Curve f({{0.0, 0.0}, {0.0, -0x1p24}});
  const Curve g({{0x1.d4p-30, 0.0}, {0.0, 0.0}, {0.0, 0.0}});
  expect_one_exact_end_root(f, g, 0.0, 1.0);
}

// A single point exactly at an end
// of the other curve. Bézier clipping missed f(1) = (0, 0) of this cubic against the point (0, 0)
// altogether; a closed quadratic through the point (a degree-1 curve with equal points) came back
// with its root t = 0 only. End points equal bit for bit are exact roots, a point curve's
// parameter free: t = 1 (and t = 0 and 1), s in [0, 1].
TEST(Collinear, PointAtAnEndIsAnExactRoot) {
  const Curve f({{0.0, -4.0}, {-8.0, -4.0}, {-0x1.0000000000001p+2, 0.0}, {0.0, 0.0}});
  const Curve g(std::vector<Point2>{{0.0, 0.0}});
  IntersectOptions options;
  options.method = IntersectMethod::bezier_clipping;
  const IntersectionResult r = intersect(f, g, options);
  ASSERT_EQ(r.status, IntersectStatus::ok);
  ASSERT_EQ(r.intersections.size(), 1u);
  EXPECT_EQ(r.intersections[0].t, 1.0);
  EXPECT_EQ(r.intersections[0].s_interval, (ParamInterval{0.0, 1.0}));
  const IntersectionResult w = intersect(g, f, options);
  ASSERT_EQ(w.intersections.size(), 1u);
  EXPECT_EQ(w.intersections[0].s, 1.0);
  EXPECT_EQ(w.intersections[0].t_interval, (ParamInterval{0.0, 1.0}));

  const Curve closed({{0.0, 0.0}, {1.0, 0x1.01p-29}, {0.0, 0.0}});
  const Curve point({{0.0, 0.0}, {0.0, 0.0}});
  const IntersectionResult c = intersect(closed, point);
  ASSERT_EQ(c.intersections.size(), 2u);
  EXPECT_TRUE(covered(c, 0.0, 0.5));
  EXPECT_TRUE(covered(c, 1.0, 0.5));
}

// Two curves on the line y = −x, f from (1, −1) to
// (−1/2, 1/2) with P1 = P2 = P3 (f'(1) = 0) and g from (−1/2, 1/2) to (0, 0). g lies on f:
// the overlap is t in [t0, 1] (f(t0) = (0, 0): f(t) = P0 + (1 − (1 − t)^3)(P3 − P0), so
// 1 − t0 = 3^(-1/3)) with s in [0, 1] reversed, and f(1) = g(0) bit for bit. f's derivative
// has a double root at t = 1, flat around it; cutting f a little inside would stop the
// overlap short of t = 1 with stray zero-width contacts beside it, none holding (1, 0).
// The answer: the one overlap, ending exactly at (1, 0), and nothing else, in both orders.
TEST(Collinear, OverlapReachesAFlatEnd) {
  const Curve f({{1.0, -1.0}, {-0.5, 0.5}, {-0.5, 0.5}, {-0.5, 0.5}});
  const Curve g({{-0.5, 0.5}, {-0.5, 0.5}, {0.0, 0.0}, {0.0, 0.0}});
  const double t0 = 1.0 - std::cbrt(1.0 / 3.0);
  for (const bool swapped : {false, true}) {
    const IntersectionResult r = swapped ? intersect(g, f) : intersect(f, g);
    ASSERT_EQ(r.status, IntersectStatus::ok);
    EXPECT_TRUE(r.intersections.empty());
    ASSERT_EQ(r.overlaps.size(), 1u);
    const Overlap& o = r.overlaps[0];
    const ParamInterval on_f = swapped ? o.s_interval : o.t_interval;
    const ParamInterval on_g = swapped ? o.t_interval : o.s_interval;
    EXPECT_NEAR(on_f.lo, t0, 1e-12);
    EXPECT_EQ(on_f.hi, 1.0);
    EXPECT_EQ(on_g, (ParamInterval{0.0, 1.0}));
    EXPECT_TRUE(o.reversed);
    EXPECT_TRUE(swapped ? covered(r, 0.0, 1.0) : covered(r, 1.0, 0.0));
  }
}

// An estimate one subnormal step outside its
// zero-width interval. f, 2^-900 long, lies on the segment g(s) = (0, 2^64 s), from s = 3 2^-1074
// to s = 2^-964; in the working frame f's positions along the line are one number, and a midpoint
// estimate s/2 + s/2 rounds to 4 2^-1074, outside a zero-width interval at 3 2^-1074. The
// answer: f touches with all of its parameters, a contact holding every (t, s) of the
// coincidence, in both orders.
TEST(Collinear, SubnormalEstimateInsideItsInterval) {
  const Curve f({{0.0, 0x3p-1010}, {0.0, 0x1p-900}});
  const Curve g({{0.0, 0.0}, {0.0, 0x1p64}});
  for (const bool swapped : {false, true}) {
    const IntersectionResult r = swapped ? intersect(g, f) : intersect(f, g);
    ASSERT_EQ(r.status, IntersectStatus::ok);
    ASSERT_EQ(r.intersections.size() + r.overlaps.size(), 1u);
    // f(0) = g(3 2^-1074), f(1) = g(2^-964) and f(1/2) = g((2^-964 + 3 2^-1074) / 2).
    for (const auto& [t, s] : {std::pair{0.0, 0x3p-1074}, std::pair{1.0, 0x1p-964},
                               std::pair{0.5, 0x1p-965 + 0x3p-1075}}) {
      EXPECT_TRUE(swapped ? covered(r, s, t) : covered(r, t, s)) << t << " " << s;
    }
    expect_intersection_contract(r, IntersectOptions{}.tolerance);
  }
}

TEST(Collinear, NearlyCollinearCurvesOfDifferentSizesCrossOnce) {
  // Two quadratics near the line x = 0: f within 2^-31 of it over its 4096 extent (1e-13 of
  // its size), g bent by 2^-30 over its extent of 8 (1e-10 of its own size). The line
  // through f's first control point made the collinear test pass in one order only (one
  // answered two overlaps along the line, the other a crossing); with the line through the
  // two control points farthest apart both orders answered the overlaps. But g is no
  // straight segment to within its own rounding, and two different quadratics share no
  // piece: with the collinear test relative to the smaller curve (as the overlap tests are)
  // both orders answer the one crossing. y_f falls monotonically from 0.031 to -4096, so f
  // has one t for each y, and g crosses the parabola f lies on (A1^2 - 4 A0 A2 = 0, exact)
  // between s = 0.32572355795 and 0.32572355796.
  const Curve f({{0x0p+0, 0x1.ff8ff2p-6}, {0x1.0000000000002p-31, -0x1p+3}, {0x0p+0, -0x1p+12}});
  const Curve g({{0x1p-31, -0x1p+0}, {0x0p+0, 0x1.fep-30}, {-0x1.fep-30, -0x1p+3}});
  const double s_lo = 0.32572355795, s_hi = 0.32572355796;
  ASSERT_LT(
      on_parabola(f, exact_point(g, s_lo)).sign() * on_parabola(f, exact_point(g, s_hi)).sign(), 0);
  // t with y_f(t) = y: the root in [0, 1] of a (1-t)^2 + 2b t(1-t) + c t^2 = y.
  const auto t_at = [&](double y) {
    const double a = f[0].y, b = f[1].y, c = f[2].y;
    const double qa = a - 2 * b + c, qb = 2 * (b - a), qc = a - y;
    return (-qb - std::sqrt(qb * qb - 4 * qa * qc)) / (2 * qa);
  };
  const double t_lo = t_at(evaluate(g, s_hi).y), t_hi = t_at(evaluate(g, s_lo).y);
  for (const bool swapped : {false, true}) {
    const IntersectionResult r = swapped ? intersect(g, f) : intersect(f, g);
    ASSERT_EQ(r.status, IntersectStatus::ok);
    EXPECT_TRUE(r.overlaps.empty()) << "swapped " << swapped;
    ASSERT_EQ(r.intersections.size(), 1u) << "swapped " << swapped;
    const Intersection& x = r.intersections[0];
    const double t = swapped ? x.s : x.t, s = swapped ? x.t : x.s;
    EXPECT_TRUE(x.resolved);
    EXPECT_EQ(x.kind, IntersectionKind::transversal);
    EXPECT_LE(s_lo, s);
    EXPECT_LE(s, s_hi);
    EXPECT_NEAR(t, (t_lo + t_hi) / 2, 1e-9);
  }
}

TEST(Collinear, ASmallCurveBentAboveItsRoundingIsNotOnALargeCurvesLine) {
  // f runs from (0, 0) out along the x axis past x = 2^28 and back to x = 2^-31 (y <= 2^-31);
  // g, about 2^-14 of its size, is the parabola from (0, 2^-13) out to x = -16381.5 and back to
  // (0, 0), tangent to the x axis there. Relative to f's size g lies on the x axis, and
  // both orders took the pair for collinear: a touch at f(0) and g's first end, 2^-13
  // apart, placed at (0, 2^-57) in one order and at (2^-70, 0) in the other. The curves
  // meet only at f(0) = g(1): x_f > 0 on (0, 1] (every control point's x >= 0, P1's > 0)
  // and x_g < 0 on (0, 1) (-2 (1 - s) s 32763 plus 0 at both ends), so a common point has
  // x = 0, t = 0 and s in {0, 1}, and g(0) = (0, 2^-13) is not f(0). Both tangents there
  // are horizontal to within 1e-13: a tangency.
  const Curve f({{0x0p+0, 0x0p+0},
                 {0x1.f404004cp+11, 0x1.000002b001204p-31},
                 {0x1.28p+29, 0x0p+0},
                 {0x1.72b0112011919p-31, 0x0p+0}});
  const Curve g({{0x0p+0, 0x1.000000c02808p-13}, {-0x1.ffecp+14, 0x0p+0}, {0x0p+0, 0x0p+0}});
  for (const bool swapped : {false, true}) {
    const IntersectionResult r = swapped ? intersect(g, f) : intersect(f, g);
    ASSERT_EQ(r.status, IntersectStatus::ok);
    EXPECT_TRUE(r.overlaps.empty()) << "swapped " << swapped;
    ASSERT_EQ(r.intersections.size(), 1u) << "swapped " << swapped;
    EXPECT_TRUE(swapped ? covered(r, 1.0, 0.0) : covered(r, 0.0, 1.0));
    EXPECT_EQ(r.intersections[0].kind, IntersectionKind::tangent);
  }
}

TEST(Collinear, ATouchAtTwoEndsIsTheSameInBothOrders) {
  // f runs from (0, 0) to x = -2^26 within 2^-28 of the x axis; g is the segment from
  // (0, 0x1.f2p-22) to (1.31, 0), 2^-26 of f's size. Both lie on the x axis to within the
  // rounding of coordinates of 2^26 (64 n u of them is 1e-6), so the pair is taken as
  // collinear, and the ranges along the axis touch at x = 0, an end of both curves. Each
  // order kept its first curve's end exact and moved the other's parameter to the foot of
  // that point on it: (0, 2^-43) one way, (0, 0) the other.
  const Curve f({{0x0p+0, 0x0p+0}, {0x0p+0, 0x1.ef8p-28}, {-0x1p+26, 0x0p+0}});
  const Curve g({{0x0p+0, 0x1.f2p-22}, {0x1.4fb8000ff8p+0, 0x0p+0}});
  for (const IntersectMethod method :
       {IntersectMethod::hybrid, IntersectMethod::bezier_clipping, IntersectMethod::subdivision}) {
    IntersectOptions options;
    options.method = method;
    const IntersectionResult a = intersect(f, g, options), b = intersect(g, f, options);
    ASSERT_EQ(a.intersections.size(), b.intersections.size());
    EXPECT_TRUE(a.overlaps.empty() && b.overlaps.empty());
    for (std::size_t i = 0; i < a.intersections.size(); ++i) {
      const Intersection &x = a.intersections[i], &y = b.intersections[i];
      EXPECT_EQ(x.t_interval, y.s_interval);
      EXPECT_EQ(x.s_interval, y.t_interval);
      EXPECT_EQ(x.t, 0.0);
      EXPECT_EQ(x.s, 0.0);
    }
  }
}

}  // namespace
}  // namespace bezier::core
