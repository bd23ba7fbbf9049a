#pragma once

#include <cmath>
#include <vector>

#include "core/base/curve.hpp"
#include "core/numeric/power_of_two.hpp"

namespace bezier::core {

/// A curve scaled by a power of two so that its largest coordinate (or `extra`'s, a target
/// measured against it) lies in [1/2, 1).
template <class P>
struct Normalised {
  BasicCurve<P> curve;
  /// The scale applied: curve = factor * original, factor = 2^-e.
  double factor = 1.0;
};

/// The power of two that brings `largest`, a largest coordinate, into [1/2, 1) (1 for zero
/// or a value that is not finite).
[[nodiscard]] inline double normalising_factor_of(double largest) {
  if (!(largest > 0.0) || !std::isfinite(largest)) return 1.0;
  return power_of_two(-(std::ilogb(largest) + 1));
}

/// The measuring kernels work on the normalised curve: hodographs (n (P_{i+1} - P_i)) and
/// products of points (the Bernstein coefficients of |B'|^2 or (B - q) · B') overflow for
/// coordinates near the double range, and a power-of-two scale is exact (except for
/// coordinates that become subnormal, more than 2^1021 below the largest), so every
/// result scales back exactly and the answers are those of the original curve.
template <class P>
[[nodiscard]] double normalising_factor(const BasicCurve<P>& curve, double extra = 0.0) {
  return normalising_factor_of(std::fmax(scale(curve), extra));
}

/// The curve times normalising_factor (a copy; a caller whose curve already has the factor
/// 1 can skip it).
template <class P>
[[nodiscard]] Normalised<P> normalised(const BasicCurve<P>& curve, double extra = 0.0) {
  const double factor = normalising_factor(curve, extra);
  if (factor == 1.0) return {curve, 1.0};
  std::vector<P> points;
  points.reserve(curve.points().size());
  for (const P& p : curve.points()) points.push_back(factor * p);
  return {BasicCurve<P>(std::move(points)), factor};
}

}  // namespace bezier::core
