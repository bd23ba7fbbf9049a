// is_point (curve.hpp): a curve is a point exactly when all its control points are equal,
// compared as the points' == compares them.

#include "core/base/curve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace bezier::core {
namespace {

TEST(IsPoint, OneControlPointIsAPoint) {
  EXPECT_TRUE(is_point(Curve({{3, -4}})));
}

TEST(IsPoint, EqualControlPointsOfAnyDegree) {
  EXPECT_TRUE(is_point(Curve({{1.5, 2}, {1.5, 2}})));
  EXPECT_TRUE(is_point(Curve({{1.5, 2}, {1.5, 2}, {1.5, 2}, {1.5, 2}})));
}

TEST(IsPoint, OneDifferentCoordinateAnywhereIsNot) {
  const double x = 0.1, next = std::nextafter(x, 1.0);
  EXPECT_FALSE(is_point(Curve({{x, 0}, {next, 0}})));
  EXPECT_FALSE(is_point(Curve({{x, 0}, {x, 0}, {x, 0}, {x, next}})));
  EXPECT_FALSE(is_point(Curve({{x, 0}, {x, 1}, {x, 0}})));  // closes on itself, not a point
}

TEST(IsPoint, SignedZerosAreOnePoint) {
  EXPECT_TRUE(is_point(Curve({{0.0, -0.0}, {-0.0, 0.0}})));
}

TEST(IsPoint, NaNIsNeverEqual) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(is_point(Curve({{nan, 0}, {nan, 0}})));
}

TEST(IsPoint, SpaceCurves) {
  EXPECT_TRUE(is_point(Curve3({{1, 2, 3}, {1, 2, 3}, {1, 2, 3}})));
  EXPECT_FALSE(is_point(Curve3({{1, 2, 3}, {1, 2, 3}, {1, 2, 4}})));
}

}  // namespace
}  // namespace bezier::core
