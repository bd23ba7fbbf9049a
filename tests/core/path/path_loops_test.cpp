// core/path/path_loops.hpp: the loops of a path's self-intersections, on paths whose loops
// and areas are known in closed form.
#include "core/path/path_loops.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "core/path/path_area.hpp"
#include "core/path/path_intersections.hpp"
#include "tests/support/parsed_path.hpp"

namespace bezier::path {
namespace {

using test::parsed_path;

constexpr double kEps = std::numeric_limits<double>::epsilon();

TEST(PathLoops, BowTieLoopIsTheTriangleBetweenTheCrossingAndTheFarSide) {
  // Segment 0 (0,0)->(2,2) crosses segment 2 (2,0)->(0,2) at (1,1), t = s = 1/2. The loop
  // from there runs (1,1) -> (2,2) -> (2,0) -> (1,1): a clockwise triangle of area 1.
  const Path path = parsed_path("M0 0 L2 2 L2 0 L0 2 Z");
  const PathSelfIntersectionResult self = self_intersections(path, {});
  const std::vector<PathLoop> found = loops(path, self);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].segment_t, 0u);
  EXPECT_EQ(found[0].segment_s, 2u);
  EXPECT_NEAR(found[0].signed_area, -1.0, 8 * kEps);
  EXPECT_NEAR(found[0].area, 1.0, 8 * kEps);
  // Green's theorem: the figure eight's whole area is its two lobes with their signs,
  // +1 for the lower one and -1 for the loop: 0.
  EXPECT_NEAR(*closed_area(path), 0.0, 8 * kEps);
}

TEST(PathLoops, LoopsBetweenSubpathsAreNotLoops) {
  // Two crossing open strokes: one intersection, no loop.
  const Path path = parsed_path("M0 0 L2 2 M0 2 L2 0");
  const PathSelfIntersectionResult self = self_intersections(path, {});
  EXPECT_EQ(self.intersections.size(), 1u);
  EXPECT_TRUE(loops(path, self).empty());
}

PathContact contact(std::size_t segment_t, double t, std::size_t segment_s, double s) {
  PathContact c;
  c.segment_t = segment_t;
  c.segment_s = segment_s;
  c.intersection.t = t;
  c.intersection.s = s;
  c.intersection.t_interval = {t, t};
  c.intersection.s_interval = {s, s};
  return c;
}

TEST(PathLoops, EachContactWithinASubpathClosesThePieceBetweenItsEnds) {
  // The square [0, 2]^2 counter-clockwise and a separate stroke. The contacts are given by
  // hand, out of order: the piece from (2, 1/2) on segment 1 to (0, 1) on segment 3, closed
  // by its chord, is the trapezoid (2, 1/2), (2, 2), (0, 2), (0, 1) of area 4 - 3/2 = 5/2;
  // the piece from (1, 0) on segment 0 to (1, 2) on segment 2 is the rectangle [1, 2] x
  // [0, 2] of area 2; both counter-clockwise. A contact with the stroke (another subpath)
  // closes no loop.
  const Path path = parsed_path("M0 0 H2 V2 H0 Z M5 0 L6 1");
  PathSelfIntersectionResult self;
  self.intersections = {contact(1, 0.25, 3, 0.5), contact(2, 0.5, 4, 0.5), contact(0, 0.5, 2, 0.5)};
  self.intersections[0].intersection.kind = core::IntersectionKind::tangent;
  const std::vector<PathLoop> found = loops(path, self);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].segment_t, 0u);
  EXPECT_EQ(found[0].segment_s, 2u);
  EXPECT_EQ(found[0].t, 0.5);
  EXPECT_NEAR(found[0].signed_area, 2.0, 8 * kEps);
  EXPECT_EQ(found[0].kind, core::IntersectionKind::transversal);
  EXPECT_EQ(found[1].segment_t, 1u);
  EXPECT_EQ(found[1].segment_s, 3u);
  EXPECT_NEAR(found[1].signed_area, 2.5, 8 * kEps);
  EXPECT_EQ(found[1].area, std::fabs(found[1].signed_area));
  EXPECT_EQ(found[1].kind, core::IntersectionKind::tangent);
}

TEST(PathLoops, ASegmentsOwnLoopHasItsClosedFormArea) {
  // The cubic (0, 0), (2, 1), (-1, 1), (1, 0): x = 1/2 + 10 u^3 - 3u/2, y = 3/4 - 3 u^2 with
  // u = t - 1/2, symmetric about x = 1/2, crosses itself where 10 u^2 = 3/2, u = ±r,
  // r = sqrt(3/20). Its loop's area is 1/2 ∫ (x y' - y x') du over [-r, r] =
  // 6 r^5 - 6 r^3 + 9 r / 8 = r (6 r^4 - 6 r^2 + 9/8) = 9 r / 25, counter-clockwise (at the
  // top, u = 0, the curve runs left).
  const Path path = parsed_path("M0 0 C2 1 -1 1 1 0");
  const double r = std::sqrt(0.15);
  core::SelfIntersection pair;
  pair.t = 0.5 - r;
  pair.s = 0.5 + r;
  pair.point = {0.5, 0.75 - 3 * 0.15};
  PathSelfIntersectionResult self;
  self.within_segments = {SegmentSelfIntersections{0, {}}};
  self.within_segments[0].result.pairs = {pair};
  const std::vector<PathLoop> found = loops(path, self);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].segment_t, 0u);
  EXPECT_EQ(found[0].segment_s, 0u);
  EXPECT_EQ(found[0].t, pair.t);
  EXPECT_EQ(found[0].s, pair.s);
  EXPECT_NEAR(found[0].signed_area, 9 * r / 25, 1e-14);
  EXPECT_NEAR(found[0].area, 9 * r / 25, 1e-14);
}

}  // namespace
}  // namespace bezier::path
