#pragma once

#include "core/intersect/result.hpp"
#include "core/base/point.hpp"

namespace bezier::core {

/// Thresholds of the classification, dimensionless so that they hold at every scale.
struct KindTolerances {
  /// A derivative counts as zero below this fraction of its curve's hodograph scale
  /// (n max |P_{i+1} - P_i|, the largest the derivative can be on [0, 1]). 2^-30 (about
  /// 1e-9): derivatives at a refined root are accurate to about u divided by the root's
  /// parameter error, far below this; a true cusp evaluates to a few ulps.
  double zero_derivative = 0x1p-30;
  /// f' x g' counts as zero below this fraction of |f'| |g'| (the sine of the angle).
  /// 2^-33 (about 1.2e-10): the tangency system puts a touching contact's estimate within a
  /// few ulps of it, where the sine is O(1e-15); two crossings 1e-8 apart in parameter, as
  /// near a perturbed tangency, cross at sines of about 1e-8 and stay transversal.
  double tangent_sine = 0x1p-33;
};

/// transversal / tangent / degenerate from the derivatives at the intersection:
/// degenerate when either derivative is zero relative to its scale, tangent when
/// the sine of the angle between them is below the threshold, transversal otherwise.
[[nodiscard]] IntersectionKind classify_intersection(Point2 df, Point2 dg, double df_scale,
                                                     double dg_scale,
                                                     const KindTolerances& tol = {}) noexcept;

/// The sine of the angle between two vectors, |a x b| / (|a| |b|); 0 when either is zero.
/// For vectors of moderate size (the working frame's): the squares must not overflow.
[[nodiscard]] double sine_between(Point2 a, Point2 b) noexcept;

}  // namespace bezier::core
