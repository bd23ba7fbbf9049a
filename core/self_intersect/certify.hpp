#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/base/curve.hpp"
#include "core/base/work_budget.hpp"
#include "core/intersect/options.hpp"
#include "core/intersect/result.hpp"
#include "core/self_intersect/self_intersection.hpp"

namespace bezier::core {

/// Self-intersections as two-curve intersections: each with guaranteed intervals, or
/// reported as found.
struct CertifiedSelfIntersections {
  /// One per pair, in the pairs' order.
  std::vector<Intersection> intersections;
  std::int64_t work = 0;   ///< work units charged (core/intersect/work_cost.hpp)
  std::int64_t steps = 0;  ///< search steps taken
  /// Pairs reported as found for want of work units (none left, or their search ran out):
  /// with a larger budget they might have been certified.
  std::size_t uncertified = 0;
};

/// Puts guaranteed intervals around the self-intersections `pairs` of `curve` (as
/// self_intersections() found them): the curve against itself by intersect_in(), in a box
/// of half-width min(2^-20, (s - t) / 4) around (t, s), which stays away from the diagonal
/// t = s where every point is a trivial solution. When the box holds exactly one
/// intersection, its intervals and estimate are reported (options.tolerance bounds their
/// width); otherwise the pair is reported as found, with point intervals, `resolved` false.
/// The pairs' searches charge `budget` in order; a pair reached with no work unit left, or
/// whose search runs out, is reported as found, and the budget is then exhausted: with a
/// larger one that pair might have been certified.
[[nodiscard]] CertifiedSelfIntersections certify_self_intersections(
    const Curve& curve, std::span<const SelfIntersection> pairs, const IntersectOptions& options,
    WorkBudget& budget);

/// A curve's self-intersections with their certification: the search as found, and its
/// pairs as two-curve intersections.
struct CertifiedSelfIntersectionResult {
  SelfIntersectionResult found;
  /// One per pair of found.pairs, in their order (empty when the search ran out).
  CertifiedSelfIntersections certified;
};

/// self_intersections() of `curve` charged to `budget`; when that search runs out the
/// budget is exhausted and nothing is certified. Then certify_self_intersections() of
/// the pairs with what is left: a certification that falls short reports its pairs as
/// found (certified.uncertified counts them) and does not exhaust the budget, since the
/// answer is still complete, only less tight. The one call a layer above (the API, regions)
/// makes for a curve's certified self-intersections.
[[nodiscard]] CertifiedSelfIntersectionResult certified_self_intersections(
    const Curve& curve, const IntersectOptions& options, WorkBudget& budget);

}  // namespace bezier::core
