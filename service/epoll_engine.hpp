#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "service/compute_pool.hpp"
#include "service/event_loop.hpp"
#include "service/router.hpp"

namespace bezier::service {

/// The service's HTTP/1.1 front end: the Router behind one EventLoop per I/O thread
/// (--io-threads; 0 sizes them from the CPUs the process may use, service/cpu_budget.hpp)
/// and one ComputePool (--threads) for the requests that are not cheap. Why this shape:
/// BENCHMARKS.md ("HTTP"): a thread per connection pays kernel scheduling on every
/// request, and a loop that computes stalls its connections.
///
/// The loops share one listening socket, bound without SO_REUSEPORT, and wait on it with
/// EPOLLEXCLUSIVE (nginx's default arrangement). One socket per loop with SO_REUSEPORT
/// would spread connections in the kernel, but would also let any later process of the
/// same user bind the same port and silently take a share of the connections; bound
/// this way, a second instance fails at start-up instead.
///
/// Why the service frames HTTP/1.1 itself (service/http_request_parser.hpp) rather than
/// serving through cpp-httplib's server: in front of proxies and the public network a
/// server must frame requests exactly as RFC 9112 says, or a proxy and the server
/// disagree on where a request ends. cpp-httplib's server (0.11.4) fails those rules: it
/// accepts two Content-Length headers of different values (RFC 9112 §6.3: an
/// unrecoverable error) and serves the bytes after the first length as a second,
/// smuggled request; it drops pipelined requests that arrive in one segment, so their
/// client waits for answers that never come; it accepts obs-fold, NUL and CR in header
/// values (RFC 9110 §5.5, RFC 9112 §5.2: reject, or replace with SP), whitespace between
/// a header name and its colon (RFC 9112 §5.1: 400) and header lines ended by a bare LF,
/// which a proxy may frame differently. A server library that fails them cannot be
/// fixed from outside; cpp-httplib stays the test suite's HTTP client.
/// The listening socket of EpollEngine::bind(), or why there is none.
struct BindResult {
  int fd = -1;
  int port = -1;       ///< the port bound (the one chosen for port 0)
  std::string error;   ///< when fd < 0: what failed, for the start-up message
};

class EpollEngine {
 public:
  explicit EpollEngine(Router& router);
  ~EpollEngine();
  EpollEngine(const EpollEngine&) = delete;
  EpollEngine& operator=(const EpollEngine&) = delete;

  /// Binds the listening socket, one descriptor of it per event loop; the port it is
  /// bound to (the chosen one for port 0), or the error.
  [[nodiscard]] BindResult bind();
  /// Serves until stop(); returns false if the listener failed.
  bool serve();
  /// Closes the listener; serve() returns once in-flight requests are answered and idle
  /// connections closed. Safe to call before serve() has started.
  void stop();

 private:
  Router& router_;
  std::vector<int> listen_fds_;
  std::atomic<int> open_connections_{0};
  std::mutex mutex_;  ///< guards loops_ against a stop() while serve() creates them
  bool stop_requested_ = false;
  std::unique_ptr<ComputePool> pool_;
  std::vector<std::unique_ptr<EventLoop>> loops_;
};

}  // namespace bezier::service
