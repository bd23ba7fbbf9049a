#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "api/batch_route.hpp"
#include "api/limits.hpp"
#include "api/problem.hpp"
#include "service/config.hpp"
#include "service/log.hpp"
#include "service/metrics.hpp"

namespace bezier::service {

/// What the router needs of a request, whichever HTTP engine parsed it. The views stay
/// valid for the duration of the call they are passed to.
struct RequestView {
  std::string_view method;  ///< "GET", "POST", ...; engines pass HEAD as "HEAD"
  std::string_view path;    ///< the target without its query
  /// The value of a header (name compared case-insensitively), empty when absent.
  std::function<std::string_view(std::string_view name)> header;
  std::string_view body;
  std::string_view client;  ///< the peer's address, for the access log
};

/// An answer in HTTP terms, for an engine to write. `headers` are the ones beyond
/// Content-Type and Content-Length (Allow, WWW-Authenticate, X-Request-Id).
struct Response {
  int status = 200;
  std::string content_type = "application/json";
  std::string body;
  std::vector<std::pair<std::string_view, std::string>> headers;
  /// api::Reply::limit_reached of a computed answer: a limit decided it, so under larger
  /// limits it may differ. Not sent; the epoll engine's inline try reads it.
  bool limit_reached = false;
  /// api::Reply::decided_by_work_cap of a computed answer (for the metrics).
  bool decided_by_work_cap = false;
};

/// The request's start time, id and client, from Router::begin to Router::finish, and
/// what CORS adds to its answer, whatever answers it (the router, a compute thread, or
/// the engine's own error).
struct Exchange {
  std::chrono::steady_clock::time_point start;
  std::string id;
  std::string client;
  /// Access-Control-Allow-Origin of the answer ("*", or the allowed Origin as sent), empty
  /// when the answer gets none.
  std::string allow_origin;
  /// Whether the answer carries "Vary: Origin": it depends on the request's Origin (CORS
  /// with a list of origins), so caches must key on it.
  bool vary_origin = false;
};

/// Everything about a request that does not depend on the transport (the event loops
/// of service/epoll_engine.hpp parse and write; this decides):
/// GET routes (health, readiness, metrics, the spec, the playground), 404 and 405 with
/// Allow, bearer authentication, the JSON media type check, CORS (preflight answers, and
/// which origin an answer admits), request ids, metrics and the access log. POST routes are computed by api::handle; the router only decides
/// whether a request gets that far, so the engine can choose the thread that runs it.
/// Thread-safe: every member may be called from any thread at once.
class Router {
 public:
  Router(const Config& config, Log log);

  /// Starts a request: the in-flight gauge, its request id (the client's X-Request-Id
  /// when short and plain, otherwise a random one) and its CORS headers.
  [[nodiscard]] Exchange begin(const RequestView& request);

  /// The answer to `request`, or nullopt when it is a valid POST to an API route: then
  /// the engine calls compute() (with the limits it chooses) on a thread of its choice.
  /// HEAD is answered as GET; the engine leaves the body out.
  [[nodiscard]] std::optional<Response> answer(const RequestView& request) const;

  /// api::handle(path, body, limits) as a Response; an exception (a bug, or bad_alloc)
  /// is logged and becomes a 500 problem instead of reaching the engine. The items of a
  /// /batch are counted in the metrics by route and status (and the work cap's decisions,
  /// of its items and of the batch itself).
  [[nodiscard]] Response compute(std::string_view path, std::string_view body,
                                 const api::Limits& limits);

  /// A /batch to be computed one item per compute_batch_item() call (api::BatchRun), so
  /// that the engine can queue its items behind other requests instead of holding a
  /// compute thread for the whole batch. Parsing, validation and the batch's own refusals
  /// happen here; an exception becomes a finished run answering 500, as in compute().
  [[nodiscard]] api::BatchRun start_batch(std::string_view body, const api::Limits& limits);
  /// Computes the next item of `batch`, counted in the metrics as compute() counts a
  /// batch's items; the batch's Response once it is finished (compute()'s, byte for byte),
  /// nullopt while items remain.
  [[nodiscard]] std::optional<Response> compute_batch_item(api::BatchRun& batch);

  /// Ends a request begun with begin(): metrics and the access line, which gives the
  /// bytes of its answer on the wire (status line, headers and body).
  void finish(const Exchange& exchange, std::string_view method, std::string_view path, int status,
              std::size_t bytes_sent);

  /// Counts and logs an answer the engine gave before routing (a malformed request,
  /// 413 before the body, a timeout), which has no Exchange.
  void finish_unrouted(std::string_view method, std::string_view path, int status, std::string_view client,
                       std::size_t bytes_sent);

  /// Ends a request begun with begin() that is not answered, because its connection
  /// closed while it waited for a compute thread: counted as dropped, and logged with
  /// status 499 (the code nginx logs for a client that closed before its answer).
  void abandon(const Exchange& exchange, std::string_view method, std::string_view path);

  /// The counters the engine updates itself (queue depth, overload, work cap).
  [[nodiscard]] Metrics& metrics() noexcept { return metrics_; }

  /// From now on /readyz answers 503 (load balancers stop sending); still serving.
  void begin_draining() noexcept { draining_.store(true); }

  [[nodiscard]] const Config& config() const noexcept { return config_; }
  [[nodiscard]] Log& log() noexcept { return log_; }

 private:
  [[nodiscard]] Response answer_get(std::string_view path) const;
  [[nodiscard]] std::optional<Response> check_post(const RequestView& request) const;
  [[nodiscard]] Response answer_other_method(const RequestView& request) const;
  /// The answer to a CORS preflight (OPTIONS with Origin and
  /// Access-Control-Request-Method) from an allowed origin to a route; nullopt otherwise.
  [[nodiscard]] std::optional<Response> answer_preflight(const RequestView& request) const;
  /// Access-Control-Allow-Origin for a request with this Origin header, empty for none.
  [[nodiscard]] std::string allowed_origin(std::string_view origin) const;
  [[nodiscard]] bool authorized(const RequestView& request) const;
  /// compute_answer(), or a logged 500 when an exception (a bug, or bad_alloc) escapes it.
  [[nodiscard]] Response guarded(std::string_view path, const std::function<Response()>& compute_answer);
  void log_access(std::string_view method, std::string_view path, int status, double seconds,
                  std::string_view id, std::string_view client, std::size_t bytes_sent);

  const Config config_;
  Log log_;
  Metrics metrics_;
  std::atomic<bool> draining_{false};
};

/// An api::Reply as a Response (same status, content type and body).
[[nodiscard]] Response to_response(api::Reply reply);

/// A problem+json Response of the API's kinds (api/problem.hpp).
[[nodiscard]] Response problem_response(api::ProblemKind kind, std::string detail);

/// Whether the work cap decided a computed answer: a 422 work-cap problem, or a 200 the
/// cap cut short (api::Reply::decided_by_work_cap). For a /batch, whose items the router
/// counts as it computes them, only the batch's own refusal by its work cap.
[[nodiscard]] bool work_cap_reached(const Response& response) noexcept;

/// The headers of a preflight answer beyond Access-Control-Allow-Origin: the methods
/// allowed, the request headers a page may send, and how long a browser may cache it.
inline constexpr std::string_view kCorsAllowHeaders = "Authorization, Content-Type, X-Request-Id";
inline constexpr std::string_view kCorsMaxAgeSeconds = "600";
/// The answer headers a page may read besides the CORS-safelisted ones.
inline constexpr std::string_view kCorsExposeHeaders = "X-Request-Id, Retry-After, Allow, WWW-Authenticate";

}  // namespace bezier::service
