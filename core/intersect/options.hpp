#pragma once

#include <cstdint>

#include "core/intersect/result.hpp"

namespace bezier::core {

/// What the caller chooses. Every number has its reason next to it.
struct IntersectOptions {
  /// Width of the reported parameter intervals (dimensionless, parameter space): every
  /// interval is narrower than this. 1e-12 is the API default: about 4500 ulps of 1, far
  /// above the rounding of the clipping steps (a few ulps), so clipping reaches it on any
  /// transversal intersection.
  double tolerance = 1e-12;
  IntersectMethod method = IntersectMethod::hybrid;
  /// Degree k of the fat curve (hybrid only): 2 or 3. Curves of degree <= k are used as they
  /// are (their distance function is then bounded exactly, delta = 0). 3 by default: on
  /// the shared benchmark (tests/bench/intersect_bench.cpp) it needs fewer steps than 2
  /// for cubics and is no slower for higher degrees.
  int fat_curve_degree = 3;
  /// The budget (work units, work_cost.hpp) of intersect() without a WorkBudget: its own,
  /// its running out reported as IntersectStatus::work_cap_reached. A caller with a budget
  /// passes it instead. Transversal cubic pairs need a few thousand.
  std::int64_t max_work = 100000000;
};

/// The smallest tolerance accepted: 2^-46 (about 1.4e-14, 64 ulps of 1). Every clipping
/// step widens its interval outward by a few ulps so that rounding can never lose a root
/// (map_to_domain in clip.hpp), and the intervals of a contact found from two sides are merged, so
/// narrower intervals cannot be guaranteed in double precision.
inline constexpr double kMinTolerance = 0x1p-46;

/// The width the search itself converges to: a quarter of the tolerance, and never coarser
/// than 2^-42 (about 2.3e-13), so that a contact found as a few adjacent boxes still fits in
/// one interval narrower than the tolerance, and two intersections farther apart than that
/// are never merged however large the requested tolerance.
[[nodiscard]] constexpr double search_width(double tolerance) noexcept {
  const double w = tolerance / 4;
  return w < 0x1p-42 ? w : 0x1p-42;
}

}  // namespace bezier::core
