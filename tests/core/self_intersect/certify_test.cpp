#include "core/self_intersect/certify.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <span>
#include <vector>

#include "core/self_intersect/self_intersection.hpp"

namespace bezier::core {
namespace {

// (-9,0), (13,16), (-13,16), (9,0): x(t) = -9 + 66 t - 198 t^2 + 132 t^3 vanishes at 1/4 and
// 3/4 (and 1/2), y(t) = 48 t (1 - t) is 9 at both: the double point (0, 9) at (1/4, 3/4).
Curve symmetric_loop() { return Curve(std::vector<Point2>{{-9, 0}, {13, 16}, {-13, 16}, {9, 0}}); }

/// The certification with a budget of `units` work units, and whether it ran out.
struct Certified : CertifiedSelfIntersections {
  bool out_of_work = false;
};

Certified certify(const Curve& c, std::span<const SelfIntersection> pairs,
                  const IntersectOptions& options, std::int64_t units) {
  WorkBudget budget(units);
  Certified out{{certify_self_intersections(c, pairs, options, budget)}};
  out.out_of_work = budget.exhausted();
  return out;
}

TEST(CertifySelfIntersections, IntervalsNarrowerThanTheToleranceContainTheExactPair) {
  const Curve c = symmetric_loop();
  const SelfIntersectionResult found = self_intersections(c);
  ASSERT_EQ(found.pairs.size(), 1u);
  IntersectOptions options;
  options.tolerance = 1e-12;
  const Certified r = certify(c, found.pairs, options, 100000);
  ASSERT_EQ(r.intersections.size(), 1u);
  const Intersection& x = r.intersections[0];
  EXPECT_TRUE(x.resolved);
  EXPECT_TRUE(x.t_interval.contains(0.25));
  EXPECT_TRUE(x.s_interval.contains(0.75));
  EXPECT_LT(x.t_interval.width(), options.tolerance);
  EXPECT_LT(x.s_interval.width(), options.tolerance);
  EXPECT_EQ(x.kind, IntersectionKind::transversal);
  EXPECT_GT(r.work, 0);
  EXPECT_GT(r.steps, 0);
  EXPECT_FALSE(r.out_of_work);
}

TEST(CertifySelfIntersections, NoBudgetReportsThePairAsFoundAndSaysSo) {
  const Curve c = symmetric_loop();
  const SelfIntersectionResult found = self_intersections(c);
  ASSERT_EQ(found.pairs.size(), 1u);
  const Certified r = certify(c, found.pairs, {}, 0);
  ASSERT_EQ(r.intersections.size(), 1u);
  const Intersection& x = r.intersections[0];
  EXPECT_FALSE(x.resolved);
  EXPECT_EQ(x.t, found.pairs[0].t);
  EXPECT_EQ(x.s, found.pairs[0].s);
  EXPECT_EQ(x.t_interval, (ParamInterval{x.t, x.t}));
  EXPECT_EQ(x.s_interval, (ParamInterval{x.s, x.s}));
  EXPECT_EQ(x.point, found.pairs[0].point);
  EXPECT_EQ(r.work, 0);
  EXPECT_TRUE(r.out_of_work);
}

TEST(CertifySelfIntersections, ThePairsShareTheBudgetInOrder) {
  const Curve c = symmetric_loop();
  const SelfIntersectionResult found = self_intersections(c);
  ASSERT_EQ(found.pairs.size(), 1u);
  const std::vector<SelfIntersection> twice{found.pairs[0], found.pairs[0]};
  const Certified one = certify(c, found.pairs, {}, 100000);
  ASSERT_TRUE(one.intersections[0].resolved);
  // Enough for both: the same search twice, at twice the cost.
  const Certified both = certify(c, twice, {}, 100000);
  EXPECT_TRUE(both.intersections[0].resolved);
  EXPECT_TRUE(both.intersections[1].resolved);
  EXPECT_EQ(both.work, 2 * one.work);
  EXPECT_FALSE(both.out_of_work);
  // The smallest budget that certifies one pair (the search stops as soon as a phase could
  // exceed its budget, so it can need more than it spends): given to two pairs, the first
  // finishes and the second runs out of what is left.
  std::int64_t lo = 0, hi = 100000;  // certify_self_intersections fails at lo, works at hi
  while (hi - lo > 1) {
    const std::int64_t mid = lo + (hi - lo) / 2;
    (certify(c, found.pairs, {}, mid).intersections[0].resolved ? hi : lo) =
        mid;
  }
  const Certified r = certify(c, twice, {}, hi);
  ASSERT_EQ(r.intersections.size(), 2u);
  EXPECT_TRUE(r.intersections[0].resolved);
  EXPECT_FALSE(r.intersections[1].resolved);
  EXPECT_TRUE(r.out_of_work);
}

TEST(CertifiedSelfIntersections, OneCallSearchesAndCertifiesUnderOneBudget) {
  const Curve c = symmetric_loop();
  WorkBudget budget(100000);
  const CertifiedSelfIntersectionResult r = certified_self_intersections(c, {}, budget);
  ASSERT_EQ(r.found.pairs.size(), 1u);
  ASSERT_EQ(r.certified.intersections.size(), 1u);
  EXPECT_TRUE(r.certified.intersections[0].resolved);
  EXPECT_TRUE(r.certified.intersections[0].t_interval.contains(0.25));
  EXPECT_TRUE(r.certified.intersections[0].s_interval.contains(0.75));
  EXPECT_EQ(r.certified.uncertified, 0u);
  EXPECT_FALSE(budget.exhausted());
  EXPECT_EQ(budget.spent(), r.found.stats.work + r.certified.work);
}

TEST(CertifiedSelfIntersections, ACertificationThatFallsShortLeavesTheBudgetUnexhausted) {
  // A cubic's pairs come from its closed form, which takes no parameter box: with no work
  // unit at all the pair is found, reported as found, and counted uncertified; the answer
  // is complete, so the budget did not run out.
  const Curve c = symmetric_loop();
  WorkBudget budget(0);
  const CertifiedSelfIntersectionResult r = certified_self_intersections(c, {}, budget);
  ASSERT_EQ(r.found.pairs.size(), 1u);
  ASSERT_EQ(r.certified.intersections.size(), 1u);
  EXPECT_FALSE(r.certified.intersections[0].resolved);
  EXPECT_EQ(r.certified.uncertified, 1u);
  EXPECT_FALSE(budget.exhausted());
}

}  // namespace
}  // namespace bezier::core
