#include "core/curve/area.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "tests/support/exact.hpp"
#include "tests/support/exact_polynomial.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

using test::Rational;

constexpr double kEps = std::numeric_limits<double>::epsilon();

/// Random control points that are multiples of 2^-12 in [-1, 1): exact in the tests'
/// rational arithmetic, generic otherwise.
Curve random_dyadic_curve(test::Mulberry32& rng, int degree) {
  std::vector<Point2> pts;
  for (int i = 0; i <= degree; ++i) {
    pts.push_back(
        {std::floor(rng.uniform(-4096, 4096)) / 4096, std::floor(rng.uniform(-4096, 4096)) / 4096});
  }
  return Curve(std::move(pts));
}

/// Σ |P_i|^2 bound on the size of any area term, for tolerances.
double area_scale(const Curve& c) {
  const double s = scale(c);
  return s * s;
}

TEST(Area, EnclosedAreaMatchesExactPowerBasisIntegralForEveryDegree) {
  test::Mulberry32 rng(2024);
  for (int degree = 1; degree <= 30; ++degree) {
    for (int k = 0; k < 4; ++k) {
      const Curve c = random_dyadic_curve(rng, degree);
      const Rational exact =
          test::exact_enclosed_area(test::power_form(c), Rational(0), Rational(1));
      // Rounding: each of the ~n^2/2 terms carries a few roundings of its size.
      const double tol = 4.0 * degree * degree * kEps * area_scale(c);
      EXPECT_NEAR(enclosed_area(c), exact.to_double(), tol)
          << "degree " << degree << " seed state " << rng.state();
    }
  }
}

TEST(Area, ExactAtDegreeThirtyOnAlternatingControlPoints) {
  // The integrand of a degree-30 curve has degree 59, beyond what a fixed 20-point Gauss
  // rule integrates exactly (39); the closed form has no such limit. Alternating control
  // points make the terms cancel heavily.
  std::vector<Point2> pts;
  for (int i = 0; i <= 30; ++i)
    pts.push_back({std::ldexp(1.0, -(i % 7)) * (i % 3 - 1), (i % 2 == 0) ? 1.0 : -1.0});
  const Curve c(pts);
  const Rational exact = test::exact_enclosed_area(test::power_form(c), Rational(0), Rational(1));
  EXPECT_NEAR(enclosed_area(c), exact.to_double(), 4.0 * 30 * 30 * kEps);
}

TEST(Area, ParabolicSegmentIsTwoThirdsOfItsTriangle) {
  // Archimedes: the segment cut off by a chord is 2/3 of the triangle P0 P1 P2 (here
  // base 2, height 2, traversed clockwise: negative).
  const Curve c({{0, 0}, {1, 2}, {2, 0}});
  EXPECT_EQ(enclosed_area(c), -4.0 / 3.0);
}

TEST(Area, GraphOfOneMinusXCubed) {
  // x = t, y = 1 - t^3: ∫_0^1 (1 - x^3) dx = 3/4, minus the triangle under the chord (1/2):
  // 1/4, clockwise. Control points: x = 0, 1/3, 2/3, 1 (rounded), y = 1, 1, 1, 0.
  const Curve c({{0, 1}, {1.0 / 3.0, 1}, {2.0 / 3.0, 1}, {1, 0}});
  EXPECT_NEAR(enclosed_area(c), -0.25, 4 * kEps);
}

TEST(Area, SignedAreaOfAPieceMatchesTheExactIntegral) {
  test::Mulberry32 rng(7);
  for (int degree = 1; degree <= 12; ++degree) {
    const Curve c = random_dyadic_curve(rng, degree);
    const test::PowerCurve pc = test::power_form(c);
    for (const auto& [a, b] :
         {std::pair{0.25, 0.75}, {0.0, 0.5}, {0.125, 1.0}, {0.75, 0.25}, {0.5, 0.5}}) {
      const double tol = 8.0 * degree * degree * kEps * area_scale(c);
      EXPECT_NEAR(signed_area(c, a, b), test::exact_green_integral(pc, a, b).to_double(), tol)
          << "degree " << degree << " [" << a << ", " << b << "]";
      EXPECT_NEAR(enclosed_area(c, a, b), test::exact_enclosed_area(pc, a, b).to_double(), tol)
          << "degree " << degree << " [" << a << ", " << b << "]";
    }
    EXPECT_NEAR(signed_area(c), test::exact_green_integral(pc, 0, 1).to_double(),
                8.0 * degree * degree * kEps * area_scale(c));
  }
}

TEST(Area, EmptyAndReversedIntervals) {
  const Curve c({{0, 0}, {1, 2}, {3, -1}, {4, 1}});
  EXPECT_EQ(enclosed_area(c, 0.3, 0.3), 0.0);
  EXPECT_NEAR(enclosed_area(c, 0.8, 0.2), -enclosed_area(c, 0.2, 0.8), 16 * kEps);
  EXPECT_NEAR(enclosed_area(c, 0.0, 0.0), 0.0, 0.0);
}

TEST(Area, SegmentsAndPointsEncloseNothing) {
  EXPECT_EQ(enclosed_area(Curve({{1, 2}, {3, 5}})), 0.0);
  EXPECT_EQ(enclosed_area(Curve({{1, 2}})), 0.0);
  EXPECT_EQ(enclosed_area(Curve({{1, 2}, {1, 2}, {1, 2}})), 0.0);
  // Collinear control points: zero area although the curve runs back and forth.
  EXPECT_EQ(enclosed_area(Curve({{0, 0}, {2, 2}, {1, 1}, {3, 3}})), 0.0);
}

TEST(Area, TranslationChangesNothing) {
  test::Mulberry32 rng(11);
  for (int degree = 2; degree <= 10; ++degree) {
    const Curve c = random_dyadic_curve(rng, degree);
    for (const Point2 shift : {Point2{0.5, -0.25}, Point2{1024, 4096}, Point2{-1e6, 3e6}}) {
      std::vector<Point2> moved;
      for (const Point2 p : c.points()) moved.push_back(p + shift);
      const double a = enclosed_area(c);
      // Coordinates near |shift| are rounded to ulp(|shift|); the area moves accordingly.
      const double tol = 16.0 * degree * degree * kEps * (area_scale(c) + length(shift) * scale(c));
      EXPECT_NEAR(enclosed_area(Curve(moved)), a, tol) << "degree " << degree;
    }
  }
}

TEST(Area, ScalingByTwoToTheKIsExact) {
  test::Mulberry32 rng(12);
  const Curve c = random_dyadic_curve(rng, 7);
  for (const int k : {-30, -1, 1, 20}) {
    std::vector<Point2> scaled;
    for (const Point2 p : c.points()) scaled.push_back({std::ldexp(p.x, k), std::ldexp(p.y, k)});
    EXPECT_EQ(enclosed_area(Curve(scaled)), std::ldexp(enclosed_area(c), 2 * k));
  }
}

TEST(Area, ExactScalingHoldsToTheEdgesOfTheDoubleRange) {
  // Coordinates near 2^520 would overflow the cross products of their differences, and
  // near 2^-530 underflow them, if taken as given; the area itself is 2^1040 / 2^-1060
  // times the unscaled one: the first overflows to infinity (with its sign, not NaN), the
  // second is a subnormal.
  test::Mulberry32 rng(18);
  const Curve c = random_dyadic_curve(rng, 6);
  const double a = enclosed_area(c);
  const auto scaled = [&](int k) {
    std::vector<Point2> pts;
    for (const Point2 p : c.points()) pts.push_back({std::ldexp(p.x, k), std::ldexp(p.y, k)});
    return Curve(pts);
  };
  EXPECT_EQ(enclosed_area(scaled(500)), std::ldexp(a, 1000));
  EXPECT_EQ(enclosed_area(scaled(-500)), std::ldexp(a, -1000));
  EXPECT_EQ(enclosed_area(scaled(-530)), std::ldexp(a, -1060));
  const double huge = enclosed_area(scaled(520));
  EXPECT_TRUE(std::isinf(huge));
  EXPECT_EQ(std::signbit(huge), std::signbit(a));
  // Differences of +-1e308 coordinates overflow if taken as given.
  EXPECT_TRUE(std::isinf(enclosed_area(Curve({{-1e308, 0}, {1e308, 1e308}, {1e308, -1e308}}))));
}

TEST(Area, ScalesWithTheSquareOfAnyFactor) {
  test::Mulberry32 rng(13);
  const Curve c = random_dyadic_curve(rng, 6);
  const double a = enclosed_area(c);
  for (const double s : {1e-8, 3.0, 0.1, 1e8}) {
    std::vector<Point2> scaled;
    for (const Point2 p : c.points()) scaled.push_back(s * p);
    EXPECT_NEAR(enclosed_area(Curve(scaled)) / (s * s), a, 1e-14 * area_scale(c)) << s;
  }
}

TEST(Area, RotationChangesNothing) {
  test::Mulberry32 rng(14);
  const Curve c = random_dyadic_curve(rng, 8);
  const double a = enclosed_area(c);
  for (const double angle : {0.3, 1.0, 2.5, -1.2}) {
    const double co = std::cos(angle), si = std::sin(angle);
    std::vector<Point2> turned;
    for (const Point2 p : c.points()) turned.push_back({co * p.x - si * p.y, si * p.x + co * p.y});
    EXPECT_NEAR(enclosed_area(Curve(turned)), a, 1e-14 * area_scale(c)) << angle;
  }
}

TEST(Area, AffineMapMultipliesByTheDeterminant) {
  test::Mulberry32 rng(15);
  for (int k = 0; k < 20; ++k) {
    const Curve c = random_dyadic_curve(rng, 3 + k % 6);
    // Dyadic matrix and shift: the mapped control points are exact, and the exact area of
    // the image is det * area exactly; the kernel must match it to rounding.
    const double m00 = std::floor(rng.uniform(-8, 8)) / 4, m01 = std::floor(rng.uniform(-8, 8)) / 4;
    const double m10 = std::floor(rng.uniform(-8, 8)) / 4, m11 = std::floor(rng.uniform(-8, 8)) / 4;
    const Point2 shift{std::floor(rng.uniform(-64, 64)) / 8, std::floor(rng.uniform(-64, 64)) / 8};
    std::vector<Point2> mapped;
    for (const Point2 p : c.points())
      mapped.push_back(Point2{m00 * p.x + m01 * p.y, m10 * p.x + m11 * p.y} + shift);
    const Curve image(mapped);
    const Rational det = Rational(m00) * Rational(m11) - Rational(m01) * Rational(m10);
    const Rational exact = det * test::exact_enclosed_area(test::power_form(c), 0, 1);
    EXPECT_EQ(test::exact_enclosed_area(test::power_form(image), 0, 1), exact);
    EXPECT_NEAR(enclosed_area(image), exact.to_double(), 1e-13 * (area_scale(image) + 1.0)) << k;
  }
}

TEST(Area, ReversalFlipsTheSign) {
  test::Mulberry32 rng(16);
  for (int degree = 2; degree <= 12; ++degree) {
    const Curve c = random_dyadic_curve(rng, degree);
    EXPECT_NEAR(enclosed_area(reversed(c)), -enclosed_area(c),
                8.0 * degree * degree * kEps * area_scale(c));
    EXPECT_NEAR(signed_area(reversed(c)), -signed_area(c),
                8.0 * degree * degree * kEps * area_scale(c));
  }
}

TEST(Area, DegreeElevationKeepsTheArea) {
  // Elevating a cubic to degree 4 divides by 4: exact in binary, and the same curve.
  test::Mulberry32 rng(17);
  const Curve c = random_dyadic_curve(rng, 3);
  const auto elevated = test::exact_curve(test::elevate(test::exact_points(c)));
  ASSERT_TRUE(elevated.has_value());
  EXPECT_NEAR(enclosed_area(*elevated), enclosed_area(c), 16 * kEps * area_scale(c));
}

TEST(Area, ClosedCurveAreaIsExact) {
  // A closed quartic and a closed cubic, against the exact integral.
  for (const Curve& c : {Curve({{0, 0}, {2, -1}, {3, 2}, {-1, 3}, {0, 0}}),
                         Curve({{1, 1}, {4, 1}, {0.5, 3}, {1, 1}})}) {
    ASSERT_TRUE(is_closed(c));
    const auto area = closed_area(c);
    ASSERT_TRUE(area.has_value());
    const Rational exact = test::exact_green_integral(test::power_form(c), 0, 1);
    EXPECT_NEAR(*area, exact.to_double(), 8 * kEps * std::fabs(exact.to_double()));
    EXPECT_EQ(*area, enclosed_area(c));
  }
}

TEST(Area, ClosedCurveEqualsTheSumOfItsTwoHalves) {
  // Green's theorem is additive: the two halves' integrals (origin-dependent each) sum to
  // the enclosed area.
  const Curve c({{0, 0}, {3, -1}, {4, 3}, {-2, 2}, {0, 0}});
  EXPECT_NEAR(signed_area(c, 0, 0.375) + signed_area(c, 0.375, 1), *closed_area(c),
              64 * kEps * area_scale(c));
}

TEST(Area, OpenCurvesHaveNoClosedArea) {
  EXPECT_FALSE(closed_area(Curve({{0, 0}, {1, 1}, {2, 0}})).has_value());
  // Nearly closed is open: the chord is part of the area.
  const Curve nearly({{0, 0}, {1, 1}, {2, 0}, {0, std::ldexp(1.0, -52)}});
  EXPECT_FALSE(is_closed(nearly));
  EXPECT_FALSE(closed_area(nearly).has_value());
}

TEST(Area, FigureEightCancelsItsLobes) {
  // P_{n-i} = -P_i gives B(1 - t) = -B(t): the second half is the first one turned by 180
  // degrees and run backwards, so the two lobes have opposite orientation and cancel.
  const Curve c({{0, 0}, {4, 4}, {4, -4}, {-4, 4}, {-4, -4}, {0, 0}});
  EXPECT_NEAR(*closed_area(c), 0.0, 64 * kEps * area_scale(c));
  EXPECT_NEAR(enclosed_area(c, 0, 0.5), -enclosed_area(c, 0.5, 1), 64 * kEps * area_scale(c));
  EXPECT_GT(std::fabs(enclosed_area(c, 0, 0.5)), 1.0);
}

}  // namespace
}  // namespace bezier::core
