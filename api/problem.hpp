#pragma once

#include <string>
#include <utility>
#include <vector>

#include "api/json_writer.hpp"

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
};

/// The kinds of problem the API reports. Each has a stable `type` URI, a `title` and an
/// HTTP status (DESIGN §3).
enum class ProblemKind {
  malformed_json,           ///< 400: body is not JSON, or not an object
  validation,               ///< 422: wrong types, missing fields, out of range, limits
  work_cap,                 ///< 422: the request needs more work than the cap allows
  payload_too_large,        ///< 413
  unsupported_media_type,   ///< 415
  not_found,                ///< 404
  method_not_allowed,       ///< 405
  unauthorized,             ///< 401
  shutting_down,            ///< 503
  internal,                 ///< 500: a bug
};

/// RFC 9457 problem details: `type`, `title`, `status`, `detail`, and for validation
/// problems an `errors` list of {pointer, message}.
[[nodiscard]] Reply problem_reply(ProblemKind kind, std::string detail,
                                  std::vector<FieldError> errors = {});

/// 422 with every field error found in the request.
[[nodiscard]] Reply validation_reply(std::vector<FieldError> errors);

/// 200 application/json with the answer's text; a 422 instead when a number of the answer
/// is not finite (a result beyond the double range), its detail naming the first such
/// field by its JSON Pointer into the answer.
[[nodiscard]] Reply json_reply(JsonWriter&& answer);

/// The HTTP status of a problem kind.
[[nodiscard]] int status_of(ProblemKind kind) noexcept;

}  // namespace bezier::api
