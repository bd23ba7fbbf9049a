#include "core/numeric/expansion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tests/support/exact.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

using test::Rational;

Rational value(const Expansion& e) {
  Rational sum(0);
  for (const double c : e.components()) sum += Rational(c);
  return sum;
}

// Shewchuk's invariants: nonzero components, strictly increasing magnitude, each smaller
// than the next one's unit in the last place's span (nonoverlapping: every component is
// below the lowest set bit of the next).
void expect_well_formed(const Expansion& e) {
  const auto c = e.components();
  for (std::size_t i = 0; i < c.size(); ++i) {
    EXPECT_NE(c[i], 0.0);
    if (i + 1 < c.size()) {
      int exp_next = 0;
      const double m = std::frexp(c[i + 1], &exp_next);
      // Lowest set bit of c[i+1]: strip mantissa bits until odd.
      double mant = std::ldexp(m, 53);
      int lsb = exp_next - 53;
      while (std::fmod(mant, 2.0) == 0.0) {
        mant /= 2;
        ++lsb;
      }
      EXPECT_LT(std::fabs(c[i]), std::ldexp(1.0, lsb));
    }
  }
}

// Doubles with random mantissas over a wide range of exponents (within the exact window).
double random_double(test::Mulberry32& rng) {
  const double m = rng.uniform(-1, 1);
  const int e = static_cast<int>(rng.uniform(-60, 60));
  return std::ldexp(m, e);
}

TEST(Expansion, SumsDifferencesAndProductsAreExact) {
  test::Mulberry32 rng(71);
  for (int i = 0; i < 400; ++i) {
    const double a = random_double(rng), b = random_double(rng), c = random_double(rng),
                 d = random_double(rng);
    const Expansion ea = Expansion::difference(a, b);  // a − b, exactly
    const Expansion ec = Expansion::difference(c, d);
    EXPECT_EQ(value(ea), Rational(a) - Rational(b));
    const Expansion sum = ea + ec, diff = ea - ec, prod = ea * ec, scaled = ea * c;
    const Expansion poly = prod * prod - sum * 3.0 + diff * ec;  // degree 4
    EXPECT_EQ(value(sum), value(ea) + value(ec));
    EXPECT_EQ(value(diff), value(ea) - value(ec));
    EXPECT_EQ(value(prod), value(ea) * value(ec));
    EXPECT_EQ(value(scaled), value(ea) * Rational(c));
    const Rational expected = value(ea) * value(ec) * value(ea) * value(ec) -
                              Rational(3) * (value(ea) + value(ec)) +
                              (value(ea) - value(ec)) * value(ec);
    EXPECT_EQ(value(poly), expected);
    EXPECT_EQ(poly.sign(), expected.sign());
    for (const Expansion* e : {&sum, &diff, &prod, &scaled, &poly}) expect_well_formed(*e);
    // The estimate is the value to within one ulp (compressed expansions).
    const double est = poly.estimate(), exact = expected.to_double();
    EXPECT_LE(std::fabs(est - exact), std::fabs(std::nextafter(exact, INFINITY) - exact));
  }
}

TEST(Expansion, CancellationToZeroAndSigns) {
  const Expansion a = Expansion::difference(1.0, 0x1p-60);  // 1 − 2^-60: two components
  EXPECT_EQ(a.components().size(), 2u);
  EXPECT_EQ((a - a).sign(), 0);
  EXPECT_TRUE((a - a).components().empty());
  EXPECT_EQ((a * 0.0).sign(), 0);
  EXPECT_EQ(Expansion(0.0).sign(), 0);
  EXPECT_EQ(Expansion(-2.0).sign(), -1);
  // (1 − 2^-60)² − 1 + 2^-59 = 2^-120: a sign only the low components carry.
  const Expansion tiny = a * a - Expansion(1.0) + Expansion(0x1p-59);
  EXPECT_EQ(tiny.sign(), 1);
  EXPECT_EQ(tiny.estimate(), 0x1p-120);
  EXPECT_EQ((-tiny).sign(), -1);
}

}  // namespace
}  // namespace bezier::core
