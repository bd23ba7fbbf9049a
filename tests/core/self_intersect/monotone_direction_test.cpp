// Tests of core/self_intersect/monotone_direction.hpp. A true answer is checked against the
// exact criterion it certifies: the difference vectors h_i = P_{i+1} - P_i lie in an open
// half-plane, i.e. 0 is not in their convex hull (separation of a point from a compact
// convex set), decided in exact rationals. Curves with a loop or a cusp on [0, 1] are not
// injective, or have B' = 0 somewhere, and must never be shown monotone.

#include "core/self_intersect/monotone_direction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "core/base/curve.hpp"
#include "core/cubic/double_point.hpp"
#include "tests/support/exact.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

using test::Rational;
using test::RPoint2;

Rational cross(const RPoint2& a, const RPoint2& b) { return a.x * b.y - a.y * b.x; }
Rational dot(const RPoint2& a, const RPoint2& b) { return a.x * b.x + a.y * b.y; }

/// Whether 0 lies in the convex hull of the vectors, exactly. In the plane a point of a
/// hull lies in a segment or a triangle of the given points (Carathéodory), so the pairs
/// (0 on the segment: parallel and not pointing the same way) and the proper triangles
/// (0 on the same side of, or on, every edge) decide it.
bool origin_in_hull(const std::vector<RPoint2>& v) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    for (std::size_t j = i; j < v.size(); ++j) {
      if (cross(v[i], v[j]).is_zero() && dot(v[i], v[j]).sign() <= 0) return true;
      for (std::size_t k = j + 1; k < v.size(); ++k) {
        if (cross(v[j] - v[i], v[k] - v[i]).is_zero()) continue;
        const int a = cross(v[i], v[j]).sign(), b = cross(v[j], v[k]).sign();
        const int c = cross(v[k], v[i]).sign();
        if ((a >= 0 && b >= 0 && c >= 0) || (a <= 0 && b <= 0 && c <= 0)) return true;
      }
    }
  }
  return false;
}

/// The exact difference vectors of the control points.
std::vector<RPoint2> differences(const std::vector<Point2>& p) {
  std::vector<RPoint2> h;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    h.push_back(RPoint2{Rational(p[i + 1].x), Rational(p[i + 1].y)} -
                RPoint2{Rational(p[i].x), Rational(p[i].y)});
  }
  return h;
}

TEST(CertainlyMonotone, CurvesTurningLessThanAHalfTurnAreShown) {
  // Along the chord (3, 0): the x differences are all 1.
  const std::vector<Point2> wave{{0, 0}, {1, 2}, {2, -1}, {3, 0}};
  // Turning by nearly a half turn: the chord (0, 1.1) is square to h_0 = (1, 0), but the
  // bisector of the end tangents (1, 0) and (-1, 0.1) has every difference on its side.
  const std::vector<Point2> hook{{0, 0}, {1, 0}, {1, 1}, {0, 1.1}};
  const std::vector<Point2> quadratic{{0, 0}, {2, 1}, {0, 2}};
  const std::vector<Point2> line{{1, 1}, {-2, 5}};
  for (const auto& p : {wave, hook, quadratic, line}) {
    EXPECT_FALSE(origin_in_hull(differences(p)));
    EXPECT_TRUE(certainly_monotone(p)) << p[1].x;
  }
}

TEST(CertainlyMonotone, LoopsCuspsAndPointsAreNeverShown) {
  // A cusp at t = 1/2 (B'(1/2) = 0), and one at the start (P_0 = P_1).
  EXPECT_FALSE(certainly_monotone(std::vector<Point2>{{0, 0}, {1, 1}, {0, 1}, {1, 0}}));
  EXPECT_FALSE(certainly_monotone(std::vector<Point2>{{0, 0}, {0, 0}, {1, 1}, {2, 0}}));
  // A loop: the closed form (exact signs) puts its double point on the segment.
  const std::vector<Point2> loop{{0, 0}, {3, 2}, {-1, 2}, {2, 0}};
  const auto dp = cubic_double_point(Curve(loop));
  ASSERT_TRUE(dp.has_value() && dp->on_segment);
  EXPECT_FALSE(certainly_monotone(loop));
  // Out and back along a line, and a single point.
  EXPECT_FALSE(certainly_monotone(std::vector<Point2>{{0, 0}, {1, 0}, {0, 0}}));
  EXPECT_FALSE(certainly_monotone(std::vector<Point2>{{2, 3}, {2, 3}}));
  EXPECT_FALSE(certainly_monotone(std::vector<Point2>{{2, 3}}));
}

/// On 4000 random cubics, `shown` (one of certainly_monotone's overloads) is never true for a
/// loop or when 0 is in the hull of the differences (exact rationals), and both kinds are
/// met often.
template <class Shown>
void expect_agreement_with_the_exact_criterion(std::uint32_t seed, const Shown& shown_of) {
  test::Mulberry32 rng(seed);
  int shown = 0, loops = 0;
  for (int k = 0; k < 4000; ++k) {
    std::vector<Point2> p;
    for (int i = 0; i < 4; ++i) p.push_back({rng.next(), rng.next()});
    const bool monotone = shown_of(p);
    const auto dp = cubic_double_point(Curve(p));
    if (dp && dp->on_segment) {
      ++loops;
      EXPECT_FALSE(monotone) << k;
    }
    if (monotone) {
      ++shown;
      EXPECT_FALSE(origin_in_hull(differences(p))) << k;
    }
  }
  EXPECT_GT(shown, 500);
  EXPECT_GT(loops, 100);
}

TEST(CertainlyMonotone, RandomCubicsAgreeWithTheExactCriterion) {
  expect_agreement_with_the_exact_criterion(
      7, [](const std::vector<Point2>& p) { return certainly_monotone(p); });
}

TEST(CertainlyMonotone, FourPointOverloadAgreesWithTheExactCriterion) {
  // The overload for a cubic's four points (fixed extent), on random cubics and the cases
  // above: never true for a loop or when 0 is in the differences' hull, and true for the
  // curves shown above.
  expect_agreement_with_the_exact_criterion(11, [](const std::vector<Point2>& p) {
    return certainly_monotone(std::span<const Point2, 4>(p.data(), 4));
  });
  const std::vector<Point2> hook{{0, 0}, {1, 0}, {1, 1}, {0, 1.1}};
  EXPECT_TRUE(certainly_monotone(std::span<const Point2, 4>(hook.data(), 4)));
  const std::vector<Point2> cusp{{0, 0}, {1, 1}, {0, 1}, {1, 0}};
  EXPECT_FALSE(certainly_monotone(std::span<const Point2, 4>(cusp.data(), 4)));
}

TEST(CertainlyMonotone, NearlyParallelDifferencesAreDecidedBySign) {
  // h_0 = (1, 0) and h_2 = (-1, e): in an open half-plane exactly when e > 0 (with
  // h_1 = (0, 1) between them); at e = 0 the two are opposite.
  for (const double e : {0x1p-40, 0.0, -0x1p-40}) {
    const std::vector<Point2> p{{0, 0}, {1, 0}, {1, 1}, {0, 1 + e}};
    if (certainly_monotone(p)) {
      EXPECT_GT(e, 0.0);
      EXPECT_FALSE(origin_in_hull(differences(p)));
    }
  }
  // The bisector of (1, 0) and (-1, e) is about (e^2 / 2, e): shown while e^2 / 2 is not
  // lost against 1 in the sum of the unit vectors.
  EXPECT_TRUE(certainly_monotone(std::vector<Point2>{{0, 0}, {1, 0}, {1, 1}, {0, 1 + 0x1p-10}}));
}

}  // namespace
}  // namespace bezier::core
