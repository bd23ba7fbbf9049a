// Tests of core/bernstein/monomial.hpp: the monomial coefficients of a Bernstein polynomial
// against the binomial expansion in exact rationals,
//   a_k = C(n,k) Σ_{i<=k} C(k,i) (-1)^(k-i) c_i,
// and the true degree of exactly degree-elevated curves.

#include "core/bernstein/monomial.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <span>
#include <vector>

#include "core/bernstein/tuning.hpp"
#include "core/numeric/unit_roundoff.hpp"
#include "tests/support/exact.hpp"
#include "tests/support/exact_bezier.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

using test::Rational;

std::vector<Rational> exact_monomial(const std::vector<double>& c) {
  const int n = static_cast<int>(c.size()) - 1;
  std::vector<Rational> a;
  for (int k = 0; k <= n; ++k) {
    Rational sum(0);
    for (int i = 0; i <= k; ++i) {
      const Rational term = Rational(test::binom(k, i)) * Rational(c[static_cast<std::size_t>(i)]);
      sum += (k - i) % 2 == 0 ? term : -term;
    }
    a.push_back(Rational(test::binom(n, k)) * sum);
  }
  return a;
}

Coeffs coeffs(const std::vector<double>& c) {
  return Coeffs(std::span<const double>(c));
}

TEST(Monomial, IntegerCoefficientsConvertExactly) {
  // 1 b_0 + 3 b_1 - 2 b_2 + 5 b_3 = 1 + 6 t - 21 t^2 + 19 t^3 (at t = 1: 5 = c_3).
  const std::vector<double> c{1, 3, -2, 5};
  const Coeffs a = monomial(c);
  ASSERT_EQ(a.size(), 4u);
  EXPECT_EQ(a[0], 1.0);
  EXPECT_EQ(a[1], 6.0);
  EXPECT_EQ(a[2], -21.0);
  EXPECT_EQ(a[3], 19.0);
  const std::vector<double> single{2.5};
  EXPECT_EQ(monomial(single)[0], 2.5);
  for (int n = 1; n <= 24; ++n) {
    std::vector<double> ints;
    for (int i = 0; i <= n; ++i) ints.push_back(static_cast<double>((i * 7) % 5 - 2));
    const Coeffs got = monomial(ints);
    const auto expected = exact_monomial(ints);
    for (int k = 0; k <= n; ++k)
      EXPECT_EQ(Rational(got[static_cast<std::size_t>(k)]), expected[static_cast<std::size_t>(k)])
          << "degree " << n << " k " << k;
  }
}

TEST(Monomial, RandomCoefficientsWithinTheDifferenceRounding) {
  // Δ^k rounds k levels of differences of values up to 2^j max|c|, and the binomial
  // factor one more time: |a_k - exact| <= γ_(k+2) C(n,k) 2^k max|c|.
  test::Mulberry32 rng(201);
  for (int n = 0; n <= 26; ++n) {
    for (int draw = 0; draw < 5; ++draw) {
      std::vector<double> c;
      double m = 0;
      for (int i = 0; i <= n; ++i) {
        c.push_back(rng.uniform(-1, 1));
        m = std::max(m, std::fabs(c.back()));
      }
      const Coeffs got = monomial(c);
      const auto expected = exact_monomial(c);
      ASSERT_EQ(got.size(), c.size());
      for (int k = 0; k <= n; ++k) {
        const double bound =
            test::rounding_gamma(k + 2) * static_cast<double>(test::binom(n, k)) * std::ldexp(m, k);
        EXPECT_LE(
            (Rational(got[static_cast<std::size_t>(k)]) - expected[static_cast<std::size_t>(k)])
                .abs(),
            Rational(bound))
            << "degree " << n << " k " << k;
      }
      // The top coefficient by its own routine is monomial()'s, bit for bit.
      EXPECT_EQ(top_monomial_coefficient(coeffs(c)), got[static_cast<std::size_t>(n)]) << n;
    }
  }
}

// Degree elevation in exact rationals: c'_i = (i c_(i-1) + (m+1-i) c_i) / (m+1).
std::vector<Rational> elevate(const std::vector<Rational>& c) {
  const long long m = static_cast<long long>(c.size()) - 1;
  std::vector<Rational> out;
  for (long long i = 0; i <= m + 1; ++i) {
    Rational v(0);
    if (i > 0) v += Rational(i) * c[static_cast<std::size_t>(i - 1)];
    if (i <= m) v += Rational(m + 1 - i) * c[static_cast<std::size_t>(i)];
    out.push_back(v / Rational(m + 1));
  }
  return out;
}

TEST(Monomial, ElevatedCurvesHaveTheirTrueDegree) {
  // A cubic (integer points) elevated exactly to degree 3 + e: the denominators divide
  // 4 5 ... (3 + e), so scaling by their product keeps every control point an exact double.
  const std::vector<double> x3{0, 3, -1, 4}, y3{1, -2, 5, 2};
  for (int e = 0; e <= 6; ++e) {
    std::vector<Rational> x(x3.begin(), x3.end()), y(y3.begin(), y3.end());
    for (int j = 0; j < e; ++j) {
      x = elevate(x);
      y = elevate(y);
    }
    long long scale = 1;
    for (int d = 4; d <= 3 + e; ++d) scale *= d;
    Coeffs cx(x.size()), cy(y.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
      const Rational sx = x[i] * Rational(scale), sy = y[i] * Rational(scale);
      ASSERT_EQ(Rational(sx.to_double()), sx);
      ASSERT_EQ(Rational(sy.to_double()), sy);
      cx[i] = sx.to_double();
      cy[i] = sy.to_double();
    }
    const Coeffs ax = monomial(cx), ay = monomial(cy);
    for (std::size_t k = 4; k < ax.size(); ++k) {
      EXPECT_EQ(ax[k], 0.0) << e << " " << k;
      EXPECT_EQ(ay[k], 0.0) << e << " " << k;
    }
    EXPECT_EQ(true_degree(ax, ay, 5.0 * static_cast<double>(scale)), 3) << e;
    // Δ^3 x = 4 - 3 (-1) + 3 (3) - 0 = 16 for the cubic itself.
    EXPECT_EQ(top_monomial_coefficient(cx), e == 0 ? 16.0 : 0.0);
  }
  // A line traversed uniformly, elevated to a cubic: x = t, y = 2t.
  const Coeffs lx(std::vector<double>{0, 1.0 / 3, 2.0 / 3, 1}),
      ly(std::vector<double>{0, 2.0 / 3, 4.0 / 3, 2});
  EXPECT_EQ(true_degree(monomial(lx), monomial(ly), 2.0), 1);
  // Constant: degree 0.
  const Coeffs k(std::vector<double>{3, 3, 3});
  EXPECT_EQ(true_degree(monomial(k), monomial(k), 3.0), 0);
}

TEST(Monomial, SignificanceThresholdIsTheStatedBound) {
  // tol = factor C(n,k) 2^k u magnitude; above it (strictly) is significant.
  const int n = 5, k = 3;
  const double magnitude = 2.0;
  const double tol =
      bernstein_tuning::kSignificantCoefficientFactor * 10.0 * 8.0 * kUnitRoundoff * magnitude;
  EXPECT_FALSE(significant_coefficient(n, k, tol, -tol, magnitude));
  EXPECT_TRUE(significant_coefficient(n, k, std::nextafter(tol, 1.0), 0.0, magnitude));
  EXPECT_TRUE(significant_coefficient(n, k, 0.0, -std::nextafter(tol, 1.0), magnitude));
}

}  // namespace
}  // namespace bezier::core
