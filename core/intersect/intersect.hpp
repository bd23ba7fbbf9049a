#pragma once

#include "core/base/curve.hpp"
#include "core/base/work_budget.hpp"
#include "core/intersect/options.hpp"
#include "core/intersect/result.hpp"

namespace bezier::core {

/// Every intersection of two planar Bézier curves f and g of any degrees n, m >= 1 (also 0:
/// a single point), over (t, s) in [0,1]^2.
///
/// Result: each intersection as intervals t_interval x s_interval, narrower than
/// options.tolerance, that certainly contain it (see Intersection for the contract and
/// `resolved`), with a best estimate (t, s) refined to full double precision, the point and
/// the kind; every overlap (coincident pieces) as an interval pair instead of points.
/// Intersections are sorted by t then s, overlaps by t. A tangency or any other contact is
/// reported once. Every phase charges `budget` (work_cost.hpp); when it runs out
/// (budget.exhausted()) the lists hold what was found, maybe not all. stats.work is what
/// the call charged. Status tolerance_too_small when options.tolerance is below
/// kMinTolerance (nothing is computed).
///
/// Method (options.method; see search.hpp): hybrid clipping with fat lines and fat curves
/// of degree options.fat_curve_degree (default), Bézier clipping (Sederberg & Nishita 1990)
/// or subdivision. All three share everything else:
///  1. The curves move to a working frame (working_curve.hpp): translated to the centre of
///     their bounding box and scaled by a power of two, held exactly as double-doubles, so
///     translations and power-of-two scalings of the input give the same parameters.
///  2. Degenerate input first: two single points; a single point against a curve (its
///     parameter is free: the interval is [0, 1], the estimate 0, the kind degenerate);
///     two curves on one common line (collinear.hpp: 1-D overlaps and touching points).
///  3. Overlaps by linear reparametrisation (overlap.hpp); the search then skips their
///     diagonals.
///  4. End points equal bit for bit are exact roots (zero-width intervals).
///  5. The search narrows boxes of the parameter square with rigorous error bounds, so no
///     root is lost to rounding; near tangencies it switches to double-double pieces.
///     A contact of order >= 3 at rational parameters is certified exactly with a box in
///     which it is the only solution (high_order_contact.hpp), and the search drops the
///     boxes inside it; the contact is an exact root when its parameters are doubles.
///  6. Touching boxes merge into one contact (merge.hpp); Newton's method with double-double
///     residuals, or on the tangency system, refines each (refine.hpp); the kind comes from
///     the derivatives there (kind.hpp).
/// Precondition: finite coordinates (api/ validates them).
[[nodiscard]] IntersectionResult intersect(const Curve& f, const Curve& g,
                                           const IntersectOptions& options, WorkBudget& budget);

/// The same with a budget of options.max_work units of its own, its running out reported
/// as status work_cap_reached.
[[nodiscard]] IntersectionResult intersect(const Curve& f, const Curve& g,
                                           const IntersectOptions& options = {});

/// The same, restricted to t in t_range and s in s_range (closed sub-intervals of [0, 1];
/// parameters stay those of the whole curves). Used to put guaranteed intervals around a
/// known intersection, e.g. the self-intersections of one curve (f = g, with boxes away
/// from the diagonal t = s). Overlaps are still reported whole.
[[nodiscard]] IntersectionResult intersect_in(const Curve& f, const Curve& g, ParamInterval t_range,
                                              ParamInterval s_range,
                                              const IntersectOptions& options, WorkBudget& budget);

}  // namespace bezier::core
