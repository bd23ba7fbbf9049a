// Rect (rect.hpp): the least rectangle of points, exact faces; closed rectangles meet when
// they share a point, touching included; against a brute-force test on a grid.

#include "core/base/rect.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

TEST(Rect, BoundingRectHasTheExtremeCoordinates) {
  const std::vector<Point2> points = {{1, 5}, {-2, 3}, {4, -1}, {0, 0}};
  EXPECT_EQ(bounding_rect(points), (Rect{{-2, -1}, {4, 5}}));
  const std::vector<Point2> one = {{0.25, -7}};
  EXPECT_EQ(bounding_rect(one), (Rect{{0.25, -7}, {0.25, -7}}));
}

TEST(Rect, IncludingAPointInsideChangesNothing) {
  const Rect r{{0, 0}, {2, 1}};
  EXPECT_EQ(r.including({1, 0.5}), r);
  EXPECT_EQ(r.including({2, 0}), r);
  EXPECT_EQ(r.including({3, -1}), (Rect{{0, -1}, {3, 1}}));
}

TEST(Rect, IncludingKeepsAFaceOnTies) {
  // -0 == +0: the face stays as it was, with its sign.
  const Rect r{{0.0, 0.0}, {0.0, 0.0}};
  const Rect s = r.including({-0.0, -0.0});
  EXPECT_FALSE(std::signbit(s.min.x));
  EXPECT_FALSE(std::signbit(s.max.y));
}

TEST(Rect, GrownMovesEveryFaceOut) {
  EXPECT_EQ((Rect{{0, 1}, {2, 3}}.grown(0.5)), (Rect{{-0.5, 0.5}, {2.5, 3.5}}));
}

/// Whether the closed rectangles share a point, searched on the half-integer grid that
/// holds every corner and every midpoint between corners of integer rectangles.
bool share_a_grid_point(const Rect& a, const Rect& b) {
  for (double x = -1; x <= 12; x += 0.5) {
    for (double y = -1; y <= 12; y += 0.5) {
      const bool in_a = a.min.x <= x && x <= a.max.x && a.min.y <= y && y <= a.max.y;
      const bool in_b = b.min.x <= x && x <= b.max.x && b.min.y <= y && y <= b.max.y;
      if (in_a && in_b) return true;
    }
  }
  return false;
}

TEST(Rect, IntersectsExactlyWhenTheyShareAPoint) {
  test::Mulberry32 rng(29);
  const auto random_rect = [&] {
    const double x = std::floor(rng.uniform(0, 8)), y = std::floor(rng.uniform(0, 8));
    return Rect{{x, y}, {x + std::floor(rng.uniform(0, 4)), y + std::floor(rng.uniform(0, 4))}};
  };
  for (int trial = 0; trial < 2000; ++trial) {
    const Rect a = random_rect(), b = random_rect();
    EXPECT_EQ(a.intersects(b), share_a_grid_point(a, b)) << "trial " << trial;
    EXPECT_EQ(a.intersects(b), b.intersects(a));
  }
}

TEST(Rect, TouchingCounts) {
  const Rect a{{0, 0}, {1, 1}};
  EXPECT_TRUE(a.intersects(Rect{{1, 1}, {2, 2}}));    // a corner
  EXPECT_TRUE(a.intersects(Rect{{1, 0.5}, {2, 3}}));  // an edge
  EXPECT_FALSE(a.intersects(Rect{{std::nextafter(1.0, 2.0), 0}, {2, 1}}));
}

TEST(Rect, NaNFacesAreNotProvenApart) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Rect a{{0, 0}, {1, 1}};
  EXPECT_FALSE(a.intersects(Rect{{nan, 5}, {nan, 6}}));  // apart in y, whatever x says
  EXPECT_TRUE(a.intersects(Rect{{nan, nan}, {nan, nan}}));
}

}  // namespace
}  // namespace bezier::core
