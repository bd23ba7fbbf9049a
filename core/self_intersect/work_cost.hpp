#pragma once

#include <cstdint>

namespace bezier::core {

// The self-intersection search counts its budget in parameter boxes
// (SelfIntersectionOptions::max_work). A request's budget is in work units
// (core/intersect/work_cost.hpp: about one coordinate update of de Casteljau in doubles),
// shared with the two-curve search; these convert one into the other, so that a cap in
// units bounds time whatever the degree.

/// Work units per parameter box of a degree-n curve: a fixed part (the stack, the arena
/// copies, classifying the box) and the halving of two pieces, (n + 1)^2 point updates in
/// all, with the Newton runs that come with the boxes (each iteration is charged as one
/// more box); measured (BENCHMARKS.md, "Worst requests at the default limits") on the costliest curves known per box: a
/// degenerate degree-12 curve whose last nine control points coincide (a Newton run in
/// most boxes next to the diagonal) and curves with many double points.
[[nodiscard]] constexpr std::int64_t self_intersection_box_cost(int n) noexcept {
  const std::int64_t a = n + 1;
  return 24 + a * a / 2;
}

/// The contact stage, in parameter boxes: a refinement takes up to about 60 Newton steps,
/// about what 8 boxes cost; 64 comparisons of contact boxes while clustering them cost one
/// box.
inline constexpr std::int64_t kContactRefinementWork = 8;
inline constexpr std::int64_t kClusterComparisonsPerWork = 64;

/// The parameter boxes a budget of `units` work units buys for a degree-n curve.
[[nodiscard]] constexpr std::int64_t self_intersection_box_budget(std::int64_t units,
                                                                  int n) noexcept {
  return units > 0 ? units / self_intersection_box_cost(n) : 0;
}

}  // namespace bezier::core
