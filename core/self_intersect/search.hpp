#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/base/point.hpp"
#include "core/base/work_budget.hpp"
#include "core/self_intersect/self_intersection.hpp"
#include "core/self_intersect/refine.hpp"

namespace bezier::core {

/// Settings of one search; self_intersections() derives them from SelfIntersectionOptions.
struct SelfIntersectionSearchSettings {
  /// Geometric tolerance in input units (dist_rel * scale).
  double dist_tol = 0.0;
  /// Rounding level of F = B(v) - B(u) in input units: a Newton root whose
  /// is_resolved_double_point fails at this level is noise near a cusp.
  double rounding = 0.0;
  int max_depth = 0;
  /// P_0 = P_n: the pieces meeting at t = 0 and t = 1 are neighbours (the "seam").
  bool closed = false;
};

/// Raw output of the subdivision, before ends are snapped and duplicates merged.
struct SelfIntersectionSearchOutcome {
  /// Newton results that converged inside a box whose pieces have disjoint tangent cones.
  std::vector<PairRefinement> crossings;
  /// Boxes u x v that could neither be discarded nor resolved before
  /// both pieces became flat to within dist_tol: tangential contacts or near misses.
  std::vector<ParameterBox> contact_boxes;
  /// stats.work: the work units the search charged.
  SelfIntersectionStats stats;
};

/// The subdivision of the (u, v) parameter square described at self_intersections():
/// classifies boxes of pairs of dyadic pieces as diagonal, adjacent, seam or apart,
/// discards them by half-plane and separating-axis tests, runs Newton where the tangent
/// cones prove a box holds at most one pair, and returns the rest as contact candidates.
/// Each box is charged self_intersection_box_cost(n) to `budget` before it is examined, each
/// Newton iteration self_intersection_newton_cost(n) (work_cost.hpp); a box that does not
/// fit in what is left is not examined: the budget is then exhausted and the outcome holds
/// what was found. Precondition: points.size() >= 2, finite.
[[nodiscard]] SelfIntersectionSearchOutcome search_self_intersections(
    std::span<const Point2> points, const SelfIntersectionSearchSettings& settings,
    WorkBudget& budget);

}  // namespace bezier::core
