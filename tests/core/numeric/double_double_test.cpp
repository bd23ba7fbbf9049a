#include "core/numeric/double_double.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tests/support/exact.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core::dd {
namespace {

using test::Rational;

Rational value(Real a) {
  return Rational(a.hi) + Rational(a.lo);
}

// The header's bounds are k u^2 with u = 2^-53, Joldes et al. (2017) state them up to a
// factor 1 / (1 - 4u) at most; the check allows that factor and nothing more.
bool within_relative(Real got, const Rational& exact, double k) {
  const Rational err = (value(got) - exact).abs();
  return err * Rational(1.0 - 0x1p-51) <= Rational(k * 0x1p-106) * exact.abs();
}

// Normalised: |lo| <= ulp(hi) / 2, i.e. hi + lo rounds to hi.
void expect_normalised(Real a) {
  EXPECT_EQ(a.hi + a.lo, a.hi);
}

// A normalised double-double with random hi (exponent in [-e, e)) and lo of any size up
// to half an ulp of hi.
Real random_real(test::Mulberry32& rng, int e) {
  const double hi = std::ldexp(rng.uniform(-1, 1), static_cast<int>(rng.uniform(-e, e)));
  const double lo =
      hi * 0x1p-53 * rng.uniform(-1, 1) * std::ldexp(1.0, -static_cast<int>(rng.uniform(0, 8)));
  const TwoTerm<double> n = two_sum(hi, lo);
  return {n.hi, n.lo};
}

TEST(DoubleDouble, FromAndToDouble) {
  constexpr Real a = from(0.1);
  static_assert(a.hi == 0.1 && a.lo == 0.0);
  static_assert(to_double(Real{1.0, 0x1p-60}) == 1.0);
  static_assert(to_double(Real{1.0, 0x1p-52}) == 1.0 + 0x1p-52);
}

TEST(DoubleDouble, FastTwoSumIsExactForOrderedOperands) {
  test::Mulberry32 rng(11);
  for (int i = 0; i < 2000; ++i) {
    double a = std::ldexp(rng.uniform(-1, 1), static_cast<int>(rng.uniform(-100, 100)));
    double b = std::ldexp(rng.uniform(-1, 1), static_cast<int>(rng.uniform(-100, 100)));
    if (std::fabs(a) < std::fabs(b)) std::swap(a, b);
    const Real r = fast_two_sum(a, b);
    EXPECT_EQ(r.hi, a + b);
    EXPECT_EQ(value(r), Rational(a) + Rational(b));
  }
  const Real z = fast_two_sum(0.0, 0.0);
  EXPECT_EQ(z.hi, 0.0);
  EXPECT_EQ(z.lo, 0.0);
}

TEST(DoubleDouble, AddAndSubWithinThreeUSquared) {
  test::Mulberry32 rng(12);
  for (int i = 0; i < 3000; ++i) {
    const Real a = random_real(rng, 40), b = random_real(rng, 40);
    const Real s = add(a, b), d = sub(a, b);
    EXPECT_TRUE(within_relative(s, value(a) + value(b), 3)) << i;
    EXPECT_TRUE(within_relative(d, value(a) - value(b), 3)) << i;
    expect_normalised(s);
    expect_normalised(d);
  }
}

TEST(DoubleDouble, AddUnderCancellation) {
  // Equal high parts cancel: the low parts carry the whole result, which is exact.
  const Real a{1.0, 0x1p-60}, b{-1.0, 0x1p-70};
  const Real s = add(a, b);
  EXPECT_EQ(value(s), Rational(0x1p-60) + Rational(0x1p-70));
  const Real x{3.0, -0x1p-55};
  const Real zero = sub(x, x);
  EXPECT_EQ(zero.hi, 0.0);
  EXPECT_EQ(zero.lo, 0.0);
  // Near-cancellation with random low parts stays within the relative bound.
  test::Mulberry32 rng(13);
  for (int i = 0; i < 1000; ++i) {
    const Real p = random_real(rng, 4);
    const Real q{-p.hi, p.hi * 0x1p-54 * rng.uniform(-1, 1)};
    const TwoTerm<double> qn = two_sum(q.hi, q.lo);
    const Real qq{qn.hi, qn.lo};
    EXPECT_TRUE(within_relative(add(p, qq), value(p) + value(qq), 3)) << i;
  }
}

TEST(DoubleDouble, NegIsExact) {
  const Real a{0.1, 0x1p-58};
  EXPECT_EQ(value(neg(a)), -value(a));
}

TEST(DoubleDouble, MulByDoubleWithinTwoUSquared) {
  test::Mulberry32 rng(14);
  for (int i = 0; i < 3000; ++i) {
    const Real a = random_real(rng, 100);
    const double b = std::ldexp(rng.uniform(-1, 1), static_cast<int>(rng.uniform(-100, 100)));
    const Real p = mul(a, b);
    EXPECT_TRUE(within_relative(p, value(a) * Rational(b), 2)) << i;
    expect_normalised(p);
  }
}

TEST(DoubleDouble, MulWithinSixUSquared) {
  test::Mulberry32 rng(15);
  for (int i = 0; i < 3000; ++i) {
    const Real a = random_real(rng, 100), b = random_real(rng, 100);
    const Real p = mul(a, b);
    EXPECT_TRUE(within_relative(p, value(a) * value(b), 6)) << i;
    expect_normalised(p);
  }
  // (1 + 2^-60)(1 - 2^-60) = 1 - 2^-120: the product of the low parts is below the bound.
  EXPECT_TRUE(within_relative(mul(Real{1.0, 0x1p-60}, Real{1.0, -0x1p-60}),
                              Rational(1) - Rational(0x1p-120), 6));
}

TEST(DoubleDouble, LerpWithinTenUSquaredOfTheLargerEnd) {
  test::Mulberry32 rng(16);
  for (int i = 0; i < 3000; ++i) {
    const Real a = random_real(rng, 20), b = random_real(rng, 20);
    const double t = rng.next();
    const Rational exact = (Rational(1) - Rational(t)) * value(a) + Rational(t) * value(b);
    const Rational err = (value(lerp(a, b, t)) - exact).abs();
    const Rational scale = std::max(value(a).abs(), value(b).abs());
    EXPECT_LE(err * Rational(1.0 - 0x1p-51), Rational(10 * 0x1p-106) * scale) << i;
  }
  // The ends are reproduced exactly.
  const Real a{0.1, 0x1p-58}, b{-7.3, 0x1p-55};
  EXPECT_EQ(value(lerp(a, b, 0.0)), value(a));
  EXPECT_EQ(value(lerp(a, b, 1.0)), value(b));
}

}  // namespace
}  // namespace bezier::core::dd
