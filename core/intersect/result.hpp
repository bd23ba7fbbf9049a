#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "core/base/enum_names.hpp"
#include "core/base/interval.hpp"
#include "core/base/point.hpp"

namespace bezier::core {

/// How two curves meet at an intersection, from the cross product of their derivatives
/// (the usual definition: transversal where it is nonzero), judged relative to the curves (see kind.hpp for the thresholds).
enum class IntersectionKind {
  transversal,  ///< f'(t) x g'(s) != 0: the curves cross at a nonzero angle
  tangent,      ///< f'(t) x g'(s) = 0 with both derivatives nonzero: they touch (or cross
                ///< tangentially, e.g. with equal curvature)
  degenerate,   ///< f'(t) = 0 or g'(s) = 0 (a cusp, a zero end derivative, a point curve)
};

/// "transversal", "tangent", "degenerate".
inline constexpr EnumNames<IntersectionKind::degenerate> kIntersectionKindNames{
    "transversal", "tangent", "degenerate"};

[[nodiscard]] constexpr std::string_view to_string(IntersectionKind kind) noexcept {
  return kIntersectionKindNames(kind);
}

/// One intersection (one contact: a tangency is reported once, never as a cloud).
///
/// Contract: every (t*, s*) in [0,1]^2 with f(t*) = g(s*) that is not part of an overlap
/// lies in the t_interval x s_interval of some reported Intersection. The intervals are
/// narrower than the requested tolerance whenever `resolved` is true; (t, s) is the best
/// estimate (Newton's method with double-double residuals, or an exact end point), always
/// inside the intervals.
struct Intersection {
  double t = 0.0;  ///< best estimate of the parameter on the first curve
  double s = 0.0;  ///< best estimate of the parameter on the second curve
  ParamInterval t_interval;
  ParamInterval s_interval;
  Point2 point;  ///< (f(t) + g(s)) / 2
  IntersectionKind kind = IntersectionKind::transversal;
  /// False when rounding did not let the intervals shrink below the tolerance (contacts of
  /// order >= 3, such as two curves with the same tangent and curvature): the intervals
  /// still contain the intersection.
  bool resolved = true;
};

/// Coincident pieces: f on t_interval and g on s_interval are the same point set (to within
/// the overlap tolerance, see overlap.hpp). The end points correspond: f(t_interval.lo) =
/// g(s_interval.lo) unless `reversed`, in which case f(t_interval.lo) = g(s_interval.hi).
struct Overlap {
  ParamInterval t_interval;
  ParamInterval s_interval;
  bool reversed = false;
};

/// Which algorithm ran (see options.hpp).
enum class IntersectMethod {
  hybrid,           ///< fat line + fat curve from L2 degree reduction (default)
  bezier_clipping,  ///< Sederberg–Nishita 1990: fat line vs convex hull of the distance curve
  subdivision,      ///< halving both domains, bounding boxes
};

/// "hybrid", "bezier-clipping", "subdivision" (the API spelling).
inline constexpr EnumNames<IntersectMethod::subdivision> kIntersectMethodNames{
    "hybrid", "bezier-clipping", "subdivision"};

[[nodiscard]] constexpr std::string_view to_string(IntersectMethod method) noexcept {
  return kIntersectMethodNames(method);
}

/// The outcome of a call.
enum class IntersectStatus {
  ok,                   ///< every intersection and overlap is reported
  work_cap_reached,     ///< the work budget ran out: the result is incomplete (the API answers 422)
  tolerance_too_small,  ///< the requested tolerance is below what doubles resolve (API: 422)
};

/// What the search cost, so methods can be compared.
struct IntersectStats {
  IntersectMethod method = IntersectMethod::hybrid;
  std::int64_t iterations = 0;         ///< box steps taken
  std::int64_t work = 0;               ///< work units spent (the budget's unit, work_cost.hpp)
  std::int64_t clipping_steps = 0;     ///< clips of one curve against the other's fat line
  std::int64_t subdivisions = 0;       ///< boxes split in halves
  std::int64_t candidate_boxes = 0;    ///< boxes that converged (or hit the precision floor)
  std::int64_t compensated_steps = 0;  ///< steps computed in double-double pieces (near tangencies)
  std::int64_t newton_iterations = 0;  ///< Newton iterations in the final refinement
  int max_depth = 0;                   ///< deepest box (clips + halvings from [0,1]^2)
};

/// Every intersection of two curves (sorted by t, then s), every overlap (sorted by t),
/// what it cost, and whether it is complete.
struct IntersectionResult {
  std::vector<Intersection> intersections;
  std::vector<Overlap> overlaps;
  IntersectStats stats;
  IntersectStatus status = IntersectStatus::ok;
};

}  // namespace bezier::core
