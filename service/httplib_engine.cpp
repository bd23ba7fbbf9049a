#include "service/httplib_engine.hpp"

#include <chrono>
#include <optional>
#include <thread>

#include <sys/socket.h>

#include "service/elastic_task_queue.hpp"

namespace bezier::service {

namespace {

// cpp-httplib serves one request at a time per thread, from the pre-routing hook to
// the logger hook, so the request's Exchange can live in thread-local storage instead
// of a per-request allocation.
thread_local std::optional<Exchange> t_exchange;

void write_response(httplib::Response& out, Response response) {
  out.status = response.status;
  for (auto& [name, value] : response.headers) out.set_header(std::string(name).c_str(), value);
  out.set_content(std::move(response.body), response.content_type.c_str());
}

RequestView view_of(const httplib::Request& request) {
  return {request.method, request.path,
          [&request](std::string_view name) -> std::string_view {
            const auto found = request.headers.find(std::string(name));
            return found == request.headers.end() ? std::string_view() : std::string_view(found->second);
          },
          request.body};
}

}  // namespace

bool HttpServer::widen_backlog(int backlog) noexcept { return ::listen(svr_sock_, backlog) == 0; }

HttplibEngine::HttplibEngine(Router& router) : router_(router) {
  const Config& config = router_.config();
  // Without TCP_NODELAY each keep-alive answer waits for the peer's delayed ACK
  // (~40 ms): about 290 requests/s per connection instead of tens of thousands.
  http_.set_tcp_nodelay(true);
  http_.set_keep_alive_timeout(config.keep_alive_timeout_s);
  http_.set_keep_alive_max_count(static_cast<std::size_t>(config.keep_alive_max_requests));
  http_.set_read_timeout(config.read_timeout_s, 0);
  http_.set_write_timeout(config.write_timeout_s, 0);
  http_.set_payload_max_length(config.limits.max_body_bytes);
  const auto min_threads = static_cast<std::size_t>(config.threads);
  const auto max_threads = static_cast<std::size_t>(config.max_connections);
  http_.new_task_queue = [min_threads, max_threads] {
    return new ElasticTaskQueue(min_threads, max_threads);
  };
  install_routes();
}

int HttplibEngine::bind() {
  const Config& config = router_.config();
  int port = -1;
  if (config.port == 0) {
    port = http_.bind_to_any_port(config.host);
  } else if (http_.bind_to_port(config.host, config.port)) {
    port = config.port;
  }
  if (port >= 0 && !http_.widen_backlog(SOMAXCONN)) router_.log().warn("could not widen the listen backlog");
  return port;
}

bool HttplibEngine::serve() {
  const bool ok = http_.listen_after_bind();
  serve_returned_.store(true);
  return ok;
}

void HttplibEngine::stop() {
  while (!http_.is_running() && !serve_returned_.load()) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  http_.stop();
}

void HttplibEngine::handle(const httplib::Request& request, httplib::Response& response) {
  const RequestView view = view_of(request);
  std::optional<Response> answer = router_.answer(view);
  if (!answer) answer = router_.compute(view.path, view.body, router_.config().limits);
  write_response(response, std::move(*answer));
}

void HttplibEngine::install_routes() {
  http_.set_pre_routing_handler([this](const httplib::Request& request, httplib::Response& response) {
    t_exchange = router_.begin(view_of(request));
    response.set_header("X-Request-Id", t_exchange->id);
    return httplib::Server::HandlerResponse::Unhandled;
  });
  const auto handler = [this](const httplib::Request& request, httplib::Response& response) {
    handle(request, response);
  };
  // HEAD reaches the GET handler (httplib leaves the body out); the router decides
  // 404/405 for every method.
  http_.Get(".*", handler);
  http_.Post(".*", handler);
  http_.Put(".*", handler);
  http_.Patch(".*", handler);
  http_.Delete(".*", handler);
  http_.Options(".*", handler);

  // Statuses httplib decides itself (413, 400 for an unparsable request line, 404 if a
  // route fell through) still answer problem+json; answers we wrote are left alone.
  http_.set_error_handler([](const httplib::Request&, httplib::Response& response) {
    if (!response.body.empty()) return;
    switch (response.status) {
      case 413:
        write_response(response, problem_response(api::ProblemKind::payload_too_large,
                                                  "request body is larger than the limit"));
        break;
      case 404:
        write_response(response, problem_response(api::ProblemKind::not_found, "no such route"));
        break;
      default: {
        const int status = response.status >= 400 ? response.status : 400;
        write_response(response, problem_response(api::ProblemKind::malformed_json, "malformed HTTP request"));
        response.status = status;
      }
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
    router_.log().error("bug: exception escaped a handler for {} {}: {}", request.method, request.path, what);
    write_response(response, problem_response(api::ProblemKind::internal, "internal error; it has been logged"));
  });
  http_.set_logger([this](const httplib::Request& request, const httplib::Response& response) {
    if (t_exchange) {
      router_.finish(*t_exchange, request.method, request.path, response.status);
      t_exchange.reset();
    } else {
      // httplib answered before routing (413, malformed request line): count it too.
      router_.finish_unrouted(request.method, request.path, response.status);
    }
  });
}

}  // namespace bezier::service
