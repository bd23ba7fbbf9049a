#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include "service/compute_pool.hpp"
#include "service/http_request_parser.hpp"
#include "service/http_response_writer.hpp"
#include "service/router.hpp"

namespace bezier::service {

/// One I/O thread of the epoll engine: it accepts from the listening socket the loops
/// share (EPOLLEXCLUSIVE: a connection wakes one waiting loop), reads, parses and
/// answers every connection it accepted, non-blocking and level-triggered. Cheap
/// requests are answered on the loop; the others go to the ComputePool and their
/// answers come back through an eventfd, so one slow request never holds up the
/// loop's other connections. A request that waits in the compute queue longer than
/// --queue-deadline is withdrawn and answered 503 by the sweep (within kSweepInterval of
/// its deadline, whatever the pool's threads are doing), and one whose connection closes
/// meanwhile (a reset or a FIN) is withdrawn and dropped. While a connection's unsent answers exceed a limit, its requests
/// wait unread until the client reads. Timeouts (read, keep-alive idle, write) are
/// checked by a sweep every kSweepInterval.
class EventLoop {
 public:
  /// Shared by the loops of one engine.
  struct Shared {
    Router& router;
    ComputePool& pool;
    std::atomic<int>& open_connections;  ///< over all loops, for max_connections
  };

  EventLoop(Shared shared, int listen_fd);
  ~EventLoop();
  EventLoop(const EventLoop&) = delete;
  EventLoop& operator=(const EventLoop&) = delete;

  /// Serves until stop() and every connection is closed; false if epoll failed.
  bool run();
  /// Thread-safe: closes the listener, answers what is in flight with
  /// "Connection: close", closes idle connections; run() returns once none is left.
  void stop();

  static constexpr std::chrono::milliseconds kSweepInterval{100};

 private:
  using Clock = std::chrono::steady_clock;
  struct Connection;
  /// A computed answer on its way from a pool thread back to the loop.
  struct Completion;
  /// What a request on the pool needs to be answered and logged when it comes back.
  struct Pending;

  void accept_all();
  void on_event(std::uint64_t id, std::uint32_t events);
  void read(Connection& c);
  /// Answers what the connection has buffered, as far as it may, sends, and sets the
  /// events it waits for.
  void process(Connection& c);
  /// Parses and answers (or hands to the pool) the buffered requests while it may.
  void answer_buffered_requests(Connection& c);
  void answer_expect_continue(Connection& c);
  void dispatch(Connection& c);
  /// On a compute thread: the answer to a queued request, posted back to the loop.
  void run_on_pool(std::uint64_t connection, const std::shared_ptr<Pending>& pending, std::string_view body);
  /// On a compute thread: the next item of a /batch, then its next step queued behind the
  /// requests waiting for a thread (ComputePool::requeue), or its answer posted back once
  /// every item is computed. A batch whose connection went away stops at its next item.
  void run_batch_item(std::uint64_t connection, const std::shared_ptr<Pending>& pending,
                      const std::shared_ptr<api::BatchRun>& batch);
  /// On a compute thread: posts the answer of a request back to the loop.
  void complete(std::uint64_t connection, const std::shared_ptr<Pending>& pending, Response response);
  /// Takes the connection's request out of the compute queue if no thread has taken it
  /// (the connection is no longer busy then; on_pool is left to the caller): whether it
  /// was there.
  bool withdraw_from_pool(Connection& c);
  [[nodiscard]] Response queue_deadline_problem() const;
  /// The client closed: its request, if still in the compute queue, is withdrawn, logged
  /// as abandoned and the connection closed (true); false when there is none waiting.
  bool drop_waiting_request(Connection& c);
  /// Queues the answer; the bytes it takes on the wire.
  std::size_t respond(Connection& c, const Response& response, const WireOptions& wire);
  void refuse(Connection& c, int status, std::string detail);
  void flush(Connection& c);
  void begin_lingering(Connection& c);
  void update_interest(Connection& c);
  void close(std::uint64_t id);
  void take_completions();
  void sweep(Clock::time_point now);
  void begin_stopping();
  [[nodiscard]] bool idle(const Connection& c) const noexcept;
  [[nodiscard]] static std::size_t unsent(const Connection& c) noexcept;
  /// Whether the connection's next request may be read, parsed and answered now.
  [[nodiscard]] static bool may_take_request(const Connection& c) noexcept;

  Shared shared_;
  const Config& config_;
  const ParserLimits parser_limits_;
  const api::Limits inline_limits_;
  const std::chrono::duration<double> queue_deadline_;
  int listen_fd_;
  int epoll_fd_ = -1;
  int wake_fd_ = -1;  ///< eventfd: completions and stop()
  std::uint64_t next_id_ = 2;
  std::unordered_map<std::uint64_t, std::unique_ptr<Connection>> connections_;
  std::atomic<bool> stop_requested_{false};
  bool stopping_ = false;
  bool listener_paused_ = false;  ///< out of descriptors: off the epoll set until the next sweep
  Clock::time_point next_sweep_{};

  std::mutex completions_mutex_;
  std::vector<Completion> completions_;
};

}  // namespace bezier::service
