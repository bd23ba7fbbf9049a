// Hard cases of curve intersection (part 2: overlaps, straight lines, points, high degree,
// scale and translation, budget), each with an independent expectation: exact rational
// arithmetic or a construction whose answer is known (portions, reversals, degree
// elevation, an independent sign count). Part 1 is intersect_hard_cases_test.cpp.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/numeric/binomial.hpp"
#include "core/base/curve.hpp"
#include "core/bernstein/degree.hpp"
#include "core/curve/evaluate.hpp"
#include "core/intersect/intersect.hpp"
#include "tests/core/intersect/exact_roots.hpp"
#include "tests/core/intersect/python_bezier_fixtures.hpp"
#include "tests/support/exact.hpp"

namespace bezier::core {
namespace {

using test::Rational;

const IntersectMethod kMethods[] = {IntersectMethod::hybrid, IntersectMethod::bezier_clipping,
                                    IntersectMethod::subdivision};

IntersectionResult run(const Curve& f, const Curve& g,
                       IntersectMethod method = IntersectMethod::hybrid) {
  IntersectOptions options;
  options.method = method;
  return intersect(f, g, options);
}

/// f(t) = (t, (t - 1/2)^2) and the horizontal line y = h from x = 0 to x = 1.
Curve parabola() {
  return Curve({{0.0, 0.25}, {0.5, -0.25}, {1.0, 0.25}});
}
Curve horizontal(double h) {
  return Curve({{0.0, h}, {1.0, h}});
}

// --- Overlaps ------------------------------------------------------------------------

/// A cubic with dyadic control points: its portions at dyadic parameters and its degree
/// elevations are exact in doubles (checked below in rationals).
Curve dyadic_cubic() {
  return Curve({{0.0, 0.0}, {0.25, 1.0}, {0.75, -0.5}, {1.0, 0.5}});
}

Curve exact_portion(const Curve& c, double a, double b) {
  std::vector<Point2> pts;
  const int n = c.degree();
  for (int i = 0; i <= n; ++i) {
    std::vector<Rational> us;
    for (int j = 0; j < n; ++j) us.push_back(Rational(j < n - i ? a : b));
    const test::RPoint2 p = test::exact_polar(test::exact_points(c), us).front();
    const Point2 d = test::to_double(p);
    EXPECT_EQ(test::RPoint2(test::exact(d)), p) << "portion not exact in doubles";
    pts.push_back(d);
  }
  return Curve(std::move(pts));
}

void expect_single_overlap(const IntersectionResult& r, ParamInterval t, ParamInterval s,
                           bool reversed) {
  ASSERT_EQ(r.status, IntersectStatus::ok);
  EXPECT_TRUE(r.intersections.empty());
  ASSERT_EQ(r.overlaps.size(), 1u);
  EXPECT_NEAR(r.overlaps[0].t_interval.lo, t.lo, 1e-15);
  EXPECT_NEAR(r.overlaps[0].t_interval.hi, t.hi, 1e-15);
  EXPECT_NEAR(r.overlaps[0].s_interval.lo, s.lo, 1e-15);
  EXPECT_NEAR(r.overlaps[0].s_interval.hi, s.hi, 1e-15);
  EXPECT_EQ(r.overlaps[0].reversed, reversed);
}

TEST(IntersectHardCases, IdenticalCurvesOverlapWhole) {
  for (const IntersectMethod m : kMethods) {
    SCOPED_TRACE(to_string(m));
    expect_single_overlap(run(dyadic_cubic(), dyadic_cubic(), m), {0, 1}, {0, 1}, false);
  }
}

TEST(IntersectHardCases, ReversedCurveOverlapsReversed) {
  for (const IntersectMethod m : kMethods) {
    SCOPED_TRACE(to_string(m));
    expect_single_overlap(run(dyadic_cubic(), reversed(dyadic_cubic()), m), {0, 1}, {0, 1}, true);
  }
}

TEST(IntersectHardCases, SubPieceOverlapsItsRange) {
  const Curve piece = exact_portion(dyadic_cubic(), 0.25, 0.75);
  for (const IntersectMethod m : kMethods) {
    SCOPED_TRACE(to_string(m));
    expect_single_overlap(run(dyadic_cubic(), piece, m), {0.25, 0.75}, {0, 1}, false);
    expect_single_overlap(run(piece, dyadic_cubic(), m), {0, 1}, {0.25, 0.75}, false);
  }
}

TEST(IntersectHardCases, ExtensionOverlapsOnTheSharedPart) {
  // g = f on [1/2, 3/2]: they share f on [1/2, 1], which is g on [0, 1/2].
  const Curve extension = exact_portion(dyadic_cubic(), 0.5, 1.5);
  for (const IntersectMethod m : kMethods) {
    SCOPED_TRACE(to_string(m));
    expect_single_overlap(run(dyadic_cubic(), extension, m), {0.5, 1.0}, {0.0, 0.5}, false);
  }
}

TEST(IntersectHardCases, DegreeElevatedCopyOverlaps) {
  // Elevation to degree 5 multiplies by i/5: not dyadic, so rounded; the overlap
  // tolerance absorbs it.
  const Curve elevated = elevate_degree(dyadic_cubic(), 5);
  for (const IntersectMethod m : kMethods) {
    SCOPED_TRACE(to_string(m));
    expect_single_overlap(run(dyadic_cubic(), elevated, m), {0, 1}, {0, 1}, false);
    expect_single_overlap(run(reversed(elevated), dyadic_cubic(), m), {0, 1}, {0, 1}, true);
  }
}

TEST(IntersectHardCases, OverlapWithACrossingOfTheSharedCurve) {
  // Fixture 33: the curves' common algebraic curve crosses itself, so besides the shared
  // end they cross once more; not an overlap inside [0,1]^2.
  const auto curves = test::python_bezier::curves();
  const IntersectionResult r = run(curves.at("42"), curves.at("43"));
  EXPECT_TRUE(r.overlaps.empty());
  EXPECT_EQ(r.intersections.size(), 2u);
}

// --- Straight lines --------------------------------------------------------------------

TEST(IntersectHardCases, CrossingSegmentsAtTheExactRationalPoint) {
  // (0,0)-(1,1) and (0,1)-(1,0) cross at t = s = 1/2; (0,0)-(3,1) and (1,0)-(1,1) at t =
  // 1/3, s = 1/3 (not dyadic: exact containment in rationals).
  for (const IntersectMethod m : kMethods) {
    SCOPED_TRACE(to_string(m));
    const IntersectionResult a = run(Curve({{0, 0}, {1, 1}}), Curve({{0, 1}, {1, 0}}), m);
    ASSERT_EQ(a.intersections.size(), 1u);
    EXPECT_EQ(a.intersections[0].t, 0.5);
    const IntersectionResult b = run(Curve({{0, 0}, {3, 1}}), Curve({{1, 0}, {1, 1}}), m);
    ASSERT_EQ(b.intersections.size(), 1u);
    EXPECT_TRUE(test::contains(b.intersections[0].t_interval, Rational(1) / Rational(3)));
    EXPECT_TRUE(test::contains(b.intersections[0].s_interval, Rational(1) / Rational(3)));
  }
}

TEST(IntersectHardCases, CollinearSegmentsOverlap) {
  // [0, 2] and [1, 3] on y = x/2: shared [1, 2] is t in [1/2, 1] and s in [0, 1/2].
  const IntersectionResult r = run(Curve({{0, 0}, {2, 1}}), Curve({{1, 0.5}, {3, 1.5}}));
  expect_single_overlap(r, {0.5, 1.0}, {0.0, 0.5}, false);
  // Touching at one end: a single tangent point, no overlap.
  const IntersectionResult touch = run(Curve({{0, 0}, {2, 1}}), Curve({{2, 1}, {4, 2}}));
  EXPECT_TRUE(touch.overlaps.empty());
  ASSERT_EQ(touch.intersections.size(), 1u);
  EXPECT_EQ(touch.intersections[0].t, 1.0);
  EXPECT_EQ(touch.intersections[0].s, 0.0);
  EXPECT_EQ(touch.intersections[0].kind, IntersectionKind::tangent);
  // Apart on the same line: nothing.
  const IntersectionResult apart = run(Curve({{0, 0}, {2, 1}}), Curve({{4, 2}, {6, 3}}));
  EXPECT_TRUE(apart.overlaps.empty());
  EXPECT_TRUE(apart.intersections.empty());
}

TEST(IntersectHardCases, StraightCurveDoublingBack) {
  // x(t) = 4t(1 - t) on y = 0: goes from 0 to 1 (t = 1/2) and back. Against the segment
  // [0, 1] it overlaps twice: t in [0, 1/2] and t in [1/2, 1], both all of s.
  const Curve back({{0, 0}, {2, 0}, {0, 0}});
  const IntersectionResult r = run(back, Curve({{0, 0}, {1, 0}}));
  ASSERT_EQ(r.overlaps.size(), 2u);
  EXPECT_NEAR(r.overlaps[0].t_interval.lo, 0.0, 1e-15);
  EXPECT_NEAR(r.overlaps[0].t_interval.hi, 0.5, 1e-12);
  EXPECT_NEAR(r.overlaps[1].t_interval.lo, 0.5, 1e-12);
  EXPECT_NEAR(r.overlaps[1].t_interval.hi, 1.0, 1e-15);
  EXPECT_FALSE(r.overlaps[0].reversed);
  EXPECT_TRUE(r.overlaps[1].reversed);
  // Crossed by a vertical line at x = 1/2: twice, at 4t(1-t) = 1/2.
  const IntersectionResult c = run(back, Curve({{0.5, -1}, {0.5, 1}}));
  ASSERT_EQ(c.intersections.size(), 2u);
  const double r0 = (1 - std::sqrt(0.5)) / 2;
  EXPECT_NEAR(c.intersections[0].t, r0, 1e-15);
  EXPECT_NEAR(c.intersections[1].t, 1 - r0, 1e-15);
}

// --- Points ----------------------------------------------------------------------------

TEST(IntersectHardCases, CurveCollapsedToAPoint) {
  const Curve point({{0.5, 0.5}, {0.5, 0.5}, {0.5, 0.5}});
  const Curve f({{0.0, 0.0}, {0.5, 1.0}, {1.0, 0.0}});  // through (1/2, 1/2) at t = 1/2
  for (const IntersectMethod m : kMethods) {
    SCOPED_TRACE(to_string(m));
    const IntersectionResult r = run(point, f, m);
    ASSERT_EQ(r.intersections.size(), 1u);
    const Intersection& x = r.intersections[0];
    EXPECT_EQ(x.kind, IntersectionKind::degenerate);
    EXPECT_EQ(x.t_interval, (ParamInterval{0.0, 1.0}));  // every t of the point curve
    EXPECT_TRUE(x.s_interval.contains(0.5));
    EXPECT_NEAR(x.s, 0.5, 1e-15);
    // Swapped, and off the curve.
    EXPECT_EQ(run(f, point, m).intersections.size(), 1u);
    EXPECT_TRUE(run(Curve({{0.5, 0.75}, {0.5, 0.75}}), f, m).intersections.empty());
  }
  // Two points: the same one (every t and s) or nothing.
  EXPECT_EQ(run(point, point).intersections.size(), 1u);
  EXPECT_TRUE(run(point, Curve({{0.0, 0.5}, {0.0, 0.5}})).intersections.empty());
}

// --- High degree -----------------------------------------------------------------------

/// Bernstein coefficients of T_10(2u - 1) (Chebyshev), from its power form in rationals.
std::vector<double> chebyshev10() {
  // T_10(x) = 512x^10 - 1280x^8 + 1120x^6 - 400x^4 + 50x^2 - 1; x = 2u - 1.
  const long long c[11] = {-1, 0, 50, 0, -400, 0, 1120, 0, -1280, 0, 512};
  std::vector<Rational> power(11, Rational(0));  // in u
  for (int k = 0; k <= 10; ++k) {
    // (2u - 1)^k = Σ_j C(k, j) 2^j u^j (-1)^(k-j)
    for (int j = 0; j <= k; ++j) {
      Rational term =
          Rational(c[k]) * Rational(static_cast<long long>(binomial(k, j))) * Rational(1LL << j);
      if ((k - j) % 2 == 1) term = -term;
      power[static_cast<std::size_t>(j)] += term;
    }
  }
  std::vector<double> b;
  for (int i = 0; i <= 10; ++i) {  // b_i = Σ_{j<=i} C(i, j) / C(10, j) a_j
    Rational sum(0);
    for (int j = 0; j <= i; ++j) {
      sum += Rational(static_cast<long long>(binomial(i, j))) /
             Rational(static_cast<long long>(binomial(10, j))) * power[static_cast<std::size_t>(j)];
    }
    b.push_back(sum.to_double());
  }
  return b;
}

TEST(IntersectHardCases, TwoDegreeTenCurvesCrossingManyTimesAllFound) {
  // f: (u, T10(2u - 1)), g: ((1 + T10(2v - 1)) / 2, 2v - 1): each oscillates ten times
  // across the other. The count is checked independently: f's x and g's y are monotone,
  // so every crossing is a sign change of x_g(v(u)) - x_f(u), v(u) solving
  // y_g(v) = y_f(u); sampled at 20000 points.
  const std::vector<double> cheb = chebyshev10();
  std::vector<Point2> fp, gp;
  for (int i = 0; i <= 10; ++i) {
    fp.push_back({i / 10.0, cheb[static_cast<std::size_t>(i)]});
    gp.push_back({(1 + cheb[static_cast<std::size_t>(i)]) / 2, 2 * (i / 10.0) - 1});
  }
  const Curve f(fp), g(gp);
  const auto at = [](const Curve& c, double t) { return evaluate(c, t); };
  int sign_changes = 0;
  double last = 0.0;
  for (int k = 0; k <= 20000; ++k) {
    const double u = k / 20000.0;
    const Point2 p = at(f, u);
    double lo = 0.0, hi = 1.0;  // y_g increasing in v
    for (int it = 0; it < 60; ++it) {
      const double mid = (lo + hi) / 2;
      (at(g, mid).y < p.y ? lo : hi) = mid;
    }
    const double phi = at(g, (lo + hi) / 2).x - p.x;
    if (k > 0 && (phi < 0) != (last < 0)) ++sign_changes;
    last = phi;
  }
  ASSERT_GE(sign_changes, 30);
  for (const IntersectMethod m : {IntersectMethod::hybrid, IntersectMethod::bezier_clipping}) {
    SCOPED_TRACE(to_string(m));
    const IntersectionResult r = run(f, g, m);
    ASSERT_EQ(r.status, IntersectStatus::ok);
    EXPECT_EQ(static_cast<int>(r.intersections.size()), sign_changes);
    for (const Intersection& x : r.intersections) {
      EXPECT_TRUE(x.resolved);
      EXPECT_LT(test::exact_gap(f, g, x.t, x.s), 1e-14);
    }
  }
}

// --- Scale and translation --------------------------------------------------------------

Curve transformed(const Curve& c, double scale, Point2 shift) {
  std::vector<Point2> pts;
  for (const Point2 p : c.points()) pts.push_back({p.x * scale + shift.x, p.y * scale + shift.y});
  return Curve(std::move(pts));
}

TEST(IntersectHardCases, TranslationAndPowerOfTwoScalingGiveTheSameBits) {
  // Coordinates on a 2^-10 grid: adding 1e7 and scaling by 2^27 are exact, and the working
  // frame moves with the curves, so every number of the answer is the same.
  const Curve f({{0.0, 0.0}, {0.25, 1.0}, {0.75, -0.5}, {1.0, 0.5}});
  const Curve g({{0.0, 0.5}, {0.5, -0.75}, {0.625, 1.25}, {1.0, 0.0}});
  const IntersectionResult base = run(f, g);
  ASSERT_GE(base.intersections.size(), 2u);
  for (const auto& [scale, shift] :
       {std::pair{1.0, Point2{1e7, -1e7}}, std::pair{0x1p27, Point2{0, 0}},
        std::pair{0x1p-27, Point2{0, 0}}, std::pair{0x1p-27, Point2{3 * 0x1p-30, -0x1p-29}}}) {
    SCOPED_TRACE(std::to_string(scale) + " " + std::to_string(shift.x));
    const IntersectionResult r = run(transformed(f, scale, shift), transformed(g, scale, shift));
    ASSERT_EQ(r.intersections.size(), base.intersections.size());
    for (std::size_t i = 0; i < r.intersections.size(); ++i) {
      EXPECT_EQ(r.intersections[i].t, base.intersections[i].t);
      EXPECT_EQ(r.intersections[i].s, base.intersections[i].s);
      EXPECT_EQ(r.intersections[i].t_interval, base.intersections[i].t_interval);
      EXPECT_EQ(r.intersections[i].s_interval, base.intersections[i].s_interval);
    }
  }
}

TEST(IntersectHardCases, DecimalScalingsGiveTheSameParametersUpToRounding) {
  // 1e-8 and 1e8 round the coordinates: the parameters move by the rounding only.
  const Curve f({{0.0, 0.0}, {0.25, 1.0}, {0.75, -0.5}, {1.0, 0.5}});
  const Curve g({{0.0, 0.5}, {0.5, -0.75}, {0.625, 1.25}, {1.0, 0.0}});
  const IntersectionResult base = run(f, g);
  for (const double scale : {1e-8, 1e8}) {
    for (const IntersectMethod m : kMethods) {
      SCOPED_TRACE(std::to_string(scale) + " " + std::string(to_string(m)));
      const IntersectionResult r =
          run(transformed(f, scale, {0, 0}), transformed(g, scale, {0, 0}), m);
      ASSERT_EQ(r.intersections.size(), base.intersections.size());
      for (std::size_t i = 0; i < r.intersections.size(); ++i) {
        EXPECT_NEAR(r.intersections[i].t, base.intersections[i].t, 1e-14);
        EXPECT_NEAR(r.intersections[i].s, base.intersections[i].s, 1e-14);
        EXPECT_NEAR(r.intersections[i].point.x, base.intersections[i].point.x * scale,
                    1e-14 * scale);
      }
    }
  }
}

TEST(IntersectHardCases, ExtremeMagnitudes) {
  // Near the top of the double range and in the subnormal range (2^-1060: the coordinates,
  // multiples of 2^-2 there, are still exact).
  const Curve f({{0.0, 0.0}, {1.0, 2.0}, {2.0, 0.0}});
  const Curve g({{0.0, 0.75}, {2.0, 0.75}});
  for (const double scale : {0x1p1000, 1e300, 0x1p-1060}) {
    SCOPED_TRACE(scale);
    const IntersectionResult r = run(transformed(f, scale, {0, 0}), transformed(g, scale, {0, 0}));
    ASSERT_EQ(r.intersections.size(), 2u);
    EXPECT_TRUE(r.intersections[0].t_interval.contains(0.25));
    EXPECT_TRUE(r.intersections[1].t_interval.contains(0.75));
    EXPECT_NEAR(r.intersections[0].t, 0.25, 1e-15);
  }
}

// --- Budget and tolerance ----------------------------------------------------------------

TEST(IntersectHardCases, NearRetracingHitsTheWorkCapNotAHang) {
  // g(s) = f(4 s (1 - s)) (found as two overlaps: common_arc_test.cpp) with its middle
  // control point moved by 2^-34: no longer an overlap, but within 2^-35 of f all along,
  // which takes the search about a million units of work: under a small budget it must
  // stop with the cap, not run on.
  const Curve f({{0.0, 0.0}, {0.5, 1.0}, {1.0, 0.0}});
  // x(s) = 4s - 4s^2 and y(s) = 8s - 40s^2 + 64s^3 - 32s^4, in Bernstein form (degree 4).
  const Curve g({{0.0, 0.0}, {1.0, 2.0}, {4.0 / 3.0, -8.0 / 3.0 + 0x1p-34}, {1.0, 2.0}, {0.0, 0.0}});
  IntersectOptions options;
  options.max_work = 3000;
  const IntersectionResult r = intersect(f, g, options);
  EXPECT_EQ(r.status, IntersectStatus::work_cap_reached);
  EXPECT_TRUE(r.overlaps.empty());
  EXPECT_LE(r.stats.iterations, options.max_work);
}

TEST(IntersectHardCases, ToleranceBelowDoublePrecisionIsRefused) {
  IntersectOptions options;
  options.tolerance = 1e-15;
  EXPECT_EQ(intersect(parabola(), horizontal(0.0), options).status,
            IntersectStatus::tolerance_too_small);
  options.tolerance = kMinTolerance;
  const IntersectionResult r = intersect(Curve({{0, 0}, {1, 1}}), Curve({{0, 1}, {1, 0}}), options);
  EXPECT_EQ(r.status, IntersectStatus::ok);
  ASSERT_EQ(r.intersections.size(), 1u);
  EXPECT_LT(r.intersections[0].t_interval.width(), kMinTolerance);
}

}  // namespace
}  // namespace bezier::core
