// Tests of core/bernstein/exact_casteljau.hpp against exact rationals (tests/support/exact.hpp):
// the value and the portion's coefficients of random polynomials at random double
// parameters, component sums compared as rationals, and the outward roundings.

#include "core/bernstein/exact_casteljau.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tests/support/exact.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

using test::Rational;

Rational exact_of(const Expansion& e) {
  Rational sum(0);
  for (const double c : e.components()) sum = sum + Rational(c);
  return sum;
}

// p(t) by de Casteljau in rationals.
Rational rational_value(std::vector<Rational> row, const Rational& t) {
  for (std::size_t count = row.size(); count > 1; --count) {
    for (std::size_t i = 0; i + 1 < count; ++i) row[i] = row[i] + (row[i + 1] - row[i]) * t;
  }
  return row[0];
}

std::vector<Rational> rationals(const std::vector<double>& c) { return {c.begin(), c.end()}; }

TEST(ExactCasteljau, ValueEqualsTheRationalValue) {
  test::Mulberry32 random(7);
  for (int trial = 0; trial < 200; ++trial) {
    const std::size_t n = 1 + trial % 12;
    std::vector<double> c(n + 1);
    for (double& x : c) x = random.uniform(-4, 4);
    const double t = random.uniform(0, 1);
    const auto value = exact_value(c, t);
    ASSERT_TRUE(value.has_value());
    EXPECT_EQ(exact_of(*value), rational_value(rationals(c), Rational(t)));
  }
}

TEST(ExactCasteljau, PortionIsTheBlossomOnTheStretch) {
  // Coefficient i of the portion on [a, b] is the blossom b(a^(n-i), b^i); its ends are
  // p(a) and p(b), and the portion evaluated at u is p at a + u (b - a).
  test::Mulberry32 random(11);
  for (int trial = 0; trial < 100; ++trial) {
    const std::size_t n = 1 + trial % 8;
    std::vector<double> c(n + 1);
    for (double& x : c) x = random.uniform(-4, 4);
    double a = random.uniform(0, 1), b = random.uniform(0, 1);
    if (a > b) std::swap(a, b);
    const auto piece = exact_portion(c, a, b);
    ASSERT_TRUE(piece.has_value());
    std::vector<Rational> coefficients;
    for (const Expansion& e : *piece) coefficients.push_back(exact_of(e));
    EXPECT_EQ(coefficients.front(), rational_value(rationals(c), Rational(a)));
    EXPECT_EQ(coefficients.back(), rational_value(rationals(c), Rational(b)));
    const Rational u(0.375);
    EXPECT_EQ(rational_value(coefficients, u),
              rational_value(rationals(c), Rational(a) + u * (Rational(b) - Rational(a))));
  }
}

TEST(ExactCasteljau, RefusesRoundsThatWouldUnderflow) {
  // Coefficients near the subnormal range and a parameter with a long mantissa: the
  // products' low bits would fall below 2^-1074.
  const std::vector<double> c = {0x1p-1000, 0x1.0000000000001p-1000, 0x1p-999};
  EXPECT_FALSE(exact_value(c, 1.0 / 3.0).has_value());
  EXPECT_FALSE(exact_portion(c, 0.1, 0.7).has_value());
  // A parameter of few bits keeps them exact.
  EXPECT_TRUE(exact_value(c, 0.5).has_value());
}

TEST(ExactCasteljau, OutwardRoundingBracketsTheValue) {
  const std::vector<double> c = {0, 1, 0};
  const auto third = exact_value(c, 1.0 / 3.0);  // 2 t (1 - t) at t = fl(1/3): no double
  ASSERT_TRUE(third.has_value());
  const Rational v = exact_of(*third);
  const double lo = rounded_down(*third), hi = rounded_up(*third);
  EXPECT_LT(Rational(lo), v);
  EXPECT_GT(Rational(hi), v);
  EXPECT_EQ(std::nextafter(lo, INFINITY), hi);
  const auto half = exact_value(c, 0.5);  // 1/2 exactly
  ASSERT_TRUE(half.has_value());
  EXPECT_EQ(rounded_down(*half), 0.5);
  EXPECT_EQ(rounded_up(*half), 0.5);
}

}  // namespace
}  // namespace bezier::core
