#include "core/self_intersect/self_intersection.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "core/curve/evaluate.hpp"
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

SelfIntersectionOptions general_path() {
  SelfIntersectionOptions o;
  o.cubic_closed_form = false;
  return o;
}

Rational q(long long p, long long d) {
  return Rational(p) / Rational(d);
}

/// The curve with power-form coordinates x(s), y(s), s = t - shift, as exact control points
/// (the constructions below are chosen so that they are doubles).
Curve from_power_in_s(const Poly& xs, const Poly& ys, const Rational& shift) {
  Poly x = test::poly_shift(xs, shift), y = test::poly_shift(ys, shift);
  const std::size_t n = std::max(x.size(), y.size());
  x.resize(n, Rational(0));
  y.resize(n, Rational(0));
  const auto curve = test::exact_curve(test::bernstein_from_power(x, y));
  EXPECT_TRUE(curve.has_value()) << "construction is not dyadic";
  return curve.value_or(Curve({{0, 0}, {1, 0}}));
}

/// Symmetric cubic with a loop between t = 1/2 - d and 1/2 + d: x = 3 (s^3 - d^2 s),
/// y = 3 s^2 (y is even in s, so y(s1) = y(s2) forces s2 = -s1, and x(s) = 0 at s = ±d).
/// Its loop area is -(24/5) d^5 (integrated by hand: 1/2 ∫ (x y' - x' y) ds =
/// -9/2 ∫_{-d}^{d} (s^4 + d^2 s^2) ds).
Curve small_loop_cubic(const Rational& d) {
  return from_power_in_s({Rational(0), Rational(-3) * d * d, Rational(0), Rational(3)},
                         {Rational(0), Rational(0), Rational(3)}, q(1, 2));
}

/// B(t) = t (a t^2 + b t + c) with c = -a T^2 - b T: B(0) = B(T) = 0, a loop closing
/// exactly at the start (a, b multiples of 3 keep the control points dyadic).
Curve loop_at_start_cubic() {
  const Rational T = q(3, 4);
  const RPoint2 a{Rational(6), Rational(3)}, b{Rational(-3), Rational(9)};
  const RPoint2 c{-(a.x * T * T + b.x * T), -(a.y * T * T + b.y * T)};
  const auto curve = test::exact_curve(
      test::bernstein_from_power({Rational(0), c.x, b.x, a.x}, {Rational(0), c.y, b.y, a.y}));
  EXPECT_TRUE(curve.has_value());
  return *curve;
}

/// x = 5 s (s^2 - d^2)^2, y = 5 s^2: the branches at s = ±d both have vertical tangents
/// there (x' = 0) and lie on opposite sides of x = 0 nearby: a tangential self-contact at
/// t = 1/2 ∓ d, and no other pair (y even).
Curve tangent_contact_quintic(const Rational& d) {
  const Rational d2 = d * d;
  return from_power_in_s({Rational(0), Rational(5) * d2 * d2, Rational(0), Rational(-10) * d2,
                          Rational(0), Rational(5)},
                         {Rational(0), Rational(0), Rational(5)}, q(1, 2));
}

/// x = 5 s (s^2 - d1^2)(s^2 - d2^2), y = 5 s^2: two nested loops, pairs 1/2 ∓ d1, 1/2 ∓ d2.
Curve nested_loops_quintic(const Rational& d1, const Rational& d2) {
  const Rational a = d1 * d1, b = d2 * d2;
  return from_power_in_s({Rational(0), Rational(5) * a * b, Rational(0), Rational(-5) * (a + b),
                          Rational(0), Rational(5)},
                         {Rational(0), Rational(0), Rational(5)}, q(1, 2));
}

Curve degree7_example() {
  return Curve({{0, 0}, {1, 1}, {2, 3}, {1, 4}, {0, 4}, {-1, 3}, {0, 1}, {1, 0}});
}

Curve elevated(const Curve& c) {
  const auto e = test::exact_curve(test::elevate(test::exact_points(c)));
  EXPECT_TRUE(e.has_value()) << "elevation is not exact";
  return e.value_or(c);
}

double exact_residual(const Curve& c, double t, double s) {
  const test::PowerCurve pc = test::power_form(c);
  const RPoint2 d = test::power_value(pc, Rational(t)) - test::power_value(pc, Rational(s));
  return std::hypot(d.x.to_double(), d.y.to_double());
}

// --- the degree-7 example --------------------------------------------------------------

TEST(SelfIntersection, Degree7ExampleAgainstExactSymmetricRoot) {
  // P_{7-i} = (1 - x_i, y_i), so B(1 - t) = (1 - x(t), y(t)): the double point pairs t with
  // 1 - t and lies on x = 1/2. t1 is the root of the exact polynomial x(t) - 1/2 in
  // (1/16, 1/8), bisected in rationals far beyond double precision.
  const Curve c = degree7_example();
  const test::PowerCurve pc = test::power_form(c);
  const Poly x_minus_half = test::poly_sub(pc.x, {q(1, 2)});
  const Rational t1 = test::bisect_root(x_minus_half, q(1, 16), q(1, 8), 90);
  const double y = test::poly_value(pc.y, t1).to_double();

  for (const auto& options : {SelfIntersectionOptions{}, general_path()}) {
    const SelfIntersectionResult r = self_intersections(c, options);
    EXPECT_EQ(r.status, IntersectStatus::ok);
    EXPECT_EQ(r.stats.method, SelfIntersectionMethod::subdivision);
    ASSERT_EQ(r.pairs.size(), 1u);
    const SelfIntersection& p = r.pairs[0];
    EXPECT_NEAR(p.t, t1.to_double(), 1e-14 * t1.to_double());
    EXPECT_NEAR(p.s, (Rational(1) - t1).to_double(), 1e-14);
    EXPECT_NEAR(p.t + p.s, 1.0, 4e-16);
    EXPECT_NEAR(p.point.x, 0.5, 1e-14 * 0.5);
    EXPECT_NEAR(p.point.y, y, 1e-14 * y);
    EXPECT_EQ(p.kind, IntersectionKind::transversal);
  }
}

// --- cubics: closed form, exact expectations ----------------------------------------------

/// The exact double point of a cubic from its power form a t^3 + b t^2 + c t + d:
/// σ = t + s = -cross(a, c) / cross(a, b), σ^2 - t s = cross(b, c) / cross(a, b).
struct ExactCubicLoop {
  double t;
  double s;
  bool real;
};

ExactCubicLoop exact_cubic_loop(const Curve& c) {
  const test::PowerCurve pc = test::power_form(c);
  const RPoint2 a{pc.x[3], pc.y[3]}, b{pc.x[2], pc.y[2]}, cc{pc.x[1], pc.y[1]};
  const Rational ab = test::rcross(a, b);
  if (ab.is_zero()) return {0, 0, false};
  const Rational sigma = -test::rcross(a, cc) / ab;
  const Rational pi = sigma * sigma - test::rcross(b, cc) / ab;
  const Rational disc = sigma * sigma - Rational(4) * pi;
  if (disc.sign() <= 0) return {0, 0, false};
  const Rational root = test::sqrt_approx(disc, 120);
  return {((sigma - root) / Rational(2)).to_double(), ((sigma + root) / Rational(2)).to_double(),
          true};
}

std::vector<Curve> random_loop_cubics(std::uint32_t seed, std::size_t count) {
  test::Mulberry32 rng(seed);
  std::vector<Curve> out;
  while (out.size() < count) {
    std::vector<Point2> p;
    for (int i = 0; i < 4; ++i) p.push_back({rng.next(), rng.next()});
    Curve c(p);
    const ExactCubicLoop e = exact_cubic_loop(c);
    // Loops on [0, 1] that are not near a cusp (well-conditioned parameters).
    if (e.real && e.t >= 0 && e.s <= 1 && e.s - e.t > 0.05) out.push_back(std::move(c));
  }
  return out;
}

TEST(SelfIntersection, CubicLoopsMatchTheExactClosedFormOnBothPaths) {
  for (const Curve& c : random_loop_cubics(99, 60)) {
    const ExactCubicLoop e = exact_cubic_loop(c);
    for (const auto& options : {SelfIntersectionOptions{}, general_path()}) {
      const SelfIntersectionResult r = self_intersections(c, options);
      ASSERT_EQ(r.pairs.size(), 1u) << c[0].x << " " << c[0].y;
      EXPECT_NEAR(r.pairs[0].t, e.t, 1e-13);
      EXPECT_NEAR(r.pairs[0].s, e.s, 1e-13);
      EXPECT_LT(exact_residual(c, r.pairs[0].t, r.pairs[0].s), 1e-14);
    }
  }
}

TEST(SelfIntersection, CubicFastPathAgreesWithTheGeneralPath) {
  // Every random cubic (loop or not, the same stream as the benchmark's): same pairs.
  test::Mulberry32 rng(1);
  int loops = 0;
  for (int k = 0; k < 3000; ++k) {
    std::vector<Point2> p;
    for (int i = 0; i < 4; ++i) p.push_back({rng.next(), rng.next()});
    const Curve c(p);
    const SelfIntersectionResult fast = self_intersections(c);
    const SelfIntersectionResult general = self_intersections(c, general_path());
    EXPECT_EQ(fast.stats.method, SelfIntersectionMethod::closed_form_cubic);
    // Loops closer to a cusp than the general method's resolution (s - t of order 1e-5)
    // may be listed by the exact closed form only.
    if (fast.pairs.size() == 1 && general.pairs.empty()) {
      EXPECT_LT(fast.pairs[0].s - fast.pairs[0].t, 1e-4) << k;
      continue;
    }
    ASSERT_EQ(fast.pairs.size(), general.pairs.size()) << k;
    for (std::size_t i = 0; i < fast.pairs.size(); ++i) {
      EXPECT_NEAR(fast.pairs[i].t, general.pairs[i].t, 1e-12) << k;
      EXPECT_NEAR(fast.pairs[i].s, general.pairs[i].s, 1e-12) << k;
      EXPECT_NEAR(fast.pairs[i].point.x, general.pairs[i].point.x, 1e-12) << k;
      EXPECT_NEAR(fast.pairs[i].point.y, general.pairs[i].point.y, 1e-12) << k;
      ++loops;
    }
  }
  EXPECT_GT(loops, 100);  // the comparison covered many loops
}

TEST(SelfIntersection, CubicsShownWithoutSelfIntersectionsHaveNone) {
  // certainly_without_self_intersections: true only for cubics the general search finds
  // nothing on, and self_intersections() then answers at once, charging nothing.
  test::Mulberry32 rng(3);
  int shown = 0;
  for (int k = 0; k < 2000; ++k) {
    std::vector<Point2> p;
    for (int i = 0; i < 4; ++i) p.push_back({rng.next(), rng.next()});
    const Curve c(p);
    if (!certainly_without_self_intersections(c)) continue;
    ++shown;
    const SelfIntersectionResult general = self_intersections(c, general_path());
    EXPECT_TRUE(general.pairs.empty() && general.overlaps.empty()) << k;
    WorkBudget budget;
    const SelfIntersectionResult r = self_intersections(c, {}, budget);
    EXPECT_TRUE(r.pairs.empty() && r.overlaps.empty());
    EXPECT_EQ(r.stats.method, SelfIntersectionMethod::closed_form_cubic);
    EXPECT_EQ(budget.spent(), 0);
  }
  EXPECT_GT(shown, 500);
  // Never a loop, never with the closed form off.
  for (const Curve& c : random_loop_cubics(5, 40)) {
    EXPECT_FALSE(certainly_without_self_intersections(c));
  }
  EXPECT_FALSE(certainly_without_self_intersections(Curve({{0, 0}, {1, 1}, {0, 1}, {1, 0}})));
  EXPECT_FALSE(certainly_without_self_intersections(Curve({{0, 0}, {1, 2}, {2, -1}, {3, 0}}),
                                                    general_path()));
  EXPECT_TRUE(certainly_without_self_intersections(Curve({{0, 0}, {1, 2}, {2, -1}, {3, 0}})));
}

TEST(SelfIntersection, MonotoneCubicsTheClosedFormDoesNotSettleAreStillSearched) {
  // Monotone along its chord, but within the distance tolerance of that line while x folds
  // back: the collinear branch answers it (and would report any retraced piece).
  const double e = 0x1p-50;
  const Curve thin({{1, 1}, {1 + 3 * e, 1 + 4 * e}, {1 - 2 * e, 1 + 8 * e}, {1 + e, 1 + 12 * e}});
  EXPECT_FALSE(certainly_without_self_intersections(thin));
  EXPECT_EQ(self_intersections(thin).stats.method, SelfIntersectionMethod::collinear);
  // Monotone in x, but coordinates spanning more than 2^400 leave the closed form's
  // predicates inexact (a tiny y lost to underflow in their exact path): the search decides.
  const double big = 0x1p210;
  const Curve spread({{0, 0}, {big, 0x1p-300}, {2 * big, big}, {3 * big, big}});
  EXPECT_FALSE(certainly_without_self_intersections(spread));
  WorkBudget budget;
  const SelfIntersectionResult r = self_intersections(spread, {}, budget);
  EXPECT_TRUE(r.pairs.empty());
  EXPECT_EQ(r.stats.method, SelfIntersectionMethod::subdivision);
  EXPECT_GT(budget.spent(), 0);
}

// --- hard cases ---------------------------------------------------------------------------

TEST(SelfIntersection, TinyLoopIsFound) {
  // d = 2^-9: loop area (24/5) 2^-45 ~ 1.4e-13 in a bounding box of about 0.75 x 1.
  for (const int k : {6, 8, 9}) {
    const Rational d = Rational(std::ldexp(1.0, -k));
    const Curve c = small_loop_cubic(d);
    const double t = 0.5 - std::ldexp(1.0, -k), s = 0.5 + std::ldexp(1.0, -k);
    for (const Curve& curve : {c, elevated(c)}) {
      for (const auto& options : {SelfIntersectionOptions{}, general_path()}) {
        const SelfIntersectionResult r = self_intersections(curve, options);
        ASSERT_EQ(r.pairs.size(), 1u) << "2^-" << k << " degree " << curve.degree();
        EXPECT_NEAR(r.pairs[0].t, t, 1e-15);
        EXPECT_NEAR(r.pairs[0].s, s, 1e-15);
        EXPECT_NEAR(r.pairs[0].point.x, 0.0, 1e-15);
      }
    }
  }
}

TEST(SelfIntersection, LoopClosingExactlyAtTheStartOrTheEnd) {
  const Curve start = loop_at_start_cubic();
  for (const Curve& c : {start, elevated(start)}) {
    for (const auto& options : {SelfIntersectionOptions{}, general_path()}) {
      const SelfIntersectionResult r = self_intersections(c, options);
      ASSERT_EQ(r.pairs.size(), 1u) << "degree " << c.degree();
      EXPECT_EQ(r.pairs[0].t, 0.0);
      EXPECT_NEAR(r.pairs[0].s, 0.75, 1e-15);
      EXPECT_NEAR(r.pairs[0].point.x, 0.0, 1e-15);
      EXPECT_NEAR(r.pairs[0].point.y, 0.0, 1e-15);

      const SelfIntersectionResult back = self_intersections(reversed(c), options);
      ASSERT_EQ(back.pairs.size(), 1u);
      EXPECT_NEAR(back.pairs[0].t, 0.25, 1e-15);
      EXPECT_EQ(back.pairs[0].s, 1.0);
    }
  }
}

TEST(SelfIntersection, TangentialSelfContactIsFoundOnce) {
  const Curve c = tangent_contact_quintic(q(1, 4));
  const SelfIntersectionResult r = self_intersections(c);
  ASSERT_EQ(r.pairs.size(), 1u);
  EXPECT_NEAR(r.pairs[0].t, 0.25, 1e-9);
  EXPECT_NEAR(r.pairs[0].s, 0.75, 1e-9);
  EXPECT_EQ(r.pairs[0].kind, IntersectionKind::tangent);
  EXPECT_EQ(r.status, IntersectStatus::ok);
  // Moved off the grid by a translation and a non-dyadic scale: still one contact.
  std::vector<Point2> moved;
  for (const Point2 p : c.points()) moved.push_back(Point2{0.3, -1.7} + 3.0 * p);
  const SelfIntersectionResult m = self_intersections(Curve(moved));
  ASSERT_EQ(m.pairs.size(), 1u);
  EXPECT_NEAR(m.pairs[0].t, 0.25, 1e-7);
  EXPECT_NEAR(m.pairs[0].s, 0.75, 1e-7);
}

TEST(SelfIntersection, NearTangencyIsTwoCrossingsOrNoneOrOneContact) {
  // x = 5 s ((s^2 - 1/16)^2 + e), y = 5 s^2. For e < 0 the branches s and -s cross where
  // (s^2 - 1/16)^2 = -e, twice and at a tiny angle; for e > 0 they miss by 10 |e| / 4 in x;
  // for |e| at rounding level they touch as far as doubles can tell.
  const auto curve = [](const Rational& e) {
    const Rational d2 = q(1, 16);
    return from_power_in_s({Rational(0), Rational(5) * (d2 * d2 + e), Rational(0),
                            Rational(-10) * d2, Rational(0), Rational(5)},
                           {Rational(0), Rational(0), Rational(5)}, q(1, 2));
  };
  for (const int k : {20, 40}) {
    const double root_e = std::ldexp(1.0, -k / 2);  // sqrt(|e|)
    const SelfIntersectionResult crossing =
        self_intersections(curve(-Rational(std::ldexp(1.0, -k))));
    ASSERT_EQ(crossing.pairs.size(), 2u) << k;
    const double s_out = std::sqrt(1.0 / 16 + root_e), s_in = std::sqrt(1.0 / 16 - root_e);
    EXPECT_NEAR(crossing.pairs[0].t, 0.5 - s_out, 1e-12);
    EXPECT_NEAR(crossing.pairs[0].s, 0.5 + s_out, 1e-12);
    EXPECT_NEAR(crossing.pairs[1].t, 0.5 - s_in, 1e-12);
    EXPECT_NEAR(crossing.pairs[1].s, 0.5 + s_in, 1e-12);
    EXPECT_EQ(crossing.pairs[0].kind, IntersectionKind::transversal);

    EXPECT_TRUE(self_intersections(curve(Rational(std::ldexp(1.0, -k)))).pairs.empty()) << k;
  }
  const SelfIntersectionResult touch = self_intersections(curve(Rational(std::ldexp(1.0, -52))));
  ASSERT_EQ(touch.pairs.size(), 1u);
  EXPECT_EQ(touch.pairs[0].kind, IntersectionKind::tangent);
  EXPECT_NEAR(touch.pairs[0].t, 0.25, 1e-9);
}

TEST(SelfIntersection, SeveralLoopsOnOneCurve) {
  const Curve c = nested_loops_quintic(q(1, 8), q(3, 8));
  const SelfIntersectionResult r = self_intersections(c);
  ASSERT_EQ(r.pairs.size(), 2u);
  EXPECT_NEAR(r.pairs[0].t, 0.125, 1e-15);
  EXPECT_NEAR(r.pairs[0].s, 0.875, 1e-15);
  EXPECT_NEAR(r.pairs[1].t, 0.375, 1e-15);
  EXPECT_NEAR(r.pairs[1].s, 0.625, 1e-15);
  for (const SelfIntersection& p : r.pairs) EXPECT_EQ(p.kind, IntersectionKind::transversal);
}

TEST(SelfIntersection, CuspsAreNotSelfIntersections) {
  // (0,0), (1,1), (0,1), (1,0): a cusp at t = 1/2 (B'(1/2) = 0).
  const Curve cusp({{0, 0}, {1, 1}, {0, 1}, {1, 0}});
  // x = 3 s^2, y = 3 s^3, s = t - 1/4: a cusp at t = 1/4, off the dyadic grid's centre.
  const Curve cusp_quarter =
      from_power_in_s({Rational(0), Rational(0), Rational(3)},
                      {Rational(0), Rational(0), Rational(0), Rational(3)}, q(1, 4));
  for (const Curve& c : {cusp, elevated(cusp), cusp_quarter, elevated(cusp_quarter)}) {
    for (const auto& options : {SelfIntersectionOptions{}, general_path()}) {
      const SelfIntersectionResult r = self_intersections(c, options);
      EXPECT_TRUE(r.pairs.empty())
          << "degree " << c.degree() << " t = " << (r.pairs.empty() ? 0 : r.pairs[0].t);
      EXPECT_EQ(r.status, IntersectStatus::ok);
    }
  }
}

TEST(SelfIntersection, ClosedCurvesNeverReportTheTrivialPair) {
  // A closed cubic (its double point is the trivial one), a smooth closed quartic (G1 at
  // the seam), and a closed figure eight P_{5-i} = -P_i: B(1 - t) = -B(t), so B(1/2) = 0 =
  // P0 = P5 and the pairs are (0, 1/2) and (1/2, 1) besides the trivial (0, 1).
  const Curve closed_cubic({{0, 0}, {1, 2}, {-1, 2}, {0, 0}});
  const Curve smooth({{0, 0}, {2, 0}, {1, 2}, {-2, 0}, {0, 0}});
  for (const Curve& c : {closed_cubic, elevated(closed_cubic), smooth}) {
    for (const auto& options : {SelfIntersectionOptions{}, general_path()}) {
      EXPECT_TRUE(self_intersections(c, options).pairs.empty()) << "degree " << c.degree();
    }
  }
  const Curve eight({{0, 0}, {4, 4}, {4, -4}, {-4, 4}, {-4, -4}, {0, 0}});
  const SelfIntersectionResult r = self_intersections(eight);
  ASSERT_EQ(r.pairs.size(), 2u);
  EXPECT_EQ(r.pairs[0].t, 0.0);
  EXPECT_NEAR(r.pairs[0].s, 0.5, 1e-15);
  EXPECT_NEAR(r.pairs[1].t, 0.5, 1e-15);
  EXPECT_EQ(r.pairs[1].s, 1.0);
}

TEST(SelfIntersection, SegmentsAndParabolasNeverSelfIntersect) {
  EXPECT_TRUE(self_intersections(Curve({{0, 0}, {3, 1}})).pairs.empty());
  EXPECT_TRUE(self_intersections(Curve({{0, 0}, {5, 1}, {-1, 2}})).pairs.empty());
  EXPECT_TRUE(self_intersections(Curve({{0, 0}, {5, 1}, {-1, 2}}), general_path()).pairs.empty());
}

TEST(SelfIntersection, CollinearCurvesReportOverlaps) {
  // Out and back along the x axis: B(t) = B(1 - t) for every t.
  const SelfIntersectionResult back = self_intersections(Curve({{0, 0}, {1, 0}, {0, 0}}));
  EXPECT_EQ(back.status, IntersectStatus::ok);
  EXPECT_FALSE(back.overlaps.empty());
  EXPECT_EQ(back.stats.method, SelfIntersectionMethod::collinear);
  EXPECT_TRUE(back.pairs.empty());
  ASSERT_EQ(back.overlaps.size(), 1u);
  EXPECT_EQ(back.overlaps[0].t_interval.lo, 0.0);
  EXPECT_NEAR(back.overlaps[0].t_interval.hi, 0.5, 1e-12);
  EXPECT_NEAR(back.overlaps[0].s_interval.lo, 0.5, 1e-12);
  EXPECT_EQ(back.overlaps[0].s_interval.hi, 1.0);

  // A collinear cubic that turns twice: x(t) with x' = 0 at two parameters; pieces 1 and 2,
  // 2 and 3, 1 and 3 overlap. Every reported interval pair maps onto the same segment.
  const Curve zigzag({{0, 0}, {2, 2}, {-1, -1}, {1, 1}});
  const SelfIntersectionResult z = self_intersections(zigzag);
  EXPECT_EQ(z.status, IntersectStatus::ok);
  EXPECT_FALSE(z.overlaps.empty());
  ASSERT_EQ(z.overlaps.size(), 3u);
  for (const Overlap& o : z.overlaps) {
    EXPECT_LE(o.t_interval.hi, o.s_interval.lo + 1e-12);
    const auto x = [&](double t) { return evaluate(zigzag, t).x; };
    const ParamInterval t = o.t_interval, s = o.s_interval;
    EXPECT_NEAR(std::min(x(t.lo), x(t.hi)), std::min(x(s.lo), x(s.hi)), 1e-9);
    EXPECT_NEAR(std::max(x(t.lo), x(t.hi)), std::max(x(s.lo), x(s.hi)), 1e-9);
  }

  const SelfIntersectionResult monotone =
      self_intersections(Curve({{0, 0}, {1, 1}, {2, 2}, {4, 4}}));
  EXPECT_EQ(monotone.status, IntersectStatus::ok);
  EXPECT_TRUE(monotone.overlaps.empty());

  const SelfIntersectionResult point = self_intersections(Curve({{2, 3}, {2, 3}, {2, 3}}));
  EXPECT_EQ(point.status, IntersectStatus::ok);
  EXPECT_FALSE(point.overlaps.empty());
  ASSERT_EQ(point.overlaps.size(), 1u);
  EXPECT_EQ(point.overlaps[0].t_interval.lo, 0.0);
  EXPECT_EQ(point.overlaps[0].s_interval.hi, 1.0);
}

/// scale * H(phi(t)) for H given by its control points and phi in power form, exactly
/// (nullopt when a control point is not a double).
std::optional<Curve> composed(const Curve& h, const Poly& phi, const Rational& scale) {
  std::vector<RPoint2> pts =
      test::exact_compose(test::exact_points(h), test::bernstein_from_power(phi));
  for (RPoint2& p : pts) p = scale * p;
  return test::exact_curve(pts);
}

/// B(t) = 3 C(p(t)) for C(p) = (p, p^2 + p / 2) and a quadratic p(t) (power form). C's
/// control points (0, 0), (1/2, 1/4), (1, 3/2) are its power form's Bernstein coefficients.
Curve composed_with_quadratic(const Poly& p) {
  const auto c = composed(Curve({{0, 0}, {0.5, 0.25}, {1, 1.5}}), p, Rational(3));
  EXPECT_TRUE(c.has_value());
  return c.value_or(Curve({{0, 0}, {1, 0}}));
}

TEST(SelfIntersection, PalindromicControlPointsRetraceTheCurve) {
  // p(t) = 4t(1 - t) is symmetric about 1/2, so B(1 - t) = B(t): the control points read
  // the same backwards, and the curve runs out along a parabola and back.
  const Curve c = composed_with_quadratic({Rational(0), Rational(4), Rational(-4)});
  ASSERT_EQ(c[0], c[4]);
  ASSERT_EQ(c[1], c[3]);
  const SelfIntersectionResult r = self_intersections(c);
  EXPECT_EQ(r.status, IntersectStatus::ok);
  EXPECT_FALSE(r.overlaps.empty());
  EXPECT_TRUE(r.pairs.empty());  // the parabola itself does not cross itself
  ASSERT_EQ(r.overlaps.size(), 1u);
  EXPECT_EQ(r.overlaps[0].t_interval.lo, 0.0);
  EXPECT_EQ(r.overlaps[0].t_interval.hi, 0.5);
  EXPECT_EQ(r.overlaps[0].s_interval.lo, 0.5);
  EXPECT_EQ(r.overlaps[0].s_interval.hi, 1.0);
}

TEST(SelfIntersection, PalindromeOfALoopHasFourPairsPerLoop) {
  // B(t) = H(4t(1 - t)) for the cubic H = (0,0), (1,1), (-1/2,1), (1/2,0). H's power form
  // a h^3 + b h^2 + c h has a = (5, 0), b = (-15/2, -3), c = (3, 3), so its double point
  // h1 + h2 = -cross(a, c) / cross(a, b) = 1 and h1 h2 = 1 - cross(b, c) / cross(a, b) =
  // 1/10: h = (1 ∓ sqrt(3/5)) / 2. 4t(1 - t) = h gives t = (1 - sqrt(1 - h)) / 2 on the way
  // out and 1 - t on the way back: four pairs.
  const Curve h({{0, 0}, {1, 1}, {-0.5, 1}, {0.5, 0}});
  // Times 15: keeps the degree-6 control points dyadic.
  const auto c = composed(h, {Rational(0), Rational(4), Rational(-4)}, Rational(15));
  ASSERT_TRUE(c.has_value());
  const double h1 = (1 - std::sqrt(0.6)) / 2, h2 = (1 + std::sqrt(0.6)) / 2;
  const double a = (1 - std::sqrt(1 - h1)) / 2, b = (1 - std::sqrt(1 - h2)) / 2;
  const SelfIntersectionResult r = self_intersections(*c);
  EXPECT_EQ(r.status, IntersectStatus::ok);
  EXPECT_FALSE(r.overlaps.empty());
  ASSERT_EQ(r.overlaps.size(), 1u);
  const double expected[4][2] = {{a, b}, {a, 1 - b}, {b, 1 - a}, {1 - b, 1 - a}};
  ASSERT_EQ(r.pairs.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(r.pairs[i].t, expected[i][0], 1e-14) << i;
    EXPECT_NEAR(r.pairs[i].s, expected[i][1], 1e-14) << i;
  }
}

TEST(SelfIntersection, AFoldThatIsNoPalindromeRetracesTheCurve) {
  // p(t) = 4 (t - 1/4)^2 is symmetric about 1/4: B(1/4 - x) = B(1/4 + x) for x in
  // [0, 1/4], a continuum of pairs, and the control points are no palindrome. B = h(p) is
  // found as improper: t in [0, 1/4] retraced by s in [1/4, 1/2].
  const Curve c = composed_with_quadratic({q(1, 4), Rational(-2), Rational(4)});
  ASSERT_NE(c[0], c[4]);
  const SelfIntersectionResult r = self_intersections(c);
  EXPECT_EQ(r.status, IntersectStatus::ok);
  EXPECT_FALSE(r.overlaps.empty());
  EXPECT_TRUE(r.pairs.empty());  // the parabola itself does not cross itself
  ASSERT_EQ(r.overlaps.size(), 1u);
  EXPECT_NEAR(r.overlaps[0].t_interval.lo, 0.0, 1e-15);
  EXPECT_NEAR(r.overlaps[0].t_interval.hi, 0.25, 1e-12);
  EXPECT_NEAR(r.overlaps[0].s_interval.lo, 0.25, 1e-12);
  EXPECT_NEAR(r.overlaps[0].s_interval.hi, 0.5, 1e-12);
}

TEST(SelfIntersection, AFoldedLoopPairsEveryPreimageOfItsDoublePoint) {
  // B(t) = H(p(t)) with H = (-9,0), (13,16), (-13,16), (9,0), whose double point is
  // H(1/4) = H(3/4) = (0, 9) (x(u) = 0 at u = 1/4, 3/4 and x is odd about 1/2), and
  // p(t) = ((3t - 1) / 2)^2, which turns at t = 1/3: B on [0, 1/3] is retraced by B on
  // [1/3, 2/3]. p(t) = 1/4 at t = 0 and 2/3, p(t) = 3/4 at t = (1 + sqrt 3) / 3 only: two
  // pairs.
  const Curve h({{-9, 0}, {13, 16}, {-13, 16}, {9, 0}});
  // Times 60: keeps the degree-6 control points dyadic.
  const auto c = composed(h, {q(1, 4), q(-3, 2), q(9, 4)}, Rational(60));
  ASSERT_TRUE(c.has_value());
  const SelfIntersectionResult r = self_intersections(*c);
  EXPECT_EQ(r.status, IntersectStatus::ok);
  EXPECT_FALSE(r.overlaps.empty());
  ASSERT_EQ(r.overlaps.size(), 1u);
  EXPECT_NEAR(r.overlaps[0].t_interval.lo, 0.0, 1e-15);
  EXPECT_NEAR(r.overlaps[0].t_interval.hi, 1.0 / 3, 1e-12);
  EXPECT_NEAR(r.overlaps[0].s_interval.lo, 1.0 / 3, 1e-12);
  EXPECT_NEAR(r.overlaps[0].s_interval.hi, 2.0 / 3, 1e-12);
  const double far = (1 + std::sqrt(3.0)) / 3;
  ASSERT_EQ(r.pairs.size(), 2u);
  EXPECT_EQ(r.pairs[0].t, 0.0);
  EXPECT_NEAR(r.pairs[0].s, far, 1e-14);
  EXPECT_NEAR(r.pairs[1].t, 2.0 / 3, 1e-14);
  EXPECT_NEAR(r.pairs[1].s, far, 1e-14);
}

TEST(SelfIntersection, WorkCapIsReportedNotHidden) {
  // The fold of AFoldThatIsNoPalindromeRetracesTheCurve with one control point moved by
  // 2^-30 of the curve's size: no longer improper, but within rounding of retracing itself
  // along [0, 1/4] x [1/4, 1/2], which needs far more than this budget.
  Curve c = composed_with_quadratic({q(1, 4), Rational(-2), Rational(4)});
  std::vector<Point2> pts(c.points().begin(), c.points().end());
  pts[2].y += 0x1p-30 * scale(c);
  // 2000 boxes' worth of work units: the search stops before the next box would pass them.
  SelfIntersectionOptions options;
  options.max_work = 2000 * self_intersection_box_cost(Curve(pts).degree());
  const SelfIntersectionResult r = self_intersections(Curve(pts), options);
  EXPECT_EQ(r.status, IntersectStatus::work_cap_reached);
  EXPECT_EQ(r.stats.work, options.max_work);
}

// --- invariances ----------------------------------------------------------------------------

TEST(SelfIntersection, ReversalMapsTToOneMinusT) {
  test::Mulberry32 rng(31);
  int pairs = 0;
  for (int k = 0; k < 200; ++k) {
    const int n = 4 + k % 5;
    std::vector<Point2> p;
    for (int i = 0; i <= n; ++i) p.push_back({rng.next(), rng.next()});
    const Curve c(p);
    const SelfIntersectionResult fwd = self_intersections(c);
    const SelfIntersectionResult bwd = self_intersections(reversed(c));
    ASSERT_EQ(fwd.pairs.size(), bwd.pairs.size()) << k;
    for (std::size_t i = 0; i < fwd.pairs.size(); ++i) {
      // Reversal also reverses the order of the list (sorted by t).
      const SelfIntersection& b = bwd.pairs[bwd.pairs.size() - 1 - i];
      const SelfIntersection& f = fwd.pairs[i];
      if (fwd.pairs.size() > 1) {
        // With several pairs the order by t and by 1 - s can differ: match by nearest.
        const auto it =
            std::min_element(bwd.pairs.begin(), bwd.pairs.end(), [&](const auto& x, const auto& y) {
              return std::fabs(1 - x.s - f.t) < std::fabs(1 - y.s - f.t);
            });
        EXPECT_NEAR(1.0 - it->s, f.t, 1e-12) << k;
        EXPECT_NEAR(1.0 - it->t, f.s, 1e-12) << k;
      } else {
        EXPECT_NEAR(1.0 - b.s, f.t, 1e-12) << k;
        EXPECT_NEAR(1.0 - b.t, f.s, 1e-12) << k;
      }
      ++pairs;
    }
  }
  EXPECT_GT(pairs, 20);
}

TEST(SelfIntersection, PowerOfTwoScalingChangesNothing) {
  const Curve c = degree7_example();
  const SelfIntersectionResult r = self_intersections(c);
  for (const int k : {-1000, -30, 30, 1000}) {
    std::vector<Point2> scaled;
    for (const Point2 p : c.points()) scaled.push_back({std::ldexp(p.x, k), std::ldexp(p.y, k)});
    const SelfIntersectionResult s = self_intersections(Curve(scaled));
    ASSERT_EQ(s.pairs.size(), 1u);
    EXPECT_EQ(s.pairs[0].t, r.pairs[0].t);
    EXPECT_EQ(s.pairs[0].s, r.pairs[0].s);
    EXPECT_EQ(s.pairs[0].point.x, std::ldexp(r.pairs[0].point.x, k));
    EXPECT_EQ(s.pairs[0].point.y, std::ldexp(r.pairs[0].point.y, k));
  }
}

TEST(SelfIntersection, TranslationAndScaleChangeOnlyRounding) {
  const Curve c = degree7_example();
  const SelfIntersectionResult r = self_intersections(c);
  for (const double scale_factor : {1e-8, 0.3, 7.0, 1e8}) {
    for (const Point2 shift : {Point2{0, 0}, Point2{10, -20}}) {
      std::vector<Point2> moved;
      for (const Point2 p : c.points()) moved.push_back(scale_factor * (p + shift));
      const SelfIntersectionResult m = self_intersections(Curve(moved));
      ASSERT_EQ(m.pairs.size(), 1u);
      EXPECT_NEAR(m.pairs[0].t, r.pairs[0].t, 1e-13);
      EXPECT_NEAR(m.pairs[0].s, r.pairs[0].s, 1e-13);
    }
  }
}

// --- against an independent slow search -----------------------------------------------------

/// The slow way: the curve as a polyline of N chords, every pair of non-neighbouring chords
/// that cross, each crossing refined by plain Newton iterations on B(v) - B(u) (fixed count,
/// no safeguards), duplicates merged.
std::vector<std::pair<double, double>> slow_search(const Curve& c, int chords) {
  std::vector<Point2> s;
  for (int i = 0; i <= chords; ++i) s.push_back(evaluate(c, static_cast<double>(i) / chords));
  const Curve h = [&] {
    std::vector<Point2> d;
    for (int i = 0; i < c.degree(); ++i) d.push_back(c.degree() * (c[i + 1] - c[i]));
    return Curve(d);
  }();
  std::vector<std::pair<double, double>> found;
  for (int i = 0; i < chords; ++i) {
    for (int j = i + 2; j < chords; ++j) {
      const Point2 r = s[i + 1] - s[i], t = s[j + 1] - s[j], w = s[j] - s[i];
      const double den = cross(r, t);
      if (den == 0) continue;
      const double al = cross(w, t) / den, be = cross(w, r) / den;
      if (!(al >= 0 && al < 1 && be >= 0 && be < 1)) continue;
      double u = (i + al) / chords, v = (j + be) / chords;
      for (int it = 0; it < 30; ++it) {
        const Point2 f = evaluate(c, v) - evaluate(c, u);
        const Point2 du = evaluate(h, u), dv = evaluate(h, v);
        const double det = cross(-du, dv);
        if (det == 0) break;
        u += cross(-f, dv) / det;
        v += cross(-du, -f) / det;
      }
      found.push_back({u, v});
    }
  }
  std::sort(found.begin(), found.end());
  std::vector<std::pair<double, double>> merged;
  for (const auto& p : found) {
    if (merged.empty() || std::fabs(p.first - merged.back().first) > 1e-9 ||
        std::fabs(p.second - merged.back().second) > 1e-9) {
      merged.push_back(p);
    }
  }
  return merged;
}

TEST(SelfIntersection, RandomCurvesOfDegree3To8AgreeWithTheSlowSearch) {
  test::Mulberry32 rng(2025);
  constexpr int kChords = 2000;
  int total = 0, several = 0;
  for (int k = 0; k < 60; ++k) {
    const int n = 3 + k % 6;
    std::vector<Point2> p;
    for (int i = 0; i <= n; ++i) p.push_back({rng.next(), rng.next()});
    const Curve c(p);
    const SelfIntersectionResult r = self_intersections(c, general_path());
    EXPECT_EQ(r.status, IntersectStatus::ok);
    const auto slow = slow_search(c, kChords);
    // Every crossing of the polyline is found...
    for (const auto& [u, v] : slow) {
      const bool matched =
          std::any_of(r.pairs.begin(), r.pairs.end(), [&](const SelfIntersection& x) {
            return std::fabs(x.t - u) < 1e-10 && std::fabs(x.s - v) < 1e-10;
          });
      EXPECT_TRUE(matched) << "k = " << k << " degree " << n << " missed (" << u << ", " << v
                           << ")";
    }
    // ... and everything found is a true double point; pairs the polyline cannot see are
    // loops narrower than a few chords.
    for (const SelfIntersection& x : r.pairs) {
      EXPECT_LT(exact_residual(c, x.t, x.s), 1e-13) << k;
      const bool seen = std::any_of(slow.begin(), slow.end(), [&](const auto& y) {
        return std::fabs(x.t - y.first) < 1e-10 && std::fabs(x.s - y.second) < 1e-10;
      });
      if (!seen) {
        EXPECT_LT(x.s - x.t, 4.0 / kChords) << k;
      }
    }
    total += static_cast<int>(r.pairs.size());
    several += r.pairs.size() > 1 ? 1 : 0;
  }
  EXPECT_GT(total, 15);
  EXPECT_GT(several, 0);
}

}  // namespace
}  // namespace bezier::core
