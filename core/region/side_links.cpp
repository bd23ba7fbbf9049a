#include "core/region/side_links.hpp"

#include <array>

namespace bezier::region {

namespace {

/// The group ends at one vertex: how many, and the first two (group, whether its
/// representative arrives there); blocked where a group there is not a plain arc.
struct VertexEnds {
  int count = 0;
  std::array<std::size_t, 2> group{0, 0};
  std::array<bool, 2> arrives{false, false};
  bool blocked = false;

  void add(std::size_t g, bool arriving) {
    if (count < 2) {
      group[static_cast<std::size_t>(count)] = g;
      arrives[static_cast<std::size_t>(count)] = arriving;
    }
    ++count;
  }
};

}  // namespace

std::vector<GroupLinks> side_links(const Arrangement& arrangement) {
  std::vector<VertexEnds> at(arrangement.vertices.size());
  for (std::size_t g = 0; g < arrangement.groups.size(); ++g) {
    const CoincidentGroup& group = arrangement.groups[g];
    const ArrangementEdge& rep = arrangement.edges[group.representative];
    bool arc = rep.from != rep.to;
    // A group of one edge is its representative, whose ends are its own.
    if (group.member_count > 1) {
      for (const std::size_t e : arrangement.group_edges(g)) {
        const ArrangementEdge& edge = arrangement.edges[e];
        const bool same_ends = (edge.from == rep.from && edge.to == rep.to) ||
                               (edge.from == rep.to && edge.to == rep.from);
        arc = arc && same_ends;
      }
    }
    if (!arc) {
      for (const std::size_t e : arrangement.group_edges(g)) {
        at[arrangement.edges[e].from].blocked = true;
        at[arrangement.edges[e].to].blocked = true;
      }
      continue;
    }
    at[rep.from].add(g, false);
    at[rep.to].add(g, true);
  }
  std::vector<GroupLinks> links(arrangement.groups.size());
  const auto add = [&](std::size_t g, SideLink l) {
    GroupLinks& to = links[g];
    to.link[to.count++] = l;  // one end of g at each of its two vertices: at most two
  };
  for (const VertexEnds& v : at) {
    if (v.blocked || v.count != 2 || v.group[0] == v.group[1]) continue;
    const bool flipped = v.arrives[0] == v.arrives[1];
    add(v.group[0], {v.group[1], flipped});
    add(v.group[1], {v.group[0], flipped});
  }
  return links;
}

}  // namespace bezier::region
