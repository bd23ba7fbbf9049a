#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

namespace bezier::core {

/// 2^e, bit for bit std::ldexp(1.0, e), without the library call when 2^e is a normal double
/// (the exponent field alone): the error bounds of the intersection set-up scale by powers
/// of two for every pair, and the call cost tens of instructions each time.
[[nodiscard]] inline double power_of_two(int e) noexcept {
  if (e < -1022 || e > 1023) return std::ldexp(1.0, e);
  return std::bit_cast<double>(static_cast<std::uint64_t>(e + 1023) << 52);
}

}  // namespace bezier::core
