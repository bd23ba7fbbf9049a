#pragma once

namespace bezier::service {

/// An HTTP/1.1 transport in front of the Router: cpp-httplib's thread per connection
/// (HttplibEngine) or one epoll event loop per I/O thread (EpollEngine), chosen by
/// --http-engine so the two can be compared on the same binary.
class HttpEngine {
 public:
  virtual ~HttpEngine() = default;
  /// Binds the listening socket(s); returns the port (the chosen one for port 0) or -1.
  [[nodiscard]] virtual int bind() = 0;
  /// Serves until stop(); returns false if the listener failed.
  virtual bool serve() = 0;
  /// Closes the listener; serve() returns once in-flight requests are answered and idle
  /// connections closed. Safe to call before serve() has started.
  virtual void stop() = 0;
};

}  // namespace bezier::service
