#pragma once

#include <atomic>

#include <httplib.h>

#include "service/http_engine.hpp"
#include "service/router.hpp"

namespace bezier::service {

/// cpp-httplib's server with the listen backlog widened: the compiled library listens
/// with a backlog of 5, so when many keep-alive connections reconnect at once (after
/// --keep-alive-max-requests) the kernel drops SYNs and clients retry after a whole
/// second: measured as 1 s p99 latencies and wrk timeouts at 64 connections.
class HttpServer : public httplib::Server {
 public:
  /// Calls listen() again on the bound socket, which Linux allows to change the backlog.
  bool widen_backlog(int backlog) noexcept;
};

/// The Router behind cpp-httplib 0.11.4 (--http-engine httplib): one blocking thread
/// per keep-alive connection (ElasticTaskQueue), every request computed on it. This
/// class adds only what httplib decides itself: its limits and timeouts, and the
/// problem+json rendering of the errors it answers before routing (413, 400).
class HttplibEngine final : public HttpEngine {
 public:
  explicit HttplibEngine(Router& router);

  [[nodiscard]] int bind() override;
  bool serve() override;
  /// Waits for the listener to run first: httplib ignores a stop() that comes before
  /// listening (a signal right after start).
  void stop() override;

 private:
  void install_routes();
  void handle(const httplib::Request& request, httplib::Response& response);

  Router& router_;
  HttpServer http_;
  std::atomic<bool> serve_returned_{false};
};

}  // namespace bezier::service
