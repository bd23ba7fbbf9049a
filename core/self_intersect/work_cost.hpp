#pragma once

#include <cstdint>

namespace bezier::core {

// What the self-intersection search charges its WorkBudget, in the work units of the
// two-curve search (core/intersect/work_cost.hpp: about one coordinate update of de
// Casteljau's algorithm in doubles, the multipliers fitted so that spent units are
// proportional to time), so that one request's budget, and the `work` it reports, are in
// one unit whichever search ran.

/// One parameter box of a degree-n curve: a fixed part (the stack, the arena copies,
/// classifying the box) and the halving of two pieces, (n + 1)^2 point updates in all;
/// measured (BENCHMARKS.md, "Worst requests at the default limits") on the costliest curves
/// known per box: a degenerate degree-12 curve whose last nine control points coincide (a
/// Newton run in most boxes next to the diagonal) and curves with many double points, so
/// that a unit costs about the time it costs in the two-curve search.
[[nodiscard]] constexpr std::int64_t self_intersection_box_cost(int n) noexcept {
  const std::int64_t a = n + 1;
  return 24 + a * a / 2;
}

/// One Newton iteration of the search (refine_double_point): the curve with its first two
/// derivatives at both parameters, one de Casteljau pass each, about what halving the box's
/// two pieces costs: charged as one box.
[[nodiscard]] constexpr std::int64_t self_intersection_newton_cost(int n) noexcept {
  return self_intersection_box_cost(n);
}

/// One contact refinement (a Newton run on F, then on the tangency system, up to about 60
/// iterations of one jet each at both parameters): about what 8 boxes cost.
inline constexpr std::int64_t kContactRefinementBoxes = 8;

[[nodiscard]] constexpr std::int64_t contact_refinement_cost(int n) noexcept {
  return kContactRefinementBoxes * self_intersection_box_cost(n);
}

/// Grouping the contact boxes into clusters compares each box with the clusters before it
/// (four comparisons of doubles each): 64 comparisons cost about one box.
inline constexpr std::int64_t kClusterComparisonsPerBox = 64;

/// What `comparisons` comparisons of the clustering cost, in whole boxes.
[[nodiscard]] constexpr std::int64_t cluster_cost(std::int64_t comparisons, int n) noexcept {
  return comparisons / kClusterComparisonsPerBox * self_intersection_box_cost(n);
}

/// The most comparisons of the clustering that `units` work units pay for.
[[nodiscard]] constexpr std::int64_t affordable_cluster_comparisons(std::int64_t units,
                                                                    int n) noexcept {
  return units > 0 ? units / self_intersection_box_cost(n) * kClusterComparisonsPerBox : 0;
}

/// One step of the collinear fold (collinear_fold.hpp): the halving of x', n coefficients,
/// with its two sign passes and the two rows it allocates. The allocations and the fixed
/// part dominate at the API's degrees: charged as one box.
[[nodiscard]] constexpr std::int64_t collinear_fold_step_cost(int n) noexcept {
  return self_intersection_box_cost(n);
}

}  // namespace bezier::core
