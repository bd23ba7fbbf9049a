#pragma once

#include <atomic>
#include <memory>

#include <httplib.h>
#include <spdlog/logger.h>

#include "service/config.hpp"
#include "service/log.hpp"
#include "service/metrics.hpp"

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

/// The HTTP front of the service: cpp-httplib set up with our routes, limits, hooks and
/// task queue. Every POST route goes to api::handle; this class adds only what needs
/// HTTP: methods, content type, body size, authentication, health, metrics, logging.
class Server {
 public:
  Server(const Config& config, Log log);

  /// Binds the listening socket; returns the port (the chosen one for port 0) or -1.
  [[nodiscard]] int bind();
  /// Serves until stop(); returns false if the listener failed.
  bool serve();
  /// From now on /readyz answers 503 (load balancers stop sending); still serving.
  void begin_draining() noexcept { draining_.store(true); }
  /// Closes the listener; serve() returns once in-flight requests are answered. Safe
  /// to call before serve() has started (a signal right after start): it waits for the
  /// listener to run, because httplib ignores a stop() that comes before listening.
  void stop();

 private:
  void install_routes();
  void handle_get(const httplib::Request& request, httplib::Response& response);
  void handle_post(const httplib::Request& request, httplib::Response& response);
  void handle_other_method(const httplib::Request& request, httplib::Response& response);
  [[nodiscard]] bool authorized(const httplib::Request& request) const;
  void log_access(const httplib::Request& request, const httplib::Response& response);

  const Config config_;
  Log log_;
  HttpServer http_;
  Metrics metrics_;
  std::atomic<bool> draining_{false};
  std::atomic<bool> serve_returned_{false};
};

}  // namespace bezier::service
