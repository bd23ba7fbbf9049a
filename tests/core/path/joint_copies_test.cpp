// core/path/joint_copies.hpp: of the copies of one contact that the segments around a joint
// each report, exactly one stays (the lowest segment pair); contacts at different places
// all stay; with one path, a joint meeting itself is no contact. Paths and contacts are
// written by hand, so every answer is known.
#include "core/path/joint_copies.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

#include "tests/support/parsed_path.hpp"

namespace bezier::path {
namespace {

using test::parsed_path;

PathContact contact(std::size_t segment_t, core::ParamInterval t, std::size_t segment_s,
                    core::ParamInterval s) {
  PathContact c;
  c.segment_t = segment_t;
  c.segment_s = segment_s;
  c.intersection.t = t.lo + (t.hi - t.lo) / 2;
  c.intersection.s = s.lo + (s.hi - s.lo) / 2;
  c.intersection.t_interval = t;
  c.intersection.s_interval = s;
  return c;
}

std::vector<std::pair<std::size_t, std::size_t>> segment_pairs(const std::vector<PathContact>& cs) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (const PathContact& c : cs) out.emplace_back(c.segment_t, c.segment_s);
  return out;
}

constexpr core::ParamInterval kAtStart{0.0, 0x1p-40};
constexpr core::ParamInterval kAtEnd{1.0 - 0x1p-40, 1.0};

TEST(JointCopies, AContactAtAJointIsKeptOnceOnTheLowerSegment) {
  // The polyline (0, 0) - (1, 1) - (2, 0) and the vertical line x = 1 from y = -1 to 2: they
  // meet at the joint (1, 1), s = 2/3, found at the end of segment 0 and the start of 1.
  const Path a = parsed_path("M0 0 L1 1 L2 0");
  const Path b = parsed_path("M1 -1 L1 2");
  const core::ParamInterval s{0.6666, 0.6667};
  const auto kept = without_joint_copies({contact(1, kAtStart, 0, s), contact(0, kAtEnd, 0, s)}, a, b, false);
  EXPECT_EQ(segment_pairs(kept), (std::vector<std::pair<std::size_t, std::size_t>>{{0, 0}}));
  // The same joint on a but two different places on b: two contacts.
  const auto both = without_joint_copies(
      {contact(1, kAtStart, 0, {0.25, 0.26}), contact(0, kAtEnd, 0, {0.6666, 0.6667})}, a, b, false);
  EXPECT_EQ(segment_pairs(both), (std::vector<std::pair<std::size_t, std::size_t>>{{1, 0}, {0, 0}}));
}

TEST(JointCopies, TheOpenEndsOfASubpathAreNoJoints) {
  // t = 0 on segment 0 and t = 1 on segment 1 are the polyline's open ends, different points:
  // both contacts stay, in their order.
  const Path a = parsed_path("M0 0 L1 1 L2 0");
  const Path b = parsed_path("M0 0 L2 0");
  const auto kept = without_joint_copies(
      {contact(1, kAtEnd, 0, kAtEnd), contact(0, kAtStart, 0, kAtStart)}, a, b, false);
  EXPECT_EQ(segment_pairs(kept), (std::vector<std::pair<std::size_t, std::size_t>>{{1, 0}, {0, 0}}));
}

TEST(JointCopies, JointsSeparatedByZeroLengthSegmentsAreOneJoint) {
  // Segment 1 is the point (1, 1): the end of 0, segment 1 and the start of 2 are one joint.
  const Path a = parsed_path("M0 0 L1 1 L1 1 L2 0");
  ASSERT_EQ(a.segments.size(), 3u);
  const Path b = parsed_path("M1 -1 L1 2");
  const core::ParamInterval s{0.6666, 0.6667};
  const auto kept = without_joint_copies(
      {contact(2, kAtStart, 0, s), contact(1, {0.0, 1.0}, 0, s), contact(0, kAtEnd, 0, s)}, a, b, false);
  EXPECT_EQ(segment_pairs(kept), (std::vector<std::pair<std::size_t, std::size_t>>{{0, 0}}));
}

TEST(JointCopies, OnOnePathAJointMeetingItselfIsNoContact) {
  // The closed triangle (0, 0), (2, 0), (1, 2): segments 0, 1, 2. Consecutive segments meet
  // at their joint, and the last segment's end meets the first one's start: joints, not
  // contacts.
  const Path p = parsed_path("M0 0 L2 0 L1 2 Z");
  ASSERT_EQ(p.segments.size(), 3u);
  ASSERT_TRUE(p.subpaths[0].closed);
  EXPECT_TRUE(without_joint_copies(
                  {contact(0, kAtEnd, 1, kAtStart), contact(1, kAtEnd, 2, kAtStart),
                   contact(0, kAtStart, 2, kAtEnd)},
                  p, p, true)
                  .empty());
}

TEST(JointCopies, OnOnePathCopiesAreFoundWithTheirEndsInEitherOrder) {
  // A square (segments 0-3) and a point inside segment 3 meeting the joint between segments
  // 0 and 1, reported three ways: (0 at its end, 3), (1 at its start, 3) and (3, 1 at its
  // start) with the ends swapped. One stays: the lowest pair, (0, 3).
  const Path p = parsed_path("M0 0 H2 V2 H0 Z");
  const core::ParamInterval inside{0.5, 0.5};
  const auto kept = without_joint_copies(
      {contact(1, kAtStart, 3, inside), contact(3, inside, 1, kAtStart), contact(0, kAtEnd, 3, inside)}, p, p,
      true);
  EXPECT_EQ(segment_pairs(kept), (std::vector<std::pair<std::size_t, std::size_t>>{{0, 3}}));
}

}  // namespace
}  // namespace bezier::path
