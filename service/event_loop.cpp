#include "service/event_loop.hpp"

#include <cerrno>
#include <cstring>
#include <optional>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/epoll.h>
#include <sys/eventfd.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include "service/http_problem.hpp"
#include "service/inline_policy.hpp"
#include "service/memory_release.hpp"

namespace bezier::service {

namespace {

constexpr std::uint64_t kListenerId = 0;
constexpr std::uint64_t kWakeId = 1;
// While this much output waits for a slow reader, the connection's requests are neither
// read nor parsed nor answered (backpressure against a client that pipelines requests and
// never reads the answers): what a connection holds is bounded by this plus one answer.
constexpr std::size_t kMaxBufferedOutput = 1 << 20;
// The sent part of the output buffer is cut off once it is this long and at least as long
// as the unsent rest (so the move costs less than the sending did): a reader that keeps
// up slowly, never emptying the buffer, does not make it grow.
constexpr std::size_t kCompactSentOutput = 64 * 1024;

constexpr std::string_view kContinue = "HTTP/1.1 100 Continue\r\n\r\n";

// How long a connection we close is drained after its last answer (see begin_lingering).
constexpr std::chrono::seconds kLingerTime{2};

// Whether the client has sent bytes the loop has not read yet: when stopping, such a
// connection holds a request (it is read, answered with "Connection: close", closed),
// not an idle keep-alive connection.
bool has_unread_input(int fd) {
  int bytes = 0;
  return ioctl(fd, FIONREAD, &bytes) == 0 && bytes > 0;
}

// The peer's address as text ("192.0.2.7", "2001:db8::1"), "-" if it is not IP.
std::string address_text(const sockaddr_storage& address) {
  char text[INET6_ADDRSTRLEN] = "-";
  if (address.ss_family == AF_INET) {
    inet_ntop(AF_INET, &reinterpret_cast<const sockaddr_in&>(address).sin_addr, text, sizeof text);
  } else if (address.ss_family == AF_INET6) {
    inet_ntop(AF_INET6, &reinterpret_cast<const sockaddr_in6&>(address).sin6_addr, text, sizeof text);
  }
  return text;
}

}  // namespace

struct EventLoop::Pending {
  Exchange exchange;
  std::string method;
  std::string path;
  WireOptions wire;
  Clock::time_point queued_at;
  ComputePool::Ticket ticket = 0;  ///< its place in the compute queue, to withdraw it
  /// Set by the loop when it closes the connection (a reset, a failed send) after a
  /// pool thread took the request: nothing could be delivered any more, so the pool
  /// does not compute it if it has not started yet.
  std::atomic<bool> connection_gone{false};
};

struct EventLoop::Completion {
  std::uint64_t connection;
  std::shared_ptr<Pending> pending;
  Response response;
};

struct EventLoop::Connection {
  Connection(int socket, std::uint64_t connection_id, ParserLimits limits, Clock::time_point now)
      : fd(socket), id(connection_id), parser(limits), idle_since(now) {}

  int fd;
  std::uint64_t id;
  std::string client;  ///< the peer's address, for the access log
  HttpRequestParser parser;
  std::string in;  ///< received, not yet given to the parser (pipelined, or while busy)
  std::size_t in_pos = 0;
  std::string out;  ///< answers not yet sent
  std::size_t out_pos = 0;
  std::uint32_t interest = 0;   ///< the epoll events registered
  bool busy = false;            ///< a request of this connection is on the compute pool
  std::shared_ptr<Pending> on_pool;  ///< that request, while busy
  bool close_after_write = false;
  bool peer_closed = false;     ///< the client shut down its side: answer, then close
  bool fin_seen = false;        ///< EPOLLRDHUP came: the client's FIN is in the socket
  bool continue_sent = false;
  bool lingering = false;       ///< answered and shut down for writing; input is discarded
  int served = 0;
  Clock::time_point request_start{};  ///< first byte of the request being read
  Clock::time_point idle_since;       ///< last answer sent (keep-alive idle timeout)
  Clock::time_point write_since{};    ///< output has been waiting since (write timeout)
  Clock::time_point linger_since{};
};

EventLoop::EventLoop(Shared shared, int listen_fd)
    : shared_(shared),
      config_(shared.router.config()),
      parser_limits_{ParserLimits{}.max_head_bytes, config_.limits.max_body_bytes},
      inline_limits_(InlinePolicy::limits(config_.limits)),
      queue_deadline_(config_.queue_deadline_s),
      listen_fd_(listen_fd) {
  epoll_fd_ = epoll_create1(EPOLL_CLOEXEC);
  wake_fd_ = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
  epoll_event ev{};
  // EPOLLEXCLUSIVE: every loop waits on the same listening socket (EpollEngine::bind),
  // and a new connection wakes one waiting loop, not all of them.
  ev.events = EPOLLIN | EPOLLEXCLUSIVE;
  ev.data.u64 = kListenerId;
  epoll_ctl(epoll_fd_, EPOLL_CTL_ADD, listen_fd_, &ev);
  ev.events = EPOLLIN;
  ev.data.u64 = kWakeId;
  epoll_ctl(epoll_fd_, EPOLL_CTL_ADD, wake_fd_, &ev);
}

EventLoop::~EventLoop() {
  for (auto& [id, c] : connections_) ::close(c->fd);
  if (listen_fd_ >= 0) ::close(listen_fd_);
  if (wake_fd_ >= 0) ::close(wake_fd_);
  if (epoll_fd_ >= 0) ::close(epoll_fd_);
}

void EventLoop::stop() {
  stop_requested_.store(true);
  const std::uint64_t one = 1;
  [[maybe_unused]] const auto n = ::write(wake_fd_, &one, sizeof one);
}

bool EventLoop::run() {
  if (epoll_fd_ < 0 || wake_fd_ < 0) return false;
  std::vector<epoll_event> events(256);
  for (;;) {
    if (stop_requested_.load() && !stopping_) begin_stopping();
    if (stopping_ && connections_.empty()) return true;
    const int n = epoll_wait(epoll_fd_, events.data(), static_cast<int>(events.size()),
                             static_cast<int>(kSweepInterval.count()));
    if (n < 0 && errno != EINTR) return false;
    for (int i = 0; i < n; ++i) on_event(events[static_cast<std::size_t>(i)].data.u64,
                                         events[static_cast<std::size_t>(i)].events);
    const auto now = Clock::now();
    if (now >= next_sweep_) {
      sweep(now);
      next_sweep_ = now + kSweepInterval;
    }
  }
}

void EventLoop::on_event(std::uint64_t id, std::uint32_t events) {
  if (id == kListenerId) return accept_all();
  if (id == kWakeId) {
    std::uint64_t count = 0;
    [[maybe_unused]] const auto n = ::read(wake_fd_, &count, sizeof count);
    return take_completions();
  }
  const auto found = connections_.find(id);
  if (found == connections_.end()) return;
  Connection& c = *found->second;
  // EPOLLHUP: both directions are shut (a reset, or the client closed while we had
  // shut ours): nothing can be delivered any more. It is reported whatever the interest,
  // so it must close here or the loop would spin on it.
  if (events & (EPOLLERR | EPOLLHUP)) return close(id);
  // The client's FIN while its request is on the pool (reading is off meanwhile, so only
  // EPOLLRDHUP tells): a request still waiting for a thread is dropped.
  if ((events & EPOLLRDHUP) && !c.fin_seen) {
    c.fin_seen = true;
    if (drop_waiting_request(c)) return;
    update_interest(c);
  }
  if (events & EPOLLIN) read(c);
  if (connections_.count(id) == 0 || !(events & EPOLLOUT)) return;
  flush(c);
  // The client read enough for the output to drop below the limit: the requests that
  // waited in `in` meanwhile are taken up again.
  if (connections_.count(id) != 0 && may_take_request(c) && c.in_pos < c.in.size()) process(c);
}

void EventLoop::accept_all() {
  while (!stopping_) {
    sockaddr_storage peer{};
    socklen_t peer_length = sizeof peer;
    const int fd = accept4(listen_fd_, reinterpret_cast<sockaddr*>(&peer), &peer_length, SOCK_NONBLOCK | SOCK_CLOEXEC);
    if (fd < 0) {
      if (errno == EMFILE || errno == ENFILE || errno == ENOBUFS || errno == ENOMEM) {
        // Out of descriptors: the listener stays readable, and level-triggered epoll
        // would spin on it. It leaves the epoll set until the next sweep, and the
        // connection waits in the backlog meanwhile.
        epoll_ctl(epoll_fd_, EPOLL_CTL_DEL, listen_fd_, nullptr);
        listener_paused_ = true;
      }
      return;  // EAGAIN: the backlog is empty
    }
    // Without TCP_NODELAY each keep-alive answer waits for the client's delayed ACK.
    const int one = 1;
    setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    if (shared_.open_connections.fetch_add(1) >= config_.max_connections) {
      shared_.open_connections.fetch_sub(1);
      shared_.router.metrics().overloaded(Overload::connections);
      // Over the limit: a best-effort 503 on the fresh socket (its buffer is empty, so
      // a short answer fits), then close.
      std::string out;
      Response busy = http_problem(503, "the service holds its maximum number of connections");
      busy.headers.emplace_back("Retry-After", "1");
      append_response(out, busy, WireOptions{1, false, false, 0, {}, {}, false});
      [[maybe_unused]] const auto n = ::send(fd, out.data(), out.size(), MSG_NOSIGNAL);
      ::close(fd);
      shared_.router.finish_unrouted("-", "-", 503, address_text(peer), out.size());
      continue;
    }
    const std::uint64_t id = next_id_++;
    auto c = std::make_unique<Connection>(fd, id, parser_limits_, Clock::now());
    Connection& ref = *c;
    ref.client = address_text(peer);
    connections_.emplace(id, std::move(c));
    epoll_event ev{};
    ev.events = EPOLLIN;
    ev.data.u64 = id;
    epoll_ctl(epoll_fd_, EPOLL_CTL_ADD, fd, &ev);
    ref.interest = EPOLLIN;
  }
}

void EventLoop::read(Connection& c) {
  char buffer[64 * 1024];
  const ssize_t n = ::recv(c.fd, buffer, sizeof buffer, 0);
  if (n < 0) {
    if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) return;
    return close(c.id);
  }
  if (c.lingering) {
    if (n == 0) close(c.id);  // the client has read our answer and closed: done
    return;
  }
  if (n == 0) {
    // The client shut down its sending side (or closed): what it sent is still
    // answered, then the connection closes.
    c.peer_closed = true;
    if (drop_waiting_request(c)) return;
    if (c.busy || c.out_pos < c.out.size()) return update_interest(c);
    if (!c.parser.started() && c.in_pos == c.in.size()) return close(c.id);
  } else {
    c.in.append(buffer, static_cast<std::size_t>(n));
  }
  process(c);
}

std::size_t EventLoop::unsent(const Connection& c) noexcept { return c.out.size() - c.out_pos; }

bool EventLoop::may_take_request(const Connection& c) noexcept {
  return !c.busy && !c.close_after_write && !c.lingering && unsent(c) < kMaxBufferedOutput;
}

void EventLoop::process(Connection& c) {
  const std::uint64_t id = c.id;
  // Sending may take the output below the limit again with requests still buffered (the
  // kernel took it all): they are answered now, as no event would come for them.
  do {
    answer_buffered_requests(c);
    flush(c);
    if (connections_.count(id) == 0) return;
  } while (may_take_request(c) && c.in_pos < c.in.size());
  update_interest(c);
}

void EventLoop::answer_buffered_requests(Connection& c) {
  while (may_take_request(c) && c.in_pos < c.in.size()) {
    if (!c.parser.started()) c.request_start = Clock::now();
    const auto progress = c.parser.feed(std::string_view(c.in).substr(c.in_pos));
    c.in_pos += progress.used;
    if (progress.state == HttpRequestParser::State::need_more) {
      const HttpRequest& r = c.parser.request();
      if (c.parser.awaiting_body() && r.expect_continue && !c.continue_sent) answer_expect_continue(c);
      break;
    }
    if (progress.state == HttpRequestParser::State::error) {
      refuse(c, c.parser.error().status, c.parser.error().detail);
      break;
    }
    dispatch(c);
  }
  if (c.in_pos == c.in.size()) {
    c.in.clear();
    c.in_pos = 0;
  } else if (c.in_pos > 64 * 1024) {
    c.in.erase(0, c.in_pos);
    c.in_pos = 0;
  }
  if (c.peer_closed && !c.busy && c.parser.started()) {
    // The stream ended in the middle of a request: nothing more will come.
    refuse(c, 400, "the connection ended in the middle of a request");
  }
}

void EventLoop::answer_expect_continue(Connection& c) {
  // "100 Continue" invites the body (curl waits up to a second for it before sending one
  // over 1 KiB). It goes only to a request the router would take, its route, method,
  // authentication and media type checked on the head alone: a refused client gets its
  // final answer instead, without being asked to upload the body first, and the
  // connection closes (RFC 9110 §10.1.1; what the client still sends is discarded by
  // begin_lingering).
  const HttpRequest& request = c.parser.request();
  const RequestView view{request.method, request.path,
                         [&request](std::string_view name) { return request.header(name); }, {}, c.client};
  const std::optional<Response> refusal = shared_.router.answer(view);
  if (!refusal || refusal->status < 400) {
    c.out += kContinue;
    c.continue_sent = true;
    return;
  }
  const Exchange exchange = shared_.router.begin(view);
  WireOptions wire{request.minor_version, false, false, 0, {}, {}, false};
  const std::size_t bytes = respond(c, *refusal, for_exchange(wire, exchange));
  shared_.router.finish(exchange, request.method, request.path, refusal->status, bytes);
  c.parser.reset();
}

void EventLoop::dispatch(Connection& c) {
  HttpRequest& request = c.parser.request();
  const RequestView view{request.method, request.path,
                         [&request](std::string_view name) { return request.header(name); }, request.body,
                         c.client};
  Router& router = shared_.router;
  Exchange exchange = router.begin(view);
  ++c.served;
  WireOptions wire;
  wire.minor_version = request.minor_version;
  wire.keep_alive = request.keep_alive && !stopping_ && !c.peer_closed &&
                    c.served < config_.keep_alive_max_requests;
  wire.head_only = request.method == "HEAD";
  wire.keep_alive_timeout_s = config_.keep_alive_timeout_s;

  const auto finish_here = [&](const Response& response) {
    const std::size_t bytes = respond(c, response, for_exchange(wire, exchange));
    router.finish(exchange, request.method, request.path, response.status, bytes);
    c.parser.reset();
    c.continue_sent = false;
  };

  if (auto answer = router.answer(view)) return finish_here(*answer);
  if (InlinePolicy::may_try(request.path, request.body.size())) {
    Response inline_answer = router.compute(request.path, request.body, inline_limits_);
    if (InlinePolicy::is_final(inline_answer)) return finish_here(inline_answer);
  }

  // To the compute pool: the task owns copies of what it needs, the connection waits
  // (reading stops) and its next pipelined request stays in `in` until the answer.
  auto pending = std::make_shared<Pending>();
  pending->exchange = std::move(exchange);
  pending->method = std::string(request.method);
  pending->path = std::string(request.path);
  pending->wire = wire;
  pending->queued_at = Clock::now();
  auto body = std::make_shared<std::string>(std::move(request.body));
  const std::uint64_t id = c.id;
  // Counted before it is queued, so that the task's decrement never comes first.
  router.metrics().compute_queued();
  pending->ticket = shared_.pool.submit([this, id, pending, body] { run_on_pool(id, pending, *body); });
  if (pending->ticket == 0) {
    router.metrics().compute_dequeued();
    router.metrics().overloaded(Overload::queue_full);
    Response full = http_problem(503, "the compute queue is full");
    full.headers.emplace_back("Retry-After", "1");
    const std::size_t bytes = respond(c, full, for_exchange(pending->wire, pending->exchange));
    router.finish(pending->exchange, pending->method, pending->path, full.status, bytes);
    c.parser.reset();
    c.continue_sent = false;
    return;
  }
  c.busy = true;
  c.on_pool = std::move(pending);
  c.parser.reset();
  c.continue_sent = false;
}

void EventLoop::run_on_pool(std::uint64_t connection, const std::shared_ptr<Pending>& pending,
                            std::string_view body) {
  Router& router = shared_.router;
  router.metrics().compute_dequeued();
  if (pending->connection_gone.load()) return router.abandon(pending->exchange, pending->method, pending->path);
  Response response;
  if (Clock::now() - pending->queued_at > queue_deadline_) {
    // Taken between two sweeps of its loop (which withdraws it from the queue once its
    // deadline passes): answered the same way.
    router.metrics().overloaded(Overload::queue_deadline);
    response = queue_deadline_problem();
  } else if (pending->path == api::kBatchPath) {
    // One item per step: the deadline was the batch's wait for its first thread.
    return run_batch_item(connection, pending, std::make_shared<api::BatchRun>(router.start_batch(body, config_.limits)));
  } else {
    response = router.compute(pending->path, body, config_.limits);
    if (work_cap_reached(response)) router.metrics().work_cap_hit();
  }
  complete(connection, pending, std::move(response));
}

void EventLoop::run_batch_item(std::uint64_t connection, const std::shared_ptr<Pending>& pending,
                               const std::shared_ptr<api::BatchRun>& batch) {
  Router& router = shared_.router;
  if (pending->connection_gone.load()) return router.abandon(pending->exchange, pending->method, pending->path);
  std::optional<Response> response = router.compute_batch_item(*batch);
  if (!response) {
    shared_.pool.requeue([this, connection, pending, batch] { run_batch_item(connection, pending, batch); });
    return;
  }
  if (work_cap_reached(*response)) router.metrics().work_cap_hit();
  complete(connection, pending, std::move(*response));
}

void EventLoop::complete(std::uint64_t connection, const std::shared_ptr<Pending>& pending, Response response) {
  release_free_memory();  // what a costly request freed goes back to the system
  {
    const std::lock_guard lock(completions_mutex_);
    completions_.push_back({connection, pending, std::move(response)});
  }
  const std::uint64_t one = 1;
  [[maybe_unused]] const auto n = ::write(wake_fd_, &one, sizeof one);
}

Response EventLoop::queue_deadline_problem() const {
  Response response = http_problem(503, "the request waited longer than " + std::to_string(config_.queue_deadline_s) +
                                            " s for a compute thread");
  response.headers.emplace_back("Retry-After", "1");
  return response;
}

bool EventLoop::withdraw_from_pool(Connection& c) {
  if (!c.on_pool || !shared_.pool.withdraw(c.on_pool->ticket)) return false;
  shared_.router.metrics().compute_dequeued();
  c.busy = false;
  return true;
}

bool EventLoop::drop_waiting_request(Connection& c) {
  // As for a reset: a client that closes while its request waits has given up (nginx
  // logs such a request 499 the same way), and computing it would make every request
  // behind it wait longer. One a thread already runs is answered, bounded by its work
  // cap.
  const std::shared_ptr<Pending> waiting = c.on_pool;
  if (!withdraw_from_pool(c)) return false;
  c.on_pool.reset();
  shared_.router.abandon(waiting->exchange, waiting->method, waiting->path);
  close(c.id);
  return true;
}

void EventLoop::take_completions() {
  std::vector<Completion> done;
  {
    const std::lock_guard lock(completions_mutex_);
    done.swap(completions_);
  }
  for (Completion& completion : done) {
    Pending& p = *completion.pending;
    const auto found = connections_.find(completion.connection);
    if (found == connections_.end()) {  // the client went away meanwhile: nothing sent
      shared_.router.finish(p.exchange, p.method, p.path, completion.response.status, 0);
      continue;
    }
    Connection& c = *found->second;
    c.busy = false;
    c.on_pool.reset();
    // Stopping may have begun while it computed: the answer then closes the connection.
    p.wire.keep_alive = p.wire.keep_alive && !stopping_;
    const std::size_t bytes = respond(c, completion.response, for_exchange(p.wire, p.exchange));
    shared_.router.finish(p.exchange, p.method, p.path, completion.response.status, bytes);
    process(c);  // the pipelined requests that waited, then flush
  }
}

std::size_t EventLoop::respond(Connection& c, const Response& response, const WireOptions& wire) {
  const std::size_t before = c.out.size();
  append_response(c.out, response, wire);
  if (!wire.keep_alive) c.close_after_write = true;
  return c.out.size() - before;
}

void EventLoop::refuse(Connection& c, int status, std::string detail) {
  // After a framing error the stream cannot be trusted to be at a request boundary:
  // answer and close. What was parsed of the request (for a 413, its whole head) still
  // gives the log line its method and path and the answer the client's X-Request-Id.
  const HttpRequest& request = c.parser.request();
  const RequestView view{request.method, request.path,
                         [&request](std::string_view name) { return request.header(name); }, {}, c.client};
  const Exchange exchange = shared_.router.begin(view);
  const Response response = http_problem(status, std::move(detail));
  WireOptions wire{1, false, false, 0, {}, {}, false};
  const std::size_t bytes = respond(c, response, for_exchange(wire, exchange));
  shared_.router.finish(exchange, request.method.empty() ? "-" : request.method,
                        request.path.empty() ? "-" : request.path, status, bytes);
  c.parser.reset();
}

void EventLoop::flush(Connection& c) {
  while (c.out_pos < c.out.size()) {
    const ssize_t n = ::send(c.fd, c.out.data() + c.out_pos, c.out.size() - c.out_pos, MSG_NOSIGNAL);
    if (n < 0) {
      if (errno == EINTR) continue;
      if (errno == EAGAIN || errno == EWOULDBLOCK) break;
      return close(c.id);
    }
    c.out_pos += static_cast<std::size_t>(n);
    c.write_since = Clock::now();  // progress: the write timeout starts again
  }
  if (c.out_pos >= kCompactSentOutput && c.out_pos >= unsent(c)) {
    c.out.erase(0, c.out_pos);
    c.out_pos = 0;
  }
  if (c.out_pos == c.out.size()) {
    c.out.clear();
    c.out_pos = 0;
    if (!c.busy) {
      if (c.close_after_write) return begin_lingering(c);
      if (c.peer_closed && !c.parser.started() && c.in_pos == c.in.size()) return close(c.id);
      if (!c.parser.started()) c.idle_since = Clock::now();
    }
  } else if (c.write_since == Clock::time_point{}) {
    c.write_since = Clock::now();
  }
  update_interest(c);
}

void EventLoop::begin_lingering(Connection& c) {
  // Closing a socket with unread input makes the kernel send a reset, which can destroy
  // our answer before the client reads it: a 413 for a body still being sent, or the
  // answers before a "Connection: close" to a client that pipelined more. So the
  // sending side is shut down (the client sees the end of the answer) and what still
  // arrives is read and discarded until the client closes, for at most kLingerTime
  // (RFC 9112 §9.6).
  if (c.peer_closed || c.lingering) return close(c.id);
  ::shutdown(c.fd, SHUT_WR);
  c.lingering = true;
  c.linger_since = Clock::now();
  c.in.clear();
  c.in_pos = 0;
  epoll_event ev{};
  ev.events = EPOLLIN;
  ev.data.u64 = c.id;
  epoll_ctl(epoll_fd_, EPOLL_CTL_MOD, c.fd, &ev);
  c.interest = EPOLLIN;
}

void EventLoop::update_interest(Connection& c) {
  if (c.lingering) return;
  std::uint32_t want = 0;
  const bool output_waiting = c.out_pos < c.out.size();
  if (may_take_request(c) && !c.peer_closed) want |= EPOLLIN;
  if (c.busy && !c.fin_seen && !c.peer_closed) want |= EPOLLRDHUP;
  if (output_waiting) want |= EPOLLOUT;
  if (!output_waiting) c.write_since = {};
  if (want == c.interest) return;
  epoll_event ev{};
  ev.events = want;
  ev.data.u64 = c.id;
  epoll_ctl(epoll_fd_, EPOLL_CTL_MOD, c.fd, &ev);
  c.interest = want;
}

void EventLoop::close(std::uint64_t id) {
  const auto found = connections_.find(id);
  if (found == connections_.end()) return;
  Connection& c = *found->second;
  if (c.on_pool) {
    // Still queued: out of the queue now, so its place is free at once. Taken by a
    // thread: it finds the flag and skips the computation if it has not begun.
    const std::shared_ptr<Pending> waiting = c.on_pool;
    if (withdraw_from_pool(c)) {
      shared_.router.abandon(waiting->exchange, waiting->method, waiting->path);
    } else {
      waiting->connection_gone.store(true);
    }
    c.on_pool.reset();
  }
  epoll_ctl(epoll_fd_, EPOLL_CTL_DEL, found->second->fd, nullptr);
  ::close(found->second->fd);
  connections_.erase(found);
  shared_.open_connections.fetch_sub(1);
}

bool EventLoop::idle(const Connection& c) const noexcept {
  return !c.busy && !c.parser.started() && c.in_pos == c.in.size() && c.out_pos == c.out.size();
}

void EventLoop::sweep(Clock::time_point now) {
  const auto read_timeout = std::chrono::seconds(config_.read_timeout_s);
  const auto write_timeout = std::chrono::seconds(config_.write_timeout_s);
  const auto idle_timeout = std::chrono::seconds(config_.keep_alive_timeout_s);
  std::vector<std::uint64_t> to_close;
  std::vector<std::uint64_t> timed_out;
  std::vector<std::uint64_t> past_deadline;
  for (auto& [id, c] : connections_) {
    if (c->busy) {
      // Waiting for a compute thread past its deadline: answered 503 now, whatever the
      // pool's threads are doing (a thread that took it meanwhile answers it).
      if (now - c->on_pool->queued_at > queue_deadline_) past_deadline.push_back(id);
      continue;  // otherwise its answer is being computed, bounded by the work cap
    }
    if (c->lingering) {
      if (now - c->linger_since > kLingerTime) to_close.push_back(id);
    } else if (c->out_pos < c->out.size()) {
      if (now - c->write_since > write_timeout) to_close.push_back(id);
    } else if (c->parser.started()) {
      // Counted from the request's first byte: a client sending a byte a second is
      // closed at the timeout however steadily it sends.
      if (now - c->request_start > read_timeout) timed_out.push_back(id);
    } else if ((stopping_ && !has_unread_input(c->fd)) || now - c->idle_since > idle_timeout) {
      to_close.push_back(id);
    }
  }
  for (const auto id : to_close) close(id);
  if (listener_paused_ && !stopping_) {
    epoll_event ev{};
    ev.events = EPOLLIN | EPOLLEXCLUSIVE;
    ev.data.u64 = kListenerId;
    epoll_ctl(epoll_fd_, EPOLL_CTL_ADD, listen_fd_, &ev);
    listener_paused_ = false;
  }
  for (const auto id : timed_out) {
    Connection& c = *connections_.at(id);
    refuse(c, 408, "the request was not complete within " + std::to_string(config_.read_timeout_s) + " s");
    flush(c);
  }
  for (const auto id : past_deadline) {
    const auto found = connections_.find(id);
    if (found == connections_.end()) continue;
    Connection& c = *found->second;
    const std::shared_ptr<Pending> waiting = c.on_pool;
    if (!withdraw_from_pool(c)) continue;
    c.on_pool.reset();
    shared_.router.metrics().overloaded(Overload::queue_deadline);
    waiting->wire.keep_alive = waiting->wire.keep_alive && !stopping_;
    const Response response = queue_deadline_problem();
    const std::size_t bytes = respond(c, response, for_exchange(waiting->wire, waiting->exchange));
    shared_.router.finish(waiting->exchange, waiting->method, waiting->path, response.status, bytes);
    process(c);  // the pipelined requests that waited, then flush
  }
}

void EventLoop::begin_stopping() {
  // Connections already in the backlog were accepted by the kernel: take them, so
  // that a request they sent is answered rather than reset with the listener.
  if (!listener_paused_) accept_all();
  stopping_ = true;
  if (!listener_paused_) epoll_ctl(epoll_fd_, EPOLL_CTL_DEL, listen_fd_, nullptr);
  ::close(listen_fd_);
  listen_fd_ = -1;
  // Idle keep-alive connections close now; the others after their current answer,
  // which goes out with "Connection: close".
  std::vector<std::uint64_t> idle_ids;
  for (const auto& [id, c] : connections_) {
    if (idle(*c) && !has_unread_input(c->fd)) idle_ids.push_back(id);
  }
  for (const auto id : idle_ids) close(id);
}

}  // namespace bezier::service
