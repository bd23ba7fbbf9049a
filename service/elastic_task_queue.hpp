#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include <httplib.h>

namespace bezier::service {

/// The task queue behind cpp-httplib's server. httplib 0.11.4 hands each accepted
/// connection to one task that serves it until it closes, keep-alive included, so a
/// fixed pool of N threads stalls the N+1-th client until a connection ends (a 64-
/// connection wrk run against 8 threads leaves 56 connections unanswered). This queue
/// starts `min_threads` workers and starts another whenever a connection arrives while
/// every worker is busy, up to `max_threads`; beyond that connections wait in order.
/// Workers that were started stay (no shrinking): the count follows the high-water
/// mark of concurrent connections, and an idle worker costs a stack, not CPU.
class ElasticTaskQueue final : public httplib::TaskQueue {
 public:
  ElasticTaskQueue(std::size_t min_threads, std::size_t max_threads);
  ~ElasticTaskQueue() override;
  ElasticTaskQueue(const ElasticTaskQueue&) = delete;
  ElasticTaskQueue& operator=(const ElasticTaskQueue&) = delete;

  void enqueue(std::function<void()> task) override;
  /// Lets queued and running tasks finish, then joins every worker.
  void shutdown() override;

 private:
  void start_worker();  // requires mutex_ held
  void work();

  const std::size_t max_threads_;
  std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<std::function<void()>> tasks_;
  std::vector<std::thread> workers_;
  std::size_t idle_ = 0;
  bool stopping_ = false;
};

}  // namespace bezier::service
