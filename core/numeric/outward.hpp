#pragma once

// The neighbouring doubles of x towards +infinity and -infinity: outward rounding of a
// bound by one ulp, from the bit pattern (std::nextafter is a library call, tens of
// instructions, on paths that round several faces per curve).

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace bezier::core {

/// The least double above x, bit for bit std::nextafter(x, +infinity): +infinity and NaN
/// stay, the largest finite double goes to +infinity, -0 and +0 go to the smallest
/// subnormal.
[[nodiscard]] inline double next_up(double x) noexcept {
  if (std::isnan(x) || x == std::numeric_limits<double>::infinity()) return x;
  if (x == 0.0) return std::numeric_limits<double>::denorm_min();
  const auto bits = std::bit_cast<std::uint64_t>(x);
  return std::bit_cast<double>(x > 0.0 ? bits + 1 : bits - 1);
}

/// The greatest double below x, bit for bit std::nextafter(x, -infinity).
[[nodiscard]] inline double next_down(double x) noexcept { return -next_up(-x); }

}  // namespace bezier::core
