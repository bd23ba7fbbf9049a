// Tests of core/curve/subdivide.hpp: splitting a curve at t by de Casteljau.
//
// Exact expectations: the left control points are L_k = b_0^k(t) and the right ones
// R_k = b_k^(n-k)(t), entries of de Casteljau's triangle, computed in rationals from the
// double inputs (tests/support/exact.hpp). Each new control point is held to the contract
// of evaluate_test.cpp (one rounding of its exact value plus c times its condition scale),
// and the halves to reproducing the curve: left(u) = B(t u), right(u) = B(t + u (1 - t)),
// exactly in rationals, up to the rounding of the halves' control points (see below).

#include "core/curve/subdivide.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <type_traits>
#include <vector>

#include "core/numeric/binomial.hpp"
#include "core/curve/evaluate.hpp"
#include "tests/support/exact_bezier.hpp"

namespace bezier::core {
namespace {

using test::case_name;
using test::compensated_coefficient;
using test::exact_abs_polar;
using test::exact_points;
using test::exact_polar;
using test::Mulberry32;
using test::random_curve;
using test::Rational;

constexpr double kU = 0x1p-53;  // unit roundoff

std::vector<double> test_parameters(Mulberry32& rng) {
  return {0.5, 1.0 / 3.0, rng.next(), rng.next(), rng.uniform(-1.5, 0.0), rng.uniform(1.0, 2.5)};
}

/// k copies of t, as de Casteljau arguments.
std::vector<Rational> repeated(std::size_t k, double t) {
  return std::vector<Rational>(k, Rational(t));
}

/// De Casteljau's triangle at t in rationals, row k = the points after k rounds, and the
/// same triangle of condition scales.
template <class RP>
struct ExactTriangle {
  std::vector<std::vector<RP>> rows;
  std::vector<std::vector<RP>> scales;
};

template <class RP>
ExactTriangle<RP> exact_triangle(const std::vector<RP>& pts, double t) {
  ExactTriangle<RP> tri{{pts}, {exact_abs_polar(pts, {})}};
  for (std::size_t k = 1; k < pts.size(); ++k) {
    tri.rows.push_back(exact_polar(tri.rows.back(), repeated(1, t)));
    tri.scales.push_back(exact_abs_polar(tri.scales.back(), repeated(1, t)));
  }
  return tri;
}

template <class P>
void for_random_curves(std::uint32_t seed, double lo, double hi, auto&& check) {
  Mulberry32 rng(seed);
  for (int n = 1; n <= 20; ++n) {
    const BasicCurve<P> c = random_curve<P>(rng, n, lo, hi);
    for (const double t : test_parameters(rng)) check(c, t, case_name(seed, n, t));
  }
}

template <class P>
void check_shared_split_point(const BasicCurve<P>& c, double t, const std::string& where) {
  const Split<P> halves = subdivide(c, t);
  ASSERT_EQ(halves.left.degree(), c.degree());
  ASSERT_EQ(halves.right.degree(), c.degree());
  EXPECT_EQ(halves.left.back(), halves.right.front()) << where;
  EXPECT_EQ(halves.left.back(), evaluate(c, t)) << where;
  EXPECT_EQ(halves.left.front(), c.front()) << where;
  EXPECT_EQ(halves.right.back(), c.back()) << where;
}

TEST(Subdivide, SplitPointSharedBitForBitWithEvaluate) {
  for_random_curves<Point2>(71, -1.0, 1.0, [](const auto& c, double t, const std::string& w) {
    check_shared_split_point(c, t, w);
  });
  for_random_curves<Point3>(72, -1e6, 1e6, [](const auto& c, double t, const std::string& w) {
    check_shared_split_point(c, t, w);
  });
}

template <class P>
void check_control_points(const BasicCurve<P>& c, double t, const std::string& where) {
  const Split<P> halves = subdivide(c, t);
  const auto tri = exact_triangle(exact_points(c), t);
  const int n = c.degree();
  for (int k = 0; k <= n; ++k) {
    const auto ku = static_cast<std::size_t>(k), rest = static_cast<std::size_t>(n - k);
    EXPECT_EQ(test::accuracy_violation(halves.left[k], tri.rows[ku].front(), tri.scales[ku].front(),
                                       compensated_coefficient(n)),
              "")
        << where << ", left " << k;
    EXPECT_EQ(test::accuracy_violation(halves.right[k], tri.rows[rest][ku], tri.scales[rest][ku],
                                       compensated_coefficient(n)),
              "")
        << where << ", right " << k;
  }
}

TEST(Subdivide, ControlPointsWithinOneRoundingOfExactTriangle) {
  for_random_curves<Point2>(73, -1.0, 1.0, [](const auto& c, double t, const std::string& w) {
    check_control_points(c, t, w);
  });
  for_random_curves<Point3>(74, -1e-6, 1e-6, [](const auto& c, double t, const std::string& w) {
    check_control_points(c, t, w);
  });
}

/// A half H (control points Ĥ_k, each within u |H*_k| + c S_k of its exact value H*_k by
/// the previous test, with S_k its condition scale in the original curve) evaluated at u:
///   |evaluate(Ĥ, u) - H*(u)| <= [u |Ĥ(u)| + c Ŝ(u)] + Σ_k |Ĥ_k - H*_k| |b_k(u)|
///                             <= u |H*(u)| + (u + 3c) R(u),   R(u) = Σ_k S_k |b_k(u)|,
/// since |Ĥ_k| <= (1 + u) S_k and |H*(u)| differs from |Ĥ(u)| by second-order terms.
template <class P>
void check_half(const BasicCurve<P>& half, const std::vector<decltype(test::exact(P{}))>& scales,
                const auto& exact_curve_at, const std::string& where) {
  for (const double u : {0.0, 0.25, 0.5, 0.8125, 1.0, 1.0 / 3.0}) {
    const auto r = exact_abs_polar(scales, repeated(scales.size() - 1, u)).front();
    EXPECT_EQ(test::accuracy_violation(evaluate(half, u), exact_curve_at(Rational(u)), r,
                                       kU + 3 * compensated_coefficient(half.degree())),
              "")
        << where << ", u = " << u;
  }
}

template <class P>
void check_halves_reproduce_curve(const BasicCurve<P>& c, double t, const std::string& where) {
  const Split<P> halves = subdivide(c, t);
  const auto pts = exact_points(c);
  const int n = c.degree();
  const Rational rt(t);
  const auto tri = exact_triangle(pts, t);
  std::vector<decltype(test::exact(P{}))> left_scales, right_scales;
  for (int k = 0; k <= n; ++k) {
    left_scales.push_back(tri.scales[static_cast<std::size_t>(k)].front());
    right_scales.push_back(
        tri.scales[static_cast<std::size_t>(n - k)][static_cast<std::size_t>(k)]);
  }
  check_half(
      halves.left, left_scales,
      [&](const Rational& u) { return test::exact_evaluate(pts, rt * u); }, where + " left");
  check_half(
      halves.right, right_scales,
      [&](const Rational& u) { return test::exact_evaluate(pts, rt + u * (Rational(1) - rt)); },
      where + " right");
}

TEST(Subdivide, HalvesReproduceTheCurve) {
  for_random_curves<Point2>(75, -1.0, 1.0, [](const auto& c, double t, const std::string& w) {
    check_halves_reproduce_curve(c, t, w);
  });
  for_random_curves<Point3>(76, -100.0, 100.0, [](const auto& c, double t, const std::string& w) {
    check_halves_reproduce_curve(c, t, w);
  });
}

TEST(Subdivide, AtTheEndsOneHalfIsTheCurveAndTheOtherAPoint) {
  Mulberry32 rng(77);
  for (int n = 1; n <= 20; ++n) {
    const Curve c = random_curve<Point2>(rng, n, -5.0, 5.0);
    const Split<Point2> at0 = subdivide(c, 0.0), at1 = subdivide(c, 1.0);
    EXPECT_EQ(at0.right, c) << "degree " << n;
    EXPECT_EQ(at1.left, c) << "degree " << n;
    EXPECT_EQ(at0.left, Curve(std::vector<Point2>(static_cast<std::size_t>(n) + 1, c.front())))
        << "degree " << n;
    EXPECT_EQ(at1.right, Curve(std::vector<Point2>(static_cast<std::size_t>(n) + 1, c.back())))
        << "degree " << n;
  }
}

TEST(Subdivide, IntegerPointsAtOneHalfSplitExactly) {
  // With integer coordinates below 2^20 and t = 1/2, L_k = 2^-k Σ_j C(k,j) P_j and
  // R_k = 2^-(n-k) Σ_j C(n-k,j) P_{k+j} (closed forms) are exact doubles, so the split must
  // reproduce them bit for bit.
  Mulberry32 rng(79);
  for (int n = 1; n <= 20; ++n) {
    std::vector<Point2> pts;
    for (int i = 0; i <= n; ++i) {
      pts.push_back({static_cast<double>(static_cast<int>(rng.uniform(-1048576.0, 1048576.0))),
                     static_cast<double>(static_cast<int>(rng.uniform(-1048576.0, 1048576.0)))});
    }
    const Split<Point2> halves = subdivide(Curve(pts), 0.5);
    const auto closed_form = [&](int first, int count) {
      test::RPoint2 sum{Rational(0), Rational(0)};
      for (int j = 0; j <= count; ++j)
        sum = sum +
              Rational(binomial(count, j)) * test::exact(pts[static_cast<std::size_t>(first + j)]);
      return Rational(test::BigInt(1), test::BigInt(1) << count) * sum;
    };
    for (int k = 0; k <= n; ++k) {
      EXPECT_EQ(test::exact(halves.left[k]), closed_form(0, k)) << "degree " << n << ", left " << k;
      EXPECT_EQ(test::exact(halves.right[k]), closed_form(k, n - k))
          << "degree " << n << ", right " << k;
    }
  }
}

TEST(Subdivide, DegreeZeroCurve) {
  const Curve point({{2.5, -1.0}});
  const Split<Point2> halves = subdivide(point, 0.3);
  EXPECT_EQ(halves.left, point);
  EXPECT_EQ(halves.right, point);
}

}  // namespace
}  // namespace bezier::core
