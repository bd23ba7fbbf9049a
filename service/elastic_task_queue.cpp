#include "service/elastic_task_queue.hpp"

#include <algorithm>

namespace bezier::service {

ElasticTaskQueue::ElasticTaskQueue(std::size_t min_threads, std::size_t max_threads)
    : max_threads_(std::max(max_threads, min_threads)) {
  const std::lock_guard lock(mutex_);
  for (std::size_t i = 0; i < min_threads; ++i) start_worker();
}

ElasticTaskQueue::~ElasticTaskQueue() { shutdown(); }

void ElasticTaskQueue::start_worker() {
  workers_.emplace_back([this] { work(); });
}

void ElasticTaskQueue::enqueue(std::function<void()> task) {
  {
    const std::lock_guard lock(mutex_);
    tasks_.push_back(std::move(task));
    // Every queued task needs an idle worker of its own, or it waits behind a
    // connection that may stay open for a long time.
    if (!stopping_ && tasks_.size() > idle_ && workers_.size() < max_threads_) start_worker();
  }
  ready_.notify_one();
}

void ElasticTaskQueue::shutdown() {
  std::vector<std::thread> workers;
  {
    const std::lock_guard lock(mutex_);
    if (stopping_ && workers_.empty()) return;
    stopping_ = true;
    workers.swap(workers_);
  }
  ready_.notify_all();
  for (auto& w : workers) w.join();
}

void ElasticTaskQueue::work() {
  for (;;) {
    std::function<void()> task;
    {
      std::unique_lock lock(mutex_);
      ++idle_;
      ready_.wait(lock, [this] { return stopping_ || !tasks_.empty(); });
      --idle_;
      if (tasks_.empty()) return;  // stopping, and nothing left to serve
      task = std::move(tasks_.front());
      tasks_.pop_front();
    }
    task();
  }
}

}  // namespace bezier::service
