// Tests of core/curve/evaluate.hpp: B(t) by compensated de Casteljau, uniform parameters, samples.
//
// Expected values are exact: every double is a dyadic rational, so B(t) for double control
// points and a double t has an exact rational value (tests/support/exact.hpp computes it by
// de Casteljau in rationals). The accuracy contract checked against it, per coordinate, is
//   |evaluate(B, t) - B(t)| <= u |B(t)| + c S(t),   u = 2^-53,   c = 4 γ_{3n+4}^2,
//   S(t) = Σ |P_i| |C(n,i) (1-t)^(n-i) t^i|   (the condition scale; S(t) >= |B(t)|),
// i.e. one rounding of the exact answer plus a second-order term (about 1e-28 S at degree
// 20). Why it holds: the compensated algorithm (Jiang, Li, Cheng, Su 2010; see
// CasteljauRow) gets the rounding error of every de Casteljau step exactly and propagates
// it, so value + error differs from B(t) by at most 2 γ_{3n}^2 S(t) (their error bound,
// doubled here for slack; the helper compensated_coefficient documents the constant), and
// the final addition rounds once. This is "within a few ulps of the exact answer" in the
// strongest form: about one ulp of B(t) itself, not just of the input scale, unless B(t)
// cancels to below ~1e-27 S(t).

#include "core/curve/evaluate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <type_traits>
#include <vector>

#include "tests/support/exact_bezier.hpp"

namespace bezier::core {
namespace {

using test::case_name;
using test::compensated_coefficient;
using test::exact_points;
using test::Mulberry32;
using test::random_curve;
using test::Rational;

/// Parameters inside [0,1], at its ends, and outside it on both sides.
std::vector<double> test_parameters(Mulberry32& rng) {
  return {0.0,
          1.0,
          0.5,
          1.0 / 3.0,
          rng.next(),
          rng.next(),
          rng.uniform(-1.5, 0.0),
          rng.uniform(1.0, 2.5)};
}

/// Checks the accuracy contract above for evaluate(curve, t); returns "" when it holds.
template <class P>
std::string evaluate_violation(const BasicCurve<P>& curve, double t) {
  const auto pts = exact_points(curve);
  const std::vector<Rational> ts(static_cast<std::size_t>(curve.degree()), Rational(t));
  return test::accuracy_violation(evaluate(curve, t), test::exact_polar(pts, ts).front(),
                                  test::exact_abs_polar(pts, ts).front(),
                                  compensated_coefficient(curve.degree()));
}

TEST(Evaluate, EndPointsExact) {
  const Curve c({{0.1, 0.2}, {1.3, 2.7}, {3.3, -0.7}});
  EXPECT_EQ(evaluate(c, 0.0), (Point2{0.1, 0.2}));
  EXPECT_EQ(evaluate(c, 1.0), (Point2{3.3, -0.7}));
  Mulberry32 rng(21);
  for (int n = 1; n <= 20; ++n) {
    const Curve3 c3 = random_curve<Point3>(rng, n, -1e3, 1e3);
    EXPECT_EQ(evaluate(c3, 0.0), c3.front()) << "degree " << n;
    EXPECT_EQ(evaluate(c3, 1.0), c3.back()) << "degree " << n;
  }
}

TEST(Evaluate, DegreeZeroIsItsPoint) {
  EXPECT_EQ(evaluate(Curve({{1.5, -2.0}}), 0.7), (Point2{1.5, -2.0}));
}

TEST(Evaluate, LinearPrecisionGivesTExactly) {
  // Σ (i/n) C(n,i) (1-t)^(n-i) t^i = t (Farin §5.2, linear precision): a closed form that
  // does not go through de Casteljau. n a power of two keeps i/n exact.
  for (const int n : {1, 2, 4, 8, 16}) {
    std::vector<Point2> pts;
    for (int i = 0; i <= n; ++i)
      pts.push_back({static_cast<double>(i) / n, 1.0 - static_cast<double>(i) / n});
    const Curve c(pts);
    for (const double t : {0.0, 0.25, 1.0 / 3.0, 0.7, 1.0, -0.375, 1.9}) {
      const test::RPoint2 exact{Rational(t), Rational(1) - Rational(t)};
      const test::RPoint2 scale =
          test::exact_abs_polar(exact_points(c), std::vector<Rational>(n, Rational(t))).front();
      EXPECT_EQ(test::accuracy_violation(evaluate(c, t), exact, scale, compensated_coefficient(n)),
                "")
          << "degree " << n << " t " << t;
    }
  }
}

template <class P>
void check_random_curves(std::uint32_t seed, double lo, double hi) {
  Mulberry32 rng(seed);
  for (int n = 1; n <= 20; ++n) {
    const BasicCurve<P> c = random_curve<P>(rng, n, lo, hi);
    for (const double t : test_parameters(rng))
      EXPECT_EQ(evaluate_violation(c, t), "") << case_name(seed, n, t);
  }
}

TEST(Evaluate, MatchesExactValueDegrees1To20In2D) {
  for (const std::uint32_t seed : {1u, 2u, 3u}) check_random_curves<Point2>(seed, -1.0, 1.0);
}

TEST(Evaluate, MatchesExactValueDegrees1To20In3D) {
  for (const std::uint32_t seed : {4u, 5u}) check_random_curves<Point3>(seed, -100.0, 100.0);
}

// evaluate_coordinate takes the same rounds on one axis, so it meets the same accuracy
// contract: it is evaluate()'s coordinate bit for bit (the error parts stay finite here).
TEST(EvaluateCoordinate, IsEvaluatesCoordinateDegrees1To20In3D) {
  Mulberry32 rng(6);
  for (int n = 1; n <= 20; ++n) {
    const Curve3 c = random_curve<Point3>(rng, n, -100.0, 100.0);
    std::vector<double> xs, ys, zs;
    for (const Point3& p : c.points()) {
      xs.push_back(p.x);
      ys.push_back(p.y);
      zs.push_back(p.z);
    }
    for (const double t : test_parameters(rng)) {
      const Point3 b = evaluate(c, t);
      EXPECT_EQ(evaluate_coordinate(xs, t), b.x) << case_name(6, n, t);
      EXPECT_EQ(evaluate_coordinate(ys, t), b.y) << case_name(6, n, t);
      EXPECT_EQ(evaluate_coordinate(zs, t), b.z) << case_name(6, n, t);
    }
  }
}

// The hard inputs: degree 20, coordinates around 1e6, around 1e-6, and
// alternating ±1000 (where B(t) cancels: the x coordinate of the pure alternating curve is
// 1000 (1 - 2t)^20, tiny near t = 1/2, yet the result stays within one rounding of it).
template <class P>
void check_degree_20(std::uint32_t seed, double magnitude, bool alternate) {
  Mulberry32 rng(seed);
  for (int trial = 0; trial < 12; ++trial) {
    // Coordinate j of point i: ±magnitude times 1 (trial 0) or a factor in [0.5, 2); the
    // sign alternates with i (and j) or is random.
    const auto coordinate = [&](int i, int j) {
      const bool negative = alternate ? (i + j) % 2 == 1 : rng.next() < 0.5;
      const double factor = trial == 0 ? 1.0 : rng.uniform(0.5, 2.0);
      return (negative ? -magnitude : magnitude) * factor;
    };
    std::vector<P> pts;
    for (int i = 0; i <= 20; ++i) {
      if constexpr (std::is_same_v<P, Point2>) {
        pts.push_back({coordinate(i, 0), coordinate(i, 1)});
      } else {
        pts.push_back({coordinate(i, 0), coordinate(i, 1), coordinate(i, 2)});
      }
    }
    const BasicCurve<P> c(pts);
    for (const double t : test_parameters(rng))
      EXPECT_EQ(evaluate_violation(c, t), "") << case_name(seed, 20, t);
    for (const double t : {0.5, 0.4999, 0.25, 0.75})
      EXPECT_EQ(evaluate_violation(c, t), "") << case_name(seed, 20, t);
  }
}

TEST(Evaluate, Degree20CoordinatesAround1e6) {
  check_degree_20<Point2>(31, 1e6, false);
  check_degree_20<Point3>(32, 1e6, false);
}

TEST(Evaluate, Degree20CoordinatesAround1eMinus6) {
  check_degree_20<Point2>(33, 1e-6, false);
  check_degree_20<Point3>(34, 1e-6, false);
}

TEST(Evaluate, Degree20AlternatingPlusMinus1000) {
  check_degree_20<Point2>(35, 1000.0, true);
  check_degree_20<Point3>(36, 1000.0, true);
}

TEST(Evaluate, PowerOfTwoScalingCommutesBitForBit) {
  // Scaling every input by 2^k scales every rounding error by 2^k too (no over- or
  // underflow here), so the result scales exactly.
  Mulberry32 rng(41);
  for (int n = 1; n <= 20; ++n) {
    const Curve c = random_curve<Point2>(rng, n, -1.0, 1.0);
    for (const double t : test_parameters(rng)) {
      for (const double s : {0x1p-60, 0x1p-20, 0x1p20, 0x1p60}) {
        std::vector<Point2> scaled;
        for (const Point2 p : c.points()) scaled.push_back(s * p);
        EXPECT_EQ(evaluate(Curve(scaled), t), s * evaluate(c, t))
            << case_name(41, n, t) << " scale " << s;
      }
    }
  }
}

TEST(Evaluate, ReversalMapsTToOneMinusT) {
  // For t in [1/2, 2], 1 - t is exact (Sterbenz), so the reversed curve at 1 - t has the
  // same exact value and must meet the same contract.
  Mulberry32 rng(43);
  for (int n = 1; n <= 20; ++n) {
    const Curve c = random_curve<Point2>(rng, n, -10.0, 10.0);
    for (const double t : {0.5, rng.uniform(0.5, 1.0), rng.uniform(1.0, 2.0), 1.0}) {
      const auto pts = exact_points(c);
      const std::vector<Rational> ts(static_cast<std::size_t>(n), Rational(t));
      EXPECT_EQ(test::accuracy_violation(
                    evaluate(reversed(c), 1.0 - t), test::exact_polar(pts, ts).front(),
                    test::exact_abs_polar(pts, ts).front(), compensated_coefficient(n)),
                "")
          << case_name(43, n, t);
    }
  }
}

TEST(UniformParameters, AreCorrectlyRoundedFractionsWithExactEnds) {
  EXPECT_EQ(uniform_parameters(1), std::vector<double>{0.0});
  for (int count = 2; count <= 257; ++count) {
    const std::vector<double> ts = uniform_parameters(count);
    ASSERT_EQ(ts.size(), static_cast<std::size_t>(count));
    EXPECT_EQ(ts.front(), 0.0);
    EXPECT_EQ(ts.back(), 1.0);
    for (int i = 0; i < count; ++i) {
      EXPECT_EQ(ts[static_cast<std::size_t>(i)], (Rational(i) / Rational(count - 1)).to_double())
          << "i " << i << " of " << count;
      if (i > 0) {
        EXPECT_LT(ts[static_cast<std::size_t>(i - 1)], ts[static_cast<std::size_t>(i)]);
      }
    }
  }
}

TEST(Sample, IsEvaluateAtUniformParameters) {
  Mulberry32 rng(47);
  const Curve3 c = random_curve<Point3>(rng, 7, -5.0, 5.0);
  const std::vector<double> ts = uniform_parameters(33);
  const std::vector<Point3> points = sample(c, 33);
  ASSERT_EQ(points.size(), ts.size());
  for (std::size_t i = 0; i < ts.size(); ++i) EXPECT_EQ(points[i], evaluate(c, ts[i])) << "i " << i;
}

}  // namespace
}  // namespace bezier::core
