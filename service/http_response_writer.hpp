#pragma once

#include <string>
#include <string_view>

#include "service/router.hpp"

namespace bezier::service {

/// How a response goes on the wire, beyond its own status, headers and body.
struct WireOptions {
  int minor_version = 1;         ///< of the request: HTTP/1.0 clients get "Connection: keep-alive"
  bool keep_alive = true;        ///< false: "Connection: close", then the connection closes
  bool head_only = false;        ///< HEAD: the headers (Content-Length of the body) without it
  int keep_alive_timeout_s = 5;  ///< advertised in "Keep-Alive: timeout=N"
  std::string_view request_id;   ///< X-Request-Id, when not empty
  /// Access-Control-Allow-Origin (with Access-Control-Expose-Headers), when not empty.
  std::string_view allow_origin;
  bool vary_origin = false;      ///< "Vary: Origin"
};

/// The CORS part of the wire options: the Exchange's (Router::begin) allowed origin and
/// Vary, and its request id. The exchange must outlive the options.
inline WireOptions& for_exchange(WireOptions& options, const Exchange& exchange) noexcept {
  options.request_id = exchange.id;
  options.allow_origin = exchange.allow_origin;
  options.vary_origin = exchange.vary_origin;
  return options;
}

/// Appends the HTTP/1.1 response (status line, headers, blank line, body) to `out`, so
/// that headers and body leave in one send. Every answer carries
/// `X-Content-Type-Options: nosniff`; an HTML one also a Content-Security-Policy that
/// admits only the service's own origin and forbids framing. A 204 has neither
/// Content-Type nor Content-Length (RFC 9110 §8.6: a 204 must not send the length).
void append_response(std::string& out, const Response& response, const WireOptions& options);

/// The reason phrase of a status ("OK", "Not Found", ...), "Unknown" for others.
[[nodiscard]] std::string_view reason_phrase(int status) noexcept;

}  // namespace bezier::service
