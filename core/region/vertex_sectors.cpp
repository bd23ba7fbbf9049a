#include "core/region/vertex_sectors.hpp"

#include <algorithm>
#include <array>
#include <cstdint>

#include "core/region/edge_germ.hpp"

namespace bezier::region {

namespace {

/// One end of a group's representative at a vertex.
struct GroupEnd {
  std::size_t group = 0;
  bool leaves = true;  ///< the representative starts at the vertex (else it ends there)
  EdgeGerm germ;
  double angle = 0.0;  ///< counter-clockwise from the vertex's first germ
};

std::array<int, 2> plus(const std::array<int, 2>& w, const std::array<int, 2>& m, int sign) {
  return {w[0] + sign * m[0], w[1] + sign * m[1]};
}

}  // namespace

VertexSectorStatus decide_around_vertices(const Arrangement& arrangement,
                                          std::vector<SideWindings>& windings,
                                          std::vector<char>& known, core::WorkBudget& budget) {
  const std::size_t vertex_count = arrangement.vertices.size();
  std::vector<std::vector<GroupEnd>> around(vertex_count);
  std::vector<bool> usable(vertex_count, true);
  for (std::size_t g = 0; g < arrangement.groups.size(); ++g) {
    const CoincidentGroup& group = arrangement.groups[g];
    const ArrangementEdge& rep = arrangement.edges[group.representative];
    for (const std::size_t e : arrangement.group_edges(g)) {
      const ArrangementEdge& x = arrangement.edges[e];
      const bool same_ends = (x.from == rep.from && x.to == rep.to) ||
                             (x.from == rep.to && x.to == rep.from);
      if (!same_ends) {
        usable[x.from] = false;
        usable[x.to] = false;
      }
    }
    around[rep.from].push_back({g, true, germ_at_start(rep.piece), 0.0});
    around[rep.to].push_back({g, false, germ_at_start(core::reversed(rep.piece)), 0.0});
  }
  std::int64_t ends = 0;
  for (std::vector<GroupEnd>& list : around) {
    ends += static_cast<std::int64_t>(list.size());
    if (list.size() < 2) continue;
    const EdgeGerm first = list.front().germ;
    for (GroupEnd& end : list) end.angle = ccw_angle(first, end.germ);
    std::stable_sort(list.begin(), list.end(),
                     [](const GroupEnd& p, const GroupEnd& q) { return p.angle < q.angle; });
  }
  // A germ that ties with a neighbour has no decided place in the order: no sector of it is
  // used.
  std::vector<std::vector<bool>> tied(vertex_count);
  for (std::size_t v = 0; v < vertex_count; ++v) {
    const std::vector<GroupEnd>& list = around[v];
    const std::size_t n = list.size();
    tied[v].assign(n, false);
    if (n < 2) continue;
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t next = (k + 1) % n;
      if (ccw_angle(list[k].germ, list[next].germ) == 0.0 ||
          ccw_angle(list[next].germ, list[k].germ) == 0.0) {
        tied[v][k] = true;
        tied[v][next] = true;
      }
    }
  }
  const auto mult = [&](std::size_t g) { return arrangement.groups[g].multiplicity; };
  bool changed = true;
  while (changed) {
    if (!budget.spend(ends + 1)) return VertexSectorStatus::work_cap_reached;
    changed = false;
    for (std::size_t v = 0; v < vertex_count; ++v) {
      const std::vector<GroupEnd>& list = around[v];
      if (!usable[v] || list.size() < 2) continue;
      for (std::size_t k = 0; k < list.size(); ++k) {
        const std::size_t next = (k + 1) % list.size();
        const GroupEnd& a = list[k];     // the sector's clockwise bound
        const GroupEnd& b = list[next];  // its counter-clockwise bound
        if (known[a.group] == known[b.group]) continue;
        if (tied[v][k] || tied[v][next]) continue;
        if (known[a.group]) {
          const SideWindings& w = windings[a.group];
          const std::array<int, 2> face = a.leaves ? w.left : w.right;
          SideWindings& x = windings[b.group];
          if (b.leaves) {
            x.right = face;
            x.left = plus(face, mult(b.group), 1);
          } else {
            x.left = face;
            x.right = plus(face, mult(b.group), -1);
          }
          known[b.group] = 1;
        } else {
          const SideWindings& w = windings[b.group];
          const std::array<int, 2> face = b.leaves ? w.right : w.left;
          SideWindings& x = windings[a.group];
          if (a.leaves) {
            x.left = face;
            x.right = plus(face, mult(a.group), -1);
          } else {
            x.right = face;
            x.left = plus(face, mult(a.group), 1);
          }
          known[a.group] = 1;
        }
        changed = true;
      }
    }
  }
  for (std::size_t g = 0; g < known.size(); ++g) {
    if (known[g]) continue;
    // A group whose edges cancel (multiplicity 0 for both operands: a piece and its retrace)
    // changes no winding number: its two sides are one face, so no operation keeps it and no
    // other group needs its windings any more. Equal sides say so.
    const std::array<int, 2>& m = arrangement.groups[g].multiplicity;
    if (m[0] != 0 || m[1] != 0) return VertexSectorStatus::undecided;
    windings[g] = SideWindings{};
  }
  return VertexSectorStatus::ok;
}

}  // namespace bezier::region
