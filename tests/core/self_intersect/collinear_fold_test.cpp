// Tests of core/self_intersect/collinear_fold.hpp on collinear curves whose folds are known
// in closed form. The cubic with x coefficients (0, 3, -2, 1) is x(t) = 16t^3 - 24t^2 + 9t,
// x' = 3 (4t - 1)(4t - 3): it runs 0 -> 1 on [0, 1/4], back 1 -> 0 on [1/4, 3/4] and
// 0 -> 1 again on [3/4, 1], so each pair of its three pieces retraces the other over the
// whole range [0, 1]. The quadratic (0, 2, 1) is x = 4t - 3t^2: 0 -> 4/3 on [0, 2/3],
// back to 1 on [2/3, 1]; the common range [1, 4/3] is t in [1/3, 2/3] on the first piece.

#include "core/self_intersect/collinear_fold.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <span>
#include <vector>

#include "core/self_intersect/work_cost.hpp"

namespace bezier::core {
namespace {

constexpr double kTol = 0x1p-44;

// The points x_i d + origin on the line through origin with direction d.
std::vector<Point2> on_line(const std::vector<double>& xs, Point2 origin, Point2 d) {
  std::vector<Point2> pts;
  for (const double x : xs) pts.push_back(origin + x * d);
  return pts;
}

bool near(ParamInterval got, double lo, double hi) {
  return std::fabs(got.lo - lo) <= 1e-12 && std::fabs(got.hi - hi) <= 1e-12;
}

TEST(CollinearFrame, LineThroughTheFirstAndFarthestPoint) {
  const auto pts = on_line({0, 3, -2, 1}, {1, 1}, {0.5, 0.25});
  const auto frame = collinear_frame(pts, kTol);
  ASSERT_TRUE(frame.has_value());
  EXPECT_EQ(frame->origin, (Point2{1, 1}));
  EXPECT_EQ(frame->direction, pts[1] - pts[0]);  // x = 3 is the farthest from x = 0
}

TEST(CollinearFrame, FourPointOverload) {
  // The overload for a cubic's four points (fixed extent): the same line, and no line for
  // a cubic bent farther from it than the tolerance.
  const auto pts = on_line({0, 3, -2, 1}, {1, 1}, {0.5, 0.25});
  const auto frame = collinear_frame(std::span<const Point2, 4>(pts.data(), 4), kTol);
  ASSERT_TRUE(frame.has_value());
  EXPECT_EQ(frame->origin, (Point2{1, 1}));
  EXPECT_EQ(frame->direction, pts[1] - pts[0]);
  const std::vector<Point2> bent{{0, 0}, {1, 0}, {2, 1e-6}, {3, 0}};
  EXPECT_FALSE(collinear_frame(std::span<const Point2, 4>(bent.data(), 4), 1e-9).has_value());
  EXPECT_TRUE(collinear_frame(std::span<const Point2, 4>(bent.data(), 4), 1e-5).has_value());
}

TEST(CollinearFrame, NotCollinearAndPointCurves) {
  const std::vector<Point2> bent{{0, 0}, {1, 0}, {2, 1e-6}};
  EXPECT_FALSE(collinear_frame(bent, 1e-9).has_value());
  EXPECT_TRUE(collinear_frame(bent, 1e-5).has_value());  // within the tolerance it is a line
  const std::vector<Point2> point{{2, 3}, {2, 3}, {2, 3}};
  const auto frame = collinear_frame(point, kTol);
  ASSERT_TRUE(frame.has_value());
  EXPECT_EQ(frame->direction, (Point2{0, 0}));
}

TEST(CollinearSelfOverlaps, CubicFoldingTwiceRetracesEachPairOfPieces) {
  const auto pts = on_line({0, 3, -2, 1}, {-1, 2}, {0.75, -0.5});
  const auto frame = collinear_frame(pts, kTol);
  ASSERT_TRUE(frame.has_value());
  WorkBudget budget;
  const std::vector<Overlap> found = collinear_self_overlaps(pts, *frame, kTol, budget);
  EXPECT_FALSE(budget.exhausted());
  ASSERT_EQ(found.size(), 3u);
  // (The direction, `reversed`, is not this function's: self_intersections() sets it.)
  struct Expected {
    double t_lo, t_hi, s_lo, s_hi;
  };
  const Expected expected[] = {
      {0, 0.25, 0.25, 0.75}, {0, 0.25, 0.75, 1.0}, {0.25, 0.75, 0.75, 1.0}};
  for (const Expected& e : expected) {
    const bool present =
        std::any_of(found.begin(), found.end(), [&](const Overlap& o) {
          return near(o.t_interval, e.t_lo, e.t_hi) && near(o.s_interval, e.s_lo, e.s_hi);
        });
    EXPECT_TRUE(present) << e.t_lo << " " << e.t_hi << " x " << e.s_lo << " " << e.s_hi;
  }
  for (std::size_t i = 0; i + 1 < found.size(); ++i)
    EXPECT_LE(found[i].t_interval.lo, found[i + 1].t_interval.lo);
  // Whole steps of the sign runs' subdivision were charged, at least the first.
  EXPECT_GT(budget.spent(), 0);
  EXPECT_EQ(budget.spent() % collinear_fold_step_cost(3), 0);
}

TEST(CollinearSelfOverlaps, QuadraticFoldOverlapsOnThePreimageOfTheCommonRange) {
  const auto pts = on_line({0, 2, 1}, {0, 0}, {1, 1});
  const auto frame = collinear_frame(pts, kTol);
  ASSERT_TRUE(frame.has_value());
  WorkBudget budget;
  const std::vector<Overlap> found = collinear_self_overlaps(pts, *frame, kTol, budget);
  ASSERT_EQ(found.size(), 1u);
  const Overlap& o = found[0];
  EXPECT_TRUE(near(o.t_interval, 1.0 / 3, 2.0 / 3)) << o.t_interval.lo << " " << o.t_interval.hi;
  EXPECT_TRUE(near(o.s_interval, 2.0 / 3, 1.0)) << o.s_interval.lo << " " << o.s_interval.hi;
}

TEST(CollinearSelfOverlaps, EvenMultiplicityTurningPointDoesNotFold) {
  // (2t - 1)^3: x' = 6 (2t - 1)^2 vanishes at t = 1/2 without changing sign.
  const auto pts = on_line({-1, 1, -1, 1}, {0, 0}, {1, 0});
  const auto frame = collinear_frame(pts, kTol);
  ASSERT_TRUE(frame.has_value());
  WorkBudget budget;
  EXPECT_TRUE(collinear_self_overlaps(pts, *frame, kTol, budget).empty());
  EXPECT_FALSE(budget.exhausted());
}

TEST(CollinearSelfOverlaps, MonotoneLineHasNoOverlap) {
  const auto pts = on_line({0, 1, 2, 3}, {0, 0}, {1, 2});
  const auto frame = collinear_frame(pts, kTol);
  ASSERT_TRUE(frame.has_value());
  WorkBudget budget;
  EXPECT_TRUE(collinear_self_overlaps(pts, *frame, kTol, budget).empty());
}

TEST(CollinearSelfOverlaps, PointCurveIsOneWholeOverlap) {
  const std::vector<Point2> point{{2, 3}, {2, 3}, {2, 3}};
  const auto frame = collinear_frame(point, kTol);
  ASSERT_TRUE(frame.has_value());
  WorkBudget budget;
  const std::vector<Overlap> found = collinear_self_overlaps(point, *frame, kTol, budget);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].t_interval, (ParamInterval{0, 1}));
  EXPECT_EQ(found[0].s_interval, (ParamInterval{0, 1}));
}

TEST(CollinearSelfOverlaps, RunningOutOfWorkExhaustsTheBudget) {
  // x' has coefficients 3, -5, 3 of mixed signs: the first step splits it, and a budget of
  // one step cannot pay for the next.
  const auto pts = on_line({0, 3, -2, 1}, {0, 0}, {1, 0});
  const auto frame = collinear_frame(pts, kTol);
  ASSERT_TRUE(frame.has_value());
  WorkBudget budget(collinear_fold_step_cost(3));
  EXPECT_TRUE(collinear_self_overlaps(pts, *frame, kTol, budget).empty());
  EXPECT_TRUE(budget.exhausted());
  EXPECT_EQ(budget.spent(), collinear_fold_step_cost(3));
}

}  // namespace
}  // namespace bezier::core
