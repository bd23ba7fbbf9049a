// Tests of tests/support/exact.hpp, the exact arithmetic every other core test trusts.
// Independent oracles: IEEE 754 +, -, *, / on doubles are correctly rounded (round to
// nearest, ties to even), so Rational(a) op Rational(b) rounded by to_double() must equal
// a op b bit for bit; decimal strings of powers of two and ten are known closed forms.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "tests/support/exact.hpp"
#include "tests/support/exact_bezier.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::test {
namespace {

constexpr double kMax = std::numeric_limits<double>::max();
constexpr double kDenormMin = std::numeric_limits<double>::denorm_min();
constexpr double kMinNormal = std::numeric_limits<double>::min();

BigInt pow_big(long long base, int k) {
  BigInt r(1);
  for (int i = 0; i < k; ++i) r = r * BigInt(base);
  return r;
}

/// A random BigInt with up to `limbs` 32-bit limbs and a random sign.
BigInt random_big(Mulberry32& rng, int limbs) {
  BigInt r;
  const int count = 1 + static_cast<int>(rng.next() * limbs);
  for (int i = 0; i < count; ++i)
    r = (r << 32) + BigInt(static_cast<long long>(rng.next() * 4294967296.0));
  return rng.next() < 0.5 ? -r : r;
}

/// A random finite double with a random sign and exponent in [lo, hi), subnormals included
/// when lo is small enough.
double random_double(Mulberry32& rng, int lo, int hi) {
  const double mantissa = 1.0 + rng.next();  // [1, 2), 32 random bits
  const double tail = rng.next() * 0x1p-32;  // the remaining bits
  const int e = lo + static_cast<int>(rng.next() * (hi - lo));
  const double x = std::ldexp(mantissa + tail, e);
  return rng.next() < 0.5 ? -x : x;
}

TEST(BigInt, DecimalStringsOfKnownPowers) {
  EXPECT_EQ(BigInt(0).str(), "0");
  EXPECT_EQ(BigInt(-42).str(), "-42");
  EXPECT_EQ((BigInt(1) << 64).str(), "18446744073709551616");
  EXPECT_EQ((BigInt(1) << 100).str(), "1267650600228229401496703205376");
  EXPECT_EQ(pow_big(10, 30).str(), "1" + std::string(30, '0'));
  EXPECT_EQ((-pow_big(10, 18) + BigInt(1)).str(), "-999999999999999999");
  EXPECT_EQ(BigInt(std::numeric_limits<long long>::min()).str(), "-9223372036854775808");
}

TEST(BigInt, SmallValuesAgreeWithBuiltInIntegers) {
  Mulberry32 rng(7);
  for (int i = 0; i < 2000; ++i) {
    const auto a = static_cast<long long>(rng.uniform(-3e9, 3e9));
    auto b = static_cast<long long>(rng.uniform(-3e9, 3e9));
    if (b == 0) b = 1;
    SCOPED_TRACE(std::to_string(a) + " " + std::to_string(b));
    EXPECT_EQ(BigInt(a) + BigInt(b), BigInt(a + b));
    EXPECT_EQ(BigInt(a) - BigInt(b), BigInt(a - b));
    EXPECT_EQ(BigInt(a) * BigInt(b), BigInt(a * b));
    EXPECT_EQ(BigInt(a) / BigInt(b), BigInt(a / b));
    EXPECT_EQ(BigInt(a) % BigInt(b), BigInt(a % b));
    EXPECT_EQ(BigInt(a) < BigInt(b), a < b);
    EXPECT_EQ(BigInt(a) << 7, BigInt(a * 128));
    EXPECT_EQ((BigInt(a) >> 5).str(), std::to_string(a / 32));  // truncation toward zero
  }
}

TEST(BigInt, DivisionIdentityOnLargeRandomOperands) {
  for (const std::uint32_t seed : {1u, 2u, 3u}) {
    Mulberry32 rng(seed);
    for (int i = 0; i < 500; ++i) {
      const BigInt a = random_big(rng, 12);
      BigInt b = random_big(rng, 6);
      if (b.is_zero()) b = BigInt(3);
      SCOPED_TRACE("seed " + std::to_string(seed) + " draw " + std::to_string(i) + ": " + a.str() +
                   " / " + b.str());
      const auto [q, r] = divmod(a, b);
      EXPECT_EQ(q * b + r, a);
      EXPECT_LT(r.abs(), b.abs());
      EXPECT_TRUE(r.is_zero() || r.sign() == a.sign());
      EXPECT_EQ((a * b) / b, a);
      EXPECT_TRUE(((a * b) % b).is_zero());
      EXPECT_EQ((a + b) - b, a);
    }
  }
}

TEST(BigInt, DivisionNeedingTheAddBackStep) {
  // Knuth's step D6 (add back) runs when the trial quotient is still one too large after
  // the two-limb test. Test data of Warren, "Hacker's Delight", §9-2 (divmnu, marked
  // "adding back required"), limbs most significant first:
  // (0x80000000, 0, 3) / (0x20000000, 0, 1) = 3 rem (0x20000000, 0, 0), and the same with 0x8000 /
  // 0x2000.
  for (const long long top : {0x80000000LL, 0x8000LL}) {
    const BigInt u = (BigInt(top) << 64) + BigInt(3);
    const BigInt v = (BigInt(top / 4) << 64) + BigInt(1);
    const auto [q, r] = divmod(u, v);
    EXPECT_EQ(q, BigInt(3));
    EXPECT_EQ(r, BigInt(top / 4) << 64);
  }
}

TEST(BigInt, Gcd) {
  const BigInt three(3), nine(9);
  EXPECT_EQ(gcd((BigInt(1) << 100) * three, (BigInt(1) << 50) * nine), (BigInt(1) << 50) * three);
  EXPECT_EQ(gcd(BigInt(0), BigInt(-12)), BigInt(12));
  EXPECT_EQ(gcd(BigInt(0), BigInt(0)), BigInt(0));
  EXPECT_EQ(gcd(pow_big(10, 40), pow_big(6, 30)), pow_big(2, 30));
  Mulberry32 rng(11);
  for (int i = 0; i < 200; ++i) {
    const BigInt g = random_big(rng, 3).abs() + BigInt(1);
    const BigInt a = random_big(rng, 4), b = random_big(rng, 4);
    const BigInt d = gcd(a * g, b * g);
    EXPECT_TRUE((d % g).is_zero()) << "draw " << i;
    if (!d.is_zero()) {
      EXPECT_TRUE(((a * g) % d).is_zero()) << "draw " << i;
      EXPECT_TRUE(((b * g) % d).is_zero()) << "draw " << i;
      EXPECT_EQ(gcd((a * g) / d, (b * g) / d), BigInt(1)) << "draw " << i;
    }
  }
}

TEST(Rational, NormalisedRepresentation) {
  const Rational r(BigInt(6), BigInt(-4));
  EXPECT_EQ(r.num(), BigInt(-3));
  EXPECT_EQ(r.den(), BigInt(2));
  EXPECT_EQ(r.str(), "-3/2");
  EXPECT_EQ(Rational(0.5).str(), "1/2");
  EXPECT_EQ(Rational(-3).str(), "-3");
  EXPECT_EQ(Rational(0.1).str(), "3602879701896397/36028797018963968");  // 0.1 = that / 2^55
  EXPECT_EQ(Rational(0), Rational(-0.0));
  EXPECT_EQ(Rational(BigInt(0), BigInt(-7)).den(), BigInt(1));
  EXPECT_EQ(Rational(18446744073709551615ull).str(), "18446744073709551615");
}

TEST(Rational, ToDoubleOfSimpleFractions) {
  EXPECT_EQ((Rational(1) / Rational(3)).to_double(), 1.0 / 3.0);
  EXPECT_EQ((Rational(2) / Rational(3)).to_double(), 2.0 / 3.0);
  EXPECT_EQ((Rational(-1) / Rational(10)).to_double(), -0.1);
  EXPECT_EQ((Rational(22) / Rational(7)).to_double(), 22.0 / 7.0);
  EXPECT_EQ(Rational(0).to_double(), 0.0);
  EXPECT_FALSE(std::signbit(Rational(-0.0).to_double()));
}

TEST(Rational, ToDoubleRoundsTiesToEven) {
  const Rational two53 = Rational(BigInt(1) << 53, BigInt(1));
  EXPECT_EQ((two53 + Rational(1)).to_double(), 0x1p53);      // tie: down to even
  EXPECT_EQ((two53 + Rational(3)).to_double(), 0x1p53 + 4);  // tie: up to even
  // Just above the tie rounds up: the sticky remainder counts.
  EXPECT_EQ((two53 + Rational(1) + Rational(BigInt(1), BigInt(1) << 80)).to_double(), 0x1p53 + 2);
  EXPECT_EQ((-(two53 + Rational(1))).to_double(), -0x1p53);
  // 1 + 2^-53 is the tie between 1 and 1 + 2^-52.
  EXPECT_EQ((Rational(1) + Rational(0x1p-53)).to_double(), 1.0);
  EXPECT_EQ((Rational(1) + Rational(0x1p-53) + Rational(0x1p-200)).to_double(), 1.0 + 0x1p-52);
}

TEST(Rational, ToDoubleOverflowAndUnderflow) {
  EXPECT_EQ(Rational(kMax).to_double(), kMax);
  EXPECT_EQ((Rational(kMax) * Rational(2)).to_double(), INFINITY);
  EXPECT_EQ((-Rational(kMax) * Rational(2)).to_double(), -INFINITY);
  // DBL_MAX + half an ulp (2^970) is the tie with 2^1024: to even, i.e. overflow.
  EXPECT_EQ((Rational(kMax) + Rational(0x1p970)).to_double(), INFINITY);
  EXPECT_EQ((Rational(kMax) + Rational(0x1p969)).to_double(), kMax);
  EXPECT_EQ(Rational(kDenormMin).to_double(), kDenormMin);
  EXPECT_EQ(Rational(kMinNormal).to_double(), kMinNormal);
  EXPECT_EQ((Rational(kDenormMin) / Rational(2)).to_double(), 0.0);  // tie to even: 0
  EXPECT_EQ((Rational(kDenormMin) * Rational(3) / Rational(4)).to_double(), kDenormMin);
  EXPECT_EQ((Rational(kDenormMin) * Rational(3) / Rational(2)).to_double(),
            2 * kDenormMin);  // tie: to even
  EXPECT_EQ((Rational(kDenormMin) / Rational(3)).to_double(), 0.0);
  EXPECT_EQ((Rational(kMinNormal) - Rational(kDenormMin)).to_double(), kMinNormal - kDenormMin);
  EXPECT_EQ((Rational(kDenormMin) * Rational(kDenormMin)).to_double(), 0.0);
}

TEST(Rational, DoublesRoundTripExactly) {
  const double specials[] = {0.0,   1.0,        -1.0,       0.1,       1.0 / 3.0, kMax,
                             -kMax, kDenormMin, kMinNormal, 0x1p-1073, 1e300,     1e-300};
  for (const double x : specials) EXPECT_EQ(Rational(x).to_double(), x) << x;
  for (const std::uint32_t seed : {1u, 5u}) {
    Mulberry32 rng(seed);
    for (int i = 0; i < 5000; ++i) {
      const double x = random_double(rng, -1080, 1024);
      ASSERT_EQ(Rational(x).to_double(), x) << "seed " << seed << " draw " << i;
    }
  }
}

TEST(Rational, ArithmeticMatchesCorrectlyRoundedIeeeOperations) {
  for (const std::uint32_t seed : {1u, 2u, 3u, 4u}) {
    Mulberry32 rng(seed);
    // Exponent ranges: moderate, mixed, and ones whose results are subnormal or overflow.
    const int lo = seed == 4 ? -1070 : -60, hi = seed == 3 ? 1023 : 60;
    for (int i = 0; i < 1500; ++i) {
      const double a = random_double(rng, lo, hi), b = random_double(rng, lo, hi);
      SCOPED_TRACE("seed " + std::to_string(seed) + " draw " + std::to_string(i));
      const Rational ra(a), rb(b);
      EXPECT_EQ((ra + rb).to_double(), a + b);
      EXPECT_EQ((ra - rb).to_double(), a - b);
      EXPECT_EQ((ra * rb).to_double(), a * b);
      EXPECT_EQ((ra / rb).to_double(), a / b);
      EXPECT_EQ((-ra).to_double(), -a);
      EXPECT_EQ(abs(ra).to_double(), std::fabs(a));
      EXPECT_EQ(ra < rb, a < b);
      EXPECT_EQ(ra <= rb, a <= b);
      EXPECT_EQ(ra == rb, a == b);
    }
  }
}

TEST(Rational, FieldIdentities) {
  Mulberry32 rng(9);
  for (int i = 0; i < 300; ++i) {
    const Rational a(random_big(rng, 3), random_big(rng, 2).abs() + BigInt(1));
    const Rational b(random_double(rng, -40, 40)), c(random_double(rng, -40, 40));
    SCOPED_TRACE("draw " + std::to_string(i));
    EXPECT_EQ((a + b) - b, a);
    EXPECT_EQ(a * (b + c), a * b + a * c);
    EXPECT_EQ((a * b) / b, a);
    EXPECT_EQ(a - a, Rational(0));
    EXPECT_EQ(abs(a) >= Rational(0), true);
    EXPECT_EQ(a.abs(), a < Rational(0) ? -a : a);
    EXPECT_EQ(a<b, b> a);
  }
}

TEST(RationalPoint, ExactDeCasteljauOfAQuadraticAtOneHalf) {
  // B(1/2) of P0 = (0,0), P1 = (1,2), P2 = (3,0) is (P0 + 2 P1 + P2) / 4 = (5/4, 1).
  const std::vector<RPoint2> pts = {exact(core::Point2{0, 0}), exact(core::Point2{1, 2}),
                                    exact(core::Point2{3, 0})};
  const RPoint2 mid = exact_evaluate(pts, Rational(1) / Rational(2));
  EXPECT_EQ(mid.x, Rational(5) / Rational(4));
  EXPECT_EQ(mid.y, Rational(1));
  EXPECT_EQ(to_double(mid), (core::Point2{1.25, 1.0}));
  // t = 1/3: B = (4/9) P0 + (4/9) P1 + (1/9) P2 = (7/9, 8/9), rounded once per coordinate.
  const RPoint2 third = exact_evaluate(pts, Rational(1) / Rational(3));
  EXPECT_EQ(third.x, Rational(7) / Rational(9));
  EXPECT_EQ(to_double(third), (core::Point2{7.0 / 9.0, 8.0 / 9.0}));
}

}  // namespace
}  // namespace bezier::test
