#include "service/epoll_engine.hpp"

#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <thread>

#include "service/cpu_budget.hpp"

namespace bezier::service {

namespace {

// A non-blocking listening socket on host:port, or the reason there is none. Without
// SO_REUSEPORT: a second process that tries the same port fails to bind (EADDRINUSE)
// instead of joining a reuseport group and silently taking a share of the connections.
// SO_REUSEADDR only lets it bind over connections of an earlier instance in TIME_WAIT;
// on Linux it never admits a second listener.
BindResult listen_on(const std::string& host, int port) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  hints.ai_flags = AI_PASSIVE | AI_NUMERICSERV;
  addrinfo* found = nullptr;
  const std::string where = host + ":" + std::to_string(port);
  if (const int rc = getaddrinfo(host.empty() ? nullptr : host.c_str(), std::to_string(port).c_str(), &hints, &found);
      rc != 0) {
    return {-1, -1, "cannot listen on " + where + ": " + gai_strerror(rc)};
  }
  int fd = -1;
  int error = 0;
  for (const addrinfo* a = found; a != nullptr && fd < 0; a = a->ai_next) {
    fd = socket(a->ai_family, a->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, a->ai_protocol);
    if (fd < 0) {
      error = errno;
      continue;
    }
    const int one = 1;
    setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    if (::bind(fd, a->ai_addr, a->ai_addrlen) != 0 || ::listen(fd, SOMAXCONN) != 0) {
      error = errno;
      ::close(fd);
      fd = -1;
    }
  }
  freeaddrinfo(found);
  if (fd < 0) {
    std::string reason = "cannot listen on " + where + ": " + std::strerror(error);
    if (error == EADDRINUSE) reason += " (another process listens on that port)";
    return {-1, -1, reason};
  }
  return {fd, port, {}};
}

int port_of(int fd) {
  sockaddr_storage address{};
  socklen_t length = sizeof address;
  if (getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length) != 0) return -1;
  if (address.ss_family == AF_INET6) return ntohs(reinterpret_cast<sockaddr_in6*>(&address)->sin6_port);
  return ntohs(reinterpret_cast<sockaddr_in*>(&address)->sin_port);
}

}  // namespace

EpollEngine::EpollEngine(Router& router) : router_(router) {}

EpollEngine::~EpollEngine() {
  for (const int fd : listen_fds_) ::close(fd);
}

BindResult EpollEngine::bind() {
  const Config& config = router_.config();
  const int loops = config.io_threads > 0 ? config.io_threads : usable_cpus_of_this_process();
  BindResult bound = listen_on(config.host, config.port);
  if (bound.fd < 0) return bound;
  bound.port = port_of(bound.fd);
  // One listening socket shared by every loop: each gets its own descriptor of it (a
  // loop closes its listener when it stops) and waits on it with EPOLLEXCLUSIVE, so a
  // new connection wakes one waiting loop rather than all of them.
  listen_fds_.push_back(bound.fd);
  for (int i = 1; i < loops; ++i) {
    const int copy = fcntl(bound.fd, F_DUPFD_CLOEXEC, 0);
    if (copy < 0) {
      const int error = errno;
      for (const int open : listen_fds_) ::close(open);
      listen_fds_.clear();
      return {-1, -1, std::string("cannot share the listening socket: ") + std::strerror(error)};
    }
    listen_fds_.push_back(copy);
  }
  return bound;
}

bool EpollEngine::serve() {
  const Config& config = router_.config();
  {
    const std::lock_guard lock(mutex_);
    pool_ = std::make_unique<ComputePool>(static_cast<std::size_t>(config.threads),
                                          static_cast<std::size_t>(config.max_queued_requests));
    for (const int fd : listen_fds_) {
      loops_.push_back(std::make_unique<EventLoop>(EventLoop::Shared{router_, *pool_, open_connections_}, fd));
    }
    listen_fds_.clear();  // the loops own them now
    if (stop_requested_) {
      for (auto& loop : loops_) loop->stop();
    }
  }
  std::vector<std::thread> threads;
  std::atomic<bool> ok{true};
  for (std::size_t i = 1; i < loops_.size(); ++i) {
    threads.emplace_back([this, i, &ok] {
      if (!loops_[i]->run()) ok.store(false);
    });
  }
  if (!loops_.front()->run()) ok.store(false);
  for (auto& t : threads) t.join();
  // Every connection is closed; tasks of connections that went away may still run on
  // the pool and post to their loop, so the pool is joined before the loops go.
  const std::lock_guard lock(mutex_);
  pool_.reset();
  loops_.clear();
  return ok.load();
}

void EpollEngine::stop() {
  const std::lock_guard lock(mutex_);
  stop_requested_ = true;
  for (auto& loop : loops_) loop->stop();
}

}  // namespace bezier::service
