// Self-intersections at the edges of what doubles hold: ill-conditioned double points, loops
// next to a cusp or an end, flat ends, closed curves, coordinates spanning more than 2^400.
// Expected values come from the cubic closed form (double_point.hpp), exact rationals or
// the pairs' defining property B(t) = B(s).

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <span>
#include <vector>

#include "core/cubic/classify.hpp"
#include "core/cubic/double_point.hpp"
#include "core/cubic/predicates.hpp"
#include "core/curve/evaluate.hpp"
#include "core/self_intersect/self_intersection.hpp"

namespace bezier::core {
namespace {

// The cubic closed form's Newton polish walks away
// from an ill-conditioned double point (a nearly collinear cubic) and still counts as
// converged. In closed form (cubic_double_point.hpp's derivation): with a = P1 − P0,
// b = P2 − 2P1 + P0, c = P3 − 3P2 + 3P1 − P0, t + s = −(a × c)/(b × c) = 6/5 and
// t s = 6/25 whatever the 2^-50 offset, so t, s = 3/5 ∓ √3/5, and the point is
// (−19/125, 19/125) up to the offset.
TEST(SelfIntersectionEdgeCases, ClosedFormDoublePointIsNotPolishedAway) {
  const Curve c({{1.0, -1.0}, {-1.0, 1.0}, {-1.0, 1.0 - 0x1p-50}, {0.0, 0.0}});
  const SelfIntersectionResult r = self_intersections(c);
  ASSERT_EQ(r.pairs.size(), 1u);
  EXPECT_NEAR(r.pairs[0].t, 0.6 - std::sqrt(3.0) / 5, 1e-9);
  EXPECT_NEAR(r.pairs[0].s, 0.6 + std::sqrt(3.0) / 5, 1e-9);
  EXPECT_NEAR(r.pairs[0].point.x, -19.0 / 125, 1e-9);
  EXPECT_NEAR(r.pairs[0].point.y, 19.0 / 125, 1e-9);
}

// F6 again, next to a cusp: the cusp cubic (0,0), (1,1), (0,1), (1,0) with P3 moved 3 ulps
// to the left has a loop of parameter width about 1.6e-8 (the perturbation's square root,
// 2 sqrt(3 * 2^-53 / ...)); the polish moved it to 0.433 .. 0.567, where B(t) and B(s) are
// 2.4e-3 apart. The pair must be a double point, and narrow.
TEST(SelfIntersectionEdgeCases, DoublePointNextToACuspIsNotPolishedAway) {
  const Curve c({{0.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}, {0x1.ffffffffffffdp-1, 0.0}});
  const SelfIntersectionResult r = self_intersections(c);
  for (const auto& p : r.pairs) {
    const Point2 a = evaluate(c, p.t), b = evaluate(c, p.s);
    EXPECT_LT(std::fmax(std::fabs(a.x - b.x), std::fabs(a.y - b.y)), 1e-12) << p.t << " " << p.s;
    EXPECT_LT(p.s - p.t, 1e-6) << p.t << " " << p.s;
  }
}

// The largest |B(t) − B(s)| over the pairs, relative to the curve's scale.
double worst_relative_gap(const Curve& c, const SelfIntersectionResult& r) {
  double worst = 0.0;
  for (const auto& p : r.pairs) {
    const Point2 a = evaluate(c, p.t), b = evaluate(c, p.s);
    worst = std::fmax(worst, std::fmax(std::fabs(a.x - b.x), std::fabs(a.y - b.y)) / scale(c));
  }
  return worst;
}

// Next to an end where B' vanishes (here P3 = P4 =
// P5, so B(s) − B(1) = O((1 − s)^3)) the general method accepts a pair far from any double
// point: |B(t) − B(s)| = 0.74 on a curve of scale 2208 (reported as transversal).
TEST(SelfIntersectionEdgeCases, PairsNextToAFlatEndAreDoublePoints) {
  const Curve c({{0.0, 0x1.2afp-25},
                 {0x1.2afp-25, -0x1.14p+11},
                 {0x1.2affb3030fbp+7, 0x1.1p-31},
                 {0.0, 0.0},
                 {0.0, 0.0},
                 {0.0, 0.0}});
  const SelfIntersectionResult r = self_intersections(c);
  ASSERT_EQ(r.status, IntersectStatus::ok);
  EXPECT_LT(worst_relative_gap(c, r), 1e-9);
}

// With coordinates spanning more than 2^400 the
// classification is not exact, and the cubic with P2 = P3 (B'(1) = 0: a cusp at t = 1 by
// CubicType's precedence, whatever the other points) came out as loop-at-end with t1 = t2 = 1, which
// self_intersections() passed on as the pair (1, 1).
TEST(SelfIntersectionEdgeCases, CuspAtTheEndIsNotALoopOfWidthZero) {
  const std::array<Point2, 4> p = {Point2{-8.0, 0x1.0000000d6fbfcp-895},
                                   Point2{0x1.0000000d6fbfcp-896, 0x1.0000000d6fbf8p-895},
                                   Point2{0.0, 0.0}, Point2{0.0, 0.0}};
  const CubicClassification k = classify(std::span<const Point2, 4>(p));
  EXPECT_EQ(k.type, CubicType::cusp);
  if (k.self_intersection) {
    EXPECT_LT(k.self_intersection->t1, k.self_intersection->t2);
  }
  const SelfIntersectionResult r =
      self_intersections(Curve(std::vector<Point2>(p.begin(), p.end())));
  for (const auto& pair : r.pairs) {
    EXPECT_LT(pair.t, pair.s);
  }
}

// The general method
// (subdivision) missed the loop of this cubic and reported status ok. The loop is certain: the
// closed form decides it exactly (cubic_double_point.hpp), at t about 0.04 and s about 0.998,
// where the branches cross at an angle of 9e-8. (The search's Newton stopped at its plain
// rounding floor, 2e-14 off the root along the branches, where |B(t) - B(s)| exceeded the
// distance tolerance.) Both methods give the closed form's pair, to the parameters' accuracy.
TEST(SelfIntersectionEdgeCases, GeneralMethodFindsTheLoopTheClosedFormFinds) {
  const std::array<Point2, 4> p = {Point2{1.0, 0.5}, Point2{-8.0, -4.0},
                                   Point2{0x1.12d00000080afp+29, 0x1.785p+13}, Point2{0.0, 0.0}};
  const auto dp = cubic_double_point(std::span<const Point2, 4>(p));
  ASSERT_TRUE(dp.has_value() && dp->on_segment);
  SelfIntersectionOptions general;
  general.cubic_closed_form = false;
  for (const auto& options : {general, SelfIntersectionOptions{}}) {
    const SelfIntersectionResult r =
        self_intersections(Curve(std::vector<Point2>(p.begin(), p.end())), options);
    ASSERT_EQ(r.status, IntersectStatus::ok);
    ASSERT_EQ(r.pairs.size(), 1u);
    EXPECT_NEAR(r.pairs[0].t, dp->t1, 1e-13);
    EXPECT_NEAR(r.pairs[0].s, dp->t2, 1e-13);
  }
}

// Coordinates spanning more than 2^400: the cubic's
// closed form is not exact (CubicPredicates::exact false), and the pair it would give is no double
// point: (0, 1) on an open curve, |B(0) − B(1)| = 0.027 on a curve of size 8. The exact double
// point (rational elimination of s + t and s t, done off-line) is at t = 1.3e-6, s = 1.0011: off
// the segment, so there is no pair (the general method finds the curve collinear to within its
// tolerance).
TEST(SelfIntersectionEdgeCases, InexactClosedFormGivesDoublePoints) {
  const Curve c({{0x1.c18000418p-6, 0x0.00000838p-1022},
                 {-4.0, 0x1.383832e61e7afp-935},
                 {-8.0, 0x1.fp-1016},
                 {0x0.6p-1022, 0.0}});
  const SelfIntersectionResult r = self_intersections(c);
  EXPECT_TRUE(r.pairs.empty());
  for (const auto& p : r.pairs) {
    const Point2 a = evaluate(c, p.t), b = evaluate(c, p.s);
    EXPECT_LT(std::fmax(std::fabs(a.x - b.x), std::fabs(a.y - b.y)), 1e-12 * scale(c))
        << p.t << " " << p.s;
  }
}

// Pairs outside the unit square, and the trivial pair of
// a closed curve leaking out (the polish after the end snapping moved parameters past the ends;
// next to a flat seam Newton and the contact stage settled on pairs the search could not tell
// from (0, 1)). Every pair must have 0 <= t < s <= 1 and never be (0, 1).
void expect_pairs_in_the_unit_square(const SelfIntersectionResult& r) {
  for (const auto& p : r.pairs) {
    EXPECT_TRUE(0.0 <= p.t && p.t < p.s && p.s <= 1.0) << p.t << " " << p.s;
    EXPECT_FALSE(p.t == 0.0 && p.s == 1.0);
  }
}

// (a) A cubic that almost closes (P3 a few ulps from P0) gave (-7.9e-16, 1 + 1.6e-13). Its double
// point, decided exactly by the closed form, lies just off the segment: no pair, by either method.
TEST(SelfIntersectionEdgeCases, LoopClosingJustOffTheSegmentIsNoPair) {
  const std::array<Point2, 4> p = {Point2{0x1.020202020202p-21, 0x1.020202020202p-21},
                                   Point2{0x1.0e1df20202006p-21, 0.0},
                                   Point2{0x1.020202020202p-21, 0x1.003ec54545454p-21},
                                   Point2{0x1.020202020201fp-21, 0x1.020202020201cp-21}};
  const auto dp = cubic_double_point(std::span<const Point2, 4>(p));
  ASSERT_TRUE(dp.has_value());
  ASSERT_TRUE(cubic_predicates(std::span<const Point2, 4>(p)).exact);
  EXPECT_FALSE(dp->on_segment);
  SelfIntersectionOptions general;
  general.cubic_closed_form = false;
  for (const auto& options : {general, SelfIntersectionOptions{}}) {
    const SelfIntersectionResult r =
        self_intersections(Curve(std::vector<Point2>(p.begin(), p.end())), options);
    expect_pairs_in_the_unit_square(r);
    EXPECT_TRUE(r.pairs.empty()) << r.pairs.size();
  }
}

// (b) A closed quintic (P0 = P5 = (0, 0)) gave (-9e-25, 1), the trivial pair with t below 0. It
// has one real self-intersection (resultant of the two coordinates' divided differences, exact
// rationals, off-line; then Newton in 60 digits): a tiny loop next to the seam at t = 1.2e-13,
// s = 1 - 5.3e-9, 3e-8 across on a curve of scale 7e7, far below the distance tolerance (2^-44
// of the scale), so by the documented resolution part of the trivial pair. A pair reported must
// be that one.
TEST(SelfIntersectionEdgeCases, TrivialPairOfAClosedCurveStaysOut) {
  const Curve c({{0.0, 0.0},
                 {-0x1.fp+14, 0x1.fp+14},
                 {-0x1p+26, 0x1.e48d4484a48p+6},
                 {0x1.4000024243224p-9, 0x1p+26},
                 {-0x1.6f6f6f6facp-1, 0x1.ef3p-23},
                 {0.0, 0.0}});
  const SelfIntersectionResult r = self_intersections(c);
  expect_pairs_in_the_unit_square(r);
  for (const auto& p : r.pairs) {
    EXPECT_NEAR(p.t, 1.20878799514914e-13, 1e-20);
    EXPECT_NEAR(p.s, 0.99999999465311446884, 1e-16);
  }
}

// (c) A closed degree-20 curve whose last 13 points are the origin gave (0, 0.9978): the trivial
// pair moved along the flat end (B(s) is 2e-32 there), and its s moved by 4e-6 when the curve was
// scaled by 2^6. The curve has no self-intersection (B = t (1 - t)^13 Q(t); off-line, in 60-digit
// arithmetic, its log-polar image sampled densely towards both ends does not cross itself), at
// any scale.
TEST(SelfIntersectionEdgeCases, FlatSeamGivesNoPair) {
  std::vector<Point2> flat_end = {{0.0, 0.0},
                                  {0x1.d93f794p+10, 0.0},
                                  {0.0, 0.0},
                                  {0x1p+20, 0.0},
                                  {0.0, 0.0},
                                  {0x1.bca0b868p-19, -0x1.e291f459f9e29p-11},
                                  {-0x1.e291f459f9e29p-12, 0x1.01a9f4561e0f6p+3},
                                  {0x1.1ap-30, 0.0}};
  flat_end.resize(21, Point2{0.0, 0.0});
  for (const int k : {0, 6}) {
    std::vector<Point2> scaled;
    for (const Point2 p : flat_end) scaled.push_back({std::ldexp(p.x, k), std::ldexp(p.y, k)});
    const SelfIntersectionResult r = self_intersections(Curve(scaled));
    EXPECT_EQ(r.status, IntersectStatus::ok);
    EXPECT_TRUE(r.pairs.empty()) << k << ": " << r.pairs.size();
  }
}

// A degree-20 curve's double point at t = 0.000195
// reported twice, out of order, the copies 1.4e-9 apart in s (above the 1e-10 merge distance),
// the second 1.8e-9 off the curve's other branch. The curve has two double points (off-line, in
// 60-digit arithmetic: a dense polyline's crossings, then Newton), each to be reported once,
// sorted, to the accuracy of the parameters.
TEST(SelfIntersectionEdgeCases, DoublePointReportedOnce) {
  const Curve c({{1.0, 1.0},
                 {-0x1.fffffep+7, -0x1.fffffep+7},
                 {-0x1.fffffep+6, 0x1.fffffep+6},
                 {-0x1.fffffe0000002p+7, -0x1.fffffe0000002p+7},
                 {-0x1.fffffe0000001p+7, -0x1.fffffe0000001p+6},
                 {1.0, -0x1p+29},
                 {-0x1.cp+2, 2.0},
                 {0x1.ffffffffffffep+0, -0x1.cp+2},
                 {2.0, 0x1.0000000000004p+0},
                 {0x1.ddd8p+5, -0x1.44291044p+16},
                 {-0x1.fffffe0000002p+7, 0x1.fffffe0000002p+7},
                 {-0x1.44437a04p-12, -0x1.fffffe0000002p+7},
                 {0x1.dddddf7f79778p-2, 0x1.dddddf7f79778p-3},
                 {0.0, 0x1.872bb1f1ap+21},
                 {0x1.03b0010c40009p-31, -0x1.82787c0000185p-1},
                 {0x1.1ap-30, 0.0},
                 {0.0, 0.0},
                 {0.0, 0.0},
                 {0.0, 0.0},
                 {0.0, 0.0},
                 {0.0, 0.0}});
  const SelfIntersectionResult r = self_intersections(c);
  ASSERT_EQ(r.status, IntersectStatus::ok);
  ASSERT_EQ(r.pairs.size(), 2u);
  EXPECT_NEAR(r.pairs[0].t, 0.000195093157093225009292, 1e-15);
  EXPECT_NEAR(r.pairs[0].s, 0.990241764320379987666646, 1e-13);
  EXPECT_NEAR(r.pairs[1].t, 0.005234862227017755711484, 1e-15);
  EXPECT_NEAR(r.pairs[1].s, 0.608300438515885438595626, 1e-13);
}

}  // namespace
}  // namespace bezier::core
