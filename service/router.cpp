#include "service/router.hpp"

#include <cctype>
#include <cstdio>
#include <random>
#include <vector>

#include "api/handler.hpp"
#include "api/nearest_name.hpp"
#include "service/static_files.hpp"

namespace bezier::service {

namespace {

using Clock = std::chrono::steady_clock;

bool is_json_media_type(std::string_view content_type) {
  // "application/json", optionally with parameters, or any "+json" suffix type.
  const std::string_view type = content_type.substr(0, content_type.find(';'));
  std::string lower;
  for (const char c : type) {
    if (c != ' ' && c != '\t') lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return lower == "application/json" ||
         (lower.size() > 5 && lower.compare(lower.size() - 5, 5, "+json") == 0 &&
          lower.rfind("application/", 0) == 0);
}

bool iequals(std::string_view a, std::string_view b) noexcept {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  }
  return true;
}

// RFC 9110 §8.4: Content-Encoding lists the codings applied to the body, in order; the
// service reads bodies as sent, so only "identity" (no coding) or no header will do.
bool only_identity_coding(std::string_view codings) noexcept {
  while (!codings.empty()) {
    const std::size_t comma = codings.find(',');
    std::string_view coding = codings.substr(0, comma);
    while (!coding.empty() && (coding.front() == ' ' || coding.front() == '\t')) coding.remove_prefix(1);
    while (!coding.empty() && (coding.back() == ' ' || coding.back() == '\t')) coding.remove_suffix(1);
    if (!coding.empty() && !iequals(coding, "identity")) return false;
    if (comma == std::string_view::npos) break;
    codings.remove_prefix(comma + 1);
  }
  return true;
}

// A client's X-Request-Id is kept when it is short and plain; otherwise one is made.
std::string request_id_for(std::string_view given) {
  bool plain = !given.empty() && given.size() <= 64;
  for (const char c : given) {
    plain = plain && (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.');
  }
  if (plain) return std::string(given);
  thread_local std::mt19937_64 random{std::random_device{}()};
  char id[17];
  std::snprintf(id, sizeof id, "%016llx", static_cast<unsigned long long>(random()));
  return id;
}

constexpr std::string_view kGetRoutes[] = {"/healthz", "/readyz", "/metrics", "/openapi.yaml",
                                           "/openapi.json"};

/// "no route P", with the nearest route's name when P looks like a misspelling of one.
std::string no_route(std::string_view path) {
  std::vector<std::string_view> routes(api::post_routes().begin(), api::post_routes().end());
  routes.insert(routes.end(), std::begin(kGetRoutes), std::end(kGetRoutes));
  return "no route " + std::string(path) + api::did_you_mean(path, routes);
}

bool is_get_route(std::string_view path) {
  for (const auto r : kGetRoutes) {
    if (r == path) return true;
  }
  return find_static_file(path).has_value();
}

Response content(std::string_view body, std::string_view content_type) {
  Response response;
  response.content_type = std::string(content_type);
  response.body = std::string(body);
  return response;
}

}  // namespace

Response to_response(api::Reply reply) {
  Response response;
  response.status = reply.status;
  response.content_type = std::move(reply.content_type);
  response.body = std::move(reply.body);
  response.limit_reached = reply.limit_reached;
  response.decided_by_work_cap = reply.decided_by_work_cap;
  return response;
}

Response problem_response(api::ProblemKind kind, std::string detail) {
  return to_response(api::problem_reply(kind, std::move(detail)));
}

bool work_cap_reached(const Response& response) noexcept {
  return response.decided_by_work_cap;
}

Router::Router(const Config& config, Log log) : config_(config), log_(std::move(log)) {}

Exchange Router::begin(const RequestView& request) {
  metrics_.request_started();
  Exchange exchange{Clock::now(), request_id_for(request.header("X-Request-Id")),
                    request.client.empty() ? std::string("-") : std::string(request.client),
                    allowed_origin(request.header("Origin")), false};
  // With a list of origins the answer depends on Origin (allowed or not, present or
  // not), so every answer says so to caches; with "*" every answer is the same.
  exchange.vary_origin = !config_.cors_origins.empty() && exchange.allow_origin != "*";
  return exchange;
}

std::string Router::allowed_origin(std::string_view origin) const {
  for (const std::string& allowed : config_.cors_origins) {
    if (allowed == "*") return allowed;
  }
  if (origin.empty()) return {};
  for (const std::string& allowed : config_.cors_origins) {
    if (allowed == origin) return allowed;
  }
  return {};
}

std::optional<Response> Router::answer(const RequestView& request) const {
  if (request.method == "GET" || request.method == "HEAD") return answer_get(request.path);
  if (request.method == "POST") return check_post(request);
  if (request.method == "OPTIONS") {
    if (auto preflight = answer_preflight(request)) return preflight;
  }
  return answer_other_method(request);
}

std::optional<Response> Router::answer_preflight(const RequestView& request) const {
  // Fetch standard, CORS protocol: a preflight is OPTIONS with Origin and
  // Access-Control-Request-Method; it carries no credentials, so it is answered without
  // the bearer token. Any other OPTIONS, or one from an origin not allowed, is answered
  // as any OPTIONS is (405 with Allow on a route), and the browser then refuses the call.
  const std::string_view origin = request.header("Origin");
  if (origin.empty() || request.header("Access-Control-Request-Method").empty() ||
      allowed_origin(origin).empty()) {
    return std::nullopt;
  }
  const std::string path(request.path);
  const char* methods = nullptr;
  if (api::is_post_route(path)) {
    methods = "POST";
  } else if (is_get_route(path)) {
    methods = "GET, HEAD";
  } else {
    return std::nullopt;
  }
  Response response;
  response.status = 204;
  response.content_type.clear();
  response.headers.emplace_back("Access-Control-Allow-Methods", methods);
  response.headers.emplace_back("Access-Control-Allow-Headers", std::string(kCorsAllowHeaders));
  response.headers.emplace_back("Access-Control-Max-Age", std::string(kCorsMaxAgeSeconds));
  return response;
}

Response Router::answer_get(std::string_view path) const {
  if (path == "/healthz") return content(R"({"status":"ok"})", "application/json");
  if (path == "/readyz") {
    if (draining_.load()) return problem_response(api::ProblemKind::shutting_down, "draining before shutdown");
    return content(R"({"status":"ready"})", "application/json");
  }
  if (path == "/metrics") return content(metrics_.render(), "text/plain; version=0.0.4; charset=utf-8");
  if (path == "/openapi.yaml") return content(api::openapi_yaml(), "application/yaml");
  if (path == "/openapi.json") return content(api::openapi_json(), "application/json");
  if (const auto file = find_static_file(path)) return content(file->content, file->content_type);
  if (api::is_post_route(path)) {
    Response response = problem_response(api::ProblemKind::method_not_allowed, "use POST on " + std::string(path));
    response.headers.emplace_back("Allow", "POST");
    return response;
  }
  return problem_response(api::ProblemKind::not_found, no_route(path));
}

std::optional<Response> Router::check_post(const RequestView& request) const {
  const std::string path(request.path);
  if (!api::is_post_route(path)) {
    if (is_get_route(path)) {
      Response response = problem_response(api::ProblemKind::method_not_allowed, "use GET on " + path);
      response.headers.emplace_back("Allow", "GET, HEAD");
      return response;
    }
    return problem_response(api::ProblemKind::not_found, no_route(path));
  }
  if (!authorized(request)) {
    Response response =
        problem_response(api::ProblemKind::unauthorized, "send Authorization: Bearer <token>");
    response.headers.emplace_back("WWW-Authenticate", "Bearer");
    return response;
  }
  const std::string_view type = request.header("Content-Type");
  if (!is_json_media_type(type)) {
    return problem_response(api::ProblemKind::unsupported_media_type,
                            "Content-Type must be application/json, got '" + std::string(type) + "'");
  }
  const std::string_view coding = request.header("Content-Encoding");
  if (!only_identity_coding(coding)) {
    Response response = problem_response(api::ProblemKind::unsupported_media_type,
                                         "Content-Encoding must be identity (no coding), got '" +
                                             std::string(coding) + "'");
    response.headers.emplace_back("Accept-Encoding", "identity");  // RFC 9110 §15.5.16
    return response;
  }
  return std::nullopt;
}

Response Router::answer_other_method(const RequestView& request) const {
  const std::string path(request.path);
  const char* allow = nullptr;
  if (api::is_post_route(path)) {
    allow = "POST";
  } else if (is_get_route(path)) {
    allow = "GET, HEAD";
  } else {
    return problem_response(api::ProblemKind::not_found, no_route(path));
  }
  Response response = problem_response(api::ProblemKind::method_not_allowed,
                                       std::string(request.method) + " is not allowed on " + path);
  response.headers.emplace_back("Allow", allow);
  return response;
}

Response Router::compute(std::string_view path, std::string_view body, const api::Limits& limits) {
  if (path == api::kBatchPath) {
    api::BatchRun batch = start_batch(body, limits);
    for (;;) {
      if (auto response = compute_batch_item(batch)) return std::move(*response);
    }
  }
  return guarded(path, [&] { return to_response(api::handle(path, body, limits)); });
}

api::BatchRun Router::start_batch(std::string_view body, const api::Limits& limits) {
  std::optional<api::BatchRun> batch;
  const Response failed = guarded(api::kBatchPath, [&] {
    batch.emplace(api::start_batch(body, limits));
    return Response{};
  });
  if (!batch) return api::BatchRun(api::Reply{failed.status, failed.content_type, failed.body});
  return std::move(*batch);
}

std::optional<Response> Router::compute_batch_item(api::BatchRun& batch) {
  const auto count_item = [this](std::string_view item_path, const api::Reply& reply) {
    metrics_.batch_item_finished(item_path, reply.status);
    if (reply.decided_by_work_cap) metrics_.work_cap_hit();
  };
  if (!batch.finished()) {
    bool computed = false;
    Response failure = guarded(api::kBatchPath, [&] {
      batch.compute_next(count_item);
      computed = true;
      return Response{};
    });
    if (!computed) return failure;
  }
  if (!batch.finished()) return std::nullopt;
  return to_response(batch.take_answer());
}

Response Router::guarded(std::string_view path, const std::function<Response()>& compute_answer) {
  std::string what = "unknown exception";
  try {
    return compute_answer();
  } catch (const std::exception& e) {
    what = e.what();
  } catch (...) {
  }
  log_.error("bug: exception escaped api::handle for POST {}: {}", path, what);
  return problem_response(api::ProblemKind::internal, "internal error; it has been logged");
}

bool Router::authorized(const RequestView& request) const {
  if (config_.auth_token.empty()) return true;
  // RFC 9110 §11.4: credentials = auth-scheme 1*SP token68, the scheme name
  // case-insensitive (§11.1): "Bearer", "bearer" and "BEARER" are one scheme.
  constexpr std::string_view kScheme = "Bearer";
  std::string_view credentials = request.header("Authorization");
  if (credentials.size() <= kScheme.size() || !iequals(credentials.substr(0, kScheme.size()), kScheme) ||
      credentials[kScheme.size()] != ' ') {
    return false;
  }
  credentials.remove_prefix(kScheme.size());
  while (!credentials.empty() && credentials.front() == ' ') credentials.remove_prefix(1);
  const std::string& expected = config_.auth_token;
  // Constant-time comparison: the time taken must not reveal how much of a guess matched.
  if (credentials.size() != expected.size()) return false;
  unsigned char diff = 0;
  for (std::size_t i = 0; i < credentials.size(); ++i) {
    diff |= static_cast<unsigned char>(credentials[i] ^ expected[i]);
  }
  return diff == 0;
}

void Router::finish(const Exchange& exchange, std::string_view method, std::string_view path, int status,
                    std::size_t bytes_sent) {
  const double seconds = std::chrono::duration<double>(Clock::now() - exchange.start).count();
  metrics_.request_finished(path, status, seconds);
  log_access(method, path, status, seconds, exchange.id, exchange.client, bytes_sent);
}

void Router::finish_unrouted(std::string_view method, std::string_view path, int status, std::string_view client,
                             std::size_t bytes_sent) {
  metrics_.request_started();
  metrics_.request_finished(path, status, 0.0);
  log_access(method, path, status, 0.0, "-", client, bytes_sent);
}

void Router::abandon(const Exchange& exchange, std::string_view method, std::string_view path) {
  metrics_.request_dropped();
  const double seconds = std::chrono::duration<double>(Clock::now() - exchange.start).count();
  log_access(method, path, 499, seconds, exchange.id, exchange.client, 0);
}

void Router::log_access(std::string_view method, std::string_view path, int status, double seconds,
                        std::string_view id, std::string_view client, std::size_t bytes_sent) {
  auto& logger = log_.logger();
  if (!logger.should_log(spdlog::level::info)) return;
  // The method and path are the client's bytes: json_escape keeps the line valid UTF-8
  // JSON whatever they are.
  if (config_.log_format == LogFormat::json) {
    logger.info(R"("msg":"access","method":"{}","path":"{}","status":{},"duration_ms":{:.3f},"request_id":"{}",)"
                R"("client":"{}","bytes_sent":{})",
                json_escape(method), json_escape(path), status, seconds * 1e3, id, json_escape(client), bytes_sent);
  } else {
    logger.info("{} {} {} {:.3f}ms id={} client={} bytes={}", method, path, status, seconds * 1e3, id, client,
                bytes_sent);
  }
}

}  // namespace bezier::service
