// is_point (curve.hpp): a curve is a point exactly when all its control points are equal,
// compared as the points' == compares them. reversed: the control points in reverse order,
// from a curve kept or from one given up (take_points: its points, in order).

#include "core/base/curve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

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

TEST(Reversed, ControlPointsInReverseOrderFromACopyOrAGivenUpCurve) {
  const Curve curve({{1, 2}, {3, -4}, {-5, 6}, {7, 8.5}});
  const Curve expected({{7, 8.5}, {-5, 6}, {3, -4}, {1, 2}});
  EXPECT_EQ(reversed(curve), expected);
  Curve given_up = curve;
  EXPECT_EQ(reversed(std::move(given_up)), expected);
  const Curve3 space({{1, 2, 3}, {4, 5, 6}});
  EXPECT_EQ(reversed(Curve3(space)), Curve3({{4, 5, 6}, {1, 2, 3}}));
}

TEST(TakePoints, TheControlPointsInOrder) {
  Curve curve({{1, 2}, {3, -4}, {-5, 6}});
  const std::vector<Point2> points = std::move(curve).take_points();
  ASSERT_EQ(points.size(), 3u);
  EXPECT_EQ(points[0], (Point2{1, 2}));
  EXPECT_EQ(points[1], (Point2{3, -4}));
  EXPECT_EQ(points[2], (Point2{-5, 6}));
}

}  // namespace
}  // namespace bezier::core
