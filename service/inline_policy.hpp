#pragma once

#include <cstddef>
#include <string_view>

#include "api/batch_route.hpp"
#include "api/limits.hpp"
#include "service/router.hpp"

namespace bezier::service {

/// Which POST requests the epoll engine computes on the I/O thread itself, and under
/// which limits. A request is tried inline when its body is small (parsing is bounded
/// by it), under limits small enough that any request within them takes tens of
/// microseconds: 1/2000 of the caller's work cap (the default 22 M units is ~100 ms,
/// so ~50 µs) for the kernels that honour max_work (/intersections, the loop search of
/// /loop-area), and at most 32 t values and degree 7 for the routes whose cost is
/// t values x degree^2 x derivatives instead (/evaluate, /polar). An answer that a limit
/// decided (api::Reply::limit_reached: the work cap, too many t values, samples,
/// derivatives or answer points, a degree too high; or a self-intersection left
/// unresolved when its certification ran out of work units) is not sent: the request is
/// computed again on the compute pool with the caller's full limits. Every other answer
/// is the one the full limits give too (each limit check refuses only what is above it),
/// so a plain validation error is answered from the inline try, and the inline limits
/// change where a request runs, never its answer.
/// BENCHMARKS.md ("HTTP") has the measurements behind the numbers.
struct InlinePolicy {
  static constexpr std::size_t kMaxBodyBytes = 4096;
  static constexpr std::int64_t kWorkDivisor = 2000;
  static constexpr int kMaxTValues = 32;
  static constexpr int kMaxDegree = 7;

  /// Whether a request to `path` with this body may be tried inline at all: not a /batch,
  /// whose items add up (each is bounded, their sum only by the batch's limits).
  [[nodiscard]] static bool may_try(std::string_view path, std::size_t body_bytes) noexcept {
    return path != api::kBatchPath && body_bytes <= kMaxBodyBytes;
  }
  /// The limits of the inline try.
  [[nodiscard]] static api::Limits limits(const api::Limits& full) noexcept;
  /// Whether the inline answer is the answer (false: re-run on the pool). A refusal by a
  /// limit the inline try does not shrink (a degree above the full limit) is re-run too:
  /// the same answer again, for one more parse of a body of at most kMaxBodyBytes.
  [[nodiscard]] static bool is_final(const Response& inline_answer) noexcept {
    return !inline_answer.limit_reached;
  }
};

}  // namespace bezier::service
