#include "core/cubic/double_point.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "core/curve/evaluate.hpp"
#include "tests/support/exact.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

using Cubic = std::array<Point2, 4>;

std::optional<CubicDoublePoint> double_point(const Cubic& p) {
  return cubic_double_point(std::span<const Point2, 4>(p));
}

Curve as_curve(const Cubic& p) {
  return Curve(std::vector<Point2>(p.begin(), p.end()));
}

// P0 + 3at + 3bt² + ct³ from a, b, c.
Cubic from_power_form(Point2 p0, Point2 a, Point2 b, Point2 c) {
  return {p0, p0 + a, p0 + 2 * a + b, p0 + 3 * a + 3 * b + c};
}

TEST(CubicDoublePoint, RecoversTheParametersItWasBuiltFrom) {
  // B(s) = B(t) iff 3a + 3b(s + t) + c(s² + st + t²) = 0; pick a, b and solve for c, with
  // s, t anywhere on the line (the unbounded curve), e.g. s = −1/2, t = 3/2.
  struct Pair {
    double s, t;
  };
  for (const Pair pr :
       {Pair{-0.5, 1.5}, Pair{0.25, 0.75}, Pair{-2, -1}, Pair{1.25, 4}, Pair{0, 0.5}}) {
    const double sum = pr.s + pr.t, q = pr.s * pr.s + pr.s * pr.t + pr.t * pr.t;
    const Point2 a{1, 2}, b{-3, 1};
    const Point2 c = (-3.0 / q) * (a + sum * b);  // not exact unless q is dyadic: close enough
    const Cubic p = from_power_form({0.5, -1}, a, b, c);
    const auto dp = double_point(p);
    ASSERT_TRUE(dp.has_value());
    EXPECT_NEAR(dp->t1, pr.s, 1e-13);
    EXPECT_NEAR(dp->t2, pr.t, 1e-13);
    EXPECT_EQ(dp->on_segment, pr.s >= 0 && pr.t <= 1);
    const Curve curve = as_curve(p);
    EXPECT_LE(length(evaluate(curve, pr.s) - dp->point), 1e-12);
  }
}

TEST(CubicDoublePoint, ClosedCurveIsTheTrivialPair) {
  const Cubic p = {Point2{1, 1}, Point2{5, 3}, Point2{-2, 6}, Point2{1, 1}};
  const auto dp = double_point(p);
  ASSERT_TRUE(dp.has_value());
  EXPECT_EQ(dp->t1, 0.0);
  EXPECT_EQ(dp->t2, 1.0);
  EXPECT_EQ(dp->point, (Point2{1, 1}));
  EXPECT_TRUE(dp->on_segment);
}

TEST(CubicDoublePoint, NoneWithoutARealLoop) {
  // Serpentine (canonical point above the cusp edge), cusp, quadratic, line, point.
  for (const Cubic& p : {Cubic{Point2{0, 0}, Point2{0, 1}, Point2{1, 1}, Point2{0, 2}},
                         Cubic{Point2{0, 0}, Point2{0, 1}, Point2{1, 1}, Point2{-1, 0}},
                         Cubic{Point2{0, 0}, Point2{2, 4}, Point2{4, 4}, Point2{6, 0}},
                         Cubic{Point2{0, 0}, Point2{2, 2}, Point2{-1, -1}, Point2{1, 1}},
                         Cubic{Point2{3, 3}, Point2{3, 3}, Point2{3, 3}, Point2{3, 3}}}) {
    EXPECT_FALSE(double_point(p).has_value());
  }
}

TEST(CubicDoublePoint, RandomLoopsMeetThemselves) {
  test::Mulberry32 rng(81);
  int found = 0;
  for (int i = 0; i < 4000; ++i) {
    Cubic p;
    for (Point2& q : p) q = {rng.uniform(-1, 1), rng.uniform(-1, 1)};
    const auto dp = double_point(p);
    if (!dp) continue;
    ++found;
    ASSERT_LT(dp->t1, dp->t2);
    const Curve curve = as_curve(p);
    // Within a few ulps of the scale of the (possibly extrapolated) control polygon.
    const double reach = std::pow(std::max({1.0, std::fabs(dp->t1), std::fabs(dp->t2)}), 3);
    EXPECT_LE(length(evaluate(curve, dp->t1) - evaluate(curve, dp->t2)), 1e-11 * reach);
    // Reversal: (t1, t2) -> (1 − t2, 1 − t1), the same point.
    const auto r = double_point({p[3], p[2], p[1], p[0]});
    ASSERT_TRUE(r.has_value());
    EXPECT_NEAR(r->t1, 1 - dp->t2, 1e-11 * reach);
    EXPECT_NEAR(r->t2, 1 - dp->t1, 1e-11 * reach);
    EXPECT_EQ(r->on_segment, dp->on_segment);
  }
  EXPECT_GT(found, 1000);
}

TEST(CubicDoublePoint, CurveOverload) {
  const Curve c({{0, 0}, {0, 1}, {1, 1}, {-3, -6}});  // canonical (−3, −6): t = (0, 1/2)
  const auto dp = cubic_double_point(c);
  ASSERT_TRUE(dp.has_value());
  EXPECT_EQ(dp->t1, 0.0);
  EXPECT_EQ(dp->t2, 0.5);
  EXPECT_EQ(dp->point, (Point2{0, 0}));
}

}  // namespace
}  // namespace bezier::core
