#include "service/epoll_engine.hpp"

#include <netdb.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <string>
#include <thread>

namespace bezier::service {

namespace {

// A non-blocking listening socket on host:port with SO_REUSEPORT, so that every loop
// can have its own on the same port and the kernel spreads new connections over them
// (no shared accept queue, no thundering herd). -1 on failure.
int listen_on(const std::string& host, int port) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  hints.ai_flags = AI_PASSIVE | AI_NUMERICSERV;
  addrinfo* found = nullptr;
  if (getaddrinfo(host.empty() ? nullptr : host.c_str(), std::to_string(port).c_str(), &hints, &found) != 0) {
    return -1;
  }
  int fd = -1;
  for (const addrinfo* a = found; a != nullptr && fd < 0; a = a->ai_next) {
    fd = socket(a->ai_family, a->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, a->ai_protocol);
    if (fd < 0) continue;
    const int one = 1;
    setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    setsockopt(fd, SOL_SOCKET, SO_REUSEPORT, &one, sizeof one);
    if (::bind(fd, a->ai_addr, a->ai_addrlen) != 0 || ::listen(fd, SOMAXCONN) != 0) {
      ::close(fd);
      fd = -1;
    }
  }
  freeaddrinfo(found);
  return fd;
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

int EpollEngine::bind() {
  const Config& config = router_.config();
  const int loops = config.io_threads > 0 ? config.io_threads
                                          : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  int port = config.port;
  for (int i = 0; i < loops; ++i) {
    const int fd = listen_on(config.host, port);
    if (fd < 0) {
      for (const int open : listen_fds_) ::close(open);
      listen_fds_.clear();
      return -1;
    }
    listen_fds_.push_back(fd);
    port = port_of(fd);  // port 0: the first socket picks it, the others share it
  }
  return port;
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
