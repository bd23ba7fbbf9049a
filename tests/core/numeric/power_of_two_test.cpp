// Powers of two (power_of_two.hpp) against the library functions they stand for
// (std::ldexp, std::ilogb), bit for bit, over normal, subnormal and extreme exponents, and
// exact scaling of points where the results are normal doubles.

#include "core/numeric/power_of_two.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace bezier::core {
namespace {

TEST(PowerOfTwo, MatchesLdexpForEveryExponent) {
  for (int e = -1080; e <= 1030; ++e) {
    EXPECT_EQ(power_of_two(e), std::ldexp(1.0, e)) << e;
  }
}

TEST(PowerOfTwo, ExponentMatchesIlogb) {
  const double values[] = {1.0,    -1.0,   0.75,   3.0,     0x1p-1022, 0x1p-1074, 0x1.8p-1060,
                           -0x1p-1073, 1e308, -1.7e308, 0x1.fffffffffffffp1023, 5e-324};
  for (const double x : values) EXPECT_EQ(exponent_of(x), std::ilogb(x)) << x;
  EXPECT_EQ(exponent_of(std::numeric_limits<double>::infinity()),
            std::ilogb(std::numeric_limits<double>::infinity()));
}

TEST(PowerOfTwo, AtMostIsTheLeadingBit) {
  EXPECT_EQ(power_of_two_at_most(3.0), 2.0);
  EXPECT_EQ(power_of_two_at_most(0.75), 0.5);
  EXPECT_EQ(power_of_two_at_most(-6.0), 4.0);
  EXPECT_EQ(power_of_two_at_most(0x1.8p-1060), 0x1p-1060);
  EXPECT_EQ(power_of_two_at_most(0x1p-20), 0x1p-20);
}

TEST(PowerOfTwo, ScalingBeyondTheDoubleRangeInTwoFactorsIsExact) {
  // 2^1074 is not a double, but subnormal input times it is: 3 * 2^-1074 -> 3.
  const PowerOfTwo up(1074);
  EXPECT_EQ(up.times(0x3p-1074), 3.0);
  // And back from 2^1000 by 2^-1050: 2^-50, exact.
  EXPECT_EQ(PowerOfTwo(-1050).times(0x1p1000), 0x1p-50);
  const std::vector<Point2> points = {{0x1p-1074, -0x5p-1074}, {0.0, 0x1p-1022}};
  const std::vector<Point2> scaled = scaled_by_power_of_two(points, 1074);
  ASSERT_EQ(scaled.size(), 2u);
  EXPECT_EQ(scaled[0].x, 1.0);
  EXPECT_EQ(scaled[0].y, -5.0);
  EXPECT_EQ(scaled[1].x, 0.0);
  EXPECT_EQ(scaled[1].y, 0x1p52);
}

}  // namespace
}  // namespace bezier::core
