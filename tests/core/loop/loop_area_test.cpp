#include "core/loop/loop_area.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/curve/area.hpp"
#include "core/self_intersect/work_cost.hpp"
#include "tests/support/exact.hpp"
#include "tests/support/exact_bezier.hpp"
#include "tests/support/exact_polynomial.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

using test::Poly;
using test::Rational;
using test::RPoint2;

Rational q(long long p, long long d) {
  return Rational(p) / Rational(d);
}

Curve degree7_example() {
  return Curve({{0, 0}, {1, 1}, {2, 3}, {1, 4}, {0, 4}, {-1, 3}, {0, 1}, {1, 0}});
}

/// The curve with power-form coordinates x(s), y(s), s = t - 1/2, as exact control points.
Curve symmetric_from_power(const Poly& xs, const Poly& ys) {
  Poly x = test::poly_shift(xs, q(1, 2)), y = test::poly_shift(ys, q(1, 2));
  const std::size_t n = std::max(x.size(), y.size());
  x.resize(n, Rational(0));
  y.resize(n, Rational(0));
  const auto curve = test::exact_curve(test::bernstein_from_power(x, y));
  EXPECT_TRUE(curve.has_value());
  return curve.value_or(Curve({{0, 0}, {1, 0}}));
}

TEST(LoopArea, Degree7ExampleAgainstTheExactIntegral) {
  // The pair is (t1, 1 - t1) with x(t1) = 1/2 (symmetry P_{7-i} = (1 - x_i, y_i)); t1 is
  // bisected in rationals to 2^-90 and the loop area integrated exactly in the power basis
  // at that t1 (the area is stationary in t1 at the double point, so the bracket's width
  // enters only squared).
  const Curve c = degree7_example();
  const test::PowerCurve pc = test::power_form(c);
  const Rational t1 = test::bisect_root(test::poly_sub(pc.x, {q(1, 2)}), q(1, 16), q(1, 8), 90);
  const double exact = test::exact_enclosed_area(pc, t1, Rational(1) - t1).to_double();
  ASSERT_GT(exact, 2.25);  // counter-clockwise, about 2.2537

  const LoopAreaResult r = loop_area(c);
  EXPECT_EQ(r.status, IntersectStatus::ok);
  ASSERT_EQ(r.loops.size(), 1u);
  EXPECT_NEAR(r.loops[0].signed_area, exact, 1e-14 * exact);
  EXPECT_EQ(r.loops[0].area, r.loops[0].signed_area);
  EXPECT_EQ(r.area, r.loops[0].area);
  EXPECT_NEAR(r.loops[0].t1 + r.loops[0].t2, 1.0, 4e-16);
  EXPECT_FALSE(r.closed);
  EXPECT_FALSE(r.closed_area.has_value());
}

TEST(LoopArea, AreasAreAccurateToAboutAnUlp) {
  // (-9,0), (13,16), (-13,16), (9,0): x(t) = 0 at t = 1/4 and 3/4, where y = 9 on both
  // branches, so the loop is [1/4, 3/4] exactly and its area an exact rational (12/5).
  const Curve c({{-9, 0}, {13, 16}, {-13, 16}, {9, 0}});
  const Rational exact = test::exact_enclosed_area(test::power_form(c), q(1, 4), q(3, 4));
  EXPECT_EQ(exact, q(12, 5));
  const LoopAreaResult r = loop_area(c);
  ASSERT_EQ(r.loops.size(), 1u);
  EXPECT_EQ(r.loops[0].t1, 0.25);
  EXPECT_EQ(r.loops[0].t2, 0.75);
  const double ulp = std::nextafter(2.4, 3.0) - 2.4;
  EXPECT_NEAR(r.loops[0].signed_area, exact.to_double(), 2 * ulp);
}

TEST(LoopArea, TinyLoopHasItsClosedFormArea) {
  // x = 3 (s^3 - d^2 s), y = 3 s^2: loop on s in [-d, d] with area
  // 1/2 ∫ (x y' - x' y) ds = -9/2 ∫_{-d}^{d} (s^4 + d^2 s^2) ds = -(24/5) d^5.
  for (const int k : {4, 6, 9}) {
    const double d = std::ldexp(1.0, -k);
    const Curve c = symmetric_from_power(
        {Rational(0), Rational(-3) * Rational(d) * Rational(d), Rational(0), Rational(3)},
        {Rational(0), Rational(0), Rational(3)});
    const double expected = -24.0 / 5.0 * std::pow(d, 5);
    const LoopAreaResult r = loop_area(c);
    ASSERT_EQ(r.loops.size(), 1u) << k;
    // The loop's size is d^2 by d^3 at coordinates of order 1: its area is known to the
    // absolute rounding of its control points (~1e-16) times its perimeter.
    EXPECT_NEAR(r.loops[0].signed_area, expected, 1e-9 * std::fabs(expected)) << k;
    EXPECT_EQ(r.loops[0].area, -r.loops[0].signed_area);
  }
}

TEST(LoopArea, CubicLoopsAgainstTheExactClosedForm) {
  // Random cubics with a loop: the exact double point from σ = t + s = -cross(a, c) /
  // cross(a, b), σ^2 - t s = cross(b, c) / cross(a, b) (power form a t^3 + b t^2 + c t + d),
  // square root to 2^-120, area integrated exactly at those parameters.
  test::Mulberry32 rng(5);
  int checked = 0;
  while (checked < 25) {
    std::vector<Point2> p;
    for (int i = 0; i < 4; ++i) p.push_back({rng.next(), rng.next()});
    const Curve c(p);
    const test::PowerCurve pc = test::power_form(c);
    const RPoint2 a{pc.x[3], pc.y[3]}, b{pc.x[2], pc.y[2]}, cc{pc.x[1], pc.y[1]};
    const Rational ab = test::rcross(a, b);
    if (ab.is_zero()) continue;
    const Rational sigma = -test::rcross(a, cc) / ab;
    const Rational prod = sigma * sigma - test::rcross(b, cc) / ab;
    const Rational disc = sigma * sigma - Rational(4) * prod;
    if (disc.sign() <= 0) continue;
    const Rational root = test::sqrt_approx(disc, 120);
    const Rational t = (sigma - root) / Rational(2), s = (sigma + root) / Rational(2);
    if (t < Rational(0) || s > Rational(1) || (s - t) < q(1, 20)) continue;
    const double exact = test::exact_enclosed_area(pc, t, s).to_double();
    const LoopAreaResult r = loop_area(c);
    ASSERT_EQ(r.loops.size(), 1u);
    EXPECT_NEAR(r.loops[0].signed_area, exact, 1e-13 * std::fabs(exact) + 1e-16);
    ++checked;
  }
}

TEST(LoopArea, LoopClosingAtTheStart) {
  // B(t) = t (a t^2 + b t + c), c = -a T^2 - b T with T = 3/4: B(0) = B(3/4); the loop
  // [0, 3/4] has an exact rational area.
  const Rational T = q(3, 4);
  const RPoint2 a{Rational(6), Rational(3)}, b{Rational(-3), Rational(9)};
  const RPoint2 c{-(a.x * T * T + b.x * T), -(a.y * T * T + b.y * T)};
  const auto curve = test::exact_curve(
      test::bernstein_from_power({Rational(0), c.x, b.x, a.x}, {Rational(0), c.y, b.y, a.y}));
  ASSERT_TRUE(curve.has_value());
  const double exact =
      test::exact_enclosed_area(test::power_form(*curve), Rational(0), T).to_double();
  const LoopAreaResult r = loop_area(*curve);
  ASSERT_EQ(r.loops.size(), 1u);
  EXPECT_EQ(r.loops[0].t1, 0.0);
  EXPECT_NEAR(r.loops[0].signed_area, exact, 1e-14 * std::fabs(exact));
  EXPECT_EQ(r.loops[0].point, (*curve)[0]);
}

TEST(LoopArea, NestedLoopsEachWithItsOwnAreaAndTheirTotal) {
  // x = 5 s (s^2 - 1/64)(s^2 - 9/64), y = 5 s^2: pairs 1/2 ∓ 1/8 and 1/2 ∓ 3/8 (dyadic), so
  // both loop areas are exact rationals. The outer loop [1/8, 7/8] contains the inner one.
  const Rational a = q(1, 64), b = q(9, 64);
  const Curve c = symmetric_from_power({Rational(0), Rational(5) * a * b, Rational(0),
                                        Rational(-5) * (a + b), Rational(0), Rational(5)},
                                       {Rational(0), Rational(0), Rational(5)});
  const test::PowerCurve pc = test::power_form(c);
  const double outer = test::exact_enclosed_area(pc, q(1, 8), q(7, 8)).to_double();
  const double inner = test::exact_enclosed_area(pc, q(3, 8), q(5, 8)).to_double();
  const LoopAreaResult r = loop_area(c);
  ASSERT_EQ(r.loops.size(), 2u);
  EXPECT_NEAR(r.loops[0].signed_area, outer, 1e-14 * std::fabs(outer));
  EXPECT_NEAR(r.loops[1].signed_area, inner, 1e-13 * std::fabs(inner));
  EXPECT_NEAR(r.area, std::fabs(outer) + std::fabs(inner),
              1e-14 * (std::fabs(outer) + std::fabs(inner)));
}

TEST(LoopArea, TangentialContactEnclosesALoop) {
  // x = 5 s (s^2 - 1/16)^2, y = 5 s^2 touches itself at t = 1/4, 3/4.
  const Rational d2 = q(1, 16);
  const Curve c = symmetric_from_power({Rational(0), Rational(5) * d2 * d2, Rational(0),
                                        Rational(-10) * d2, Rational(0), Rational(5)},
                                       {Rational(0), Rational(0), Rational(5)});
  const double exact = test::exact_enclosed_area(test::power_form(c), q(1, 4), q(3, 4)).to_double();
  const LoopAreaResult r = loop_area(c);
  ASSERT_EQ(r.loops.size(), 1u);
  EXPECT_EQ(r.loops[0].kind, IntersectionKind::tangent);
  EXPECT_NEAR(r.loops[0].signed_area, exact, 1e-12 * std::fabs(exact));
}

TEST(LoopArea, ClosedCurves) {
  // A closed cubic: no loop (its double point is the trivial pair), the whole area exact.
  const Curve cubic({{0, 0}, {3, 1}, {-1, 2}, {0, 0}});
  const LoopAreaResult r = loop_area(cubic);
  EXPECT_TRUE(r.closed);
  EXPECT_TRUE(r.loops.empty());
  EXPECT_EQ(r.area, 0.0);
  ASSERT_TRUE(r.closed_area.has_value());
  EXPECT_NEAR(*r.closed_area, test::exact_green_integral(test::power_form(cubic), 0, 1).to_double(),
              1e-15);

  // A closed figure eight with B(1 - t) = -B(t): two lobes (0, 1/2) and (1/2, 1) of opposite
  // orientation and equal size; the closed area cancels.
  const Curve eight({{0, 0}, {4, 4}, {4, -4}, {-4, 4}, {-4, -4}, {0, 0}});
  const LoopAreaResult e = loop_area(eight);
  EXPECT_TRUE(e.closed);
  ASSERT_EQ(e.loops.size(), 2u);
  const double lobe = test::exact_enclosed_area(test::power_form(eight), 0, q(1, 2)).to_double();
  EXPECT_NEAR(e.loops[0].signed_area, lobe, 1e-14 * std::fabs(lobe));
  EXPECT_NEAR(e.loops[1].signed_area, -lobe, 1e-14 * std::fabs(lobe));
  EXPECT_NEAR(*e.closed_area, 0.0, 1e-13);
}

TEST(LoopArea, AreaFollowsSimilarityMapsAndReversal) {
  const Curve c = degree7_example();
  const LoopAreaResult base = loop_area(c);
  ASSERT_EQ(base.loops.size(), 1u);
  const double a = base.loops[0].signed_area;
  for (const double s : {1e-8, 0.5, 3.0, 1e8}) {
    for (const double angle : {0.0, 0.7, 2.0}) {
      for (const Point2 shift : {Point2{0, 0}, Point2{-5, 12}}) {
        const double co = std::cos(angle), si = std::sin(angle);
        std::vector<Point2> mapped;
        for (const Point2 p : c.points())
          mapped.push_back(s * Point2{co * p.x - si * p.y, si * p.x + co * p.y} + s * shift);
        const LoopAreaResult m = loop_area(Curve(mapped));
        ASSERT_EQ(m.loops.size(), 1u);
        EXPECT_NEAR(m.loops[0].signed_area / (s * s), a, 1e-12 * a) << s << " " << angle;
      }
    }
  }
  const LoopAreaResult back = loop_area(reversed(c));
  ASSERT_EQ(back.loops.size(), 1u);
  EXPECT_NEAR(back.loops[0].signed_area, -a, 1e-14 * a);
  EXPECT_NEAR(back.loops[0].area, base.loops[0].area, 1e-14 * a);
}

TEST(LoopArea, CollinearCurvesHaveOverlapsAndNoArea) {
  const LoopAreaResult r = loop_area(Curve({{0, 0}, {2, 1}, {0, 0}}));
  EXPECT_EQ(r.status, IntersectStatus::ok);
  EXPECT_FALSE(r.overlaps.empty());
  EXPECT_TRUE(r.loops.empty());
  EXPECT_EQ(r.area, 0.0);
  EXPECT_EQ(r.overlaps.size(), 1u);
  EXPECT_TRUE(r.closed);
  EXPECT_EQ(r.closed_area, 0.0);
}

TEST(LoopArea, WorkCapPassesThrough) {
  // Three boxes' worth of work units: the search stops before a fourth.
  SelfIntersectionOptions options;
  options.max_work = 3 * self_intersection_box_cost(7);
  const LoopAreaResult r = loop_area(degree7_example(), options);
  EXPECT_EQ(r.status, IntersectStatus::work_cap_reached);
  EXPECT_EQ(r.stats.work, options.max_work);
}

}  // namespace
}  // namespace bezier::core
