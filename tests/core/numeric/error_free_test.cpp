#include "core/numeric/error_free.hpp"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>

#include "tests/support/exact.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

using test::Rational;

// A random double with a full random mantissa and an exponent drawn from [lo_exp, hi_exp).
double random_double(test::Mulberry32& rng, int lo_exp, int hi_exp) {
  const double m = rng.uniform(-1, 1);
  const int e = static_cast<int>(rng.uniform(lo_exp, hi_exp));
  return std::ldexp(m, e);
}

// hi + lo equals the exact value, hi is the rounded value, and lo is at most half an ulp
// of hi (the defining properties of an error-free transformation).
void expect_exact_split(const TwoTerm<double>& r, const Rational& exact, double rounded) {
  EXPECT_EQ(r.hi, rounded);
  EXPECT_EQ(Rational(r.hi) + Rational(r.lo), exact);
  EXPECT_LE(std::fabs(r.lo), 0.5 * (std::nextafter(std::fabs(r.hi), INFINITY) - std::fabs(r.hi)));
}

TEST(TwoSum, ExactOnRandomPairsOfAnyMagnitudeOrder) {
  test::Mulberry32 rng(29);
  for (int i = 0; i < 4000; ++i) {
    // Exponents far apart and close together, either operand larger.
    const double a = random_double(rng, -200, 200);
    const double b = random_double(rng, -200, 200);
    SCOPED_TRACE(testing::Message() << std::hexfloat << a << " + " << b);
    expect_exact_split(two_sum(a, b), Rational(a) + Rational(b), a + b);
    expect_exact_split(two_sum(b, a), Rational(a) + Rational(b), a + b);
  }
}

TEST(TwoSum, CancellationLeavesNoError) {
  // Sterbenz: b/2 <= a <= 2b makes a - b exact, so the error term is zero.
  const auto r = two_sum(1.0 + 0x1p-52, -1.0);
  EXPECT_EQ(r.hi, 0x1p-52);
  EXPECT_EQ(r.lo, 0.0);
  const auto z = two_sum(3.5, -3.5);
  EXPECT_EQ(z.hi, 0.0);
  EXPECT_EQ(z.lo, 0.0);
}

TEST(TwoSum, ErrorOfATinyAddendIsTheAddendItself) {
  // 1 + 2^-60 rounds to 1: the whole addend is the error.
  const auto r = two_sum(1.0, 0x1p-60);
  EXPECT_EQ(r.hi, 1.0);
  EXPECT_EQ(r.lo, 0x1p-60);
  // Half an ulp of 1 (2^-53) is a tie, rounded to the even 1.
  const auto tie = two_sum(1.0, 0x1p-53);
  EXPECT_EQ(tie.hi, 1.0);
  EXPECT_EQ(tie.lo, 0x1p-53);
}

TEST(TwoSum, SubnormalOperandsAreExact) {
  const double tiny = std::numeric_limits<double>::denorm_min();
  const double sub = 0x0.fffffffffffffp-1022;  // the largest subnormal
  expect_exact_split(two_sum(1.0, tiny), Rational(1.0) + Rational(tiny), 1.0 + tiny);
  expect_exact_split(two_sum(sub, tiny), Rational(sub) + Rational(tiny), sub + tiny);
  expect_exact_split(two_sum(sub, -DBL_MIN), Rational(sub) - Rational(DBL_MIN), sub - DBL_MIN);
  // Sums of subnormals are exact multiples of 2^-1074: no error term.
  EXPECT_EQ(two_sum(sub, tiny).lo, 0.0);
}

TEST(TwoSum, ExactNextToOverflow) {
  // DBL_MAX + 2^969 is below DBL_MAX + ulp/2 (ulp = 2^971): it rounds to DBL_MAX and the
  // addend is the error, without overflow.
  expect_exact_split(two_sum(DBL_MAX, 0x1p969), Rational(DBL_MAX) + Rational(0x1p969), DBL_MAX);
  expect_exact_split(two_sum(DBL_MAX, -0x1p969), Rational(DBL_MAX) - Rational(0x1p969),
                     DBL_MAX - 0x1p969);
  expect_exact_split(two_sum(-DBL_MAX, 0x1.8p1023), Rational(-DBL_MAX) + Rational(0x1.8p1023),
                     -DBL_MAX + 0x1.8p1023);
  expect_exact_split(two_sum(0x1.fffffffffffffp1022, 0x1.fffffffffffffp1022),
                     Rational(0x1.fffffffffffffp1022) * Rational(2), DBL_MAX);
}

TEST(TwoSum, IsUsableInConstantExpressions) {
  constexpr TwoTerm<double> r = two_sum(1.0, 0x1p-60);
  static_assert(r.hi == 1.0 && r.lo == 0x1p-60);
}

TEST(TwoProduct, ExactOnRandomPairs) {
  test::Mulberry32 rng(4);
  for (int i = 0; i < 4000; ++i) {
    // Products between 2^-900 and 2^900: neither over- nor underflow of the error term.
    const double a = random_double(rng, -450, 450);
    const double b = random_double(rng, -450, 450);
    SCOPED_TRACE(testing::Message() << std::hexfloat << a << " * " << b);
    expect_exact_split(two_product(a, b), Rational(a) * Rational(b), a * b);
  }
}

TEST(TwoProduct, KnownErrorTerms) {
  // (1 + 2^-52)^2 = 1 + 2^-51 + 2^-104: the last term is the rounding error.
  const auto r = two_product(1.0 + 0x1p-52, 1.0 + 0x1p-52);
  EXPECT_EQ(r.hi, 1.0 + 0x1p-51);
  EXPECT_EQ(r.lo, 0x1p-104);
  // (1 - 2^-53)(1 + 2^-52) = 1 + 2^-53 - 2^-105: just below the tie between 1 and
  // 1 + 2^-52, so it rounds to 1, leaving 2^-53 - 2^-105.
  const auto s = two_product(1.0 - 0x1p-53, 1.0 + 0x1p-52);
  EXPECT_EQ(s.hi, 1.0);
  EXPECT_EQ(s.lo, 0x1p-53 - 0x1p-105);
}

TEST(TwoProduct, SubnormalFactorWithRepresentableError) {
  // The largest subnormal (52 significant bits) times a 53-bit number near 2^600: the
  // product is near 2^-422, and its error term near 2^-528 is a normal double.
  const double sub = 0x0.fffffffffffffp-1022;
  const double big = 0x1.0000000000001p600;
  expect_exact_split(two_product(sub, big), Rational(sub) * Rational(big), sub * big);
  // The smallest subnormal times a power of two: exact, no error term.
  const double tiny = std::numeric_limits<double>::denorm_min();
  const auto r = two_product(3 * tiny, 0x1p1000);
  EXPECT_EQ(r.hi, 0x1.8p-73);
  EXPECT_EQ(r.lo, 0.0);
}

TEST(TwoProduct, ExactNextToOverflow) {
  // (2^512 - 2^459)(2^511 + 2^459) is just below DBL_MAX; its error is exact.
  const double a = 0x1.fffffffffffffp511, b = 0x1.0000000000001p511;
  expect_exact_split(two_product(a, b), Rational(a) * Rational(b), a * b);
  expect_exact_split(two_product(-a, a), -(Rational(a) * Rational(a)), -(a * a));
}

TEST(ErrorFreePoints, CoordinatesAreTransformedIndependently) {
  test::Mulberry32 rng(7);
  for (int i = 0; i < 200; ++i) {
    const Point3 a{random_double(rng, -60, 60), random_double(rng, -60, 60),
                   random_double(rng, -60, 60)};
    const Point3 b{random_double(rng, -60, 60), random_double(rng, -60, 60),
                   random_double(rng, -60, 60)};
    const double s = random_double(rng, -60, 60);
    const auto sum3 = two_sum(a, b);
    const auto prod3 = two_product(s, a);
    const auto sum2 = two_sum(Point2{a.x, a.y}, Point2{b.x, b.y});
    const auto prod2 = two_product(s, Point2{a.x, a.y});
    const double ac[] = {a.x, a.y, a.z}, bc[] = {b.x, b.y, b.z};
    const double sh[] = {sum3.hi.x, sum3.hi.y, sum3.hi.z}, sl[] = {sum3.lo.x, sum3.lo.y, sum3.lo.z};
    const double ph[] = {prod3.hi.x, prod3.hi.y, prod3.hi.z},
                 pl[] = {prod3.lo.x, prod3.lo.y, prod3.lo.z};
    for (int k = 0; k < 3; ++k) {
      expect_exact_split({sh[k], sl[k]}, Rational(ac[k]) + Rational(bc[k]), ac[k] + bc[k]);
      expect_exact_split({ph[k], pl[k]}, Rational(s) * Rational(ac[k]), s * ac[k]);
    }
    EXPECT_EQ(sum2.hi.x, sum3.hi.x);
    EXPECT_EQ(sum2.lo.y, sum3.lo.y);
    EXPECT_EQ(prod2.hi.y, prod3.hi.y);
    EXPECT_EQ(prod2.lo.x, prod3.lo.x);
  }
}

}  // namespace
}  // namespace bezier::core
