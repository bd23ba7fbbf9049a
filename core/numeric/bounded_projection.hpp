#pragma once

#include <cmath>
#include <limits>

#include "core/base/point.hpp"
#include "core/numeric/unit_roundoff.hpp"

namespace bezier::core {

/// The projection d . (p - r) of the difference of two points onto a direction, computed in
/// doubles, with a bound on its rounding error: the exact real value E lies in
/// [value - error, value + error].
///
/// value = fl(fl(d.x fl(p.x - r.x)) + fl(d.y fl(p.y - r.y))): five roundings, each term
/// rounded three times, so |value - E| <= gamma_3 (|d.x (p.x - r.x)| + |d.y (p.y - r.y)|)
/// with gamma_3 = 3u / (1 - 3u) (Higham, "Accuracy and Stability of Numerical Algorithms",
/// 2nd ed., §3.1). The computed products a^, b^ are the exact ones times (1 + d1)(1 + d2),
/// so |d.x (p.x - r.x)| <= |a^| / (1 - u)^2; the bound's own sum and product round down by at
/// most (1 - u) each; and 4u >= gamma_3 / (1 - u)^4. Hence error = fl(4u fl(|a^| + |b^|))
/// covers the relative error. Underflow adds an absolute error: a difference or a sum that
/// underflows is exact, each of the two products and the bound's product lose at most 2^-1075,
/// so the smallest normal double (2^-1022) added to the bound covers them.
///
/// Overflow: an intermediate that overflows makes `error` infinite or NaN (or `value` NaN),
/// so the tests certainly_positive and certainly_negative, written so that NaN and infinity
/// fail them, say "not certain" and never a wrong sign.
struct BoundedProjection {
  double value = 0.0;
  double error = 0.0;
  /// fl(|a^| + |b^|): |d.x (p.x - r.x)| + |d.y (p.y - r.y)| to within rounding, the size
  /// against which a margin is measured.
  double size = 0.0;

  /// d . (p - r) > 0 for certain.
  [[nodiscard]] bool certainly_positive() const noexcept { return value > error; }
  /// d . (p - r) < 0 for certain.
  [[nodiscard]] bool certainly_negative() const noexcept { return -value > error; }
};

[[nodiscard]] inline BoundedProjection bounded_projection(Point2 d, Point2 p,
                                                          Point2 r) noexcept {
  const double a = d.x * (p.x - r.x);
  const double b = d.y * (p.y - r.y);
  const double size = std::fabs(a) + std::fabs(b);
  return {a + b, 4.0 * kUnitRoundoff * size + std::numeric_limits<double>::min(), size};
}

}  // namespace bezier::core
