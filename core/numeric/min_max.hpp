#pragma once

// The larger and the smaller of two doubles, for the kernel's inner loops (control boxes,
// magnitudes, interval ends), where the values are finite.
//
// Why not the standard ones: max2(a, b) is `a > b ? a : b`, the very rule of the x86-64
// instruction maxsd (minsd for min2), so it compiles to that one instruction with a in the
// destination register. std::fmax gives NaN its own rule (the other operand wins), which
// GCC does not inline without -ffinite-math-only: each call is a call into libm.
// std::max(a, b) is `a < b ? b : a`: also one maxsd, but with the operands the other way
// round (an extra move when the result goes to a's register) and the opposite answer on
// ties and NaN; the kernel writes one of them, always the same one, so that equal inputs
// give equal bits wherever a bound is computed.
//
// Ties and NaN: max2(a, b) and min2(a, b) return b unless a is strictly larger (smaller),
// so a NaN in either operand gives b, and max2(+0, -0) is -0. Callers pass finite values;
// where a NaN can reach a bound, the caller tests the result (std::isfinite).

namespace bezier::core {

/// a if a > b, else b (see above for NaN and signed zeros).
[[nodiscard]] constexpr double max2(double a, double b) noexcept {
  return a > b ? a : b;
}

/// a if a < b, else b (see above for NaN and signed zeros).
[[nodiscard]] constexpr double min2(double a, double b) noexcept {
  return a < b ? a : b;
}

}  // namespace bezier::core
