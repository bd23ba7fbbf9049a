// is_point (curve.hpp): a curve is a point exactly when all its control points are equal,
// compared as the points' == compares them. reversed: the control points in reverse order,
// from a curve kept or from one given up (take_points: its points, in order). The same
// points, degree and equality whichever way a curve is built and whether its points fit
// inline (degree below 4) or not.

#include "core/base/curve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <span>
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

/// The control points (k, k^2 / 8 - k) for k = 0..n: a curve of degree n.
std::vector<Point2> points_of_degree(int n) {
  std::vector<Point2> out;
  for (int k = 0; k <= n; ++k) out.push_back({static_cast<double>(k), k * k / 8.0 - k});
  return out;
}

TEST(CurveStorage, EveryConstructorGivesThePointsInOrderAtEveryDegree) {
  for (int n = 0; n <= 7; ++n) {
    const std::vector<Point2> pts = points_of_degree(n);
    const Curve from_vector(pts);
    const Curve from_span{std::span<const Point2>(pts)};
    const Curve from_points{Curve::Points(std::span<const Point2>(pts))};
    for (const Curve* c : {&from_vector, &from_span, &from_points}) {
      EXPECT_EQ(c->degree(), n);
      EXPECT_EQ(std::vector<Point2>(c->points().begin(), c->points().end()), pts);
      EXPECT_EQ(c->front(), pts.front());
      EXPECT_EQ(c->back(), pts.back());
      for (int i = 0; i <= n; ++i) EXPECT_EQ((*c)[i], pts[static_cast<std::size_t>(i)]);
    }
    EXPECT_EQ(from_vector, from_span);
    EXPECT_EQ(from_vector, from_points);
  }
}

TEST(CurveStorage, CopiesMovesAndTakenPointsAtEveryDegree) {
  for (int n = 1; n <= 7; ++n) {
    const std::vector<Point2> pts = points_of_degree(n);
    const Curve original(pts);
    Curve copy = original;
    EXPECT_EQ(copy, original);
    Curve moved = std::move(copy);
    EXPECT_EQ(moved, original);
    Curve assigned({{0, 0}, {1, 1}});
    assigned = moved;
    EXPECT_EQ(assigned, original);
    EXPECT_EQ(std::move(assigned).take_points(), pts);
    std::vector<Point2> backwards(pts.rbegin(), pts.rend());
    EXPECT_EQ(reversed(original), Curve(backwards));
    EXPECT_EQ(reversed(std::move(moved)), Curve(backwards));
  }
}

TEST(CurveStorage, CurvesOfDifferentDegreeOrPointsDiffer) {
  EXPECT_FALSE(Curve(points_of_degree(3)) == Curve(points_of_degree(4)));
  EXPECT_FALSE(Curve(points_of_degree(5)) == Curve(points_of_degree(4)));
  std::vector<Point2> pts = points_of_degree(5);
  pts[5].y = std::nextafter(pts[5].y, 100.0);
  EXPECT_FALSE(Curve(pts) == Curve(points_of_degree(5)));
}

}  // namespace
}  // namespace bezier::core
