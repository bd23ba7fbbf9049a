#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "core/base/curve.hpp"
#include "core/base/enum_names.hpp"
#include "core/base/point.hpp"
#include "core/base/work_budget.hpp"
#include "core/intersect/result.hpp"

namespace bezier::core {

/// One self-intersection: 0 <= t < s <= 1 with B(t) = B(s). The kind is that of two-curve
/// intersections, from the cross product of the tangents B'(t) and B'(s) (kind.hpp):
/// transversal where the curve crosses itself, tangent where it touches itself, degenerate
/// where a tangent is zero (a cusp of one branch lies on the other).
struct SelfIntersection {
  double t = 0.0;
  double s = 0.0;
  /// The double point, (B(t) + B(s)) / 2.
  Point2 point;
  IntersectionKind kind = IntersectionKind::transversal;
};

enum class SelfIntersectionMethod {
  closed_form_cubic,  ///< cubic: the double point from the quadratic in t + s and t s
  subdivision,        ///< any degree: subdivision of the parameter square (see below)
  collinear,          ///< 1-D analysis of a collinear curve
};

/// The method's name as the API writes it: "closed-form-cubic", "subdivision", "collinear".
inline constexpr EnumNames<SelfIntersectionMethod::collinear> kSelfIntersectionMethodNames{
    "closed-form-cubic", "subdivision", "collinear"};

[[nodiscard]] constexpr std::string_view to_string(SelfIntersectionMethod method) noexcept {
  return kSelfIntersectionMethodNames(method);
}

/// What the search cost; for benchmarks and the API's `stats`.
struct SelfIntersectionStats {
  SelfIntersectionMethod method = SelfIntersectionMethod::subdivision;
  /// Work units the call charged (core/intersect/work_cost.hpp's unit, shared with
  /// two-curve intersection): its parameter boxes, Newton iterations, contact refinements
  /// and steps of the collinear fold, by the costs of core/self_intersect/work_cost.hpp.
  std::int64_t work = 0;
  /// Deepest subdivision level reached (boxes of width 2^-depth).
  int max_depth = 0;
  /// Newton refinements started, and their iterations in all.
  int newton_runs = 0;
  int newton_iterations = 0;
  /// Boxes left undecided at the resolution limit (tangential contacts, near misses).
  int contact_candidates = 0;
  /// Boxes next to the diagonal dropped at the resolution limit: cusps and near-cusps.
  int cusp_regions = 0;
};

struct SelfIntersectionResult {
  /// Every pair, sorted by t then s; never the trivial pair (0, 1) of a closed curve.
  std::vector<SelfIntersection> pairs;
  /// Retraced pieces, sorted by t_interval.lo then s_interval.lo:
  /// a continuum of self-intersections, B on t_interval runs over the same points as B on
  /// s_interval (t_interval.hi <= s_interval.lo), reversed when B(t_interval.lo) is nearer
  /// B(s_interval.hi) than B(s_interval.lo). Reported for collinear curves (every control
  /// point within the distance tolerance of one line), single points (both intervals
  /// [0, 1]), palindromic control points (P_i = P_{n-i}: B(1 - t) = B(t), the overlap
  /// [0, 1/2] x [1/2, 1]) and any other improper parametrisation B = C(p(t)) with p turning
  /// back (the pieces where p(t) = p(s)).
  std::vector<Overlap> overlaps;
  /// ok: every pair is in `pairs` and every retraced piece in `overlaps`, unless the
  /// caller's WorkBudget ran out (budget.exhausted(): then they hold what was found, maybe
  /// not all); work_cap_reached only from the overload without a budget, whose own budget
  /// ran out. (Never tolerance_too_small: the pairs are located to full precision.)
  IntersectStatus status = IntersectStatus::ok;
  SelfIntersectionStats stats;
};

/// Tolerances and budget. The defaults suit any input scale: the distance tolerance is
/// relative to scale(curve).
struct SelfIntersectionOptions {
  /// The budget (work units, core/self_intersect/work_cost.hpp) of self_intersections()
  /// without a WorkBudget: its own, its running out reported as status work_cap_reached. A
  /// caller with a budget passes it instead. It covers 200 000 parameter boxes at every
  /// degree up to 29, far more than a curve that does not come within rounding of
  /// retracing itself needs.
  std::int64_t max_work = 100000000;
  /// dist_tol = dist_rel * scale(curve): two points closer than this are "the same point"
  /// for tangential contacts and collinearity. 2^-44 is about 256 ulps of the largest
  /// coordinate: above the rounding of de Casteljau subdivision over ~50 levels at degree
  /// 20 (about depth * n * 2^-53), far below any geometric feature worth reporting.
  double dist_rel = 0x1p-44;
  /// Deepest subdivision level, a backstop for the flatness tests that normally stop it
  /// near level 25 (boxes of width 2^-max_depth).
  int max_depth = 48;
  /// Cubics: use the exact closed form of cubic_double_point.hpp (the general method gives
  /// the same pairs above its resolution; tests compare).
  bool cubic_closed_form = true;
};

/// Every pair 0 <= t < s <= 1 with B(t) = B(s), for any degree n >= 1.
///
/// Method (any degree): the pairs are the zeros of F(u, v) = B(v) - B(u) with u < v in the
/// parameter square, searched by subdivision. A box I x J pairs two dyadic pieces of B:
///  - I = J (diagonal): no pair inside when the piece's hodograph control vectors lie in an
///    open half-plane (B is then strictly monotone along a direction, hence injective);
///    otherwise split into two diagonal boxes and one adjacent box.
///  - I, J adjacent (sharing B(c)), and for a closed curve the pieces meeting at P_0 = P_n:
///    the same half-plane test on the union; otherwise split. These boxes contain the
///    trivial zeros of the diagonal (and cusps, where B' = 0): when they shrink below the
///    distance tolerance they are dropped, so cusps are never reported as pairs.
///  - I, J apart: discarded when a separating axis exists (their chords, the chords'
///    normals, x, y: convex hulls of the control points disjoint). When both pieces are
///    monotone and their tangent cones, taken as lines, are disjoint, the box holds at most
///    one pair (a second one would give a chord direction in both cones); Newton's method
///    on F from the chords' crossing finds it, and a result inside the box is final.
///    Otherwise split; pieces flat to within the distance tolerance that still cannot be
///    separated are tangential-contact candidates, refined by refine_self_contact.
/// Results are refined to full double precision (Newton with quadratic convergence, then
/// Newton steps on a compensated residual B(s) - B(t)), moved to exactly t = 0 or s = 1
/// when the end point satisfies B(t) = B(s) as well (a root found just outside [0, 1] that
/// does not snap is a double point off the segment, not reported), and merged when found
/// twice. Cubics take the exact closed form of cubic_double_point.hpp instead of the search
/// (unless options.cubic_closed_form is off); where its predicates are not exact (coordinates
/// spanning more than about 2^400) it is trusted only for a pair with B(t) = B(s) to within
/// the distance tolerance, and the search decides otherwise. Before the closed form, a cubic
/// shown injective by its hodograph (certainly_monotone, monotone_direction.hpp) that is not
/// collinear and lies where the closed form is exact is answered at once with what the
/// closed form would answer: nothing, method closed_form_cubic, nothing charged (the
/// argument is at certainly_loop_free_cubic in self_intersection.cpp). Curves that retrace themselves
/// get a named branch each (see SelfIntersectionResult::overlaps):
/// collinear ones a 1-D analysis, palindromic control points (B(1 - t) = B(t)) the
/// self-intersections of the outbound half and their mirror images.
///
/// Why a search of its own rather than the two-curve search (intersect/search.hpp) run on
/// the curve against itself away from the diagonal: that search narrows every box by
/// clipping with error bounds down to the search width, and switches to double-double pieces
/// where pieces run side by side (a nearly collinear curve does so everywhere); here a box
/// whose tangent cones are disjoint holds at most one pair, so one Newton run settles it, and
/// only the pairs found are certified afterwards (certify.hpp, by the two-curve search in a
/// small box around each). The diagonal, the seam and the cusps, of which the two-curve
/// search knows nothing, need the box classes above in any case. What the two share: the
/// kinds, the overlaps, the status and the certification.
///
/// Resolution: next to a cusp, |B(s) - B(t)| stays at rounding level for s - t up to about
/// 1e-5, so pairs there are accepted only when rounding could not move them onto the
/// diagonal (is_resolved_double_point); loops closer to a cusp than that (s - t below
/// roughly 1e-4, area below ~1e-18 of the curve's size) are treated as the cusp and not
/// reported. On a closed curve the seam (t, s) = (0, 1) is treated like the diagonal (with
/// s - t replaced by 1 - (s - t)): loops next to it that small count as the trivial pair.
/// The exact cubic closed form has no such limit. Distinct pairs closer than 1e-10 in both t
/// and s are merged.
/// Tangential contacts are located by refine_self_contact (to full precision when the branches'
/// curvatures differ, to about half the digits when they agree). Every stage charges `budget`
/// (core/self_intersect/work_cost.hpp, in the two-curve search's work units): a stage whose
/// next step does not fit in what is left stops, the budget is then exhausted and the lists
/// hold what was found, never a long run; stats.work is what the call charged. Other curves that
/// retrace part of themselves (improper parametrisations C(p(t)) with p not symmetric about 1/2,
/// e.g. p = (t - 1/4)^2) are factored (intersect/common_arc.hpp): their retraced pieces come
/// from p, their pairs from C's own double points. Curves within rounding of retracing
/// themselves without doing so can exhaust the budget.
///
/// The approach of classifying boxes of the (t, s) square follows the divided-difference
/// view of self-intersection (Pekerman, Elber, Kim, "Self-intersection detection and
/// elimination in freeform curves and surfaces", Computer-Aided Design 40(2), 2008); the
/// half-plane and cone criteria are the classical ones for curve pieces without loops
/// (Sederberg & Meyers 1988, "Loop detection in surface patch intersections").
/// Precondition: finite coordinates.
[[nodiscard]] SelfIntersectionResult self_intersections(const Curve& curve,
                                                        const SelfIntersectionOptions& options,
                                                        WorkBudget& budget);

/// The same with a budget of options.max_work units of its own, its running out reported
/// as status work_cap_reached.
[[nodiscard]] SelfIntersectionResult self_intersections(
    const Curve& curve, const SelfIntersectionOptions& options = {});

/// True only when self_intersections(curve, options, budget) answers nothing (no pair, no
/// overlap) and charges nothing: a cubic that self_intersections() answers at once, without
/// its closed form (see there; the argument is at certainly_loop_free_cubic in
/// self_intersection.cpp). False means "not shown". Lets a caller with many segments skip
/// the call and its result. Cost: O(1), no allocation.
[[nodiscard]] bool certainly_without_self_intersections(
    const Curve& curve, const SelfIntersectionOptions& options = {}) noexcept;

}  // namespace bezier::core
