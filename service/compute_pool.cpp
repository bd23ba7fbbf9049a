#include "service/compute_pool.hpp"

#include <algorithm>

namespace bezier::service {

ComputePool::ComputePool(std::size_t threads, std::size_t max_queued) : max_queued_(max_queued) {
  workers_.reserve(threads);
  for (std::size_t i = 0; i < threads; ++i) workers_.emplace_back([this] { work(); });
}

ComputePool::~ComputePool() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  ready_.notify_all();
  for (auto& w : workers_) w.join();
}

ComputePool::Ticket ComputePool::submit(std::function<void()> task) {
  Ticket ticket = 0;
  {
    const std::lock_guard lock(mutex_);
    if (tasks_.size() >= max_queued_) return 0;
    ticket = next_ticket_++;
    tasks_.push_back({ticket, std::move(task)});
  }
  ready_.notify_one();
  return ticket;
}

void ComputePool::requeue(std::function<void()> step) {
  {
    const std::lock_guard lock(mutex_);
    // Withdrawal finds no ticket of a step: nobody holds it (0 is never a task's).
    tasks_.push_back({0, std::move(step)});
  }
  ready_.notify_one();
}

bool ComputePool::withdraw(Ticket ticket) {
  if (ticket == 0) return false;  // a step's
  std::function<void()> dropped;  // destroyed after the lock is released
  {
    const std::lock_guard lock(mutex_);
    // The queue holds at most max_queued tasks and a step per worker.
    const auto found = std::find_if(tasks_.begin(), tasks_.end(), [ticket](const Queued& q) { return q.ticket == ticket; });
    if (found == tasks_.end()) return false;
    dropped = std::move(found->task);
    tasks_.erase(found);
  }
  return true;
}

void ComputePool::work() {
  for (;;) {
    std::function<void()> task;
    {
      std::unique_lock lock(mutex_);
      ready_.wait(lock, [this] { return stopping_ || !tasks_.empty(); });
      if (tasks_.empty()) return;  // stopping, and nothing left to run
      task = std::move(tasks_.front().task);
      tasks_.pop_front();
    }
    task();
  }
}

}  // namespace bezier::service
