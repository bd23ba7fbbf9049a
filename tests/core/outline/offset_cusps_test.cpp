// Tests of core/outline/offset_cusps.hpp: where the parallel curve B + d N turns back.
//
// Closed form: the parabola B(t) = (2t - 1, (2t - 1)^2) is y = x^2 with x = 2t - 1, whose
// radius of curvature is R(x) = (1 + 4x^2)^(3/2) / 2 on its concave (left, upper) side; the
// parallel curve at d > 0 has its cusps where R(x) = d. Independent property: on random
// curves 1 - d κ(t), with κ from the derivatives, changes sign between dense samples only
// around a reported cusp, and vanishes at each.

#include "core/outline/offset_cusps.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/curve/derivative.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::outline {
namespace {

using core::Curve;
using core::Point2;

/// 1 - d κ(t), κ = cross(B', B'') / |B'|^3 from derivatives_at.
double one_minus_d_kappa(const Curve& curve, double d, double t) {
  const auto k = core::derivatives_at(curve, t, 2);
  const double speed = core::length(k[0]);
  return 1.0 - d * core::cross(k[0], k[1]) / (speed * speed * speed);
}

TEST(OffsetCusps, ParabolaCuspsWhereTheRadiusIsTheDistance) {
  const Curve parabola({{-1, 1}, {0, -1}, {1, 1}});
  // R(1/2) = 2^(3/2) / 2 = sqrt(2): cusps at x = ±1/2, t = 1/4 and 3/4.
  const std::vector<double> cusps = offset_cusps(parabola, std::sqrt(2.0));
  ASSERT_EQ(cusps.size(), 2u);
  EXPECT_NEAR(cusps[0], 0.25, 1e-12);
  EXPECT_NEAR(cusps[1], 0.75, 1e-12);
  // On the convex side, and closer than the smallest radius 1/2: none.
  EXPECT_TRUE(offset_cusps(parabola, -std::sqrt(2.0)).empty());
  EXPECT_TRUE(offset_cusps(parabola, 0.25).empty());
  // R(3/4) = (13/4)^(3/2) / 2: t = 1/8 and 7/8.
  const std::vector<double> wide = offset_cusps(parabola, std::pow(3.25, 1.5) / 2);
  ASSERT_EQ(wide.size(), 2u);
  EXPECT_NEAR(wide[0], 0.125, 1e-12);
  EXPECT_NEAR(wide[1], 0.875, 1e-12);
}

TEST(OffsetCusps, LinesAndTheCurveItselfHaveNone) {
  EXPECT_TRUE(offset_cusps(Curve({{0, 0}, {1, 1}}), 1.0).empty());
  EXPECT_TRUE(offset_cusps(Curve({{0, 0}, {1, 1}, {2, 2}, {3, 3}}), 1.0).empty());
  EXPECT_TRUE(offset_cusps(Curve({{0, 0}, {1, 2}, {2, 0}}), 0.0).empty());
}

TEST(OffsetCusps, CuspOfTheCurveItselfIsNotOneOfTheOffset) {
  // (0,0),(2,2),(-1,2),(1,0): B'(1/2) = 0. Its parallel curves jump there; they turn back only
  // where the radius is |d|.
  const Curve cusped({{0, 0}, {2, 2}, {-1, 2}, {1, 0}});
  for (const double d : {0.05, -0.05, 0.3}) {
    for (const double t : offset_cusps(cusped, d)) {
      EXPECT_GT(std::fabs(t - 0.5), 1e-6) << d;
      EXPECT_NEAR(one_minus_d_kappa(cusped, d, t), 0.0, 1e-8) << d << " " << t;
    }
  }
}

TEST(OffsetCusps, SignChangesOfOneMinusDKappaAreTheCusps) {
  test::Mulberry32 rng(2031);
  for (int trial = 0; trial < 40; ++trial) {
    const int n = 2 + trial % 4;
    std::vector<Point2> p;
    for (int k = 0; k <= n; ++k) p.push_back({rng.uniform(-1, 1), rng.uniform(-1, 1)});
    const Curve curve(p);
    const double d = rng.uniform(-0.5, 0.5);
    const std::vector<double> cusps = offset_cusps(curve, d);
    for (const double t : cusps) EXPECT_NEAR(one_minus_d_kappa(curve, d, t), 0.0, 1e-7) << trial;
    // Every sign change between samples brackets a reported cusp.
    const int samples = 4000;
    double previous = one_minus_d_kappa(curve, d, 0.0);
    for (int i = 1; i <= samples; ++i) {
      const double t0 = static_cast<double>(i - 1) / samples, t1 = static_cast<double>(i) / samples;
      const double value = one_minus_d_kappa(curve, d, t1);
      if (std::isfinite(value) && std::isfinite(previous) && (value > 0) != (previous > 0)) {
        const bool found = std::any_of(cusps.begin(), cusps.end(),
                                       [&](double t) { return t >= t0 - 1e-9 && t <= t1 + 1e-9; });
        // A sign change through infinity (B' = 0 between the samples) is not a cusp of O.
        const bool through_infinity = std::fabs(value) > 1e3 || std::fabs(previous) > 1e3;
        EXPECT_TRUE(found || through_infinity)
            << "trial " << trial << " between " << t0 << " and " << t1;
      }
      previous = value;
    }
  }
}

/// The hairpin B(t) = (3 t (1 - t), g (3 t^2 - 2 t^3)) (control points (0,0), (1,0), (1,g),
/// (0,g)): out along the x axis and back g above it, turning at t = 1/2 where |B'| = 3g/2.
/// f(t) = |B'|^3 - d cross(B', B''), from B' = (3 - 6t, 6g t (1 - t)) and B'' = (-6, 6g (1 - 2t)),
/// in long double: the parallel curve at d turns back where f changes sign.
long double hairpin_f(long double g, long double d, long double t) {
  const long double x1 = 3 - 6 * t, y1 = 6 * g * t * (1 - t), x2 = -6, y2 = 6 * g * (1 - 2 * t);
  const long double speed = std::sqrt(x1 * x1 + y1 * y1);
  return speed * speed * speed - d * (x1 * y2 - y1 * x2);
}

/// The root of hairpin_f between lo and hi (of opposite signs there), by bisection.
long double hairpin_root(long double g, long double d, long double lo, long double hi) {
  const bool rising = hairpin_f(g, d, hi) > 0;
  for (int i = 0; i < 200; ++i) {
    const long double mid = (lo + hi) / 2;
    ((hairpin_f(g, d, mid) > 0) == rising ? hi : lo) = mid;
  }
  return (lo + hi) / 2;
}

TEST(OffsetCusps, HairpinsTurnBackNextToTheirTip) {
  // Next to the tip |B'| is small but not zero, so |B'|^3 at the cusps of O (about
  // (9 g d)^(1/3) / 6 from t = 1/2) is far below the coefficients of p on [0, 1]; the
  // cusps are found on halved pieces. The radius at the tip, (3g/2)^3 / (9g), is below d on
  // the left for every g here, and f > 0 at t = 0.4 and 0.6, so there are two cusps.
  const double d = 0.005;
  for (const double g : {1e-2, 1e-3, 3e-4, 1e-6, 1e-9}) {
    const Curve hairpin({{0, 0}, {1, 0}, {1, g}, {0, g}});
    const std::vector<double> cusps = offset_cusps(hairpin, d);
    ASSERT_EQ(cusps.size(), 2u) << g;
    EXPECT_NEAR(cusps[0], static_cast<double>(hairpin_root(g, d, 0.4L, 0.5L)), 1e-12) << g;
    EXPECT_NEAR(cusps[1], static_cast<double>(hairpin_root(g, d, 0.5L, 0.6L)), 1e-12) << g;
    // On the right the curve turns away: no cusp.
    EXPECT_TRUE(offset_cusps(hairpin, -d).empty()) << g;
  }
}

TEST(OffsetCusps, PowerOfTwoScalingScalesTheDistance) {
  // The arch (3t, 6t(1 - t)) has radius 3/4 at its apex on its right: at d = -1 its parallel
  // curve turns back twice around the apex.
  const Curve curve({{0, 0}, {1, 2}, {2, 2}, {3, 0}});
  const std::vector<double> unit = offset_cusps(curve, -1.0);
  ASSERT_EQ(unit.size(), 2u);
  // 1 - d κ = 1 - 36 / (9 + u^2)^(3/2) with u = 6 - 12 t: zero at u^2 = 36^(2/3) - 9.
  const double u = std::sqrt(std::cbrt(36.0 * 36.0) - 9.0);
  EXPECT_NEAR(unit[0], (6 - u) / 12, 1e-12);
  EXPECT_NEAR(unit[1], (6 + u) / 12, 1e-12);
  for (const double s : {0x1p-500, 0x1p500}) {
    std::vector<Point2> scaled;
    for (const Point2 q : curve.points()) scaled.push_back(s * q);
    EXPECT_EQ(offset_cusps(Curve(scaled), -s), unit) << s;
  }
}

}  // namespace
}  // namespace bezier::outline
