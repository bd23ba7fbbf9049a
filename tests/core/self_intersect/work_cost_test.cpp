// The self-intersection search's charges (core/self_intersect/work_cost.hpp) are in the work
// units of the two-curve search (core/intersect/work_cost.hpp): what a call reports as
// stats.work is what it charged its WorkBudget, whichever branch answered (search,
// collinear fold, retraced or improper curve), and one cap stops both searches after
// spending it.
//
// The curves: the degree-7 loop of loop_area_test.cpp (one transversal loop, found by the
// search); the loop cubic (9,-9) (-7,13) (-7,-13) (9,9) by the general search; a collinear
// cubic, x(t) = 16t^3 - 24t^2 + 9t along a line (collinear_fold_test.cpp); a palindromic
// quartic; the near-retraced quartic of intersections_route_test.cpp (B = C(4 (t - 1/4)^2),
// C quadratic, one coordinate moved by 1e-9: within rounding of retracing [0, 1/4] over
// [1/4, 1/2], which no budget here finishes); the nearly retraced pair of
// tests/core/intersect/work_cost_test.cpp (a parabola and a quartic running along it and
// back, 2^-35 away), which no budget here finishes either.

#include "core/self_intersect/work_cost.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <vector>

#include "core/base/work_budget.hpp"
#include "core/intersect/intersect.hpp"
#include "core/intersect/work_cost.hpp"
#include "core/loop/loop_area.hpp"
#include "core/self_intersect/self_intersection.hpp"

namespace bezier::core {
namespace {

const Curve kDegree7({{0, 0}, {1, 1}, {2, 3}, {1, 4}, {0, 4}, {-1, 3}, {0, 1}, {1, 0}});
const Curve kLoopCubic({{9, -9}, {-7, 13}, {-7, -13}, {9, 9}});
const Curve kCollinearCubic({{0, 0}, {3, 1.5}, {-2, -1}, {1, 0.5}});
const Curve kPalindrome({{0, 0}, {2, 1}, {1, 3}, {2, 1}, {0, 0}});
const Curve kNearlyRetracedQuartic(
    {{0.75, 0.5625}, {-0.75, -0.9375}, {-0.25, 1.562500001}, {2.25, -3.9375}, {6.75, 18.5625}});

SelfIntersectionOptions general_search() {
  SelfIntersectionOptions options;
  options.cubic_closed_form = false;
  return options;
}

TEST(SelfIntersectionWorkCost, StatsWorkIsWhatTheCallCharged) {
  struct Case {
    const Curve* curve;
    SelfIntersectionMethod method;
  };
  for (const Case& c : {Case{&kDegree7, SelfIntersectionMethod::subdivision},
                        Case{&kLoopCubic, SelfIntersectionMethod::subdivision},
                        Case{&kCollinearCubic, SelfIntersectionMethod::collinear},
                        Case{&kPalindrome, SelfIntersectionMethod::subdivision}}) {
    // A budget that has already paid for something else: the call reports its own part.
    WorkBudget budget;
    budget.charge(12345);
    const SelfIntersectionResult r = self_intersections(*c.curve, general_search(), budget);
    EXPECT_FALSE(budget.exhausted());
    EXPECT_EQ(r.stats.method, c.method);
    EXPECT_GT(r.stats.work, 0);
    EXPECT_EQ(r.stats.work, budget.spent() - 12345);
    // The overload with a budget of its own charges the same.
    EXPECT_EQ(self_intersections(*c.curve, general_search()).stats.work, r.stats.work);
  }
}

TEST(SelfIntersectionWorkCost, TheSearchChargesWholeBoxesAndNewtonIterations) {
  // Every charge of the search proper is a box or a Newton iteration of a degree-7 curve,
  // both self_intersection_box_cost(7), and every contact refinement a multiple of it.
  const SelfIntersectionResult r = self_intersections(kDegree7);
  ASSERT_EQ(r.pairs.size(), 1u);
  EXPECT_EQ(r.stats.work % self_intersection_box_cost(7), 0);
  EXPECT_GE(r.stats.work, (1 + r.stats.newton_iterations) * self_intersection_box_cost(7));
}

TEST(SelfIntersectionWorkCost, TheClosedFormChargesNothing) {
  WorkBudget budget(0);
  const SelfIntersectionResult r = self_intersections(kLoopCubic, {}, budget);
  EXPECT_EQ(r.stats.method, SelfIntersectionMethod::closed_form_cubic);
  ASSERT_EQ(r.pairs.size(), 1u);
  EXPECT_EQ(r.stats.work, 0);
  EXPECT_FALSE(budget.exhausted());
}

TEST(SelfIntersectionWorkCost, LoopAreaReportsTheSearchsCharges) {
  WorkBudget budget;
  const LoopAreaResult r = loop_area(kDegree7, {}, budget);
  ASSERT_EQ(r.loops.size(), 1u);
  EXPECT_EQ(r.stats.work, budget.spent());
  EXPECT_EQ(r.stats.work, self_intersections(kDegree7).stats.work);
}

TEST(SelfIntersectionWorkCost, OneCapStopsBothSearchesAfterSpendingIt) {
  constexpr std::int64_t kCap = 400000;
  // One curve: the search stops when the next box does not fit, so it spent more than the
  // cap less one box; a Newton run started in the last box adds at most its 24 iterations.
  WorkBudget one(kCap);
  const SelfIntersectionResult self = self_intersections(kNearlyRetracedQuartic, {}, one);
  ASSERT_TRUE(one.exhausted());
  EXPECT_EQ(self.stats.work, one.spent());
  const std::int64_t box = self_intersection_box_cost(4);
  EXPECT_GT(one.spent(), kCap - box);
  EXPECT_LE(one.spent(), kCap + 24 * self_intersection_newton_cost(4));

  // Two curves: the search stops before a step that does not fit; the last step may add an
  // implicit clip, and each contact refinement (started only when its most is covered) its
  // Newton iterations (work_cost_test.cpp, CappedSearchSpendsAtMostTheBudget).
  const Curve f({{0.0, 0.0}, {0.5, 1.0}, {1.0, 0.0}});
  const Curve g({{0.0, 0.0}, {1.0, 2.0}, {4.0 / 3.0, -8.0 / 3.0 + 0x1p-34}, {1.0, 2.0}, {0.0, 0.0}});
  WorkBudget two(kCap);
  const IntersectionResult pair = intersect(f, g, {}, two);
  ASSERT_TRUE(two.exhausted());
  EXPECT_EQ(pair.stats.work, two.spent());
  EXPECT_GT(two.spent(), kCap - step_cost(2, 4, true) - 2 * implicit_clip_cost(4));
  EXPECT_LE(two.spent() - pair.stats.newton_iterations * newton_cost(2, 4),
            kCap + implicit_clip_cost(4));

  // Both spent the cap, to within one step of either search: the same units.
  const std::int64_t one_step = step_cost(2, 4, true) + 2 * implicit_clip_cost(4);
  EXPECT_LE(std::abs(one.spent() - two.spent()),
            one_step + 24 * self_intersection_newton_cost(4) +
                pair.stats.newton_iterations * newton_cost(2, 4));
}

TEST(SelfIntersectionWorkCost, CollinearFoldIsChargedInWholeSteps) {
  WorkBudget budget;
  const SelfIntersectionResult r = self_intersections(kCollinearCubic, general_search(), budget);
  ASSERT_EQ(r.stats.method, SelfIntersectionMethod::collinear);
  EXPECT_EQ(r.overlaps.size(), 3u);
  EXPECT_GT(r.stats.work, 0);
  EXPECT_EQ(r.stats.work % collinear_fold_step_cost(3), 0);
}

TEST(SelfIntersectionWorkCost, TheDefaultBudgetCoversWhatItPromises) {
  // SelfIntersectionOptions::max_work: 200 000 parameter boxes at every degree up to 29.
  for (int n = 1; n <= 29; ++n) {
    EXPECT_LE(200000 * self_intersection_box_cost(n), SelfIntersectionOptions{}.max_work) << n;
  }
}

TEST(SelfIntersectionWorkCost, ClusterComparisonsAreChargedInWholeBoxes) {
  for (const int n : {1, 3, 7, 20}) {
    const std::int64_t box = self_intersection_box_cost(n);
    EXPECT_EQ(cluster_cost(kClusterComparisonsPerBox - 1, n), 0);
    EXPECT_EQ(cluster_cost(3 * kClusterComparisonsPerBox + 5, n), 3 * box);
    // What a budget affords is what it pays for, and one more comparison is not.
    for (const std::int64_t units : {std::int64_t{0}, box - 1, box, 7 * box + 3}) {
      const std::int64_t affordable = affordable_cluster_comparisons(units, n);
      EXPECT_LE(cluster_cost(affordable, n), units);
      EXPECT_GT(cluster_cost(affordable + kClusterComparisonsPerBox, n), units);
    }
    EXPECT_EQ(affordable_cluster_comparisons(-5, n), 0);
  }
}

}  // namespace
}  // namespace bezier::core
