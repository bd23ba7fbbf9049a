#pragma once

// What the fuzz targets share: turning the fuzzer's bytes into doubles and curves, and
// reporting a broken invariant. A broken invariant aborts, so libFuzzer saves the input
// as crash-<sha1> and prints the message above its own report.

#include <fuzzer/FuzzedDataProvider.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/base/curve.hpp"
#include "core/base/point.hpp"

namespace bezier::fuzz {

/// Whether FUZZ_PRINT is set in the environment: the targets then print each input as
/// they decode it (for triage: `FUZZ_PRINT=1 ./intersect_fuzzer crash-...`).
[[nodiscard]] inline bool print_inputs() {
  static const bool print = std::getenv("FUZZ_PRINT") != nullptr;
  return print;
}

/// Stops the run: prints what broke and where, then aborts (libFuzzer keeps the input).
/// (__builtin_FILE/__builtin_LINE rather than std::source_location: clang 14 with
/// libstdc++ 12 has no <source_location>.)
[[noreturn]] inline void fail(std::string_view what, const char* file = __builtin_FILE(),
                              int line = __builtin_LINE()) {
  std::fprintf(stderr, "\n*** invariant broken at %s:%d: %.*s\n", file, line,
               static_cast<int>(what.size()), what.data());
  std::abort();
}

/// fail(what) unless `ok`. `what` is a string, or a function returning one, which is only
/// called on failure (building messages on every execution would halve the fuzzer's speed).
template <class Message>
void check(bool ok, const Message& what, const char* file = __builtin_FILE(),
           int line = __builtin_LINE()) {
  if (ok) return;
  if constexpr (std::is_invocable_v<const Message&>) {
    fail(std::string(what()), file, line);
  } else {
    fail(std::string_view(what), file, line);
  }
}

/// Doubles drawn from the fuzzer's bytes. Raw bit patterns alone almost never give the
/// inputs where geometry code breaks (equal points, collinear points, values a few ulps
/// apart, exact dyadic fractions, extreme exponents), so a selector byte picks how each
/// number is made; libFuzzer's comparison tracing then steers the selector and the
/// payload independently.
class NumberSource {
 public:
  /// exponent_limit > 0 folds every binary exponent into [-exponent_limit, exponent_limit]
  /// (so all nonzero magnitudes lie within 2^(2 exponent_limit) of each other); 0 leaves
  /// the whole double range.
  explicit NumberSource(FuzzedDataProvider& data, int exponent_limit = 0)
      : data_(data), exponent_limit_(exponent_limit) {}

  /// Any double: NaN and the infinities included (only through the raw bit pattern).
  [[nodiscard]] double any() { return remember(make()); }

  /// A finite double (non-finite bit patterns become 0): for core/, whose functions
  /// assert finite input (api/ validates it).
  [[nodiscard]] double finite() {
    const double x = make();
    return remember(std::isfinite(x) ? x : 0.0);
  }

  /// A finite double of magnitude at most 2^max_exponent (larger ones are scaled down by
  /// a power of two), so that products of a few coordinates cannot overflow.
  [[nodiscard]] double bounded(int max_exponent) {
    double x = make();
    if (!std::isfinite(x)) x = 0.0;
    int e = 0;
    (void)std::frexp(x, &e);
    if (e > max_exponent) x = std::ldexp(x, max_exponent - e);
    return remember(x);
  }

 private:
  double make() {
    const auto selector = data_.ConsumeIntegral<std::uint8_t>();
    switch (selector % 8) {
      case 0:  // raw IEEE 754 bits: every exponent, subnormals, NaN, infinities
        return std::bit_cast<double>(data_.ConsumeIntegral<std::uint64_t>());
      case 1:  // small integers: exact arithmetic, coincidences
        return static_cast<double>(data_.ConsumeIntegralInRange<int>(-8, 8));
      case 2: {  // dyadic fractions k / 2^j: exact de Casteljau at t = 1/2
        const auto k = data_.ConsumeIntegral<std::int16_t>();
        return std::ldexp(static_cast<double>(k), -data_.ConsumeIntegralInRange<int>(0, 20));
      }
      case 3:    // a previous number again (coincident and collinear points) ...
      case 4: {  // ... or a few ulps away from it (near-degenerate input)
        if (previous_.empty()) return 0.0;
        double x = previous_[data_.ConsumeIntegralInRange<std::size_t>(0, previous_.size() - 1)];
        if (selector % 8 == 4) {
          const int steps = data_.ConsumeIntegralInRange<int>(-4, 4);
          const double toward = steps < 0 ? -std::numeric_limits<double>::infinity()
                                          : std::numeric_limits<double>::infinity();
          for (int i = 0; i < (steps < 0 ? -steps : steps); ++i) x = std::nextafter(x, toward);
        }
        return x;
      }
      case 5:  // a unit-range value with full mantissa
        return data_.ConsumeFloatingPointInRange<double>(-1.0, 1.0);
      case 6: {  // an integer mantissa at a moderate exponent: scale invariance, 1e-8 .. 1e8
        const auto m = data_.ConsumeIntegral<std::int32_t>();
        return std::ldexp(static_cast<double>(m), data_.ConsumeIntegralInRange<int>(-80, 40));
      }
      default:  // the value of another number of this input, negated or halved
        if (previous_.empty()) return 1.0;
        return previous_.back() * (selector & 0x80 ? -1.0 : 0.5);
    }
  }

  double remember(double x) {
    if (exponent_limit_ > 0 && std::isfinite(x) && x != 0.0) {
      int e = 0;
      const double m = std::frexp(x, &e);
      const int span = 2 * exponent_limit_ + 1;
      const int folded = ((e + exponent_limit_) % span + span) % span - exponent_limit_;
      x = std::ldexp(m, folded);
    }
    if (std::isfinite(x) && previous_.size() < 64) previous_.push_back(x);
    return x;
  }

  FuzzedDataProvider& data_;
  int exponent_limit_ = 0;
  std::vector<double> previous_;
};

/// A planar curve of degree `degree` with finite coordinates from `numbers`.
[[nodiscard]] inline core::Curve finite_curve(NumberSource& numbers, int degree) {
  std::vector<core::Point2> points;
  points.reserve(static_cast<std::size_t>(degree) + 1);
  for (int i = 0; i <= degree; ++i) {
    const double x = numbers.finite();
    points.push_back({x, numbers.finite()});
  }
  return core::Curve(std::move(points));
}

/// Whether every coordinate is finite.
[[nodiscard]] inline bool is_finite(const core::Point2& p) noexcept {
  return core::is_finite(p);
}

}  // namespace bezier::fuzz
