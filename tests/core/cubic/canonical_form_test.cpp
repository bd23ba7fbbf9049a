#include "core/cubic/canonical_form.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "tests/core/cubic/classify_oracle.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

using Cubic = std::array<Point2, 4>;

std::optional<Point2> canonical(const Cubic& p) {
  return canonical_point(std::span<const Point2, 4>(p));
}

TEST(CanonicalForm, PointOfAnAffineImage) {
  // P0, P1, P2 = (0,0), (0,1), (1,1) map to themselves, so P3 is its own canonical point;
  // any affine image has the same one. Here x -> (2x − y + 3, x + y − 1), det 3: the cross
  // products are exact, so each quotient is the correctly rounded canonical coordinate, q.
  const Point2 q{-1.25, 0.5};
  const auto m = [](Point2 p) { return Point2{2 * p.x - p.y + 3, p.x + p.y - 1}; };
  const auto c = canonical({m({0, 0}), m({0, 1}), m({1, 1}), m(q)});
  ASSERT_TRUE(c.has_value());
  EXPECT_EQ(*c, q);
  // The primer's formula divides by P1.y − P0.y; a horizontal first leg is fine here.
  const auto h = canonical({Point2{0, 0}, Point2{2, 0}, Point2{2, 2}, Point2{1, 3}});
  ASSERT_TRUE(h.has_value());
  // u = (2,0), v = (2,2), w = (1,3): x = (u × w)/(u × v) = 6/4, y = ((P1 − P2) × w)/4 = 2/4.
  EXPECT_EQ(*h, (Point2{1.5, 0.5}));
}

TEST(CanonicalForm, UndefinedWhenTheFirstThreePointsAreCollinear) {
  EXPECT_FALSE(canonical({Point2{0, 0}, Point2{0, 0}, Point2{1, 1}, Point2{2, 0}}).has_value());
  EXPECT_FALSE(canonical({Point2{0, 0}, Point2{1, 1}, Point2{1, 1}, Point2{2, 0}}).has_value());
  EXPECT_FALSE(canonical({Point2{0, 0}, Point2{1, 2}, Point2{3, 6}, Point2{2, 0}}).has_value());
  // Nearly collinear is still defined (decided exactly), with a large canonical point.
  const auto near =
      canonical({Point2{0, 0}, Point2{1, 2}, Point2{3, std::nextafter(6.0, 7.0)}, Point2{2, 0}});
  ASSERT_TRUE(near.has_value());
  EXPECT_GT(std::fabs(near->x) + std::fabs(near->y), 1e14);
}

TEST(CanonicalForm, RegionsAndEdges) {
  struct Case {
    Point2 q;
    CubicType type;
  };
  for (const Case& c : {
           Case{{0, 2}, CubicType::single_inflection},
           Case{{-1, 0.5}, CubicType::double_inflection},
           Case{{0.5, -1}, CubicType::arch},
           Case{{-1, -0.5}, CubicType::loop},
           Case{{-1, 0}, CubicType::cusp},
           Case{{1, 1}, CubicType::cusp},
           Case{{2, 0.75}, CubicType::arch},
           Case{{-3, -6}, CubicType::loop_at_start},
           Case{{0, 0}, CubicType::loop_at_start},
           Case{{0, 1}, CubicType::double_inflection},
           Case{{1.5, 1}, CubicType::single_inflection},
           Case{{3, 0}, CubicType::quadratic},
       }) {
    EXPECT_EQ(canonical_region(c.q), c.type) << c.q.x << ", " << c.q.y;
  }
}

TEST(CanonicalForm, RegionAgreesWithExactRationalEdges) {
  // Random doubles and points on a coarse grid (many on edges): the expansion-arithmetic
  // comparisons and the rational ones decide alike.
  test::Mulberry32 rng(91);
  for (int i = 0; i < 20000; ++i) {
    const Point2 q = i % 2 == 0 ? Point2{rng.uniform(-6, 4), rng.uniform(-12, 3)}
                                : Point2{std::floor(rng.uniform(-48, 32)) / 8,
                                         std::floor(rng.uniform(-3072, 768)) / 256};
    ASSERT_EQ(canonical_region(q), test::exact_region(q.x, q.y)) << q.x << ", " << q.y;
  }
}

}  // namespace
}  // namespace bezier::core
