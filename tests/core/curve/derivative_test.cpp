// Tests of core/curve/derivative.hpp: hodographs of any order and derivatives at t.
//
// Exact expectations: the k-th hodograph of the (double) control points, n!/(n-k)! Δ^k P_i,
// and its value at t, computed in rationals (tests/support/exact.hpp). The contract checked,
// per coordinate (see evaluate_test.cpp for the derivation and the constant c):
//   |derivatives_at(B, t, k)[k-1] - B^(k)(t)| <= u |B^(k)(t)| + c S_k(t),
//   S_k(t) = n!/(n-k)! Σ_i (Σ_j C(k,j) |P_{i+j}|) |b_{i,n-k}(t)|,
// the condition scale of the k-th derivative as computed from the control points: each
// hodograph round m (Q_{i+1} - Q_i) is bounded by m (|Q_{i+1}| + |Q_i|). The hodograph
// differences are split exactly and carried with the de Casteljau error row, so the only
// first-order error left is the final rounding.

#include "core/curve/derivative.hpp"
#include "core/curve/evaluate.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <type_traits>
#include <vector>

#include "tests/support/exact_bezier.hpp"

namespace bezier::core {
namespace {

using test::compensated_coefficient;
using test::exact_points;
using test::Mulberry32;
using test::random_curve;
using test::Rational;

std::string context(std::uint32_t seed, int degree, int k, double t) {
  char text[140];
  std::snprintf(text, sizeof text, "seed %u, degree %d, derivative %d, t = %.17g", seed, degree, k,
                t);
  return text;
}

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

/// The exact k-th hodograph control points and their condition scales
/// n!/(n-k)! Σ_j C(k,j) |P_{i+j}| (the same rounds on |P| with + for -).
template <class RP>
struct ExactHodograph {
  std::vector<RP> points;
  std::vector<RP> scales;
};

template <class RP>
ExactHodograph<RP> exact_hodograph(std::vector<RP> pts, int k) {
  std::vector<RP> scales;
  for (const RP& p : pts) scales.push_back(abs(p));
  for (int j = 0; j < k; ++j) {
    pts = test::exact_hodograph(pts);
    if (scales.size() == 1) {
      scales = {Rational(0) * scales[0]};
      continue;
    }
    const Rational m(static_cast<long long>(scales.size() - 1));
    for (std::size_t i = 0; i + 1 < scales.size(); ++i) scales[i] = m * (scales[i + 1] + scales[i]);
    scales.pop_back();
  }
  return {std::move(pts), std::move(scales)};
}

/// Checks the contract above for the first `order` derivatives of `curve` at t.
template <class P>
void check_derivatives_at(const BasicCurve<P>& curve, double t, int order,
                          const std::string& where) {
  const std::vector<P> got = derivatives_at(curve, t, order);
  ASSERT_EQ(got.size(), static_cast<std::size_t>(order));
  for (int k = 1; k <= order; ++k) {
    const auto h = exact_hodograph(exact_points(curve), k);
    const std::vector<Rational> ts(h.points.size() - 1, Rational(t));
    EXPECT_EQ(test::accuracy_violation(got[static_cast<std::size_t>(k - 1)],
                                       test::exact_polar(h.points, ts).front(),
                                       test::exact_abs_polar(h.scales, ts).front(),
                                       compensated_coefficient(curve.degree())),
              "")
        << where << ", derivative " << k;
  }
}

TEST(Derivative, HodographOfSmallIntegerPointsByTheFormula) {
  // P'_i = n (P_{i+1} - P_i) with n = 3: 3 (1,2), 3 (2,1), 3 (4,-4).
  const Curve c({{0, 0}, {1, 2}, {3, 3}, {7, -1}});
  EXPECT_EQ(derivative(c), Curve({{3, 6}, {6, 3}, {12, -12}}));
  // Second hodograph: 2 (P'_{i+1} - P'_i) = 2 (3,-3), 2 (6,-15).
  EXPECT_EQ(derivative(c, 2), Curve({{6, -6}, {12, -30}}));
  EXPECT_EQ(derivative(c, 3), Curve({{6, -24}}));
}

TEST(Derivative, OrderZeroIsTheCurveAndBeyondTheDegreeIsZero) {
  Mulberry32 rng(51);
  for (int n = 1; n <= 20; ++n) {
    const Curve3 c = random_curve<Point3>(rng, n, -3.0, 3.0);
    EXPECT_EQ(derivative(c, 0), c) << "degree " << n;
    EXPECT_EQ(derivative(c, n + 1), Curve3({Point3{}})) << "degree " << n;
    EXPECT_EQ(derivative(c, n + 3), Curve3({Point3{}})) << "degree " << n;
    EXPECT_EQ(derivative(c, n).degree(), 0);
  }
  EXPECT_EQ(derivative(Curve({{4, 5}})), Curve({Point2{}}));
  EXPECT_TRUE(derivatives_at(Curve({{1, 2}, {3, 4}}), 0.5, 0).empty());
}

template <class P>
void check_hodograph_points(std::uint32_t seed, double lo, double hi) {
  Mulberry32 rng(seed);
  for (int n = 1; n <= 20; ++n) {
    const BasicCurve<P> c = random_curve<P>(rng, n, lo, hi);
    for (int k = 1; k <= n; ++k) {
      const BasicCurve<P> got = derivative(c, k);
      const auto h = exact_hodograph(exact_points(c), k);
      ASSERT_EQ(got.degree(), n - k);
      for (int i = 0; i <= n - k; ++i) {
        const auto idx = static_cast<std::size_t>(i);
        EXPECT_EQ(test::accuracy_violation(got[i], h.points[idx], h.scales[idx],
                                           compensated_coefficient(n)),
                  "")
            << context(seed, n, k, 0.0) << ", control point " << i;
      }
    }
  }
}

TEST(Derivative, HodographPointsWithinOneRoundingDegrees1To20) {
  check_hodograph_points<Point2>(53, -1.0, 1.0);
  check_hodograph_points<Point3>(54, 1e5, 1e5 + 1.0);  // close points: the differences cancel
}

TEST(DerivativesAt, ClosedFormForAPowerOfT) {
  // x(t) = t^n (only P_n.x = 1) has x^(k)(t) = n!/(n-k)! t^(n-k); y(t) = t (P_i.y = i/n,
  // linear precision, n a power of two) has y' = 1 and y^(k) = 0 for k >= 2.
  for (const int n : {1, 2, 4, 8, 16}) {
    std::vector<Point2> pts;
    for (int i = 0; i <= n; ++i) pts.push_back({i == n ? 1.0 : 0.0, static_cast<double>(i) / n});
    const Curve c(pts);
    for (const double t : {0.0, 0.5, 0.3, 1.0, -0.7, 1.6}) {
      const std::vector<Point2> got = derivatives_at(c, t, n + 1);
      for (int k = 1; k <= n + 1; ++k) {
        Rational x(0);
        if (k <= n) {
          x = Rational(1);
          for (int j = 0; j < k; ++j) x *= Rational(n - j);
          for (int j = 0; j < n - k; ++j) x *= Rational(t);
        }
        const test::RPoint2 exact{x, Rational(k == 1 ? 1 : 0)};
        const auto h = exact_hodograph(exact_points(c), k);
        const test::RPoint2 scale =
            test::exact_abs_polar(h.scales, std::vector<Rational>(h.scales.size() - 1, Rational(t)))
                .front();
        EXPECT_EQ(test::accuracy_violation(got[static_cast<std::size_t>(k - 1)], exact, scale,
                                           compensated_coefficient(n)),
                  "")
            << "degree " << n << ", derivative " << k << ", t " << t;
      }
    }
  }
}

TEST(DerivativesAt, MatchExactValuesDegrees1To20In2D) {
  for (const std::uint32_t seed : {55u, 56u}) {
    Mulberry32 rng(seed);
    for (int n = 1; n <= 20; ++n) {
      const Curve c = random_curve<Point2>(rng, n, -1.0, 1.0);
      for (const double t : test_parameters(rng))
        check_derivatives_at(c, t, std::min(n + 1, 3), context(seed, n, 0, t));
    }
  }
}

TEST(DerivativesAt, MatchExactValuesDegrees1To20In3D) {
  Mulberry32 rng(57);
  for (int n = 1; n <= 20; ++n) {
    const Curve3 c = random_curve<Point3>(rng, n, -50.0, 50.0);
    for (const double t : test_parameters(rng))
      check_derivatives_at(c, t, std::min(n + 1, 3), context(57, n, 0, t));
  }
}

// The hard inputs for the first and second derivatives (the point is in
// evaluate_test.cpp): degree 20, coordinates around 1e6, around 1e-6, alternating ±1000.
template <class P>
void check_degree_20(std::uint32_t seed, double magnitude, bool alternate) {
  Mulberry32 rng(seed);
  for (int trial = 0; trial < 8; ++trial) {
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
      check_derivatives_at(c, t, 2, context(seed, 20, 0, t));
    for (const double t : {0.5, 0.4999, 0.25})
      check_derivatives_at(c, t, 2, context(seed, 20, 0, t));
  }
}

TEST(DerivativesAt, Degree20CoordinatesAround1e6) {
  check_degree_20<Point2>(61, 1e6, false);
  check_degree_20<Point3>(62, 1e6, false);
}

TEST(DerivativesAt, Degree20CoordinatesAround1eMinus6) {
  check_degree_20<Point2>(63, 1e-6, false);
  check_degree_20<Point3>(64, 1e-6, false);
}

TEST(DerivativesAt, Degree20AlternatingPlusMinus1000) {
  check_degree_20<Point2>(65, 1000.0, true);
  check_degree_20<Point3>(66, 1000.0, true);
}

TEST(DerivativesAt, RoundedHodographThenEvaluateAddsOneRoundingOfTheScale) {
  // evaluate(derivative(c, k), t) rounds the hodograph points first: each is within
  // u |H_i| + c S_i of exact, which adds at most u S_k(t) + c S_k(t) to the contract.
  Mulberry32 rng(67);
  for (int n = 1; n <= 20; ++n) {
    const Curve c = random_curve<Point2>(rng, n, -1.0, 1.0);
    for (const double t : test_parameters(rng)) {
      for (int k = 1; k <= std::min(n, 2); ++k) {
        const auto h = exact_hodograph(exact_points(c), k);
        const std::vector<Rational> ts(h.points.size() - 1, Rational(t));
        const double coefficient = 0x1p-53 + 3 * compensated_coefficient(n);
        EXPECT_EQ(test::accuracy_violation(
                      evaluate(derivative(c, k), t), test::exact_polar(h.points, ts).front(),
                      test::exact_abs_polar(h.scales, ts).front(), coefficient),
                  "")
            << context(67, n, k, t);
      }
    }
  }
}

}  // namespace
}  // namespace bezier::core
