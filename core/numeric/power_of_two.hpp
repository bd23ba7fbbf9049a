#pragma once

// Powers of two: exact scaling of coordinates, built from the exponent field without the
// library calls (std::ldexp, std::ilogb cost tens of instructions each, and the set-up of
// every intersection and area computation scales by powers of two).

#include <bit>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "core/base/point.hpp"

namespace bezier::core {

/// 2^e, bit for bit std::ldexp(1.0, e), without the library call when 2^e is a normal double
/// (the exponent field alone).
[[nodiscard]] inline double power_of_two(int e) noexcept {
  if (e < -1022 || e > 1023) return std::ldexp(1.0, e);
  return std::bit_cast<double>(static_cast<std::uint64_t>(e + 1023) << 52);
}

/// std::ilogb(x), without the library call for normal x (the exponent field alone).
[[nodiscard]] inline int exponent_of(double x) noexcept {
  const int biased = static_cast<int>((std::bit_cast<std::uint64_t>(x) >> 52) & 0x7ff);
  if (biased == 0 || biased == 0x7ff) return std::ilogb(x);
  return biased - 1023;
}

/// 2^ilogb(x), bit for bit std::ldexp(1.0, std::ilogb(x)).
[[nodiscard]] inline double power_of_two_at_most(double x) noexcept {
  return power_of_two(exponent_of(x));
}

/// Multiplication by 2^e as two factors (2^e itself may be beyond the double range, e.g.
/// e up to 1074 for subnormal input): exact whenever the result is a normal double.
struct PowerOfTwo {
  double first, second;
  explicit PowerOfTwo(int e) noexcept
      : first(power_of_two(e / 2)), second(power_of_two(e - e / 2)) {}
  [[nodiscard]] double times(double x) const noexcept { return x * first * second; }
  [[nodiscard]] Point2 times(Point2 p) const noexcept { return {times(p.x), times(p.y)}; }
};

/// The points times 2^e (PowerOfTwo): exact whenever the results are normal doubles.
[[nodiscard]] inline std::vector<Point2> scaled_by_power_of_two(std::span<const Point2> points,
                                                                int e) {
  const PowerOfTwo factor(e);
  std::vector<Point2> scaled;
  scaled.reserve(points.size());
  for (const Point2 p : points) scaled.push_back(factor.times(p));
  return scaled;
}

}  // namespace bezier::core
