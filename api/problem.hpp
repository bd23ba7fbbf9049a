#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "api/write_json.hpp"

namespace bezier::api {

/// One rejected field: a JSON Pointer (RFC 6901) into the request, and why.
struct FieldError {
  std::string pointer;
  std::string message;
};

/// An HTTP-shaped answer without any socket: what the service writes back.
struct Reply {
  int status = 200;
  std::string content_type = "application/json";
  std::string body;
  /// A limit of Limits decided this answer: it refused the request (a 422: a degree, a
  /// count of t values, samples, derivatives or answer points above its limit, a
  /// `derivatives` or `samples` below the range whose message names the limit, or the work
  /// cap), or the work cap cut part of the answer short (a 200 with a self-intersection
  /// left unresolved because its certification ran out of work units). Such an answer may
  /// differ under larger limits (its message names the limit, if nothing else); every other
  /// answer is the same under any limits at least as large, since each limit check only
  /// refuses what is above it. A caller that tries a request under smaller limits first
  /// (the epoll engine's inline try) must compute it again only when this is set.
  bool limit_reached = false;
  /// The work cap decided this answer: a 422 work-cap problem, or a 200 it cut short (a
  /// self-intersection left unresolved). Implies limit_reached. A /batch sets it only when
  /// the batch itself is refused by its work cap; its items carry their own.
  bool decided_by_work_cap = false;
};

/// The kinds of problem the API reports. Each has a stable `type` URI, a `title` and an
/// HTTP status (api/openapi.yaml).
enum class ProblemKind {
  malformed_json,           ///< 400: body is not JSON, or not an object
  validation,               ///< 422: wrong types, missing fields, out of range, limits
  work_cap,                 ///< 422: the request needs more work than the cap allows
  memory_cap,               ///< 422: the request would store more than the memory limit
  result_overflow,          ///< 422: a valid request whose answer is beyond the double range
  payload_too_large,        ///< 413
  unsupported_media_type,   ///< 415
  not_found,                ///< 404
  method_not_allowed,       ///< 405
  unauthorized,             ///< 401
  shutting_down,            ///< 503
  internal,                 ///< 500: a bug
};

/// RFC 9457 problem details: `type`, `title`, `status`, `detail`, and for validation
/// problems an `errors` list of {pointer, message}. A work_cap problem has limit_reached and
/// decided_by_work_cap set.
[[nodiscard]] Reply problem_reply(ProblemKind kind, std::string detail,
                                  std::vector<FieldError> errors = {});

/// The work-cap problem of a self-intersection search (/intersections with one curve,
/// /loop-area) that spent `work` units of the cap `max_work`.
[[nodiscard]] Reply self_intersection_work_cap_reply(std::int64_t work, std::int64_t max_work);

/// The memory-cap problem: the input at `pointer` (a JSON Pointer into the request) would
/// make the kernel store more than the per-request memory limit; `why` says what. Sets
/// limit_reached (not decided_by_work_cap).
[[nodiscard]] Reply memory_cap_reply(const std::string& pointer, std::string why);

/// 422 with every field error found in the request (limit_reached not set: a field refused
/// by a limit is RequestReader::refusal()'s).
[[nodiscard]] Reply validation_reply(std::vector<FieldError> errors);

/// 200 application/json with the answer's text; a 422 instead when a number of the answer
/// is not finite (a result beyond the double range), its detail naming the first such
/// field by its JSON Pointer into the answer.
[[nodiscard]] Reply json_reply(JsonWriter&& answer);

/// The HTTP status of a problem kind.
[[nodiscard]] int status_of(ProblemKind kind) noexcept;

}  // namespace bezier::api
