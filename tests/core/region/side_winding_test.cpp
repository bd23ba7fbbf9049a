// core/region/side_winding.hpp: the windings a ray finds do not depend on how the index
// finds the edges near it. The first SideWindingIndex::kLinearScanRays rays of an index scan
// every box, later ones go through the box hierarchy; each group's answer, status and work
// through an index past that point equal those through a fresh index (a scan), and on two
// nested squares the rays give the windings the nesting fixes.
#include "core/region/side_winding.hpp"

#include <gtest/gtest.h>

#include <array>
#include <sstream>
#include <string>

#include "tests/support/parsed_path.hpp"

namespace bezier::region {
namespace {

using test::parsed_path;

/// A closed zigzag of `teeth` teeth: from (x0, 0) up to height h and back, then closed along
/// y = -depth.
std::string zigzag(int teeth, double x0, double h, double depth) {
  std::ostringstream d;
  d << "M" << x0 << " 0";
  for (int k = 0; k < teeth; ++k) d << " L" << x0 + 2 * k + 1 << " " << h << " L" << x0 + 2 * k + 2 << " 0";
  d << " V" << -depth << " H" << x0 << " Z";
  return d.str();
}

TEST(SideWindings, TheBoxHierarchyFindsWhatTheScanFinds) {
  // Two zigzags, the second shifted by half a tooth, taller and deeper: every tooth crosses
  // two of the other's, so the arrangement has many groups, more than twice the rays a scan
  // serves.
  const path::Path a = parsed_path(zigzag(12, 0.0, 3.0, 1.0));
  const path::Path b = parsed_path(zigzag(12, 0.5, 4.0, 2.0));
  core::WorkBudget search_budget(100000000);
  const Arrangement arrangement = build_arrangement(a, &b, search_budget);
  ASSERT_EQ(arrangement.status, core::IntersectStatus::ok);
  ASSERT_GT(arrangement.groups.size(), 2 * SideWindingIndex::kLinearScanRays);
  const SideWindingIndex shared(arrangement);
  int compared = 0;
  for (std::size_t g = 0; g < arrangement.groups.size(); ++g) {
    core::WorkBudget through_shared, through_fresh;
    const SideWindingResult r = side_windings(arrangement, shared, g, through_shared);
    const SideWindingIndex fresh(arrangement);
    const SideWindingResult s = side_windings(arrangement, fresh, g, through_fresh);
    EXPECT_FALSE(fresh.hierarchy.has_value());
    ASSERT_EQ(r.status, s.status) << "group " << g;
    EXPECT_EQ(r.windings.left, s.windings.left) << "group " << g;
    EXPECT_EQ(r.windings.right, s.windings.right) << "group " << g;
    EXPECT_EQ(through_shared.spent(), through_fresh.spent()) << "group " << g;
    if (shared.hierarchy.has_value()) ++compared;
  }
  EXPECT_GT(compared, 0);  // some groups were answered through the hierarchy
}

TEST(SideWindings, NestedSquaresGiveTheNestingsWindings) {
  // a (0..4) holds b (1..3), both counter-clockwise: just outside b the winding is (1, 0),
  // just inside (1, 1); just outside a (0, 0), just inside (1, 0). Each group is one side of
  // one square, its representative running counter-clockwise, so its left is inside.
  const path::Path a = parsed_path("M0 0 H4 V4 H0 Z");
  const path::Path b = parsed_path("M1 1 H3 V3 H1 Z");
  core::WorkBudget search_budget(100000000);
  const Arrangement arrangement = build_arrangement(a, &b, search_budget);
  ASSERT_EQ(arrangement.status, core::IntersectStatus::ok);
  ASSERT_EQ(arrangement.groups.size(), 8u);
  const SideWindingIndex index(arrangement);
  for (std::size_t g = 0; g < arrangement.groups.size(); ++g) {
    core::WorkBudget budget;
    const SideWindingResult r = side_windings(arrangement, index, g, budget);
    ASSERT_EQ(r.status, SideWindingStatus::ok) << "group " << g;
    const bool of_a = arrangement.edges[arrangement.groups[g].representative].source == Operand::a;
    const std::array<int, 2> left = of_a ? std::array<int, 2>{1, 0} : std::array<int, 2>{1, 1};
    const std::array<int, 2> right = of_a ? std::array<int, 2>{0, 0} : std::array<int, 2>{1, 0};
    EXPECT_EQ(r.windings.left, left) << "group " << g;
    EXPECT_EQ(r.windings.right, right) << "group " << g;
  }
}

}  // namespace
}  // namespace bezier::region
