// core/path/joint_separation.hpp: two segments sharing a joint are shown to meet only
// there when their control polygons, seen from the joint, lie on the two sides of a line
// through it; every case below has its common points known by construction, and a true
// answer is checked against the two-curve search of the pair.
#include "core/path/joint_separation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/intersect/intersect.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::path {
namespace {

using core::Curve;
using core::Point2;

Curve curve(std::vector<Point2> points) { return Curve(std::move(points)); }

/// Every contact the two-curve search reports for the pair lies at the joint (t = 1 on
/// `before`, s = 0 on `after`), and there is no overlap.
bool search_finds_the_joint_alone(const Curve& before, const Curve& after) {
  const core::IntersectionResult r = core::intersect(before, after);
  EXPECT_EQ(r.status, core::IntersectStatus::ok);
  if (!r.overlaps.empty()) return false;
  for (const core::Intersection& x : r.intersections) {
    if (x.t_interval.hi < 1.0 || x.s_interval.lo > 0.0) return false;
  }
  return true;
}

TEST(JointSeparation, ACornerOfTwoLinesMeetsOnlyAtItsJoint) {
  const Curve a = curve({{0, 0}, {1, 0}});
  const Curve b = curve({{1, 0}, {1, 1}});
  EXPECT_TRUE(meet_only_at_joint(a, b));
  EXPECT_TRUE(search_finds_the_joint_alone(a, b));
}

TEST(JointSeparation, ALineGoingOnStraightMeetsOnlyAtItsJoint) {
  EXPECT_TRUE(meet_only_at_joint(curve({{0, 0}, {1, 1}}), curve({{1, 1}, {3, 3}})));
}

TEST(JointSeparation, ALineTurningBackOverItselfIsNotSeparated) {
  // (1, 0) -> (0.5, 0) retraces the half [0.5, 1] of the line before it: an overlap.
  EXPECT_FALSE(meet_only_at_joint(curve({{0, 0}, {1, 0}}), curve({{1, 0}, {0.5, 0}})));
}

TEST(JointSeparation, TheSmoothJointsOfACircleOfFourCubicsMeetOnlyThere) {
  // Tangent-continuous joints: the end tangents are opposite, the line across them
  // separates the arcs.
  const double k = 0.5523;
  const Curve q1 = curve({{1, 0}, {1, k}, {k, 1}, {0, 1}});
  const Curve q2 = curve({{0, 1}, {-k, 1}, {-1, k}, {-1, 0}});
  const Curve q3 = curve({{-1, 0}, {-1, -k}, {-k, -1}, {0, -1}});
  const Curve q4 = curve({{0, -1}, {k, -1}, {1, -k}, {1, 0}});
  for (const auto& [before, after] : {std::pair{&q1, &q2}, {&q2, &q3}, {&q3, &q4}, {&q4, &q1}}) {
    EXPECT_TRUE(meet_only_at_joint(*before, *after));
    EXPECT_TRUE(search_finds_the_joint_alone(*before, *after));
  }
}

TEST(JointSeparation, ACubicCrossingBackOverTheLineBeforeItIsNotSeparated) {
  // The cubic (4,0) (4,4) (0,4) (2,-2) has y(s) = 12 s (1 - s) - 2 s^3, zero again at
  // s = sqrt(15) - 3 where x(s) is in (0, 4): it crosses the line y = 0 before it.
  const Curve line = curve({{0, 0}, {4, 0}});
  const Curve cubic = curve({{4, 0}, {4, 4}, {0, 4}, {2, -2}});
  EXPECT_FALSE(meet_only_at_joint(line, cubic));
  EXPECT_FALSE(search_finds_the_joint_alone(line, cubic));
}

TEST(JointSeparation, TwoSegmentsMeetingAtBothEndsAreNotSeparated) {
  // A closed subpath of two segments: the second one ends where the first one starts.
  const Curve a = curve({{0, 0}, {1, 1}, {2, 0}});
  const Curve b = curve({{2, 0}, {1, -1}, {0, 0}});
  EXPECT_FALSE(meet_only_at_joint(a, b));
  EXPECT_FALSE(meet_only_at_joint(b, a));
}

TEST(JointSeparation, ControlPointsOnTheJointAddNothing) {
  // The quadratic's middle control point and the cubic's first inner one are the joint
  // (2, 0) itself: exact zeros, skipped; the other control points decide.
  const Curve a = curve({{0, 0}, {2, 0}, {2, 0}});
  const Curve b = curve({{2, 0}, {2, 0}, {3, 1}, {4, 1}});
  EXPECT_TRUE(meet_only_at_joint(a, b));
  EXPECT_TRUE(search_finds_the_joint_alone(a, b));
}

TEST(JointSeparation, ASegmentClosedOnItselfIsNotSeparated) {
  // `before` starts at the joint too (a loop through it): the joint is then a second
  // common point at t = 0.
  EXPECT_FALSE(meet_only_at_joint(curve({{1, 0}, {0, 1}, {0, -1}, {1, 0}}), curve({{1, 0}, {2, 0}})));
  EXPECT_FALSE(meet_only_at_joint(curve({{0, 0}, {1, 0}}), curve({{1, 0}, {2, 1}, {2, -1}, {1, 0}})));
}

TEST(JointSeparation, EndsThatDifferOrPointsAreNotSeparated) {
  EXPECT_FALSE(meet_only_at_joint(curve({{0, 0}, {1, 0}}), curve({{1, 0x1p-52}, {1, 1}})));
  EXPECT_FALSE(meet_only_at_joint(curve({{1, 0}}), curve({{1, 0}, {1, 1}})));
  EXPECT_FALSE(meet_only_at_joint(curve({{0, 0}, {1, 0}}), curve({{1, 0}})));
}

TEST(JointSeparation, ASpikeNarrowerThanTheMarginIsLeftToTheSearch) {
  // Two lines leaving (1, 0) at an angle of about 1e-9 radians meet only at the joint, but
  // closer than the margin (2^-16 radians): not decided here. At 1e-3 radians it is.
  const Curve a = curve({{0, 0}, {1, 0}});
  EXPECT_FALSE(meet_only_at_joint(a, curve({{1, 0}, {0, 1e-9}})));
  EXPECT_TRUE(meet_only_at_joint(a, curve({{1, 0}, {0, 1e-3}})));
  EXPECT_TRUE(search_finds_the_joint_alone(a, curve({{1, 0}, {0, 1e-3}})));
}

TEST(JointSeparation, TheSameAtEveryScaleAndOffset) {
  // A corner of two cubics scaled by powers of two and moved far from the origin.
  for (const double scale : {0x1p-900, 0x1p-30, 1.0, 0x1p40, 0x1p900}) {
    for (const double offset : {0.0, 1e6, -3e12}) {
      const auto p = [&](double x, double y) { return Point2{offset + scale * x, offset + scale * y}; };
      const Curve a = curve({p(0, 0), p(1, 1), p(2, 1), p(3, 0)});
      const Curve b = curve({p(3, 0), p(4, -1), p(5, -1), p(6, 0)});
      if (offset == 0.0 || scale >= 1.0) {
        EXPECT_TRUE(meet_only_at_joint(a, b)) << scale << " " << offset;
      }
    }
  }
}

TEST(JointSeparation, CoordinatesWhoseDifferencesOverflowAreNotDecided) {
  // Corners that meet only at their joints, but whose control points are farther apart
  // than the largest double: left to the search, never a wrong answer.
  const double big = 1.7e308;
  EXPECT_FALSE(meet_only_at_joint(curve({{-big, 0}, {big, 0}}), curve({{big, 0}, {big, big}})));
  EXPECT_FALSE(meet_only_at_joint(curve({{-big, -big}, {big, big}}), curve({{big, big}, {big, -big}})));
}

TEST(JointSeparation, RandomJointsDecidedHereHaveNothingElseForTheSearch) {
  // Random segments of degree 1 to 4 sharing a joint, some of them turning back: whenever
  // the filter decides, the two-curve search finds the joint alone.
  test::Mulberry32 rng(4242);
  const auto random_point = [&] { return Point2{rng.next(), rng.next()}; };
  int decided = 0, undecided = 0;
  for (int round = 0; round < 3000; ++round) {
    const Point2 joint = random_point();
    const int n = 1 + static_cast<int>(rng.next() * 4);
    const int m = 1 + static_cast<int>(rng.next() * 4);
    // Control points near the joint in a narrowing range, so that tight turns and crossings
    // back over the other segment both occur.
    const double reach = round % 3 == 0 ? 0.05 : 1.0;
    std::vector<Point2> p, q{joint};
    for (int i = 0; i < n; ++i) p.push_back(joint + reach * (random_point() - Point2{0.5, 0.5}));
    p.push_back(joint);
    for (int j = 0; j < m; ++j) q.push_back(joint + reach * (random_point() - Point2{0.5, 0.5}));
    const Curve before(std::move(p)), after(std::move(q));
    if (meet_only_at_joint(before, after)) {
      ++decided;
      EXPECT_TRUE(search_finds_the_joint_alone(before, after)) << "round " << round;
    } else {
      ++undecided;
    }
  }
  // Both answers occur often enough for the check to mean something.
  EXPECT_GT(decided, 300);
  EXPECT_GT(undecided, 300);
}

}  // namespace
}  // namespace bezier::path
