#include "core/region/boolean.hpp"

#include <cmath>
#include <utility>

#include "core/curve/area.hpp"
#include "core/path/path_area.hpp"
#include "core/region/contour_chain.hpp"
#include "core/region/side_links.hpp"
#include "core/region/side_winding.hpp"
#include "core/region/vertex_sectors.hpp"

namespace bezier::region {

namespace {

/// Every group's side windings: a ray for the first group of each chain of groups that
/// share their sides (side_links.hpp), and from there along the chain; a group no ray
/// decides is taken from its neighbours around a vertex (vertex_sectors.hpp). ok, or why not.
BooleanStatus decide_side_windings(const Arrangement& arrangement, core::WorkBudget& budget,
                                   std::vector<SideWindings>& windings) {
  const std::size_t group_count = arrangement.groups.size();
  const SideWindingIndex index(arrangement);
  const std::vector<GroupLinks> links = side_links(arrangement);
  if (!budget.spend(static_cast<std::int64_t>(arrangement.edges.size() + group_count))) {
    return BooleanStatus::work_cap_reached;
  }
  windings.assign(group_count, SideWindings{});
  std::vector<char> known(group_count, 0);  // bytes, not bits: each read and written often
  std::vector<std::size_t> pending;
  bool undecided = false;
  for (std::size_t g = 0; g < group_count; ++g) {
    if (known[g]) continue;
    const SideWindingResult sides = side_windings(arrangement, index, g, budget);
    if (sides.status == SideWindingStatus::work_cap_reached) {
      return BooleanStatus::work_cap_reached;
    }
    if (sides.status == SideWindingStatus::unclear) {
      // Decided below from its neighbours around a vertex, if it can be.
      undecided = true;
      continue;
    }
    windings[g] = sides.windings;
    known[g] = 1;
    pending.assign(1, g);
    while (!pending.empty()) {
      const std::size_t h = pending.back();
      pending.pop_back();
      for (const SideLink& link : links[h]) {
        if (known[link.group]) continue;
        const SideWindings& w = windings[h];
        windings[link.group] = link.flipped ? SideWindings{w.right, w.left} : w;
        known[link.group] = 1;
        pending.push_back(link.group);
      }
    }
  }
  if (undecided) {
    const VertexSectorStatus around = decide_around_vertices(arrangement, windings, known, budget);
    if (around != VertexSectorStatus::ok) {
      return around == VertexSectorStatus::work_cap_reached ? BooleanStatus::work_cap_reached
                                                            : BooleanStatus::unresolved;
    }
  }
  return BooleanStatus::ok;
}

BooleanResult run(BooleanOperation op, const Region& a, const Region* b, core::WorkBudget& budget) {
  BooleanResult result;
  const std::int64_t spent_before = budget.spent();
  // Not const: once every side is decided, a kept group's representative gives its piece
  // to the result (below).
  Arrangement arrangement = build_arrangement(a.path, b != nullptr ? &b->path : nullptr, budget);
  result.work = arrangement.work;
  if (arrangement.status != core::IntersectStatus::ok) {
    result.status = BooleanStatus::work_cap_reached;
    return result;
  }
  const FillRule rule_b = b != nullptr ? b->fill_rule : FillRule::nonzero;
  const auto inside = [&](const std::array<int, 2>& w) {
    return keeps(op, fills(a.fill_rule, w[0]), fills(rule_b, w[1]));
  };

  std::vector<SideWindings> windings;
  const BooleanStatus decided = decide_side_windings(arrangement, budget, windings);
  if (decided != BooleanStatus::ok) {
    result.work = budget.spent() - spent_before;
    result.status = decided;
    return result;
  }
  const std::size_t group_count = arrangement.groups.size();
  std::vector<DirectedEdge> kept;
  std::vector<char> kept_reversed;  // bytes, not bits
  kept.reserve(group_count);
  kept_reversed.reserve(group_count);
  for (std::size_t g = 0; g < group_count; ++g) {
    const bool left = inside(windings[g].left);
    const bool right = inside(windings[g].right);
    if (left == right) continue;
    const std::size_t e = arrangement.groups[g].representative;
    ArrangementEdge& edge = arrangement.edges[e];
    if (left) {
      // Each group is looked at once here and its representative's piece is not read again
      // (the result takes only its source and parameters), so the piece moves (reversed in
      // its own storage when it runs the other way).
      kept.emplace_back(edge.from, edge.to, std::move(edge.piece), e);
    } else {
      kept.emplace_back(edge.to, edge.from, core::reversed(std::move(edge.piece)), e);
    }
    kept_reversed.push_back(left ? 0 : 1);
  }
  if (!budget.spend(static_cast<std::int64_t>(kept.size()) * 16)) {
    result.work = budget.spent() - spent_before;
    result.status = BooleanStatus::work_cap_reached;
    return result;
  }
  const auto chains = chain_contours(kept, arrangement.vertices.size());
  result.work = budget.spent() - spent_before;
  if (!chains) {
    result.status = BooleanStatus::unresolved;
    return result;
  }
  const double zero_area = 0x1p-80 * arrangement.scale * arrangement.scale;
  std::vector<const core::Curve*> contour_curves;
  contour_curves.reserve(kept.size());  // a contour holds at most every kept edge
  result.segments.reserve(kept.size());
  result.contours.reserve(chains->size());
  for (const std::vector<std::size_t>& chain : *chains) {
    contour_curves.clear();
    for (std::size_t k : chain) contour_curves.push_back(&kept[k].curve);
    const double area = path::closed_chain_area(contour_curves);
    if (!(std::fabs(area) > zero_area)) continue;
    ResultContour contour;
    contour.first_segment = result.segments.size();
    for (std::size_t k : chain) {
      const ArrangementEdge& edge = arrangement.edges[kept[k].tag];
      const bool backwards = kept_reversed[k] != 0;
      // Each kept edge is in one chain only: its curve moves to the result (built in place,
      // not through a temporary moved twice).
      result.segments.emplace_back(edge.source, edge.segment, backwards ? edge.t1 : edge.t0,
                                   backwards ? edge.t0 : edge.t1, std::move(kept[k].curve));
    }
    contour.end_segment = result.segments.size();
    contour.area = area;
    result.area += area;
    result.contours.push_back(contour);
  }
  return result;
}

}  // namespace

BooleanResult boolean_operation(BooleanOperation op, const Region& a, const Region& b,
                                core::WorkBudget& budget) {
  return run(op, a, op == BooleanOperation::simplify ? nullptr : &b, budget);
}

BooleanResult simplify(const Region& a, core::WorkBudget& budget) {
  return run(BooleanOperation::simplify, a, nullptr, budget);
}

BooleanResult boolean_operation(BooleanOperation op, const Region& a, const Region& b,
                                std::int64_t max_work) {
  core::WorkBudget budget(max_work);
  return boolean_operation(op, a, b, budget);
}

BooleanResult simplify(const Region& a, std::int64_t max_work) {
  core::WorkBudget budget(max_work);
  return simplify(a, budget);
}

}  // namespace bezier::region
