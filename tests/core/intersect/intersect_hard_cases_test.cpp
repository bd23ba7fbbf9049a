// Hard cases of curve intersection (part 1: tangencies, near-tangencies, end points), each
// with an independent expectation: exact roots built into the input (dyadic parameters) or
// exact rational arithmetic. Part 2 is intersect_overlap_cases_test.cpp.

#include <gtest/gtest.h>

#include <cmath>
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

// --- Tangencies ----------------------------------------------------------------------

TEST(IntersectHardCases, TangentContactFoundOnceWithKindTangent) {
  // y = (x - 1/2)^2 touches y = 0 at x = 1/2 only; both parameters are exactly 1/2.
  for (const IntersectMethod m : kMethods) {
    SCOPED_TRACE(to_string(m));
    const IntersectionResult r = run(parabola(), horizontal(0.0), m);
    ASSERT_EQ(r.status, IntersectStatus::ok);
    ASSERT_EQ(r.intersections.size(), 1u);
    const Intersection& x = r.intersections[0];
    EXPECT_EQ(x.kind, IntersectionKind::tangent);
    EXPECT_TRUE(x.resolved);
    EXPECT_TRUE(x.t_interval.contains(0.5));
    EXPECT_TRUE(x.s_interval.contains(0.5));
    EXPECT_LT(x.t_interval.width(), 1e-12);
    EXPECT_NEAR(x.t, 0.5, 1e-15);
  }
}

TEST(IntersectHardCases, TangentCurvesWithDifferentCurvatureTouchOnce) {
  // y = 2 (x - 1/2)^2 and y = -(x - 1/2)^2 + ... both through (1/2, 0) with slope 0.
  const Curve f({{0.0, 0.5}, {0.5, -0.5}, {1.0, 0.5}});      // y = 2 (x - 1/2)^2
  const Curve g({{0.0, -0.25}, {0.5, 0.25}, {1.0, -0.25}});  // y = -(x - 1/2)^2
  for (const IntersectMethod m : kMethods) {
    SCOPED_TRACE(to_string(m));
    const IntersectionResult r = run(f, g, m);
    ASSERT_EQ(r.intersections.size(), 1u);
    EXPECT_EQ(r.intersections[0].kind, IntersectionKind::tangent);
    EXPECT_TRUE(r.intersections[0].t_interval.contains(0.5));
    EXPECT_TRUE(r.intersections[0].s_interval.contains(0.5));
    EXPECT_LT(r.intersections[0].t_interval.width(), 1e-12);
  }
}

TEST(IntersectHardCases, NearTangentPairTwoIntersectionsAboutOneE8ApartBothFound) {
  // y = (x - 1/2)^2 meets y = h = 2^-56 at x = 1/2 -+ 2^-28, exactly: two crossings 7.45e-9
  // apart, while the curves stay within 2^-56 (below double rounding of the coordinates)
  // between them.
  const double h = 0x1p-56;
  const double r0 = 0.5 - 0x1p-28, r1 = 0.5 + 0x1p-28;
  for (const IntersectMethod m : kMethods) {
    SCOPED_TRACE(to_string(m));
    const IntersectionResult r = run(parabola(), horizontal(h), m);
    ASSERT_EQ(r.status, IntersectStatus::ok);
    ASSERT_EQ(r.intersections.size(), 2u);
    const Intersection& a = r.intersections[0];
    const Intersection& b = r.intersections[1];
    EXPECT_TRUE(a.t_interval.contains(r0));
    EXPECT_TRUE(b.t_interval.contains(r1));
    EXPECT_TRUE(a.s_interval.contains(r0));
    EXPECT_TRUE(b.s_interval.contains(r1));
    EXPECT_LT(a.t_interval.hi, b.t_interval.lo);  // distinct
    EXPECT_EQ(a.t, r0);
    EXPECT_EQ(b.t, r1);
    EXPECT_EQ(a.kind, IntersectionKind::transversal);
    EXPECT_EQ(b.kind, IntersectionKind::transversal);
  }
}

TEST(IntersectHardCases, NearMissBelowRoundingIsNotAnIntersection) {
  // y = -2^-56 passes below the parabola's vertex: no intersection, although the gap is
  // below the rounding of the coordinates.
  for (const IntersectMethod m : kMethods) {
    SCOPED_TRACE(to_string(m));
    EXPECT_TRUE(run(parabola(), horizontal(-0x1p-56), m).intersections.empty());
  }
}

TEST(IntersectHardCases, PerturbedTangencyOfFixture46CrossesTwiceExactly) {
  // Fixture case 46 ("tangent only up to machine precision"): with the control point
  // rounded to a double, curve 64 crosses curve 63 (y = 4x (1 - x)) twice near s = 0.552.
  // Exactly: h(s) = y(s) - 4 x(s) (1 - x(s)) changes sign at both ends of each interval.
  const auto curves = test::python_bezier::curves();
  const Curve& f = curves.at("63");
  const Curve& g = curves.at("64");
  const IntersectionResult r = run(f, g);
  std::vector<Intersection> near;
  for (const Intersection& x : r.intersections) {
    if (std::fabs(x.s - 0.552) < 1e-3) near.push_back(x);
  }
  ASSERT_EQ(near.size(), 2u);
  const auto h = [&](double s) {
    const test::RPoint2 p = test::exact_evaluate(test::exact_points(g), Rational(s));
    return p.y - Rational(4) * p.x * (Rational(1) - p.x);
  };
  for (const Intersection& x : near) {
    EXPECT_NE(h(x.s_interval.lo).sign(), h(x.s_interval.hi).sign()) << x.s;
    EXPECT_EQ(x.kind, IntersectionKind::transversal);
  }
  EXPECT_GT(near[1].s - near[0].s, 3e-9);
}

// --- End points ----------------------------------------------------------------------

TEST(IntersectHardCases, SharedEndPointIsAnExactRoot) {
  const Curve f({{0.0, 0.0}, {0.25, 0.5}, {1.0, 1.0}});
  const Curve g({{1.0, 1.0}, {1.5, 0.25}, {2.0, 1.0}});
  for (const IntersectMethod m : kMethods) {
    SCOPED_TRACE(to_string(m));
    const IntersectionResult r = run(f, g, m);
    ASSERT_EQ(r.intersections.size(), 1u);
    const Intersection& x = r.intersections[0];
    EXPECT_EQ(x.t, 1.0);
    EXPECT_EQ(x.s, 0.0);
    EXPECT_TRUE(x.t_interval.contains(1.0));
    EXPECT_TRUE(x.s_interval.contains(0.0));
    EXPECT_EQ(x.point, (Point2{1.0, 1.0}));
    EXPECT_EQ(x.kind, IntersectionKind::transversal);
  }
}

TEST(IntersectHardCases, TangentAtSharedEndPoint) {
  // Both start at (0, 0) heading along +x, bending apart: fixture-43 style.
  const Curve f({{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}});
  const Curve g({{0.0, 0.0}, {1.0, 0.0}, {1.0, -1.0}});
  for (const IntersectMethod m : kMethods) {
    SCOPED_TRACE(to_string(m));
    const IntersectionResult r = run(f, g, m);
    ASSERT_EQ(r.intersections.size(), 1u);
    EXPECT_EQ(r.intersections[0].t, 0.0);
    EXPECT_EQ(r.intersections[0].s, 0.0);
    EXPECT_EQ(r.intersections[0].kind, IntersectionKind::tangent);
  }
}

TEST(IntersectHardCases, EndPointOnTheInteriorOfTheOtherCurve) {
  // g starts exactly on f at f(1/2) = (1/2, 1/2) and leaves it transversally.
  const Curve f({{0.0, 0.0}, {0.5, 1.0}, {1.0, 0.0}});
  const Curve g({{0.5, 0.5}, {0.75, -0.5}});
  for (const IntersectionResult& r : {run(f, g), run(g, f)}) {
    ASSERT_EQ(r.intersections.size(), 1u);
  }
  const Intersection x = run(f, g).intersections[0];
  EXPECT_TRUE(x.t_interval.contains(0.5));
  EXPECT_TRUE(x.s_interval.contains(0.0));
  EXPECT_EQ(x.s, 0.0);
}

TEST(IntersectHardCases, ACrossingOnAHalvingLineIsFoundOnce) {
  // f = (0, 0), (1, 4), (3, -4), (-3, 0) has y(t) = 12 t (1 - t) (1 - 2 t): it crosses the
  // x axis at t = 0, 1/2 and 1, at x = 0, 9/8 and -3. g runs along the axis from x = -1 to
  // 5, so s = (x + 1) / 6: the crossings are (0, 1/6) and (1/2, 17/48); x = -3 is beyond g.
  // t = 1/2 is where the first box is halved: the crossing lies on the edge of two boxes,
  // and both of their last separation tests in doubles are within rounding (a search width
  // away from the crossing, the fast pieces cannot tell), so each box is tested again in
  // compensated pieces; the two boxes make one contact.
  const Curve f({{0.0, 0.0}, {1.0, 4.0}, {3.0, -4.0}, {-3.0, 0.0}});
  const Curve g({{-1.0, 0.0}, {5.0, 0.0}});
  const Rational expected_t[2] = {Rational(0), Rational(1) / Rational(2)};
  const Rational expected_s[2] = {Rational(1) / Rational(6), Rational(17) / Rational(48)};
  for (const IntersectMethod m : kMethods) {
    SCOPED_TRACE(to_string(m));
    for (const bool swapped : {false, true}) {
      const IntersectionResult r = swapped ? run(g, f, m) : run(f, g, m);
      ASSERT_EQ(r.status, IntersectStatus::ok);
      ASSERT_EQ(r.intersections.size(), 2u) << "swapped " << swapped;
      for (std::size_t k = 0; k < 2; ++k) {  // sorted by the first curve's parameter either way
        const Intersection& x = r.intersections[k];
        const ParamInterval ti = swapped ? x.s_interval : x.t_interval;
        const ParamInterval si = swapped ? x.t_interval : x.s_interval;
        EXPECT_TRUE(x.resolved);
        EXPECT_EQ(x.kind, IntersectionKind::transversal);
        EXPECT_TRUE(Rational(ti.lo) <= expected_t[k] && expected_t[k] <= Rational(ti.hi));
        EXPECT_TRUE(Rational(si.lo) <= expected_s[k] && expected_s[k] <= Rational(si.hi));
      }
    }
  }
}

}  // namespace
}  // namespace bezier::core
