// lerp_levels_error_bound (lerp_error_bound.hpp) against exact arithmetic: de Casteljau
// values and portions (blossoms with two parameters) computed in doubles stay within the
// bound of the same recurrence in rationals, from normal magnitudes down to subnormal ones,
// where the bound's absolute term is what covers them.

#include "core/numeric/lerp_error_bound.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <vector>

#include "core/bernstein/bernstein1d.hpp"
#include "tests/support/exact.hpp"
#include "tests/support/exact_bezier.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

using test::Rational;

/// n levels of lerp with one t, written as bernstein::lerp rounds it.
double casteljau(std::vector<double> c, double t) {
  for (std::size_t level = c.size() - 1; level > 0; --level) {
    for (std::size_t k = 0; k < level; ++k) c[k] = (1.0 - t) * c[k] + t * c[k + 1];
  }
  return c[0];
}

double largest_abs(const std::vector<double>& c) {
  double m = 0.0;
  for (const double v : c) m = std::fabs(v) > m ? std::fabs(v) : m;
  return m;
}

std::vector<Rational> exact(const std::vector<double>& c) {
  return {c.begin(), c.end()};
}

/// Coefficients c_i = u_i 2^scale, u_i uniform in [-1, 1], some of them 0 or +-1 exactly.
std::vector<double> random_coefficients(test::Mulberry32& rng, int degree, int scale) {
  std::vector<double> c;
  for (int i = 0; i <= degree; ++i) {
    const double pick = rng.next();
    const double sign = rng.next() < 0.5 ? -1.0 : 1.0;
    const double u = pick < 0.05 ? 0.0 : pick < 0.1 ? sign : rng.uniform(-1, 1);
    c.push_back(std::ldexp(u, scale));
  }
  return c;
}

/// t in [0, 1]: uniform, or an end, or next to one.
double random_parameter(test::Mulberry32& rng) {
  const double pick = rng.next();
  if (pick < 0.05) return 0.0;
  if (pick < 0.1) return 1.0;
  if (pick < 0.15) return std::nextafter(1.0, 0.0);
  if (pick < 0.2) return 0x1p-30 * rng.next();
  return rng.next();
}

/// |computed - exact| <= bound, in rationals (the bound itself as the double it rounds to).
::testing::AssertionResult within(double computed, const Rational& exact_value, double bound) {
  const Rational error = abs(Rational(computed) - exact_value);
  if (error <= Rational(bound)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "error " << error.to_double() << " > bound " << bound;
}

TEST(LerpLevelsErrorBound, DeCasteljauValuesAtNormalScales) {
  test::Mulberry32 rng(29);
  for (int trial = 0; trial < 3000; ++trial) {
    const int degree = 1 + static_cast<int>(rng.next() * 15);
    const int scale = static_cast<int>(rng.uniform(-60, 60));
    const std::vector<double> c = random_coefficients(rng, degree, scale);
    const double t = random_parameter(rng);
    const Rational want = test::exact_evaluate(exact(c), Rational(t));
    EXPECT_TRUE(within(casteljau(c, t), want, lerp_levels_error_bound(degree, largest_abs(c))))
        << "trial " << trial << " degree " << degree << " t " << t;
  }
}

TEST(LerpLevelsErrorBound, PortionsOfBernsteinPolynomials) {
  // bernstein::portion_into: coefficient i of p on [a, b] is the blossom b(a^(n-i), b^i),
  // n levels of lerps with a or b.
  test::Mulberry32 rng(4);
  for (int trial = 0; trial < 1500; ++trial) {
    const int degree = 1 + static_cast<int>(rng.next() * 12);
    const int scale = static_cast<int>(rng.uniform(-20, 20));
    const std::vector<double> c = random_coefficients(rng, degree, scale);
    double a = random_parameter(rng), b = random_parameter(rng);
    if (b < a) std::swap(a, b);
    std::vector<double> piece(c.size());
    bernstein::portion_into(std::span<const double>(c), a, b, piece.data());
    const double bound = lerp_levels_error_bound(degree, largest_abs(c));
    for (int i = 0; i <= degree; ++i) {
      std::vector<Rational> us(static_cast<std::size_t>(degree - i), Rational(a));
      us.insert(us.end(), static_cast<std::size_t>(i), Rational(b));
      const Rational want = test::exact_polar(exact(c), us).front();
      EXPECT_TRUE(within(piece[static_cast<std::size_t>(i)], want, bound))
          << "trial " << trial << " degree " << degree << " coefficient " << i;
    }
  }
}

TEST(LerpLevelsErrorBound, SubnormalMagnitudesNeedTheAbsoluteTerm) {
  // Coefficients of a few hundred times the least subnormal: the products underflow and err
  // by up to half of it each, far beyond 3.02 n u magnitude (which rounds to 0 here).
  test::Mulberry32 rng(1074);
  int beyond_relative_term = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const int degree = 1 + static_cast<int>(rng.next() * 10);
    const std::vector<double> c = random_coefficients(rng, degree, -1066);
    const double t = random_parameter(rng);
    const Rational want = test::exact_evaluate(exact(c), Rational(t));
    const double computed = casteljau(c, t);
    EXPECT_TRUE(within(computed, want, lerp_levels_error_bound(degree, largest_abs(c))))
        << "trial " << trial;
    const double relative_term = 3.02 * degree * kUnitRoundoff * largest_abs(c);
    if (abs(Rational(computed) - want) > Rational(relative_term)) ++beyond_relative_term;
  }
  EXPECT_GT(beyond_relative_term, 0);
}

TEST(LerpLevelsErrorBound, NoLevelsIsExact) {
  // No arithmetic: only the absolute term, which keeps the bound positive.
  EXPECT_EQ(lerp_levels_error_bound(0, 5.0), 0x1p-1000);
  EXPECT_EQ(lerp_levels_error_bound(3, 0.0), 0x1p-1000);
}

}  // namespace
}  // namespace bezier::core
