// core/region/side_links.hpp: groups share their sides through vertices where only the two
// of them end. Hand-built arrangements (only the vertices, edge ends and groups matter) give
// every link and its orientation exactly; on real arrangements, the windings a ray finds on
// each side of every group equal those carried along the links from a neighbour.
#include "core/region/side_links.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "core/region/side_winding.hpp"
#include "tests/support/parsed_path.hpp"

namespace bezier::region {
namespace {

using test::parsed_path;

/// An arrangement with `vertices` vertices and the given edges (from, to), each edge its own
/// group unless `groups` lists the edges of each group (the first one representing it).
Arrangement hand_built(std::size_t vertices, const std::vector<std::pair<std::size_t, std::size_t>>& edges,
                       std::vector<std::vector<std::size_t>> groups = {}) {
  Arrangement a;
  a.vertices.resize(vertices);
  for (const auto& [from, to] : edges) {
    ArrangementEdge e;
    e.from = from;
    e.to = to;
    a.edges.push_back(e);
  }
  if (groups.empty()) {
    for (std::size_t e = 0; e < edges.size(); ++e) groups.push_back({e});
  }
  for (std::size_t g = 0; g < groups.size(); ++g) {
    CoincidentGroup group;
    group.representative = groups[g].front();
    group.first_member = a.group_members.size();
    group.member_count = groups[g].size();
    a.group_members.insert(a.group_members.end(), groups[g].begin(), groups[g].end());
    for (const std::size_t e : groups[g]) a.edges[e].group = g;
    a.groups.push_back(group);
  }
  return a;
}

bool has_link(const std::vector<GroupLinks>& links, std::size_t g, std::size_t h,
              bool flipped) {
  for (const SideLink& l : links[g]) {
    if (l.group == h && l.flipped == flipped) return true;
  }
  return false;
}

TEST(SideLinks, AContourOfThreeEdgesLinksEachJointWithoutFlipping) {
  const auto links = side_links(hand_built(3, {{0, 1}, {1, 2}, {2, 0}}));
  ASSERT_EQ(links.size(), 3u);
  for (std::size_t g = 0; g < 3; ++g) {
    EXPECT_EQ(links[g].count, 2u);
    EXPECT_TRUE(has_link(links, g, (g + 1) % 3, false));
    EXPECT_TRUE(has_link(links, g, (g + 2) % 3, false));
  }
}

TEST(SideLinks, RepresentativesMeetingHeadToHeadOrTailToTailAreFlipped) {
  // 0 -> 1 <- 2 -> 0: at vertex 1 both arrive, at vertex 2 both leave, at vertex 0 one
  // arrives and one leaves.
  const auto links = side_links(hand_built(3, {{0, 1}, {2, 1}, {2, 0}}));
  EXPECT_TRUE(has_link(links, 0, 1, true));
  EXPECT_TRUE(has_link(links, 1, 0, true));
  EXPECT_TRUE(has_link(links, 1, 2, true));
  EXPECT_TRUE(has_link(links, 2, 0, false));
  EXPECT_TRUE(has_link(links, 0, 2, false));
}

TEST(SideLinks, ACrossingVertexLinksNothing) {
  // Two contours through vertex 0: four group ends there; vertices 1..4 have two each.
  const auto links = side_links(hand_built(5, {{0, 1}, {1, 0}, {0, 2}, {2, 0}, {3, 4}, {4, 3}}));
  EXPECT_EQ(links[0].count, 1u);  // to group 1, at vertex 1
  EXPECT_TRUE(has_link(links, 0, 1, false));
  EXPECT_EQ(links[2].count, 1u);
  EXPECT_TRUE(has_link(links, 2, 3, false));
  // Two groups between the same two vertices: linked at both (both links are the same).
  EXPECT_EQ(links[4].count, 2u);
  EXPECT_TRUE(has_link(links, 4, 5, false));
}

TEST(SideLinks, CoincidentEdgesCountAsOneEndOfTheirGroup) {
  // Edges 1 and 2 are one group (same ends, opposite directions): vertices 1 and 2 each
  // hold one end of that group and one of another.
  const auto links = side_links(hand_built(3, {{0, 1}, {1, 2}, {2, 1}, {2, 0}}, {{0}, {1, 2}, {3}}));
  EXPECT_TRUE(has_link(links, 0, 1, false));
  EXPECT_TRUE(has_link(links, 1, 2, false));
  EXPECT_TRUE(has_link(links, 2, 0, false));
}

TEST(SideLinks, ALoopOrAGroupOfDifferentEndsBlocksItsVertices) {
  // Group 1 is a loop at vertex 1: vertex 1 links nothing, vertex 0 links 0 and 2.
  const auto loop = side_links(hand_built(2, {{0, 1}, {1, 1}, {1, 0}}));
  EXPECT_EQ(loop[1].count, 0u);
  EXPECT_EQ(loop[0].count, 1u);
  EXPECT_TRUE(has_link(loop, 0, 2, false));
  // A group whose second edge joins other vertices than its representative: its vertices
  // (0, 1 and 2) link nothing; vertex 3 links the other two groups.
  const auto odd = side_links(hand_built(4, {{0, 1}, {1, 2}, {2, 3}, {3, 0}}, {{0, 1}, {2}, {3}}));
  EXPECT_EQ(odd[0].count, 0u);
  ASSERT_EQ(odd[1].count, 1u);
  EXPECT_TRUE(has_link(odd, 1, 2, false));
  ASSERT_EQ(odd[2].count, 1u);
}

TEST(SideLinks, CarriedWindingsEqualTheRaysOfEveryGroup) {
  // Overlapping and nested shapes with curves, shared edges and tangencies: for every group
  // and each of its links, the linked group's windings (a ray of its own) are the group's,
  // swapped when the link is flipped.
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"M0 0 H2 V2 H0 Z", "M1 1 H3 V3 H1 Z"},
      {"M0 0 C1 -1 3 1 4 0 C5 2 3 4 2 3 C1 4 -1 2 0 0 Z", "M1 -1 C3 -2 4 1 3 2 C2 3 0 2 1 -1 Z"},
      {"M0 0 H4 V4 H0 Z M1 1 V3 H3 V1 Z", "M2 0 H6 V4 H2 Z"},
      {"M0 0 H2 V2 H0 Z", "M2 0 H4 V2 H2 Z"},
      {"M0 0 Q2 2 4 0 Q2 -2 0 0 Z", "M2 1 Q3 0 2 -1 Q1 0 2 1 Z"},
      {"M0 0 L4 4 L4 0 L0 4 Z", "M1 0 H3 V4 H1 Z"},
  };
  int links_checked = 0;
  for (const auto& [pa, pb] : cases) {
    const path::Path a = parsed_path(pa), b = parsed_path(pb);
    core::WorkBudget search_budget(100000000);
    const Arrangement arrangement = build_arrangement(a, &b, search_budget);
    ASSERT_EQ(arrangement.status, core::IntersectStatus::ok);
    const SideWindingIndex index(arrangement);
    const auto links = side_links(arrangement);
    std::vector<SideWindings> rays;
    for (std::size_t g = 0; g < arrangement.groups.size(); ++g) {
      core::WorkBudget budget;
      const SideWindingResult r = side_windings(arrangement, index, g, budget);
      ASSERT_EQ(r.status, SideWindingStatus::ok) << pa << " / " << pb << " group " << g;
      rays.push_back(r.windings);
    }
    for (std::size_t g = 0; g < links.size(); ++g) {
      for (const SideLink& l : links[g]) {
        const SideWindings& here = rays[g];
        const SideWindings& there = rays[l.group];
        EXPECT_EQ(here.left, l.flipped ? there.right : there.left) << pa << " / " << pb << " group " << g;
        EXPECT_EQ(here.right, l.flipped ? there.left : there.right) << pa << " / " << pb << " group " << g;
        ++links_checked;
      }
    }
  }
  EXPECT_GT(links_checked, 20);
}

}  // namespace
}  // namespace bezier::region
