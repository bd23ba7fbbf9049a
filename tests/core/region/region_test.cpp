#include "core/region/region.hpp"

#include <gtest/gtest.h>

#include <optional>

#include <vector>

#include "tests/support/parsed_path.hpp"

namespace bezier::region {
namespace {

using core::Curve;
using core::Point2;

Curve line(Point2 a, Point2 b) {
  return Curve({a, b});
}

TEST(FillRule, NamesAndTheFilledWindings) {
  EXPECT_EQ(to_string(FillRule::nonzero), "nonzero");
  EXPECT_EQ(to_string(FillRule::evenodd), "evenodd");
  EXPECT_FALSE(fills(FillRule::nonzero, 0));
  EXPECT_TRUE(fills(FillRule::nonzero, -2));
  EXPECT_TRUE(fills(FillRule::nonzero, 1));
  EXPECT_FALSE(fills(FillRule::evenodd, 0));
  EXPECT_FALSE(fills(FillRule::evenodd, 2));
  EXPECT_FALSE(fills(FillRule::evenodd, -2));
  EXPECT_TRUE(fills(FillRule::evenodd, -1));
  EXPECT_TRUE(fills(FillRule::evenodd, 3));
}

TEST(RegionFromPath, AnOpenSubpathIsClosedByALineBackToItsStart) {
  const Region r = region_from_path(test::parsed_path("M0 0 L4 0 L4 3"), FillRule::evenodd);
  EXPECT_EQ(r.fill_rule, FillRule::evenodd);
  ASSERT_EQ(r.path.segments.size(), 3u);
  ASSERT_EQ(r.path.subpaths.size(), 1u);
  EXPECT_TRUE(r.path.subpaths[0].closed);
  EXPECT_EQ(r.path.subpaths[0].segment_count, 3u);
  EXPECT_EQ(r.path.segments[2], line({4, 3}, {0, 0}));
}

TEST(RegionFromPath, ClosedSubpathsKeepTheirSegmentsAndLaterOnesMoveOn) {
  // The first subpath returns to its start without Z: marked closed, no line added; the
  // second is open and gets its line, the third is closed by Z.
  const Region r =
      region_from_path(test::parsed_path("M0 0 L1 0 L0 1 L0 0 M5 5 L6 5 L6 6 M9 9 L10 9 L9 10 Z"),
                       FillRule::nonzero);
  ASSERT_EQ(r.path.subpaths.size(), 3u);
  EXPECT_EQ(r.path.subpaths[0].first_segment, 0u);
  EXPECT_EQ(r.path.subpaths[0].segment_count, 3u);
  EXPECT_EQ(r.path.subpaths[1].first_segment, 3u);
  EXPECT_EQ(r.path.subpaths[1].segment_count, 3u);
  EXPECT_EQ(r.path.segments[5], line({6, 6}, {5, 5}));
  EXPECT_EQ(r.path.subpaths[2].first_segment, 6u);
  EXPECT_EQ(r.path.subpaths[2].segment_count, 3u);
  for (const auto& s : r.path.subpaths) {
    EXPECT_TRUE(s.closed);
    EXPECT_EQ(r.path.segments[s.first_segment + s.segment_count - 1].back(),
              r.path.segments[s.first_segment].front());
  }
}

TEST(RegionFromPath, TheEmptyPathIsTheEmptyRegion) {
  const Region r = region_from_path(path::Path{}, FillRule::nonzero);
  EXPECT_TRUE(r.path.segments.empty());
  EXPECT_TRUE(r.path.subpaths.empty());
}

TEST(RegionFromPath, KeepsThePathsArcTolerance) {
  path::Path arcs = test::parsed_path("M0 0 L4 0 L4 3");
  arcs.arc_tolerance = 0.25;
  EXPECT_EQ(region_from_path(arcs, FillRule::nonzero).path.arc_tolerance, std::optional<double>(0.25));
  EXPECT_FALSE(region_from_path(test::parsed_path("M0 0 L4 0 L4 3"), FillRule::nonzero).path.arc_tolerance);
}

TEST(RegionFromCurves, ChainsCloseWhereTheyStartedAndTheNextStartsAnywhere) {
  std::vector<Curve> curves = {
      Curve({{0, 0}, {2, -1}, {4, 0}}), line({4, 0}, {0, 0}),         // chain 1, closed
      Curve({{10, 0}, {11, 1}, {12, 1}, {13, 0}, {14, 2}, {15, 0}}),  // chain 2, degree 5
      line({15, 0}, {12, -3})};                                       // left open
  EXPECT_FALSE(chain_break(curves));
  const Region r = region_from_curves(curves, FillRule::evenodd);
  ASSERT_EQ(r.path.subpaths.size(), 2u);
  EXPECT_EQ(r.path.subpaths[0].segment_count, 2u);
  EXPECT_EQ(r.path.subpaths[1].first_segment, 2u);
  EXPECT_EQ(r.path.subpaths[1].segment_count, 3u);
  EXPECT_EQ(r.path.segments[4], line({12, -3}, {10, 0}));
  EXPECT_EQ(r.path.segments[2].degree(), 5);
}

TEST(RegionFromCurves, ACurveThatStartsElsewhereInsideAChainIsABreak) {
  const std::vector<Curve> curves = {line({0, 0}, {1, 0}), line({1, 0}, {1, 1}),
                                     line({1, 1.5}, {0, 0})};
  EXPECT_EQ(chain_break(curves), 2u);
  EXPECT_FALSE(chain_break({}));
  EXPECT_FALSE(chain_break({line({0, 0}, {1, 0})}));
}

}  // namespace
}  // namespace bezier::region
