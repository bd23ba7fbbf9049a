#pragma once

#include <condition_variable>
#include <cstddef>
#include <cstdint>
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
/// waiting work (and its memory) grow without bound. A task no worker has taken yet can
/// be withdrawn (its deadline passed, its client went away): it then never runs and
/// frees its place in the queue at once, whatever the workers are doing. A task may run
/// in steps (requeue()), each queued behind the tasks waiting when the last one ended, so
/// that a long task shares the workers with the requests that arrive while it runs.
class ComputePool {
 public:
  /// Names a queued task for withdraw(); 0 is never a task.
  using Ticket = std::uint64_t;

  ComputePool(std::size_t threads, std::size_t max_queued);
  /// Runs the tasks still queued, then joins the workers.
  ~ComputePool();
  ComputePool(const ComputePool&) = delete;
  ComputePool& operator=(const ComputePool&) = delete;

  /// Queues `task`; its ticket, or 0 (and `task` is dropped) when max_queued tasks are
  /// waiting.
  [[nodiscard]] Ticket submit(std::function<void()> task);
  /// Queues the next step of a task a worker is running (a batch's next item), behind the
  /// tasks that wait, whatever their number: it was admitted when its first step was
  /// submitted. Steps count in the queue's length, which submit() compares with
  /// max_queued, and a worker queues at most one step per task it takes, so the queue
  /// holds at most max_queued plus one per worker. A step cannot be withdrawn.
  void requeue(std::function<void()> step);
  /// Takes the task out of the queue if no worker has taken it yet: true when it was
  /// there (it will never run, and is destroyed before this returns), false when a
  /// worker runs or ran it.
  bool withdraw(Ticket ticket);

 private:
  struct Queued {
    Ticket ticket;
    std::function<void()> task;
  };
  void work();

  const std::size_t max_queued_;
  std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<Queued> tasks_;
  Ticket next_ticket_ = 1;
  std::vector<std::thread> workers_;
  bool stopping_ = false;
};

}  // namespace bezier::service
