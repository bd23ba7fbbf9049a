#pragma once

#include <optional>
#include <vector>

#include "core/base/curve.hpp"
#include "core/base/point.hpp"
#include "core/base/work_budget.hpp"
#include "core/self_intersect/self_intersection.hpp"

namespace bezier::core {

/// One loop of a curve: the closed sub-curve B on [t1, t2] between the two parameters of a
/// self-intersection (B(t1) = B(t2)).
struct Loop {
  double t1 = 0.0;
  double t2 = 0.0;
  /// The double point where the loop closes.
  Point2 point;
  /// |signed_area|, in squared input units.
  double area = 0.0;
  /// 1/2 ∮ (x dy - y dx) over B on [t1, t2]: positive when the loop runs counter-clockwise
  /// (y up). Exact Bernstein form (enclosed_area); the chord B(t2) -> B(t1) has zero length.
  double signed_area = 0.0;
  IntersectionKind kind = IntersectionKind::transversal;
};

struct LoopAreaResult {
  /// One loop per self-intersection pair, in the order of self_intersections() (by t1).
  /// A loop containing another (nested pairs t1 < t3 < t4 < t2) counts the inner region
  /// with its winding number, as Green's theorem does.
  std::vector<Loop> loops;
  /// Σ loop.area over `loops`.
  double area = 0.0;
  /// P_0 = P_n exactly.
  bool closed = false;
  /// The whole closed curve's signed area (closed_area()); nullopt when not closed.
  std::optional<double> closed_area;
  /// Pieces the curve retraces (collinear curves, palindromic control points): they
  /// enclose no area. The loops of a palindromic curve are still listed.
  std::vector<Overlap> overlaps;
  /// ok, or work_cap_reached from the overload without a budget (self_intersections()).
  IntersectStatus status = IntersectStatus::ok;
  SelfIntersectionStats stats;
};

/// Every loop of B (any degree n >= 1) with its area, and the closed curve's area: the
/// pairs of self_intersections(curve, options, budget), each loop's area by
/// enclosed_area(curve, t1, t2), closed and closed_area by is_closed() and closed_area(). A
/// closed curve's trivial pair (0, 1) is not a loop: its area is closed_area. The search
/// charges `budget` (the areas are closed forms, bounded by the degree); when it runs out
/// (budget.exhausted()) the loops found so far are listed but may be incomplete.
/// stats.work is what the call charged. Precondition: finite coordinates.
[[nodiscard]] LoopAreaResult loop_area(const Curve& curve, const SelfIntersectionOptions& options,
                                       WorkBudget& budget);

/// The same with a budget of options.max_work units of its own, its running out reported
/// as status work_cap_reached.
[[nodiscard]] LoopAreaResult loop_area(const Curve& curve,
                                       const SelfIntersectionOptions& options = {});

}  // namespace bezier::core
