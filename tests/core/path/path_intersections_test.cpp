#include "core/path/path_intersections.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

#include "core/cubic/double_point.hpp"
#include "core/curve/evaluate.hpp"
#include "core/intersect/intersect.hpp"
#include "core/path/segment_boxes.hpp"
#include "tests/support/mulberry32.hpp"
#include "tests/support/parsed_path.hpp"

namespace bezier::path {
namespace {

using test::parsed_path;

constexpr double kTol = 1e-12;

bool meet(core::ParamInterval a, core::ParamInterval b) { return a.lo <= b.hi && b.lo <= a.hi; }

/// Whether a path search reported the crossing x of segments i and j found by searching that
/// pair alone: on the same pair with meeting parameter intervals, or dropped as the copy of a
/// contact kept at the same point on a neighbouring pair, at a joint.
bool reported(const std::vector<PathContact>& contacts, std::size_t i, std::size_t j,
              const core::Intersection& x) {
  for (const PathContact& c : contacts) {
    const bool same_pair = c.segment_t == i && c.segment_s == j &&
                           meet(c.intersection.t_interval, x.t_interval) &&
                           meet(c.intersection.s_interval, x.s_interval);
    const bool at_joint = (x.t_interval.lo == 0 || x.t_interval.hi == 1 ||
                           x.s_interval.lo == 0 || x.s_interval.hi == 1) &&
                          core::length(c.intersection.point - x.point) <= 1e-9;
    if (same_pair || at_joint) return true;
  }
  return false;
}

TEST(PathIntersections, TwoOverlappingSquaresCrossTwice) {
  // A = [0,2]^2 and B = [1,3]^2, both counter-clockwise: A's right side (segment 1) crosses
  // B's bottom (segment 0) at (2, 1), A's top (segment 2, drawn right to left) crosses B's
  // left side (segment 3, drawn downwards) at (1, 2); each at the middle of both segments.
  const PathIntersectionResult r =
      intersect(parsed_path("M0 0 H2 V2 H0 Z"), parsed_path("M1 1 H3 V3 H1 Z"), {});
  ASSERT_EQ(r.status, core::IntersectStatus::ok);
  ASSERT_EQ(r.intersections.size(), 2u);
  EXPECT_EQ(r.intersections[0].segment_t, 1u);
  EXPECT_EQ(r.intersections[0].segment_s, 0u);
  EXPECT_EQ(r.intersections[1].segment_t, 2u);
  EXPECT_EQ(r.intersections[1].segment_s, 3u);
  for (const PathContact& c : r.intersections) {
    EXPECT_NEAR(c.intersection.t, 0.5, kTol);
    EXPECT_NEAR(c.intersection.s, 0.5, kTol);
  }
  EXPECT_TRUE(r.overlaps.empty());
}

TEST(PathIntersections, ALineThroughAJointCountsOnce) {
  // A's joint (1, 1) lies on B: found on A's segments 0 (t = 1) and 1 (t = 0), kept once,
  // on the lower segment.
  const PathIntersectionResult r = intersect(parsed_path("M0 0 L1 1 L2 0"), parsed_path("M1 0 L1 2"), {});
  ASSERT_EQ(r.intersections.size(), 1u);
  EXPECT_EQ(r.intersections[0].segment_t, 0u);
  EXPECT_EQ(r.intersections[0].segment_s, 0u);
  EXPECT_EQ(r.intersections[0].intersection.t, 1.0);
  EXPECT_NEAR(r.intersections[0].intersection.s, 0.5, kTol);
  // The same with the roles swapped: the joint is then on the second path's side.
  const PathIntersectionResult swapped =
      intersect(parsed_path("M1 0 L1 2"), parsed_path("M0 0 L1 1 L2 0"), {});
  ASSERT_EQ(swapped.intersections.size(), 1u);
  EXPECT_EQ(swapped.intersections[0].segment_s, 0u);
  EXPECT_EQ(swapped.intersections[0].intersection.s, 1.0);
}

TEST(PathIntersections, TwoJointsAtOnePointCountOnce) {
  // A V and an inverted V touching at their corners (1, 1): four segment pairs find it.
  const PathIntersectionResult r =
      intersect(parsed_path("M0 0 L1 1 L2 0"), parsed_path("M0 2 L1 1 L2 2"), {});
  ASSERT_EQ(r.intersections.size(), 1u);
  EXPECT_EQ(r.intersections[0].segment_t, 0u);
  EXPECT_EQ(r.intersections[0].segment_s, 0u);
  EXPECT_EQ(r.intersections[0].intersection.t, 1.0);
  EXPECT_EQ(r.intersections[0].intersection.s, 1.0);
}

TEST(PathIntersections, ClosingJointOfAClosedSubpathKeepsTheLowerSegment) {
  // Triangle A's start (0, 0), where its last segment (the closing line) ends and its
  // first starts, lies on B.
  const PathIntersectionResult r =
      intersect(parsed_path("M0 0 L2 1 L2 -1 Z"), parsed_path("M0 -1 L0 1"), {});
  ASSERT_EQ(r.intersections.size(), 1u);
  EXPECT_EQ(r.intersections[0].segment_t, 0u);
  EXPECT_EQ(r.intersections[0].intersection.t, 0.0);
}

/// A random path of `segments` segments of degree 1 to 3 in [0, 1)^2, in one or two
/// subpaths, sometimes closed.
std::string random_path(test::Mulberry32& rng, int segments) {
  const auto point = [&](std::string& out) {
    for (int i = 0; i < 2; ++i) {
      out += std::to_string(rng.next());
      out += ' ';
    }
  };
  std::string data = "M";
  point(data);
  for (int k = 0; k < segments; ++k) {
    if (k == segments / 2 && rng.next() < 0.3) {
      data += " M";
      point(data);
    }
    const int degree = 1 + static_cast<int>(rng.next() * 3);
    data += degree == 1 ? " L" : degree == 2 ? " Q" : " C";
    for (int i = 0; i < degree; ++i) point(data);
  }
  if (rng.next() < 0.5) data += "Z";
  return data;
}

TEST(PathIntersections, RandomPathsAgreeWithEverySegmentPairSearchedAlone) {
  test::Mulberry32 rng(2121);
  std::size_t all_rounds = 0;
  for (int round = 0; round < 60; ++round) {
    const Path a = parsed_path(random_path(rng, 2 + static_cast<int>(rng.next() * 10)));
    const Path b = parsed_path(random_path(rng, 2 + static_cast<int>(rng.next() * 10)));
    const PathIntersectionResult r = intersect(a, b, {});
    ASSERT_EQ(r.status, core::IntersectStatus::ok);
    // Every pair, no culling.
    std::size_t total = 0;
    for (std::size_t i = 0; i < a.segments.size(); ++i) {
      for (std::size_t j = 0; j < b.segments.size(); ++j) {
        const core::IntersectionResult alone = core::intersect(a.segments[i], b.segments[j]);
        for (const core::Intersection& x : alone.intersections) {
          ++total;
          EXPECT_TRUE(reported(r.intersections, i, j, x))
              << "round " << round << " pair " << i << ", " << j << " t " << x.t;
        }
      }
    }
    all_rounds += total;
    // Nothing beyond what the pairs find.
    EXPECT_LE(r.intersections.size(), total) << "round " << round;
    for (const PathContact& c : r.intersections) {
      const core::IntersectionResult alone =
          core::intersect(a.segments[c.segment_t], b.segments[c.segment_s]);
      bool found = false;
      for (const core::Intersection& x : alone.intersections) {
        found = found || (x.t == c.intersection.t && x.s == c.intersection.s);
      }
      EXPECT_TRUE(found) << "round " << round;
    }
  }
  EXPECT_GT(all_rounds, 100u) << "the random paths should cross often";
}

TEST(PathSelfIntersections, ConvexPolygonsAndTheirJointsDoNotIntersect) {
  // Regular polygons (closed) and their open versions: every joint is shared by two
  // consecutive segments only.
  for (int corners = 3; corners <= 24; ++corners) {
    std::string closed = "M";
    for (int k = 0; k < corners; ++k) {
      const double angle = 2 * M_PI * k / corners;
      closed += k == 0 ? "" : " L";
      closed += std::to_string(std::cos(angle));
      closed += ' ';
      closed += std::to_string(std::sin(angle));
    }
    const PathSelfIntersectionResult r = self_intersections(parsed_path(closed + " Z"), {});
    EXPECT_EQ(r.status, core::IntersectStatus::ok);
    EXPECT_TRUE(r.intersections.empty()) << closed;
    EXPECT_TRUE(r.overlaps.empty()) << closed;
  }
}

TEST(PathSelfIntersections, SmoothClosedOutlineOfCubicsHasNone) {
  // A circle of four cubic arcs (kappa = 0.5523): tangent-continuous joints, and the seam
  // where the last arc ends at the first one's start.
  const PathSelfIntersectionResult r = self_intersections(
      parsed_path("M1 0 C1 .5523 .5523 1 0 1 C-.5523 1 -1 .5523 -1 0 C-1 -.5523 -.5523 -1 0 -1 "
             "C.5523 -1 1 -.5523 1 0 Z"),
      {});
  EXPECT_EQ(r.status, core::IntersectStatus::ok);
  EXPECT_TRUE(r.intersections.empty());
  EXPECT_TRUE(r.within_segments.empty());
}

TEST(PathSelfIntersections, ALoopingSegmentIsSearchedAndMonotoneOnesAddNothing) {
  // Segment 0 loops (its exact double point lies on it); segments 1 and 2 are monotone along
  // x, which the search clears without looking further.
  const Path path = parsed_path("M0 0 C3 2 -1 2 2 0 L4 0 C5 1 6 -1 7 0");
  const PathSelfIntersectionResult r = self_intersections(path, {});
  ASSERT_EQ(r.status, core::IntersectStatus::ok);
  ASSERT_EQ(r.within_segments.size(), 1u);
  EXPECT_EQ(r.within_segments[0].segment, 0u);
  const auto loop = core::cubic_double_point(path.segments[0]);
  ASSERT_TRUE(loop.has_value() && loop->on_segment);
  ASSERT_EQ(r.within_segments[0].result.pairs.size(), 1u);
  EXPECT_NEAR(r.within_segments[0].result.pairs[0].t, loop->t1, 1e-12);
  EXPECT_NEAR(r.within_segments[0].result.pairs[0].s, loop->t2, 1e-12);
  EXPECT_FALSE(core::certainly_without_self_intersections(path.segments[0]));
  EXPECT_TRUE(core::certainly_without_self_intersections(path.segments[2]));
}

TEST(PathSelfIntersections, BowTieCrossesOnceAtItsCentre) {
  const PathSelfIntersectionResult r = self_intersections(parsed_path("M0 0 L2 2 L2 0 L0 2 Z"), {});
  ASSERT_EQ(r.intersections.size(), 1u);
  EXPECT_EQ(r.intersections[0].segment_t, 0u);
  EXPECT_EQ(r.intersections[0].segment_s, 2u);
  EXPECT_NEAR(r.intersections[0].intersection.t, 0.5, kTol);
  EXPECT_NEAR(r.intersections[0].intersection.s, 0.5, kTol);
}

TEST(PathSelfIntersections, ConsecutiveSegmentsMeetingAwayFromTheirJointIntersect) {
  // Segment 0 is y = 0 from (0, 0) to (4, 0); segment 1, the cubic (4,0) (4,4) (0,4)
  // (2,-2), has y(s) = 12 s (1 - s) - 2 s^3, which is 0 again at s^2 + 6 s - 6 = 0,
  // s = sqrt(15) - 3, where it crosses segment 0 at t = x(s) / 4.
  const Path path = parsed_path("M0 0 L4 0 C4 4 0 4 2 -2");
  const PathSelfIntersectionResult r = self_intersections(path, {});
  ASSERT_EQ(r.intersections.size(), 1u);
  const double s = std::sqrt(15.0) - 3;
  EXPECT_EQ(r.intersections[0].segment_t, 0u);
  EXPECT_EQ(r.intersections[0].segment_s, 1u);
  EXPECT_NEAR(r.intersections[0].intersection.s, s, kTol);
  EXPECT_NEAR(r.intersections[0].intersection.t, core::evaluate(path.segments[1], s).x / 4, kTol);
}

TEST(PathSelfIntersections, AJointOnAnotherSegmentCountsOnce) {
  // The joint (2, 0) of segments 1 and 2 lies on segment 0... of the same path: the path
  // runs right along y = 0 to (4, 0), up to (2, 2), down to (2, -2) through (2, 0).
  const PathSelfIntersectionResult r = self_intersections(parsed_path("M0 0 L4 0 L2 2 L2 -2"), {});
  ASSERT_EQ(r.intersections.size(), 1u);
  EXPECT_EQ(r.intersections[0].segment_t, 0u);
  EXPECT_EQ(r.intersections[0].segment_s, 2u);
  EXPECT_NEAR(r.intersections[0].intersection.t, 0.5, kTol);
  EXPECT_NEAR(r.intersections[0].intersection.s, 0.5, kTol);
}

TEST(PathSelfIntersections, RandomPathsNeverReportTheirJoints) {
  test::Mulberry32 rng(77);
  for (int round = 0; round < 60; ++round) {
    const Path path = parsed_path(random_path(rng, 2 + static_cast<int>(rng.next() * 10)));
    const PathSelfIntersectionResult r = self_intersections(path, {});
    ASSERT_EQ(r.status, core::IntersectStatus::ok);
    for (const PathContact& c : r.intersections) {
      EXPECT_LT(c.segment_t, c.segment_s);
      // Never the shared end point of consecutive segments.
      const auto next = next_segment(path, c.segment_t);
      const bool joint_forward = next == c.segment_s && c.intersection.t_interval.hi == 1 &&
                                 c.intersection.s_interval.lo == 0;
      const auto back = next_segment(path, c.segment_s);
      const bool joint_back = back == c.segment_t && c.intersection.s_interval.hi == 1 &&
                              c.intersection.t_interval.lo == 0;
      EXPECT_FALSE(joint_forward || joint_back) << "round " << round;
    }
  }
}

TEST(PathSelfIntersections, RandomPathsAgreeWithEverySegmentPairSearchedAlone) {
  // The pairs the path search settles without a search (consecutive segments that meet
  // only at their joint, joint_separation.hpp) lose nothing: every contact of every pair
  // searched alone, other than the joint of two consecutive segments, is in the answer
  // (on the same pair, or as the copy kept at the same point of a neighbouring pair).
  test::Mulberry32 rng(3131);
  std::size_t all_rounds = 0;
  for (int round = 0; round < 60; ++round) {
    const Path path = parsed_path(random_path(rng, 2 + static_cast<int>(rng.next() * 10)));
    const PathSelfIntersectionResult r = self_intersections(path, {});
    ASSERT_EQ(r.status, core::IntersectStatus::ok);
    for (std::size_t i = 0; i < path.segments.size(); ++i) {
      for (std::size_t j = i + 1; j < path.segments.size(); ++j) {
        const core::IntersectionResult alone = core::intersect(path.segments[i], path.segments[j]);
        for (const core::Intersection& x : alone.intersections) {
          const bool joint_forward = next_segment(path, i) == j && x.t_interval.hi == 1 &&
                                     x.s_interval.lo == 0;
          const bool joint_back = next_segment(path, j) == i && x.s_interval.hi == 1 &&
                                  x.t_interval.lo == 0;
          if (joint_forward || joint_back) continue;
          ++all_rounds;
          EXPECT_TRUE(reported(r.intersections, i, j, x))
              << "round " << round << " pair " << i << ", " << j << " t " << x.t;
        }
        for (const core::Overlap& o : alone.overlaps) {
          bool found = false;
          for (const PathOverlap& p : r.overlaps) {
            found = found || (p.segment_t == i && p.segment_s == j &&
                              p.overlap.t_interval.lo == o.t_interval.lo &&
                              p.overlap.t_interval.hi == o.t_interval.hi);
          }
          EXPECT_TRUE(found) << "round " << round << " overlap of " << i << ", " << j;
        }
      }
    }
  }
  EXPECT_GT(all_rounds, 50u) << "the random paths should cross themselves often";
}

TEST(PathIntersections, WorkCapIsSharedByThePairs) {
  // Two paths of many crossing lines: a cap below what the pairs need stops the search.
  std::string a = "M0 0", b = "M0 0.5";
  for (int k = 1; k <= 40; ++k) {
    a += " L";
    a += std::to_string(k);
    a += k % 2 ? " 1" : " 0";
    b += " L";
    b += std::to_string(k);
    b += k % 2 ? " 0.5" : " 0.25";
  }
  core::IntersectOptions options;
  const PathIntersectionResult full = intersect(parsed_path(a), parsed_path(b), options);
  ASSERT_EQ(full.status, core::IntersectStatus::ok);
  options.max_work = full.stats.work / 2;
  const PathIntersectionResult capped = intersect(parsed_path(a), parsed_path(b), options);
  EXPECT_EQ(capped.status, core::IntersectStatus::work_cap_reached);
  EXPECT_LE(capped.stats.work, options.max_work + full.stats.work / 40);
}

TEST(PathSelfIntersections, CertifiedOnesAddTheLoopsWithinSegmentsInOneSortedList) {
  // The cubic (-9, 0) (13, 16) (-13, 16) (9, 0), whose double point (0, 9) is at t = 1/4,
  // s = 3/4 (x(t) = -9 + 66 t - 144 t^2 + 96 t^3 vanishes at 1/4 and 3/4, y = 48 t (1 - t)
  // is 9 at both), then the line from (9, 0) to (-9, 18), x + y = 9: it meets the cubic
  // where 16 t^3 - 32 t^2 + 19 t - 3 = (t - 1)(4 t - 1)(4 t - 3) vanishes, at its joint
  // t = 1 (not an intersection) and at t = 1/4 and 3/4, both its own s = 1/2. Three contacts:
  // the segment's own pair, certified, and the two of the line.
  const Path p = parsed_path("M-9 0 C13 16 -13 16 9 0 L-9 18");
  core::WorkBudget budget;
  const PathSelfIntersectionResult r = certified_self_intersections(p, {}, budget);
  ASSERT_FALSE(budget.exhausted());
  ASSERT_EQ(r.status, core::IntersectStatus::ok);
  EXPECT_EQ(r.uncertified_pairs, 0u);
  std::size_t within = 0;
  for (const PathContact& c : r.intersections) {
    if (c.segment_t != c.segment_s) continue;
    ++within;
    EXPECT_EQ(c.segment_t, 0u);
    EXPECT_TRUE(c.intersection.resolved);
    EXPECT_TRUE(c.intersection.t_interval.contains(0.25));
    EXPECT_TRUE(c.intersection.s_interval.contains(0.75));
    EXPECT_LT(c.intersection.t_interval.width(), 1e-12);
  }
  EXPECT_EQ(within, 1u);
  EXPECT_EQ(r.intersections.size(), 3u);
  EXPECT_GT(r.stats.certification_steps, 0);
  // The other contacts are the plain search's, and the whole list is sorted.
  core::WorkBudget plain_budget;
  const PathSelfIntersectionResult plain = self_intersections(p, {}, plain_budget);
  EXPECT_EQ(r.intersections.size(), plain.intersections.size() + 1);
  for (std::size_t k = 1; k < r.intersections.size(); ++k) {
    const PathContact& a = r.intersections[k - 1];
    const PathContact& b = r.intersections[k];
    EXPECT_LE(std::tuple(a.segment_t, a.intersection.t, a.segment_s, a.intersection.s),
              std::tuple(b.segment_t, b.intersection.t, b.segment_s, b.intersection.s));
  }
  // Every unit the certification spent is in the budget and in stats.work.
  EXPECT_EQ(r.stats.work, budget.spent());
  EXPECT_GT(budget.spent(), plain_budget.spent());
}

TEST(PathSelfIntersections, TheSweepsPairsAreChargedToTheMemoryLimit) {
  // Twelve equal zero-length segments at the origin: all 66 pairs of their boxes meet.
  // A limit of 65 pairs' bytes stops the sweep at the 66th; 66 admits them, and the copy
  // of the pairs without a point segment is empty.
  std::string data = "M0 0";
  for (int k = 0; k < 12; ++k) data += " L0 0";
  const Path p = parsed_path(data);
  core::WorkBudget short_of_one(core::WorkBudget::kUnlimited, 65 * kStoredPairBytes);
  (void)self_intersections(p, {}, short_of_one);
  EXPECT_EQ(short_of_one.exhaustion(), core::Exhaustion::memory);
  core::WorkBudget enough(core::WorkBudget::kUnlimited, 66 * kStoredPairBytes);
  const PathSelfIntersectionResult r = self_intersections(p, {}, enough);
  EXPECT_FALSE(enough.exhausted());
  EXPECT_EQ(enough.memory(), 66 * kStoredPairBytes);
  EXPECT_TRUE(r.intersections.empty());
}

}  // namespace
}  // namespace bezier::path
