#pragma once

#include <cstddef>
#include <string_view>

#include "api/limits.hpp"
#include "service/router.hpp"

namespace bezier::service {

/// Which POST requests the epoll engine computes on the I/O thread itself, and under
/// which limits. A request is tried inline when its body is small (parsing is bounded
/// by it), under limits small enough that any request within them takes tens of
/// microseconds: 1/2000 of the caller's work cap (the default 22 M units is ~100 ms,
/// so ~50 µs) for the kernels that honour max_work (/intersections, the loop search of
/// /loop-area), and at most 32 t values and degree 7 for the routes whose cost is
/// t values x degree^2 x derivatives instead (/evaluate, /polar). A request those
/// limits refuse (422: work cap, too many t values, degree too high) is not answered:
/// it is computed again on the compute pool with the caller's full limits, so the
/// inline limits change where a request runs, never its answer.
/// BENCHMARKS.md §3 has the measurements behind the numbers.
struct InlinePolicy {
  static constexpr std::size_t kMaxBodyBytes = 4096;
  static constexpr std::int64_t kWorkDivisor = 2000;
  static constexpr int kMaxTValues = 32;
  static constexpr int kMaxDegree = 7;

  /// Whether a request with this body may be tried inline at all.
  [[nodiscard]] static bool may_try(std::size_t body_bytes) noexcept { return body_bytes <= kMaxBodyBytes; }
  /// The limits of the inline try.
  [[nodiscard]] static api::Limits limits(const api::Limits& full) noexcept;
  /// Whether the inline answer is the answer (false: re-run on the pool).
  [[nodiscard]] static bool is_final(const Response& inline_answer) noexcept {
    return inline_answer.status != 422;
  }
};

}  // namespace bezier::service
