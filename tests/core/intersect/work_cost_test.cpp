// The work cost model (core/intersect/work_cost.hpp, core/self_intersect/work_cost.hpp):
// higher degrees and compensated arithmetic cost more, and a budget in units buys fewer
// steps the costlier they are. No timing here: BENCHMARKS.md, "Worst requests at the default
// limits", has the times.

#include <gtest/gtest.h>

#include <vector>

#include "core/bernstein/degree.hpp"
#include "core/intersect/intersect.hpp"
#include "core/intersect/work_cost.hpp"
#include "core/self_intersect/work_cost.hpp"

namespace bezier::core {
namespace {

TEST(WorkCost, HigherDegreeCostsMoreInEveryCharge) {
  for (int m = 1; m <= 20; ++m) {
    for (int n = 1; n < 20; ++n) {
      for (const bool compensated : {false, true}) {
        EXPECT_LT(step_cost(m, n, compensated), step_cost(m, n + 1, compensated)) << m << " " << n;
        EXPECT_LT(step_cost(n, m, compensated), step_cost(n + 1, m, compensated)) << m << " " << n;
      }
      EXPECT_LT(newton_cost(m, n), newton_cost(m, n + 1));
      EXPECT_LT(subdivision_test_cost(m, n), subdivision_test_cost(m, n + 1));
      EXPECT_LT(coincidence_test_cost(m, n, 5), coincidence_test_cost(m, n + 1, 5));
    }
    EXPECT_LT(implicit_clip_cost(m), implicit_clip_cost(m + 1));
    EXPECT_LT(self_intersection_box_cost(m), self_intersection_box_cost(m + 1));
  }
}

TEST(WorkCost, CompensatedStepsCostMoreThanPlainOnes) {
  for (int m = 1; m <= 20; ++m) {
    for (int n = 1; n <= 20; ++n) EXPECT_GT(step_cost(m, n, true), step_cost(m, n, false));
  }
}

/// f(q) with q = 4s(1 - s), g's middle control point then moved by 2^-34: g runs along the
/// parabola f and back, never more than 2^-35 away from it and meeting it only at f(0)
/// (tangentially, at s = 0 and s = 1). No overlap (far above the overlap tolerance), but a
/// near-coincidence that the search resolves only with about a million units of work (the
/// hybrid method; subdivision, converging linearly along it, not at all): more than any
/// budget used here.
struct NearlyRetraced {
  Curve f{{{0.0, 0.0}, {0.5, 1.0}, {1.0, 0.0}}};
  Curve g{{{0.0, 0.0}, {1.0, 2.0}, {4.0 / 3.0, -8.0 / 3.0 + 0x1p-34}, {1.0, 2.0}, {0.0, 0.0}}};
};

TEST(WorkCost, SubdivisionStepsAreChargedTheirTests) {
  // The nearly retracing pair by subdivision, to the cap: every step is charged at least
  // its step_cost, and a step that gets past the bounding boxes (the first, on [0, 1]^2,
  // where both curves' boxes overlap and neither domain is converged) also its separation
  // tests.
  const NearlyRetraced c;
  const Curve& f = c.f;
  const Curve& g = c.g;
  IntersectOptions options;
  options.method = IntersectMethod::subdivision;
  options.max_work = 200000;
  const IntersectionResult r = intersect(f, g, options);
  ASSERT_EQ(r.status, IntersectStatus::work_cap_reached);
  EXPECT_GE(r.stats.work, r.stats.iterations * step_cost(2, 4, false) + subdivision_test_cost(2, 4));
}

TEST(WorkCost, SymmetricInTheTwoCurves) {
  for (int m = 1; m <= 20; ++m) {
    for (int n = 1; n <= 20; ++n) {
      EXPECT_EQ(step_cost(m, n, false), step_cost(n, m, false));
      EXPECT_EQ(step_cost(m, n, true), step_cost(n, m, true));
      EXPECT_EQ(newton_cost(m, n), newton_cost(n, m));
      EXPECT_EQ(subdivision_test_cost(m, n), subdivision_test_cost(n, m));
      EXPECT_EQ(coincidence_test_cost(m, n, 5), coincidence_test_cost(n, m, 5));
    }
  }
}

TEST(WorkCost, CappedSearchSpendsAtMostTheBudget) {
  const NearlyRetraced c;
  IntersectOptions options;
  options.max_work = 200000;
  const IntersectionResult r = intersect(c.f, c.g, options);
  ASSERT_EQ(r.status, IntersectStatus::work_cap_reached);
  // Every step is charged at least its plain cost, and the search stops before a step
  // would cross the budget. What a step adds after that check, one implicit clip of a
  // piece (degree 4 at most here), and the last contact's refinement may overshoot it.
  EXPECT_GE(r.stats.work, r.stats.iterations * step_cost(2, 4, false));
  EXPECT_LE(r.stats.work - r.stats.newton_iterations * newton_cost(2, 4),
            options.max_work + implicit_clip_cost(4));
}

TEST(WorkCost, SameBudgetBuysFewerStepsAtHigherDegree) {
  // The same two curves, elevated from degrees 2 and 4 to degree 20: the same nearly
  // retracing geometry, each step on degree-20 pieces.
  const NearlyRetraced c;
  const Curve f20 = elevate_degree(c.f, 20), g20 = elevate_degree(c.g, 20);
  IntersectOptions options;
  options.max_work = 400000;
  const IntersectionResult low = intersect(c.f, c.g, options);
  const IntersectionResult high = intersect(f20, g20, options);
  ASSERT_EQ(low.status, IntersectStatus::work_cap_reached);
  ASSERT_EQ(high.status, IntersectStatus::work_cap_reached);
  EXPECT_GT(high.stats.work / high.stats.iterations, low.stats.work / low.stats.iterations);
  // A degree-20 step costs at least step_cost(20, 20, false); a low one at most a
  // compensated step with two implicit clips.
  const std::int64_t low_most = step_cost(2, 4, true) + 2 * implicit_clip_cost(4);
  EXPECT_LE(high.stats.iterations, options.max_work / step_cost(20, 20, false));
  EXPECT_GE(low.stats.iterations, (options.max_work - low.stats.newton_iterations * newton_cost(2, 4)) / low_most - 1);
  EXPECT_LT(high.stats.iterations, low.stats.iterations);
}

TEST(WorkCost, TransversalCubicsSpendAFewThousandUnits) {
  // Two cubics crossing once at a right angle: the ordinary case is far below any cap.
  const Curve f({{0.0, 0.0}, {1.0, 0.1}, {2.0, -0.1}, {3.0, 0.0}});
  const Curve g({{1.5, -1.0}, {1.6, 0.0}, {1.4, 0.5}, {1.5, 1.0}});
  const IntersectionResult r = intersect(f, g);
  ASSERT_EQ(r.status, IntersectStatus::ok);
  ASSERT_EQ(r.intersections.size(), 1u);
  EXPECT_GE(r.stats.work, r.stats.iterations * step_cost(3, 3, false));
  EXPECT_LT(r.stats.work, 100000);
}

}  // namespace
}  // namespace bezier::core
