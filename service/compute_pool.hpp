#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace bezier::service {

/// The threads that run requests too expensive for an I/O thread (the epoll engine's
/// event loops must never stall their other connections on one request). A fixed
/// number of workers takes tasks in order from a bounded queue: when it is full,
/// submit() refuses, and the caller answers 503 with Retry-After rather than letting
/// waiting work (and its memory) grow without bound.
class ComputePool {
 public:
  ComputePool(std::size_t threads, std::size_t max_queued);
  /// Runs the tasks still queued, then joins the workers.
  ~ComputePool();
  ComputePool(const ComputePool&) = delete;
  ComputePool& operator=(const ComputePool&) = delete;

  /// Queues `task`; false (and `task` is dropped) when max_queued tasks are waiting.
  [[nodiscard]] bool submit(std::function<void()> task);

 private:
  void work();

  const std::size_t max_queued_;
  std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<std::function<void()>> tasks_;
  std::vector<std::thread> workers_;
  bool stopping_ = false;
};

}  // namespace bezier::service
