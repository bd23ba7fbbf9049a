#include "service/server.hpp"

#include <chrono>
#include <random>
#include <thread>

#include <sys/socket.h>

#include "api/handler.hpp"
#include "api/problem.hpp"
#include "service/elastic_task_queue.hpp"
#include "service/log.hpp"
#include "service/static_files.hpp"

namespace bezier::service {

namespace {

using Clock = std::chrono::steady_clock;

// cpp-httplib serves one request at a time per thread, from the pre-routing hook to
// the logger hook, so the request's start time and id can live in thread-local storage
// instead of a per-request allocation.
struct RequestScope {
  Clock::time_point start{};
  bool active = false;
  std::string id;
};
thread_local RequestScope t_request;

void write_reply(httplib::Response& response, const api::Reply& reply) {
  response.status = reply.status;
  response.set_content(reply.body, reply.content_type.c_str());
}

void write_problem(httplib::Response& response, api::ProblemKind kind, std::string detail) {
  write_reply(response, api::problem_reply(kind, std::move(detail)));
}

bool is_json_media_type(const std::string& content_type) {
  // "application/json", optionally with parameters, or any "+json" suffix type.
  const std::string type = content_type.substr(0, content_type.find(';'));
  std::string lower;
  for (const char c : type) {
    if (c != ' ' && c != '\t') lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return lower == "application/json" ||
         (lower.size() > 5 && lower.compare(lower.size() - 5, 5, "+json") == 0 &&
          lower.rfind("application/", 0) == 0);
}

// A client's X-Request-Id is kept when it is short and plain; otherwise one is made.
std::string request_id_for(const httplib::Request& request) {
  const std::string& given = request.get_header_value("X-Request-Id");
  bool plain = !given.empty() && given.size() <= 64;
  for (const char c : given) plain = plain && (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.');
  if (plain) return given;
  thread_local std::mt19937_64 random{std::random_device{}()};
  char id[17];
  std::snprintf(id, sizeof id, "%016llx", static_cast<unsigned long long>(random()));
  return id;
}

constexpr std::string_view kGetRoutes[] = {"/healthz", "/readyz", "/metrics", "/openapi.yaml"};

bool is_get_route(std::string_view path) {
  for (const auto r : kGetRoutes) {
    if (r == path) return true;
  }
  return find_static_file(path).has_value();
}

}  // namespace

Server::Server(const Config& config, Log log) : config_(config), log_(std::move(log)) {
  // Without TCP_NODELAY each keep-alive answer waits for the peer's delayed ACK
  // (~40 ms): about 290 requests/s per connection instead of tens of thousands.
  http_.set_tcp_nodelay(true);
  http_.set_keep_alive_timeout(config_.keep_alive_timeout_s);
  http_.set_keep_alive_max_count(static_cast<std::size_t>(config_.keep_alive_max_requests));
  http_.set_read_timeout(config_.read_timeout_s, 0);
  http_.set_write_timeout(config_.write_timeout_s, 0);
  http_.set_payload_max_length(config_.limits.max_body_bytes);
  const auto min_threads = static_cast<std::size_t>(config_.threads);
  const auto max_threads = static_cast<std::size_t>(config_.max_connections);
  http_.new_task_queue = [min_threads, max_threads] {
    return new ElasticTaskQueue(min_threads, max_threads);
  };
  install_routes();
}

bool HttpServer::widen_backlog(int backlog) noexcept { return ::listen(svr_sock_, backlog) == 0; }

int Server::bind() {
  int port = -1;
  if (config_.port == 0) {
    port = http_.bind_to_any_port(config_.host);
  } else if (http_.bind_to_port(config_.host, config_.port)) {
    port = config_.port;
  }
  if (port >= 0 && !http_.widen_backlog(SOMAXCONN)) log_.warn("could not widen the listen backlog");
  return port;
}

bool Server::serve() {
  const bool ok = http_.listen_after_bind();
  serve_returned_.store(true);
  return ok;
}

void Server::stop() {
  while (!http_.is_running() && !serve_returned_.load()) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  http_.stop();
}

void Server::install_routes() {
  http_.set_pre_routing_handler([this](const httplib::Request& request, httplib::Response& response) {
    t_request.start = Clock::now();
    t_request.active = true;
    t_request.id = request_id_for(request);
    response.set_header("X-Request-Id", t_request.id);
    metrics_.request_started();
    return httplib::Server::HandlerResponse::Unhandled;
  });
  http_.Get(".*", [this](const auto& request, auto& response) { handle_get(request, response); });
  http_.Post(".*", [this](const httplib::Request& request, httplib::Response& response) {
    handle_post(request, response);
  });
  const auto other = [this](const httplib::Request& request, httplib::Response& response) {
    handle_other_method(request, response);
  };
  http_.Put(".*", other);
  http_.Patch(".*", other);
  http_.Delete(".*", other);
  http_.Options(".*", other);

  // Statuses httplib decides itself (413, 400 for an unparsable request line, 404 if a
  // route fell through) still answer problem+json; answers we wrote are left alone.
  http_.set_error_handler([](const httplib::Request&, httplib::Response& response) {
    if (!response.body.empty()) return;
    switch (response.status) {
      case 413:
        write_problem(response, api::ProblemKind::payload_too_large, "request body is larger than the limit");
        break;
      case 404:
        write_problem(response, api::ProblemKind::not_found, "no such route");
        break;
      default:
        write_problem(response, api::ProblemKind::malformed_json, "malformed HTTP request");
        response.status = response.status >= 400 ? response.status : 400;
    }
  });
  http_.set_exception_handler([this](const httplib::Request& request, httplib::Response& response,
                                     std::exception_ptr error) {
    std::string what = "unknown exception";
    try {
      if (error) std::rethrow_exception(error);
    } catch (const std::exception& e) {
      what = e.what();
    } catch (...) {
    }
    log_.error("bug: exception escaped a handler for {} {}: {}", request.method, request.path, what);
    write_problem(response, api::ProblemKind::internal, "internal error; it has been logged");
  });
  http_.set_logger([this](const httplib::Request& request, const httplib::Response& response) {
    log_access(request, response);
  });
}

bool Server::authorized(const httplib::Request& request) const {
  if (config_.auth_token.empty()) return true;
  const std::string& header = request.get_header_value("Authorization");
  const std::string expected = "Bearer " + config_.auth_token;
  // Constant-time comparison: the time taken must not reveal how much of a guess matched.
  if (header.size() != expected.size()) return false;
  unsigned char diff = 0;
  for (std::size_t i = 0; i < header.size(); ++i) {
    diff |= static_cast<unsigned char>(header[i] ^ expected[i]);
  }
  return diff == 0;
}

void Server::handle_get(const httplib::Request& request, httplib::Response& response) {
  const std::string& path = request.path;
  if (path == "/healthz") {
    response.set_content(R"({"status":"ok"})", "application/json");
  } else if (path == "/readyz") {
    if (draining_.load()) {
      write_problem(response, api::ProblemKind::shutting_down, "draining before shutdown");
    } else {
      response.set_content(R"({"status":"ready"})", "application/json");
    }
  } else if (path == "/metrics") {
    response.set_content(metrics_.render(), "text/plain; version=0.0.4; charset=utf-8");
  } else if (path == "/openapi.yaml") {
    const auto spec = api::openapi_yaml();
    response.set_content(spec.data(), spec.size(), "application/yaml");
  } else if (const auto file = find_static_file(path)) {
    response.set_content(file->content.data(), file->content.size(), std::string(file->content_type).c_str());
  } else if (api::is_post_route(path)) {
    response.set_header("Allow", "POST");
    write_problem(response, api::ProblemKind::method_not_allowed, "use POST on " + path);
  } else {
    write_problem(response, api::ProblemKind::not_found, "no route " + path);
  }
}

void Server::handle_post(const httplib::Request& request, httplib::Response& response) {
  const std::string& path = request.path;
  if (!api::is_post_route(path)) {
    if (is_get_route(path)) {
      response.set_header("Allow", "GET, HEAD");
      write_problem(response, api::ProblemKind::method_not_allowed, "use GET on " + path);
    } else {
      write_problem(response, api::ProblemKind::not_found, "no route " + path);
    }
    return;
  }
  if (!authorized(request)) {
    response.set_header("WWW-Authenticate", "Bearer");
    write_problem(response, api::ProblemKind::unauthorized, "send Authorization: Bearer <token>");
    return;
  }
  if (!is_json_media_type(request.get_header_value("Content-Type"))) {
    write_problem(response, api::ProblemKind::unsupported_media_type,
                  "Content-Type must be application/json, got '" +
                      request.get_header_value("Content-Type") + "'");
    return;
  }
  write_reply(response, api::handle(path, request.body, config_.limits));
}

void Server::handle_other_method(const httplib::Request& request, httplib::Response& response) {
  if (api::is_post_route(request.path)) {
    response.set_header("Allow", "POST");
  } else if (is_get_route(request.path)) {
    response.set_header("Allow", "GET, HEAD");
  } else {
    write_problem(response, api::ProblemKind::not_found, "no route " + request.path);
    return;
  }
  write_problem(response, api::ProblemKind::method_not_allowed,
                request.method + " is not allowed on " + request.path);
}

void Server::log_access(const httplib::Request& request, const httplib::Response& response) {
  double seconds = 0.0;
  if (t_request.active) {
    seconds = std::chrono::duration<double>(Clock::now() - t_request.start).count();
    metrics_.request_finished(request.path, response.status, seconds);
  } else {
    // httplib answered before routing (413, malformed request line): count it too.
    metrics_.request_started();
    metrics_.request_finished(request.path, response.status, 0.0);
  }
  const std::string_view id = t_request.active ? std::string_view(t_request.id) : std::string_view("-");
  t_request.active = false;
  auto& logger = log_.logger();
  if (!logger.should_log(spdlog::level::info)) return;
  if (config_.log_format == LogFormat::json) {
    logger.info(R"("msg":"access","method":"{}","path":"{}","status":{},"duration_ms":{:.3f},"request_id":"{}")",
                  json_escape(request.method), json_escape(request.path), response.status,
                  seconds * 1e3, id);
  } else {
    logger.info("{} {} {} {:.3f}ms id={}", request.method, request.path, response.status,
                  seconds * 1e3, id);
  }
}

}  // namespace bezier::service
