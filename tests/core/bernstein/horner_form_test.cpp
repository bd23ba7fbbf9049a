// bernstein::HornerForm (core/bernstein/horner_form.hpp): p(t) and p'(t) of a Bernstein
// polynomial by Horner's rule in t / (1 - t), against the Bernstein sums in exact rationals,
// every value within the stated value_bound() of the exact one.
#include "core/bernstein/horner_form.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "core/numeric/binomial.hpp"
#include "core/numeric/unit_roundoff.hpp"
#include "tests/support/exact.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

using test::Rational;

/// Σ c_k C(n, k) t^k (1 - t)^(n - k), exactly.
Rational exact_bernstein(const std::vector<Rational>& c, const Rational& t) {
  const int n = static_cast<int>(c.size()) - 1;
  const Rational s = Rational(1) - t;
  std::vector<Rational> t_powers{Rational(1)}, s_powers{Rational(1)};
  for (int k = 0; k < n; ++k) {
    t_powers.push_back(t_powers.back() * t);
    s_powers.push_back(s_powers.back() * s);
  }
  Rational sum(0);
  for (int k = 0; k <= n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    sum += c[i] * Rational(binomial(n, k)) * t_powers[i] * s_powers[static_cast<std::size_t>(n - k)];
  }
  return sum;
}

/// The parameters tried: the ends, the middle and its neighbours (where the form switches
/// from t / (1 - t) to (1 - t) / t), tiny ones and random ones.
std::vector<double> parameters(test::Mulberry32& rng) {
  std::vector<double> ts{0.0, 1.0, 0.5, std::nextafter(0.5, 0.0), std::nextafter(0.5, 1.0), 1e-300,
                         1.0 - 0x1p-53, 0x1p-20};
  for (int i = 0; i < 12; ++i) ts.push_back(rng.next());
  return ts;
}

/// Coefficients of mixed signs and magnitudes: uniform in [-1, 1], or spread over
/// 2^-40..2^40, or alternating signs (the largest cancellation near t = 1/2).
std::vector<double> coefficients(test::Mulberry32& rng, std::size_t size, int kind) {
  std::vector<double> c(size);
  for (std::size_t k = 0; k < size; ++k) {
    switch (kind) {
      case 0: c[k] = rng.uniform(-1.0, 1.0); break;
      case 1: c[k] = std::ldexp(rng.uniform(-1.0, 1.0), static_cast<int>(rng.uniform(-40.0, 40.0))); break;
      default: c[k] = (k % 2 == 0 ? 1.0 : -1.0) * rng.uniform(0.5, 1.0); break;
    }
  }
  return c;
}

template <std::size_t E>
void check_size(test::Mulberry32& rng) {
  constexpr int n = static_cast<int>(E) - 1;
  for (int kind = 0; kind < 3; ++kind) {
    const std::vector<double> c = coefficients(rng, E, kind);
    const bernstein::HornerForm<E> form(c.data());
    ASSERT_TRUE(form.prepared());
    double largest = 0.0;
    for (const double v : c) largest = std::max(largest, std::fabs(v));
    EXPECT_GE(form.value_bound(), (6 * n + 1) * kUnitRoundoff * largest);
    std::vector<Rational> exact_c(c.begin(), c.end());
    std::vector<Rational> exact_slope_c;
    double largest_difference = 0.0;
    for (int k = 0; k < n; ++k) {
      const auto i = static_cast<std::size_t>(k);
      exact_slope_c.push_back(Rational(n) * (exact_c[i + 1] - exact_c[i]));
      largest_difference = std::max(largest_difference, n * std::fabs(c[i + 1] - c[i]));
    }
    for (const double t : parameters(rng)) {
      const bernstein::ValueAndSlope computed = form.value_and_slope(t);
      const Rational exact = exact_bernstein(exact_c, Rational(t));
      EXPECT_LE(abs(Rational(computed.value) - exact), Rational(form.value_bound()))
          << "degree " << n << " kind " << kind << " t " << t;
      // The slope's weights n C(n-1, k) (c_{k+1} - c_k) round twice more than the value's:
      // within the same count of roundings plus two of its largest coefficient.
      const Rational exact_slope = n == 0 ? Rational(0) : exact_bernstein(exact_slope_c, Rational(t));
      const double slope_bound = (6 * n + 4) * 1.01 * kUnitRoundoff * largest_difference +
                                 (2 * n + 2) * std::numeric_limits<double>::denorm_min();
      EXPECT_LE(abs(Rational(computed.slope) - exact_slope), Rational(slope_bound))
          << "degree " << n << " kind " << kind << " t " << t;
    }
  }
}

template <std::size_t... I>
void check_sizes(test::Mulberry32& rng, std::index_sequence<I...>) {
  (check_size<I + 1>(rng), ...);
}

TEST(HornerForm, ValueWithinItsBoundAndSlopeCloseToTheExactOnes) {
  test::Mulberry32 rng(20);
  check_sizes(rng, std::make_index_sequence<24>{});
}

TEST(HornerForm, ExactAtTheEnds) {
  // p(0) = c_0 and p(1) = c_n: every other term has a zero factor, and the power is 1.
  const std::array<double, 5> c{0.3, -2.0, 5.0, 1.0 / 3.0, -0.7};
  const bernstein::HornerForm<5> form(c.data());
  EXPECT_EQ(form.value_and_slope(0.0).value, c[0]);
  EXPECT_EQ(form.value_and_slope(1.0).value, c[4]);
  EXPECT_EQ(form.value_and_slope(0.0).slope, 4 * (c[1] - c[0]));
  EXPECT_EQ(form.value_and_slope(1.0).slope, 4 * (c[4] - c[3]));
}

TEST(HornerForm, RefusesCoefficientsBeyondItsRange) {
  const std::array<double, 3> c{1.0, 0x1p901, -1.0};
  EXPECT_FALSE(bernstein::HornerForm<3>(c.data()).prepared());
}

}  // namespace
}  // namespace bezier::core
