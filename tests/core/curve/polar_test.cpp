// Tests of core/curve/polar.hpp: first and k-th polars, the blossom, portions.
//
// Facts checked exactly in rationals on the (double) inputs (the mathematics, independent
// of rounding): the polar identity b(t0, t0^(n-1)) = B(t0); the first polar curve is tangent
// to B at t0, Q'(t0) = (n-1)/n B'(t0); the blossom is symmetric and multi-affine.
// Facts checked on the kernel's doubles against those exact values: every polar control
// point and blossom value meets the contract of evaluate_test.cpp (one rounding of the
// exact value plus c times its condition scale, c = compensated_coefficient(n)); curves
// built from rounded control points are held to that plus one rounding of their scale.
// And the identities that follow from sharing one routine (CasteljauRow) hold bit for bit.

#include "core/curve/polar.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <string>
#include <type_traits>
#include <vector>

#include "core/curve/derivative.hpp"
#include "core/curve/evaluate.hpp"
#include "core/curve/subdivide.hpp"
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

/// A parameter inside [0,1] most of the time, outside it otherwise.
double random_parameter(Mulberry32& rng) {
  const double r = rng.next();
  return r < 0.6 ? rng.next() : (r < 0.8 ? rng.uniform(-1.5, 0.0) : rng.uniform(1.0, 2.5));
}

std::vector<double> test_parameters(Mulberry32& rng) {
  return {0.0, 1.0, 0.5, rng.next(), rng.uniform(-1.5, 0.0), rng.uniform(1.0, 2.5)};
}

std::vector<Rational> rationals(const std::vector<double>& us) {
  return {us.begin(), us.end()};
}

/// Runs check(curve, t0, context) over degrees 1..20 in 2-D and 3-D.
void for_random_curves(std::uint32_t seed, auto&& check) {
  Mulberry32 rng(seed);
  for (int n = 1; n <= 20; ++n) {
    const Curve c2 = random_curve<Point2>(rng, n, -1.0, 1.0);
    const Curve3 c3 = random_curve<Point3>(rng, n, -1e3, 1e3);
    for (const double t0 : test_parameters(rng)) {
      check(c2, t0, case_name(seed, n, t0));
      check(c3, t0, case_name(seed, n, t0) + " 3-D");
    }
  }
}

/// Checks each control point of `got` against the exact polar of `curve` at `us`.
template <class P>
void expect_polar_points(const BasicCurve<P>& got, const BasicCurve<P>& curve,
                         const std::vector<double>& us, const std::string& where) {
  const auto exact = exact_polar(exact_points(curve), rationals(us));
  const auto scale = exact_abs_polar(exact_points(curve), rationals(us));
  ASSERT_EQ(got.points().size(), exact.size()) << where;
  for (std::size_t i = 0; i < exact.size(); ++i) {
    EXPECT_EQ(test::accuracy_violation(got.points()[i], exact[i], scale[i],
                                       compensated_coefficient(curve.degree())),
              "")
        << where << ", control point " << i;
  }
}

TEST(FirstPolar, ControlPointsWithinOneRounding) {
  for_random_curves(81, [](const auto& c, double t0, const std::string& where) {
    const auto q = first_polar(c, t0);
    EXPECT_EQ(q.degree(), c.degree() - 1) << where;
    expect_polar_points(q, c, {t0}, where);
    EXPECT_EQ(q, polar(c, std::vector<double>{t0})) << where;
  });
}

TEST(Polar, IdentityPolarAtT0IsCurvePointExactly) {
  // b(t0, t0^(n-1)): the polar curve evaluated at t0 is B(t0), in exact arithmetic.
  for_random_curves(82, [](const auto& c, double t0, const std::string& where) {
    const auto pts = exact_points(c);
    const auto q = exact_polar(pts, {Rational(t0)});
    EXPECT_EQ(test::exact_evaluate(q, Rational(t0)), test::exact_evaluate(pts, Rational(t0)))
        << where;
  });
}

TEST(Polar, FirstPolarAtT0IsCurvePoint) {
  // The kernel's polar curve (rounded control points Q_i, each within u |Q*_i| + c S_i)
  // evaluated at t0 is within u |B(t0)| + (u + 3c) S(t0) of B(t0): the rounding of Q moves
  // the value by at most Σ (u + c) S_i |b_i(t0)| = (u + c) S(t0). The blossom with every
  // argument t0 runs evaluate's own steps, so it equals evaluate(c, t0) bit for bit.
  for_random_curves(83, [](const auto& c, double t0, const std::string& where) {
    const int n = c.degree();
    const auto pts = exact_points(c);
    const std::vector<double> all_t0(static_cast<std::size_t>(n), t0);
    EXPECT_EQ(test::accuracy_violation(evaluate(first_polar(c, t0), t0),
                                       test::exact_evaluate(pts, Rational(t0)),
                                       exact_abs_polar(pts, rationals(all_t0)).front(),
                                       kU + 3 * compensated_coefficient(n)),
              "")
        << where;
    EXPECT_EQ(blossom(c, all_t0), evaluate(c, t0)) << where;
  });
}

TEST(Polar, FirstPolarIsTangentAtT0Exactly) {
  // Q(t) = b(t0, t^(n-1)) has Q'(t0) = (n-1)/n B'(t0) (Ramshaw 1987: B'(t) = n b(t^(n-1), δ)
  // with δ the direction 1 - 0; Q'(t) = (n-1) b(t0, t^(n-2), δ)), in exact arithmetic.
  for_random_curves(84, [](const auto& c, double t0, const std::string& where) {
    const int n = c.degree();
    const auto pts = exact_points(c);
    const auto q = exact_polar(pts, {Rational(t0)});
    const auto dq = test::exact_evaluate(test::exact_hodograph(q), Rational(t0));
    const auto db = test::exact_evaluate(test::exact_hodograph(pts), Rational(t0));
    EXPECT_EQ(dq, (Rational(n - 1) / Rational(n)) * db) << where;
  });
}

TEST(Polar, FirstPolarIsTangentAtT0) {
  // The kernel's polar curve: Q'(t0) by derivatives_at on the rounded control points.
  // Rounding Q_i by at most (u + c) S_i changes Q'(t0) by at most (u + c) T, with
  // T = (n-1) Σ_i (S_{i+1} + S_i) |b_{i,n-2}(t0)| the hodograph scale of the S_i; the
  // evaluation adds u |Q'(t0)| + c T. Bound: u |exact| + (u + 3c) T.
  for_random_curves(85, [](const auto& c, double t0, const std::string& where) {
    const int n = c.degree();
    if (n < 2) return;  // a degree-0 polar curve has derivative 0 = (n-1)/n B' exactly
    const auto pts = exact_points(c);
    auto scales = exact_abs_polar(pts, {Rational(t0)});
    const Rational m(n - 1);
    for (std::size_t i = 0; i + 1 < scales.size(); ++i) scales[i] = m * (scales[i + 1] + scales[i]);
    scales.pop_back();
    const auto t_scale =
        exact_abs_polar(scales, std::vector<Rational>(scales.size() - 1, Rational(t0))).front();
    const auto exact =
        (m / Rational(n)) * test::exact_evaluate(test::exact_hodograph(pts), Rational(t0));
    const auto got = derivatives_at(first_polar(c, t0), t0, 1).front();
    EXPECT_EQ(test::accuracy_violation(got, exact, t_scale, kU + 3 * compensated_coefficient(n)),
              "")
        << where;
  });
  const Curve line({{0, 0}, {2, 4}});
  EXPECT_EQ(derivatives_at(first_polar(line, 0.3), 0.3, 1).front(), (Point2{0, 0}));
}

TEST(Blossom, SymmetricAndMultiAffineExactly) {
  Mulberry32 rng(86);
  for (int n = 1; n <= 20; ++n) {
    const auto pts = exact_points(random_curve<Point3>(rng, n, -10.0, 10.0));
    std::vector<double> us;
    for (int j = 0; j < n; ++j) us.push_back(random_parameter(rng));
    const auto b = exact_polar(pts, rationals(us)).front();
    // Symmetric: any order of the arguments (here: reversed, and a rotation).
    std::vector<double> reordered(us.rbegin(), us.rend());
    EXPECT_EQ(exact_polar(pts, rationals(reordered)).front(), b) << "seed 86, degree " << n;
    std::rotate(reordered.begin(), reordered.begin() + n / 2, reordered.end());
    EXPECT_EQ(exact_polar(pts, rationals(reordered)).front(), b) << "seed 86, degree " << n;
    // Multi-affine: affine in each argument, b(.., αa + (1-α)c, ..) = α b(.., a, ..) + (1-α) b(..,
    // c, ..).
    const auto slot = static_cast<std::size_t>(rng.next() * n);
    const Rational alpha(rng.uniform(-2.0, 3.0)), a(random_parameter(rng)),
        c(random_parameter(rng));
    auto args = rationals(us);
    args[slot] = a;
    const auto ba = exact_polar(pts, args).front();
    args[slot] = c;
    const auto bc = exact_polar(pts, args).front();
    args[slot] = alpha * a + (Rational(1) - alpha) * c;
    EXPECT_EQ(exact_polar(pts, args).front(), alpha * ba + (Rational(1) - alpha) * bc)
        << "seed 86, degree " << n;
  }
}

TEST(Blossom, MatchesExactValueInAnyArgumentOrder) {
  Mulberry32 rng(87);
  for (int n = 1; n <= 20; ++n) {
    const Curve c = random_curve<Point2>(rng, n, -1.0, 1.0);
    std::vector<double> us;
    for (int j = 0; j < n; ++j) us.push_back(random_parameter(rng));
    const auto exact = exact_polar(exact_points(c), rationals(us)).front();
    const auto scale = exact_abs_polar(exact_points(c), rationals(us)).front();
    for (int order = 0; order < 3; ++order) {
      EXPECT_EQ(test::accuracy_violation(blossom(c, us), exact, scale, compensated_coefficient(n)),
                "")
          << "seed 87, degree " << n << ", order " << order;
      std::next_permutation(us.begin(), us.end());  // another order: the same exact value
    }
  }
}

TEST(Polar, KthPolarControlPointsWithinOneRounding) {
  Mulberry32 rng(88);
  for (int n = 1; n <= 20; ++n) {
    const Curve3 c = random_curve<Point3>(rng, n, -1e6, 1e6);
    for (int k = 1; k <= n; ++k) {
      std::vector<double> us;
      for (int j = 0; j < k; ++j) us.push_back(random_parameter(rng));
      const Curve3 q = polar(c, us);
      EXPECT_EQ(q.degree(), n - k);
      expect_polar_points(q, c, us,
                          "seed 88, degree " + std::to_string(n) + ", k " + std::to_string(k));
    }
  }
}

TEST(Polar, EqualArgumentsGiveTheSubdivisionTriangle) {
  // polar(c, t^k) is row k of de Casteljau's triangle: its ends are subdivide's control
  // points L_k and R_(n-k), computed by the same steps, hence bit for bit equal.
  for_random_curves(89, [](const auto& c, double t, const std::string& where) {
    const int n = c.degree();
    const auto halves = subdivide(c, t);
    for (int k = 0; k <= n; ++k) {
      const auto q = polar(c, std::vector<double>(static_cast<std::size_t>(k), t));
      EXPECT_EQ(q.front(), halves.left[k]) << where << ", k " << k;
      EXPECT_EQ(q.back(), halves.right[n - k]) << where << ", k " << k;
    }
  });
}

TEST(Portion, ControlPointsAreBlossomValues) {
  // Control point i of B on [a, b] is b(a^(n-i), b^i) (Ramshaw 1987).
  Mulberry32 rng(90);
  for (int n = 1; n <= 20; ++n) {
    const Curve c = random_curve<Point2>(rng, n, -1.0, 1.0);
    const double a = random_parameter(rng), b = random_parameter(rng);
    const Curve piece = portion(c, a, b);
    ASSERT_EQ(piece.degree(), n);
    for (int i = 0; i <= n; ++i) {
      std::vector<double> args(static_cast<std::size_t>(n), a);
      std::fill(args.begin() + (n - i), args.end(), b);
      const auto exact = exact_polar(exact_points(c), rationals(args)).front();
      const auto scale = exact_abs_polar(exact_points(c), rationals(args)).front();
      EXPECT_EQ(test::accuracy_violation(piece[i], exact, scale, compensated_coefficient(n)), "")
          << case_name(90, n, a) << ", b = " << b << ", control point " << i;
    }
  }
}

TEST(Portion, ReproducesTheCurveOnItsInterval) {
  // piece(u) = B(a + u (b - a)) exactly in rationals; the rounded control points (each
  // within (u + c) S_i) add at most (u + c) Σ S_i |b_i(u)| (see FirstPolarAtT0IsCurvePoint).
  Mulberry32 rng(91);
  for (int n = 1; n <= 20; ++n) {
    const Curve3 c = random_curve<Point3>(rng, n, -100.0, 100.0);
    const double a = random_parameter(rng), b = random_parameter(rng);
    const Curve3 piece = portion(c, a, b);
    std::vector<test::RPoint3> scales;
    for (int i = 0; i <= n; ++i) {
      std::vector<double> args(static_cast<std::size_t>(n), a);
      std::fill(args.begin() + (n - i), args.end(), b);
      scales.push_back(exact_abs_polar(exact_points(c), rationals(args)).front());
    }
    for (const double u : {0.0, 0.25, 0.6, 1.0}) {
      const Rational ru(u), ra(a), rb(b);
      const auto exact = test::exact_evaluate(exact_points(c), ra + ru * (rb - ra));
      const auto r =
          exact_abs_polar(scales, std::vector<Rational>(static_cast<std::size_t>(n), ru)).front();
      EXPECT_EQ(test::accuracy_violation(evaluate(piece, u), exact, r,
                                         kU + 3 * compensated_coefficient(n)),
                "")
          << case_name(91, n, a) << ", b = " << b << ", u = " << u;
    }
  }
}

TEST(Portion, SpecialIntervalsBitForBit) {
  // Rounds with u = 0 or u = 1 are exact (they keep or shift the points), so these follow
  // from sharing CasteljauRow: [0,1] is the curve, [1,0] the reversed curve, [t,t] the
  // point B(t) repeated, [0,t] and [t,1] the halves of subdivide(c, t).
  for_random_curves(92, [](const auto& c, double t, const std::string& where) {
    const std::size_t count = c.points().size();
    EXPECT_EQ(portion(c, 0.0, 1.0), c) << where;
    EXPECT_EQ(portion(c, 1.0, 0.0), reversed(c)) << where;
    using Curve_ = std::remove_cvref_t<decltype(c)>;
    EXPECT_EQ(portion(c, t, t), Curve_(std::vector(count, evaluate(c, t)))) << where;
    const auto halves = subdivide(c, t);
    EXPECT_EQ(portion(c, 0.0, t), halves.left) << where;
    EXPECT_EQ(portion(c, t, 1.0), halves.right) << where;
  });
  EXPECT_EQ(portion(Curve({{3, 4}}), 0.2, 0.9), Curve({{3, 4}}));
}

TEST(Portion, EachControlPointIsItsBlossomBitForBit) {
  // portion shares the rounds with a among the control points; each must still be the
  // blossom b(a^(n-i), b^i) as polar rounds it, to the bit (signs of zeros included), for
  // any parameters: inside [0, 1], reversed, equal, at the ends and outside; degrees 0 to 12
  // (past the rows' inline entries), in 2-D and 3-D.
  Mulberry32 rng(4242);
  const auto coordinate = [&]() {
    const double u = rng.next();
    if (u < 0.05) return u < 0.025 ? 0.0 : -0.0;
    return std::ldexp(rng.next() - 0.5, static_cast<int>(rng.next() * 200) - 100);
  };
  const auto same_bits = [](double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; };
  const double fixed[] = {0.0, 1.0, -0.0, 0.5, -0.75, 1.25, 0x1p-60, 1.0 - 0x1p-53};
  const auto pick = [&]() { return fixed[static_cast<std::size_t>(rng.next() * 8)]; };
  for (int round = 0; round < 3000; ++round) {
    const int n = round % 13;
    const double a = round % 3 == 0 ? pick() : rng.next() * 1.5 - 0.25;
    const double b = round % 5 == 0 ? a : (round % 3 == 1 ? pick() : rng.next());
    std::vector<Point2> points;
    std::vector<Point3> points3;
    for (int i = 0; i <= n; ++i) {
      points.push_back({coordinate(), coordinate()});
      points3.push_back({coordinate(), coordinate(), coordinate()});
    }
    const Curve c(points);
    const Curve3 c3(points3);
    const Curve piece = portion(c, a, b);
    const Curve3 piece3 = portion(c3, a, b);
    ASSERT_EQ(piece.degree(), n);
    ASSERT_EQ(piece3.degree(), n);
    for (int i = 0; i <= n; ++i) {
      std::vector<double> args(static_cast<std::size_t>(n));
      for (int j = 0; j < n; ++j) args[static_cast<std::size_t>(j)] = j < n - i ? a : b;
      const Point2 p = n == 0 ? c.front() : blossom(c, args);
      const Point3 p3 = n == 0 ? c3.front() : blossom(c3, args);
      EXPECT_TRUE(same_bits(piece[i].x, p.x) && same_bits(piece[i].y, p.y))
          << "round " << round << " i " << i << " a " << a << " b " << b;
      EXPECT_TRUE(same_bits(piece3[i].x, p3.x) && same_bits(piece3[i].y, p3.y) &&
                  same_bits(piece3[i].z, p3.z))
          << "3-D round " << round << " i " << i << " a " << a << " b " << b;
    }
  }
}

}  // namespace
}  // namespace bezier::core
