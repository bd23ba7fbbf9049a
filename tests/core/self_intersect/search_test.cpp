// Tests of core/self_intersect/search.hpp on curves whose self-intersections are known in
// closed form (refine_test.cpp derives them):
//   the loop cubic (9,-9) (-7,13) (-7,-13) (9,9): one transversal double point at
//   (t, s) = (1/4, 3/4);
//   the quintic (60,-45) (-4,69) (-36,-89) (-36,89) (-4,-69) (60,45): one tangential
//   self-contact at (1/4, 3/4);
//   a convex quadratic arc: none.
// The settings are those self_intersections() derives from its default options.

#include "core/self_intersect/search.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/self_intersect/work_cost.hpp"

namespace bezier::core {
namespace {

const std::vector<Point2> kLoopCubic{{9, -9}, {-7, 13}, {-7, -13}, {9, 9}};
const std::vector<Point2> kTouchingQuintic{{60, -45}, {-4, 69},  {-36, -89},
                                           {-36, 89}, {-4, -69}, {60, 45}};

SelfIntersectionSearchSettings settings_for(const std::vector<Point2>& pts) {
  double s = 0;
  for (const Point2& p : pts) s = std::fmax(s, std::fmax(std::fabs(p.x), std::fabs(p.y)));
  const SelfIntersectionOptions defaults;
  SelfIntersectionSearchSettings settings;
  settings.dist_tol = defaults.dist_rel * s;
  settings.rounding = 4.0 * static_cast<double>(pts.size()) * 0x1p-53 * s;
  settings.max_depth = defaults.max_depth;
  settings.closed = pts.front() == pts.back();
  return settings;
}

TEST(SelfIntersectionSearch, FindsTheLoopOfACubic) {
  WorkBudget budget;
  const SelfIntersectionSearchOutcome out =
      search_self_intersections(kLoopCubic, settings_for(kLoopCubic), budget);
  EXPECT_FALSE(budget.exhausted());
  ASSERT_FALSE(out.crossings.empty());
  // Neighbouring boxes may find the same root: every crossing is the double point.
  for (const PairRefinement& r : out.crossings) {
    EXPECT_TRUE(r.converged);
    EXPECT_NEAR(r.u, 0.25, 0x1p-46);
    EXPECT_NEAR(r.v, 0.75, 0x1p-46);
  }
  EXPECT_TRUE(out.contact_boxes.empty());
  EXPECT_GE(out.stats.newton_runs, 1);
  // stats.work is what the search charged: whole boxes and Newton iterations of a cubic.
  EXPECT_GT(out.stats.work, 0);
  EXPECT_EQ(out.stats.work, budget.spent());
  EXPECT_EQ(out.stats.work % self_intersection_box_cost(3), 0);
}

TEST(SelfIntersectionSearch, ConvexArcHasNothing) {
  const std::vector<Point2> arc{{0, 0}, {1, 2}, {3, 2}, {4, 0}};
  WorkBudget budget;
  const SelfIntersectionSearchOutcome out = search_self_intersections(arc, settings_for(arc), budget);
  EXPECT_FALSE(budget.exhausted());
  EXPECT_TRUE(out.crossings.empty());
  EXPECT_TRUE(out.contact_boxes.empty());
}

TEST(SelfIntersectionSearch, TangentialContactIsLeftAsContactBoxesAroundIt) {
  WorkBudget budget;
  const SelfIntersectionSearchOutcome out =
      search_self_intersections(kTouchingQuintic, settings_for(kTouchingQuintic), budget);
  EXPECT_FALSE(budget.exhausted());
  // The tangent cones of the two branches never separate at the contact, so no box
  // there is resolved by Newton: all that is left are contact boxes at (1/4, 3/4).
  EXPECT_TRUE(out.crossings.empty());
  ASSERT_FALSE(out.contact_boxes.empty());
  for (const ParameterBox& b : out.contact_boxes) {
    EXPECT_LE(std::fabs(0.5 * (b.u.lo + b.u.hi) - 0.25), 1e-6) << b.u.lo << " " << b.u.hi;
    EXPECT_LE(std::fabs(0.5 * (b.v.lo + b.v.hi) - 0.75), 1e-6) << b.v.lo << " " << b.v.hi;
  }
}

TEST(SelfIntersectionSearch, ClosedCurveSeamIsNotACrossing) {
  // A closed cubic whose only self-intersection is the trivial pair (0, 1) at P0 = P3,
  // where the pieces meet at an angle (the tangents (1, 0) and (0, -1) at the ends).
  const std::vector<Point2> closed{{0, 0}, {3, 0}, {0, 3}, {0, 0}};
  const SelfIntersectionSearchSettings settings = settings_for(closed);
  ASSERT_TRUE(settings.closed);
  WorkBudget budget;
  const SelfIntersectionSearchOutcome out = search_self_intersections(closed, settings, budget);
  EXPECT_FALSE(budget.exhausted());
  for (const PairRefinement& r : out.crossings)
    EXPECT_GT(parameter_separation(r.u, r.v, true), 1e-6) << r.u << " " << r.v;
  EXPECT_TRUE(out.crossings.empty());
}

TEST(SelfIntersectionSearch, StopsAtTheWorkCap) {
  // Three boxes of a cubic and one unit short of a fourth: the fourth is not examined.
  const std::int64_t box = self_intersection_box_cost(3);
  WorkBudget budget(4 * box - 1);
  const SelfIntersectionSearchOutcome out =
      search_self_intersections(kLoopCubic, settings_for(kLoopCubic), budget);
  EXPECT_TRUE(budget.exhausted());
  EXPECT_EQ(out.stats.work, budget.spent());
  // Boxes stop at the cap; a Newton run started before it is charged its iterations
  // (at most refine_double_point's default 24) on top.
  EXPECT_GE(out.stats.work, 3 * box);
  EXPECT_LE(out.stats.work, 3 * box + 24 * self_intersection_newton_cost(3));
}

}  // namespace
}  // namespace bezier::core
