#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/base/curve.hpp"
#include "core/intersect/options.hpp"
#include "core/intersect/result.hpp"
#include "core/self_intersect/self_intersection.hpp"

namespace bezier::core {

/// Self-intersections as two-curve intersections: each with guaranteed intervals, or
/// reported as found.
struct CertifiedSelfIntersections {
  /// One per pair, in the pairs' order.
  std::vector<Intersection> intersections;
  std::int64_t work = 0;   ///< work units spent (core/intersect/work_cost.hpp)
  std::int64_t steps = 0;  ///< search steps taken
  /// Some pair was left unresolved for want of work units (none left, or its search ran out
  /// of them): with a larger budget it might have been certified.
  bool out_of_work = false;
};

/// Puts guaranteed intervals around the self-intersections `pairs` of `curve` (as
/// self_intersections() found them): the curve against itself by intersect_in(), in a box
/// of half-width min(2^-20, (s - t) / 4) around (t, s), which stays away from the diagonal
/// t = s where every point is a trivial solution. When the box holds exactly one
/// intersection, its intervals and estimate are reported (options.tolerance bounds their
/// width); otherwise the pair is reported as found, with point intervals, `resolved` false.
/// The pairs' searches share `budget` work units in order; a pair reached with none left is
/// reported as found.
[[nodiscard]] CertifiedSelfIntersections certify_self_intersections(
    const Curve& curve, std::span<const SelfIntersection> pairs, const IntersectOptions& options,
    std::int64_t budget);

}  // namespace bezier::core
