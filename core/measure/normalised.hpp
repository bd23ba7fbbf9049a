#pragma once

#include <cmath>
#include <vector>

#include "core/base/curve.hpp"
#include "core/numeric/power_of_two.hpp"

namespace bezier::core {

/// A curve scaled by a power of two so that its largest coordinate (or `extra`'s, a target
/// measured against it) lies in [1/2, 1).
///
/// The scale 2^exponent is applied in two factors (PowerOfTwo): for a curve whose largest
/// coordinate is subnormal the exponent exceeds 1023, and 2^exponent itself is not a
/// double, while each half of it is. Scaling up is exact; scaling a result back is exact
/// unless it lands among the subnormals, where it is rounded once (the correctly rounded
/// value of the exact result).
template <class P>
struct Normalised {
  BasicCurve<P> curve;
  /// curve = 2^exponent * original.
  int exponent = 0;

  [[nodiscard]] double to_unit(double x) const noexcept { return PowerOfTwo(exponent).times(x); }
  [[nodiscard]] P to_unit(P p) const noexcept { return scaled(p, exponent); }
  [[nodiscard]] double from_unit(double x) const noexcept { return PowerOfTwo(-exponent).times(x); }
  [[nodiscard]] P from_unit(P p) const noexcept { return scaled(p, -exponent); }

 private:
  static P scaled(P p, int e) noexcept {
    const PowerOfTwo factor(e);
    return (p * factor.first) * factor.second;
  }
};

/// The power of two's exponent that brings `largest`, a largest coordinate, into [1/2, 1)
/// (0 for zero or a value that is not finite). A subnormal `largest` gives an exponent
/// up to 1074.
[[nodiscard]] inline int normalising_exponent_of(double largest) {
  if (!(largest > 0.0) || !std::isfinite(largest)) return 0;
  return -(exponent_of(largest) + 1);
}

/// The measuring kernels work on the normalised curve: hodographs (n (P_{i+1} - P_i)) and
/// products of points (the Bernstein coefficients of |B'|^2 or (B - q) · B') overflow for
/// coordinates near the double range, and underflow into the subnormals (losing every
/// digit) for coordinates near its bottom. A power-of-two scale is exact (except for
/// coordinates that become subnormal, more than 2^1021 below the largest), so every
/// result scales back exactly and the answers are those of the original curve.
template <class P>
[[nodiscard]] int normalising_exponent(const BasicCurve<P>& curve, double extra = 0.0) {
  return normalising_exponent_of(std::fmax(scale(curve), extra));
}

/// The curve times 2^normalising_exponent (a copy; a caller whose curve already has the
/// exponent 0 can skip it).
template <class P>
[[nodiscard]] Normalised<P> normalised(const BasicCurve<P>& curve, double extra = 0.0) {
  const int exponent = normalising_exponent(curve, extra);
  if (exponent == 0) return {curve, 0};
  Normalised<P> out{curve, exponent};
  typename BasicCurve<P>::Points points(curve.points().size());
  for (std::size_t i = 0; i < points.size(); ++i) points[i] = out.to_unit(curve.points()[i]);
  out.curve = BasicCurve<P>(std::move(points));
  return out;
}

}  // namespace bezier::core
