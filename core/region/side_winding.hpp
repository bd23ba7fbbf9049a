#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/base/work_budget.hpp"
#include "core/region/arrangement.hpp"
#include "core/region/edge_box_index.hpp"

namespace bezier::region {

/// The winding numbers of both operands just left and just right of a coincident group (left
/// of its representative edge's direction).
struct SideWindings {
  std::array<int, 2> left{0, 0};
  std::array<int, 2> right{0, 0};
};

/// What side_windings found.
enum class SideWindingStatus { ok, unclear, work_cap_reached };

struct SideWindingResult {
  SideWindings windings;
  SideWindingStatus status = SideWindingStatus::ok;
};

/// What side_windings shares between the groups of one arrangement.
struct SideWindingIndex {
  /// Rays skip the edges whose boxes show they cannot matter only while the scale is below
  /// 2^1000: then no difference or product of coordinates overflows.
  static constexpr double kPruneScaleLimit = 0x1p1000;

  /// Rays that scan the edges' boxes in turn before the hierarchy is built. A scan tests
  /// the boxes of blocks of kBlockEdges consecutive edges and then the edges' own boxes in
  /// the blocks that pass (consecutive edges follow their path, so a block's box stays near
  /// its edges); building the hierarchy sorts the boxes (O(E log E), a few dozen box
  /// operations per edge), after which a ray visits about log E nodes plus those near it.
  /// Most operations cast only a few rays (one per chain of linked groups, side_links.hpp),
  /// which the scan serves for less than the build; an operation that casts more builds it
  /// once.
  static constexpr std::size_t kLinearScanRays = 16;
  static constexpr std::size_t kBlockEdges = 8;

  explicit SideWindingIndex(const Arrangement& arrangement);

  /// Appends to `out`, in increasing order, every edge whose box passes
  /// `may_meet(const EdgeBox&)` (every edge when the scale is beyond kPruneScaleLimit): by
  /// a scan of the boxes for the first kLinearScanRays calls, then through the hierarchy
  /// (both report the same edges as testing every edge's box: a box that fails a test
  /// monotone in its corners fails with every box holding it, so an edge in a block or node
  /// whose box fails fails too). Not thread-safe: it builds the hierarchy on first need.
  template <class MayMeet>
  void collect(const MayMeet& may_meet, std::vector<std::size_t>& out) const;

  /// The edges' boxes, edge e's at index e (control_point_box of its piece).
  std::vector<EdgeBox> boxes;
  /// block_boxes[b]: the smallest box holding those of edges b * kBlockEdges up to
  /// (b + 1) * kBlockEdges - 1 (fewer in the last block).
  std::vector<EdgeBox> block_boxes;
  /// The hierarchy over `boxes`, once built.
  mutable std::optional<EdgeBoxIndex> hierarchy;
  /// How many times collect has been called.
  mutable std::size_t rays = 0;
  /// pass_cost_before[e]: the work of the first control-point pass of edges 0 .. e - 1, the
  /// sum of their (n + 1).
  std::vector<std::int64_t> pass_cost_before;
  bool prune = true;
};

template <class MayMeet>
void SideWindingIndex::collect(const MayMeet& may_meet, std::vector<std::size_t>& out) const {
  const std::size_t first = out.size();
  if (rays++ < kLinearScanRays) {
    for (std::size_t b = 0; b < block_boxes.size(); ++b) {
      if (prune && !may_meet(block_boxes[b])) continue;
      const std::size_t end = std::min(boxes.size(), (b + 1) * kBlockEdges);
      for (std::size_t e = b * kBlockEdges; e < end; ++e) {
        if (!prune || may_meet(boxes[e])) out.push_back(e);
      }
    }
    return;
  }
  if (!hierarchy) hierarchy.emplace(boxes);
  hierarchy->collect([&](const EdgeBox& box) { return !prune || may_meet(box); }, out);
  std::sort(out.begin() + static_cast<std::ptrdiff_t>(first), out.end());
}

/// Each operand's winding number on both sides of group g, by a ray from the middle m of the
/// representative edge (its exact piece at t = 1/2; at a cusp there, or where the piece moves
/// too slowly for its tangent to be known, at the first of a few other parameters where it
/// does not, since a cusp's two branches leave it on one side) into its left side.
///
/// The winding number of a closed path about a point p is the signed count of the path's
/// crossings of any half-line from p: +1 where the path crosses it from right to left
/// (cross(d, B'(t)) > 0 for the ray direction d). The arrangement's edges meet only at
/// vertices and coincide only inside a group, so the ray from m meets no edge at m except
/// those of g. Its crossings with the other edges give each operand's winding just left of g
/// (the open half-line counts the point m + eps d for small eps); the representative's own
/// crossings away from m count once for every edge of g (they are the same point set),
/// signed by the multiplicity; the right side differs by the multiplicity (crossing g from
/// right to left adds it).
///
/// Counting crossings of one edge: the edge's control points give c_i = cross(d, P_i - m)
/// (the signed distance to the ray's line, in Bernstein form) and r_i = dot(d, P_i - m)
/// (the position along it). No crossing when all c_i have one sign or every r_i < 0; one
/// crossing, signed by c_n - c_0, when the c_i are monotone with c_0, c_n of opposite signs
/// and every r_i > 0; otherwise the edge is halved (de Casteljau) and both halves counted.
/// A ray is unclear, and the next direction is tried, when it passes within
/// kRayClearanceRel * scale of a vertex or of its origin, or a piece stays undecided after
/// kRayMaxDepth halvings (a tangency to the ray). Directions: the left normal of the
/// representative at m, then turned by fixed angles up to +-1.4 radians (still on the left).
/// When the piece left undecided at the deepest halving has every control point within
/// twice the clearance of m, the edge passes that close to m and every direction would meet
/// it there: the group is unclear at once (boolean.cpp then decides it around its vertices,
/// vertex_sectors.hpp).
/// Each control-point pass is charged (n + 1) units and each halving (n + 1)^2, each by
/// budget.spend (work_cap_reached once the spent work passes the limit).
///
/// The edges are counted in their order in the arrangement, stopping at the first unclear
/// one. An edge whose control-point box shows at once that it neither crosses the ray nor
/// comes near it (`index`) is not looked at, but its first pass is still charged: the
/// answer, the work and where the cap is met are those of counting every edge.
[[nodiscard]] SideWindingResult side_windings(const Arrangement& arrangement,
                                              const SideWindingIndex& index, std::size_t group,
                                              core::WorkBudget& budget);

}  // namespace bezier::region
