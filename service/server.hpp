#pragma once

#include "service/config.hpp"
#include "service/epoll_engine.hpp"
#include "service/log.hpp"
#include "service/router.hpp"

namespace bezier::service {

/// The HTTP front of the service: the Router (every transport-neutral decision) behind
/// the epoll engine.
class Server {
 public:
  Server(const Config& config, Log log) : router_(config, std::move(log)), engine_(router_) {}

  /// Binds the listening socket: the port bound (the chosen one for port 0), or the error.
  [[nodiscard]] BindResult bind() { return engine_.bind(); }
  /// Serves until stop(); returns false if the listener failed.
  bool serve() { return engine_.serve(); }
  /// From now on /readyz answers 503 (load balancers stop sending); still serving.
  void begin_draining() noexcept { router_.begin_draining(); }
  /// Closes the listener; serve() returns once in-flight requests are answered. Safe
  /// to call before serve() has started (a signal right after start).
  void stop() { engine_.stop(); }

 private:
  Router router_;
  EpollEngine engine_;
};

}  // namespace bezier::service
