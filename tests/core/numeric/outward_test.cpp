// next_up and next_down (core/numeric/outward.hpp) against std::nextafter towards
// +-infinity, bit for bit, on the special values and on random bit patterns.
#include "core/numeric/outward.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

void expect_same_bits(double got, double want, double x) {
  if (std::isnan(want)) {
    EXPECT_TRUE(std::isnan(got)) << x;
  } else {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(got), std::bit_cast<std::uint64_t>(want)) << x;
  }
}

void check(double x) {
  expect_same_bits(next_up(x), std::nextafter(x, kInf), x);
  expect_same_bits(next_down(x), std::nextafter(x, -kInf), x);
}

TEST(Outward, SpecialValuesAsNextafter) {
  const std::vector<double> specials{0.0,
                                     -0.0,
                                     1.0,
                                     -1.0,
                                     std::numeric_limits<double>::denorm_min(),
                                     -std::numeric_limits<double>::denorm_min(),
                                     std::numeric_limits<double>::min(),
                                     -std::numeric_limits<double>::min(),
                                     std::numeric_limits<double>::max(),
                                     -std::numeric_limits<double>::max(),
                                     kInf,
                                     -kInf,
                                     std::numeric_limits<double>::quiet_NaN()};
  for (const double x : specials) check(x);
}

TEST(Outward, RandomBitPatternsAsNextafter) {
  test::Mulberry32 rng(3);
  for (int i = 0; i < 100000; ++i) {
    const auto high = static_cast<std::uint64_t>(rng.next() * 4294967296.0);
    const auto low = static_cast<std::uint64_t>(rng.next() * 4294967296.0);
    check(std::bit_cast<double>((high << 32) | low));
  }
}

}  // namespace
}  // namespace bezier::core
