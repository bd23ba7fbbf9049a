#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <vector>

#include "service/compute_pool.hpp"
#include "service/event_loop.hpp"
#include "service/http_engine.hpp"
#include "service/router.hpp"

namespace bezier::service {

/// The Router behind our own HTTP/1.1 front end (--http-engine epoll): one EventLoop
/// per I/O thread (--io-threads, default one per core), each with its own
/// SO_REUSEPORT listening socket, and one ComputePool (--threads) for the requests that
/// are not cheap. Why this shape: BENCHMARKS.md §3 (thread per connection costs ~30 µs
/// of kernel and scheduling per request; a loop that computes stalls its connections).
class EpollEngine final : public HttpEngine {
 public:
  explicit EpollEngine(Router& router);
  ~EpollEngine() override;

  [[nodiscard]] int bind() override;
  bool serve() override;
  void stop() override;

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
