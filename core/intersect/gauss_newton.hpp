#pragma once

#include <cmath>

#include "core/numeric/min_max.hpp"
#include "core/base/point.hpp"
#include "core/intersect/tuning.hpp"

namespace bezier::core {

/// The residual r(t) of a one-parameter least-squares problem and its derivative r'(t).
struct ResidualAndSlope {
  Point2 r;
  Point2 slope;
};

/// Gauss-Newton for min |r(t)|^2 from a close guess: t -= (r . r') / |r'|^2 until a step is
/// at most `converged` or after `max_steps`. A refinement, not a search: a step above
/// intersect_tuning::kGaussNewtonLargestStep (or a vanishing r') means r' nearly vanishes
/// here, where the iteration is unreliable, and ends it with the t reached. Clamped to [0, 1].
template <class Residual>
[[nodiscard]] double gauss_newton(double t, int max_steps, double converged, Residual&& at) {
  for (int i = 0; i < max_steps; ++i) {
    const ResidualAndSlope e = at(t);
    const double d2 = e.slope.x * e.slope.x + e.slope.y * e.slope.y;
    if (!(d2 > 0)) break;
    const double step = (e.r.x * e.slope.x + e.r.y * e.slope.y) / d2;
    if (!std::isfinite(step) || std::fabs(step) > intersect_tuning::kGaussNewtonLargestStep) break;
    t -= step;
    if (std::fabs(step) <= converged) break;
  }
  return min2(1.0, max2(0.0, t));
}

}  // namespace bezier::core
