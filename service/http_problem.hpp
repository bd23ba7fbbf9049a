#pragma once

#include <string>

#include "service/router.hpp"

namespace bezier::service {

/// The problem+json answer (RFC 9457, the same members as api::problem_reply) for an
/// error of the HTTP layer itself, decided before a request reaches the Router:
/// 400 malformed request, 408 request timeout, 413 body too large, 414 / 431 request
/// line or headers too large, 501 transfer coding, 503 compute queue full or shutting
/// down, 505 HTTP version. 413 and the shutdown 503 are the API's own kinds
/// (payload-too-large, shutting-down); the others are `bad-request` and `overloaded`.
[[nodiscard]] Response http_problem(int status, std::string detail, bool shutting_down = false);

}  // namespace bezier::service
