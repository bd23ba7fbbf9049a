#pragma once

#include <cstdint>

namespace bezier::test {

/// mulberry32, the 32-bit generator of the shared benchmark input (BENCHMARKS.md), so
/// random inputs are reproducible here and comparable with other libraries' runs.
/// All arithmetic is mod 2^32.
class Mulberry32 {
 public:
  explicit constexpr Mulberry32(std::uint32_t seed) noexcept : state_(seed) {}

  /// The next draw in [0, 1).
  constexpr double next() noexcept {
    state_ += 0x6D2B79F5u;
    std::uint32_t t = (state_ ^ (state_ >> 15)) * (state_ | 1u);
    t = (t + ((t ^ (t >> 7)) * (t | 61u))) ^ t;
    return static_cast<double>(t ^ (t >> 14)) / 4294967296.0;
  }

  /// A draw in [lo, hi).
  constexpr double uniform(double lo, double hi) noexcept { return lo + (hi - lo) * next(); }

  [[nodiscard]] constexpr std::uint32_t state() const noexcept { return state_; }

 private:
  std::uint32_t state_;
};

}  // namespace bezier::test
