// Overlaps along polynomial reparametrisations (common_arc.hpp): curves g = h(q(s)) that
// trace an arc of a proper curve h at a non-uniform speed, or more than once. Each curve is
// built in exact rationals (the composition of Bézier curves through de Casteljau's
// algorithm on polynomials in Bernstein form) and rounded once; each expected overlap comes
// from the closed form of the reparametrisations: f(t) = h(p(t)) and g(s) = h(q(s)) meet
// exactly where p(t) = q(s).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/base/curve.hpp"
#include "core/bernstein/degree.hpp"
#include "core/curve/evaluate.hpp"
#include "core/intersect/intersect.hpp"
#include "tests/support/exact.hpp"
#include "tests/support/exact_bezier.hpp"
#include "tests/support/intersection_checks.hpp"

namespace bezier::core {
namespace {

using test::expect_no_common_point;
using test::Rational;
using test::RPoint2;
using Poly = test::BernsteinPoly;

/// h(q(s)) rounded once per coordinate (test::exact_compose).
Curve compose(const std::vector<RPoint2>& h, const Poly& q) {
  std::vector<Point2> pts;
  for (const RPoint2& p : test::exact_compose(h, q)) pts.push_back(test::to_double(p));
  return Curve(pts);
}

/// A parabola through (0, 0), (1, 2), (3, 0): proper (a quadratic that is not a line).
std::vector<RPoint2> parabola() {
  return {{Rational(0), Rational(0)}, {Rational(1), Rational(2)}, {Rational(3), Rational(0)}};
}

/// A cubic with a loop-free S shape: proper.
std::vector<RPoint2> s_cubic() {
  return {{Rational(0), Rational(0)},
          {Rational(1), Rational(3)},
          {Rational(2), Rational(-3)},
          {Rational(3), Rational(0)}};
}

Curve curve_of(const std::vector<RPoint2>& h) {
  return compose(h, {Rational(0), Rational(1)});
}

/// q(s) = s^2, s^3, 4 s (1 - s), ... in Bernstein form.
const Poly kSquare = {Rational(0), Rational(0), Rational(1)};
const Poly kCube = {Rational(0), Rational(0), Rational(0), Rational(1)};
const Poly kOutAndBack = {Rational(0), Rational(2), Rational(0)};  // 4 s (1 - s)

struct Expected {
  double t_lo, t_hi, s_lo, s_hi;
  bool reversed;
};

void expect_overlaps(const IntersectionResult& r, const std::vector<Expected>& expected,
                     double tol = 1e-12) {
  ASSERT_EQ(r.status, IntersectStatus::ok);
  EXPECT_TRUE(r.intersections.empty()) << r.intersections.size() << " intersections, first at t "
                                       << (r.intersections.empty() ? 0 : r.intersections[0].t);
  ASSERT_EQ(r.overlaps.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_NEAR(r.overlaps[i].t_interval.lo, expected[i].t_lo, tol);
    EXPECT_NEAR(r.overlaps[i].t_interval.hi, expected[i].t_hi, tol);
    EXPECT_NEAR(r.overlaps[i].s_interval.lo, expected[i].s_lo, tol);
    EXPECT_NEAR(r.overlaps[i].s_interval.hi, expected[i].s_hi, tol);
    EXPECT_EQ(r.overlaps[i].reversed, expected[i].reversed);
  }
}

/// The same pair in the other order: every overlap with t and s swapped.
std::vector<Expected> swapped(std::vector<Expected> e) {
  for (Expected& x : e) {
    std::swap(x.t_lo, x.s_lo);
    std::swap(x.t_hi, x.s_hi);
  }
  std::sort(e.begin(), e.end(), [](const Expected& a, const Expected& b) {
    return a.t_lo != b.t_lo ? a.t_lo < b.t_lo : a.s_lo < b.s_lo;
  });
  return e;
}

const IntersectMethod kMethods[] = {IntersectMethod::hybrid, IntersectMethod::bezier_clipping,
                                    IntersectMethod::subdivision};

void check_both_orders(const Curve& f, const Curve& g, const std::vector<Expected>& expected,
                       double tol = 1e-12) {
  for (const IntersectMethod m : kMethods) {
    SCOPED_TRACE(std::string(to_string(m)));
    IntersectOptions options;
    options.method = m;
    expect_overlaps(intersect(f, g, options), expected, tol);
    expect_overlaps(intersect(g, f, options), swapped(expected), tol);
  }
}

TEST(ArcOverlap, ParabolaAtNonUniformSpeed) {
  // g(s) = h(s^2): the whole of h, t = s^2.
  check_both_orders(curve_of(parabola()), compose(parabola(), kSquare), {{0, 1, 0, 1, false}});
}

TEST(ArcOverlap, CubicTracedByADegreeSixCurve) {
  check_both_orders(curve_of(s_cubic()), compose(s_cubic(), kSquare), {{0, 1, 0, 1, false}});
}

TEST(ArcOverlap, OutAndBack) {
  // g(s) = h(4 s (1 - s)) runs along h to its end at s = 1/2 and back.
  check_both_orders(curve_of(parabola()), compose(parabola(), kOutAndBack),
                    {{0, 1, 0, 0.5, false}, {0, 1, 0.5, 1, true}});
}

TEST(ArcOverlap, BothImproper) {
  // h(t^2) against h(s^3): p(t) = q(s) on the curve t^2 = s^3, the whole square.
  check_both_orders(compose(parabola(), kSquare), compose(parabola(), kCube), {{0, 1, 0, 1, false}});
}

TEST(ArcOverlap, ImproperCurveAgainstItself) {
  // f = g = h(4 t (1 - t)): the identity and the mirror t = 1 - s, each on two pieces.
  const Curve f = compose(s_cubic(), kOutAndBack);
  check_both_orders(f, f,
                    {{0, 0.5, 0, 0.5, false},
                     {0, 0.5, 0.5, 1, true},
                     {0.5, 1, 0, 0.5, true},
                     {0.5, 1, 0.5, 1, false}});
}

TEST(ArcOverlap, ASearchWindowKeepsTheOverlapsThatMeetIt) {
  // The same curve against itself, searched only in t in [0.1, 0.2], s in [0.8, 0.9] (as the
  // one-curve certification searches a small box): of the four overlaps only the mirror
  // t = 1 - s on t in [0, 1/2], s in [1/2, 1] meets the window, and the points there are all
  // on it.
  const Curve f = compose(s_cubic(), kOutAndBack);
  for (const IntersectMethod m : kMethods) {
    SCOPED_TRACE(std::string(to_string(m)));
    IntersectOptions options;
    options.method = m;
    WorkBudget budget;
    expect_overlaps(intersect_in(f, f, {0.1, 0.2}, {0.8, 0.9}, options, budget),
                    {{0, 0.5, 0.5, 1, true}});
  }
}

TEST(ArcOverlap, SpeedsUpBeyondTheOtherCurve) {
  // q(s) = (3 s^2 - 1/2) / 2 runs over [-1/4, 5/4]: the overlap is where q is in [0, 1],
  // s in [sqrt(1/6), sqrt(5/6)].
  const Poly q = {Rational(-1, 4), Rational(-1, 4), Rational(5, 4)};
  check_both_orders(curve_of(parabola()), compose(parabola(), q),
                    {{0, 1, std::sqrt(1.0 / 6), std::sqrt(5.0 / 6), false}});
}

TEST(ArcOverlap, TurningPointsOnBothCurvesAndNoEndOnTheOther) {
  // p(t) = 1 - 12/5 t (1 - t) turns at u = 2/5, q(s) = 12/5 s (1 - s) at u = 3/5: neither
  // curve's ends lie on the other, and the arc u in [2/5, 3/5] is traced twice by each.
  // p in [2/5, 3/5] where t (1 - t) >= 1/6: t in [a, 1 - a], a = (1 - 1/sqrt 3) / 2.
  const Poly p = {Rational(1), Rational(-1, 5), Rational(1)};
  const Poly q = {Rational(0), Rational(6, 5), Rational(0)};
  const double a = (1 - 1 / std::sqrt(3.0)) / 2;
  check_both_orders(compose(parabola(), p), compose(parabola(), q),
                    {{a, 0.5, a, 0.5, true},
                     {a, 0.5, 0.5, 1 - a, false},
                     {0.5, 1 - a, a, 0.5, false},
                     {0.5, 1 - a, 0.5, 1 - a, true}});
}

TEST(ArcOverlap, HighDegreeRetracing) {
  // A degree-10 curve h (proper: it is degree-elevated from nothing, its control points
  // are on no lower-degree curve) traced as h(s^2) at degree 20 against h itself.
  std::vector<RPoint2> h;
  for (int i = 0; i <= 10; ++i) h.push_back({Rational(i), Rational((i * i * 7) % 11 - 5)});
  check_both_orders(curve_of(h), compose(h, kSquare), {{0, 1, 0, 1, false}}, 1e-10);
}

TEST(ArcOverlap, AFactorThatFallsOnTheUnitInterval) {
  // q(s) = 2s - s^2: its monic form s^2 - 2s falls on [0, 1], and the factorisation must
  // turn it around (p scaled to the range [0, 1] either way).
  check_both_orders(curve_of(parabola()), compose(parabola(), {Rational(0), Rational(1), Rational(1)}),
                    {{0, 1, 0, 1, false}});
}

TEST(ArcOverlap, HighDegreeBothImproper) {
  // The degree-10 h of HighDegreeRetracing at two quadratic speeds, t/2 + t^2/2 and
  // 3s/2 - s^2/2 (both onto [0, 1]): two degree-20 curves overlapping all along. The second
  // one's power form cancels a lot (coefficients up to 4e5 on control points below 1), so
  // its factor from the top coefficients is 5e-7 off and has to be refined on the curve.
  std::vector<RPoint2> h;
  for (int i = 0; i <= 10; ++i) h.push_back({Rational(i), Rational((i * i * 7) % 11 - 5)});
  check_both_orders(compose(h, {Rational(0), Rational(1, 4), Rational(1)}),
                    compose(h, {Rational(0), Rational(3, 4), Rational(1)}), {{0, 1, 0, 1, false}},
                    1e-10);
}

TEST(ArcOverlap, ACurveOffTheArcIsNotAnOverlap) {
  // h(s^2) moved off h by 2^-20 at one control point: no overlap may be claimed.
  Curve g = compose(parabola(), kSquare);
  std::vector<Point2> pts(g.points().begin(), g.points().end());
  pts[2].y += 0x1p-20;
  IntersectOptions options;
  const IntersectionResult r = intersect(curve_of(parabola()), Curve(pts), options);
  EXPECT_TRUE(r.overlaps.empty());
}

TEST(ArcOverlap, TheArcsOwnCrossingIsStillFound) {
  // h, a cubic with a loop, against h(s^2): they overlap along all of h, and h's double
  // point h(u1) = h(u2) is besides that a crossing of f = h and g at (u1, sqrt u2) and
  // (u2, sqrt u1), which the overlap must not hide.
  const std::vector<RPoint2> loop = {
      {Rational(0), Rational(0)}, {Rational(3), Rational(3)}, {Rational(-1), Rational(3)},
      {Rational(2), Rational(0)}};
  const Curve f = curve_of(loop), g = compose(loop, kSquare);
  for (const IntersectMethod m : kMethods) {
    SCOPED_TRACE(std::string(to_string(m)));
    IntersectOptions options;
    options.method = m;
    const IntersectionResult r = intersect(f, g, options);
    ASSERT_EQ(r.status, IntersectStatus::ok);
    ASSERT_EQ(r.overlaps.size(), 1u);
    ASSERT_EQ(r.intersections.size(), 2u);
    const double u1 = r.intersections[0].t, u2 = r.intersections[1].t;
    EXPECT_GT(u2 - u1, 0.1);
    const Point2 a = evaluate(f, u1), b = evaluate(f, u2);  // the double point, twice
    EXPECT_NEAR(a.x, b.x, 1e-12);
    EXPECT_NEAR(a.y, b.y, 1e-12);
    EXPECT_NEAR(r.intersections[0].s, std::sqrt(u2), 1e-12);
    EXPECT_NEAR(r.intersections[1].s, std::sqrt(u1), 1e-12);
  }
}

TEST(CommonArc, ACurveBesideALineSegmentDoesNotOverlapIt) {
  // f(t) = (2 c t (1 - t), 32768 t^2) with c = 0x1.90005010a01p-31 leaves the y axis for
  // every t in (0, 1); g, a quartic on the y axis (x = 0), has y(s) = a (1 - s)^4 + b s^4
  // with a = 0x1.6cp-23 and b = 0x1.858585858p-2, so 0 < y(s) <= b. A common point needs x = 0
  // on f: t = 0 or 1, the points (0, 0) and (0, 32768), and neither is on g. So there is no
  // intersection and no overlap, in either order. (intersect_fuzzer: g, read as a quadratic
  // through a quadratic to within the frame's tolerance, gave an overlap in one order, its
  // points all within 5e-12 of f but f's piece starting at (0, 0), 8e-8 below g.)
  const Curve f({{0.0, 0.0}, {0x1.90005010a01p-31, 0.0}, {0.0, 0x1p+15}});
  const Curve g({{0.0, 0x1.6cp-23}, {0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}, {0.0, 0x1.858585858p-2}});
  expect_no_common_point(f, g);
}

TEST(CommonArc, AnOverlapEndsWhereBothCurvesAre) {
  // f = (0, 0), (c, h), (X, 0) with c = 0x1.9p-31, h = 0x1.018p-12, X = 0x1.fp+29 has
  // y(t) = 2 h t (1 - t) > 0 inside (0, 1); g, a quartic on the x axis, has x(s) =
  // A (1 - s)^4 + s^4 with A = 0x1.2p+27, so 0 < x(s) <= A < X. A common point needs y = 0
  // on f, t = 0 or 1, and f(0) = (0, 0) has x below g's, f(1) = (X, 0) beyond them: none.
  // f lies within 1.2e-4 of g's line along its 1.5e8 (8e-13 of g's length), and the
  // common-arc search reported an overlap whose end paired f's start (0, 0) with g's point
  // nearest to it, 0.99 away. Every overlap's ends must be points of both curves;
  // here there are none.
  const Curve f({{0.0, 0.0}, {0x1.9p-31, 0x1.018p-12}, {0x1.fp+29, 0.0}});
  const Curve g({{0x1.2p+27, 0.0}, {0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}, {1.0, 0.0}});
  expect_no_common_point(f, g);
}

}  // namespace
}  // namespace bezier::core
