// A measurement prototype, not the service: the same api::handle behind a minimal epoll
// HTTP/1.1 loop (one event loop per thread, one SO_REUSEPORT listening socket each,
// level-triggered, keep-alive, pipelining, headers and body in one send), to measure what
// the socket layer costs next to cpp-httplib 0.11.4's thread per connection (BENCHMARKS.md,
// "HTTP"). It has none of the service's hardening (timeouts, 413/415 problems, metrics,
// logging, shutdown) and serves a request on the loop thread, so a slow request holds up
// the other connections of its loop. Build against a Release build directory and run it
// where compare_peer.sh expects the service binary:
//
//   g++ -std=c++20 -O2 -DNDEBUG -I. tests/bench/http/epoll_prototype.cpp -o /tmp/epoll_prototype
//       build/api/libbezier_api.a build/core/libbezier_core.a -lpthread      (one line)
//   tests/bench/http/compare_peer.sh /tmp/epoll_prototype 10 3
//
// Flags: --port N (0 picks a free port; prints "listening on http://127.0.0.1:PORT"),
// --threads N (event loops, default 2: one per core of this machine).
#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/epoll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <charconv>
#include <cstdio>
#include <cstring>
#include <string>
#include <string_view>
#include <thread>
#include <unordered_map>
#include <vector>

#include "api/handler.hpp"

namespace {

struct Conn {
  std::string in;
  std::string out;
  std::size_t out_pos = 0;
  bool want_out = false;
};

int listen_on(int& port) {
  const int fd = socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK, 0);
  int one = 1;
  setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  setsockopt(fd, SOL_SOCKET, SO_REUSEPORT, &one, sizeof one);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<uint16_t>(port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) { perror("bind"); _exit(1); }
  listen(fd, SOMAXCONN);
  socklen_t len = sizeof a;
  getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len);
  port = ntohs(a.sin_port);
  return fd;
}

bool iequals_prefix(std::string_view line, std::string_view name) {
  if (line.size() < name.size()) return false;
  for (std::size_t i = 0; i < name.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(line[i])) != name[i]) return false;
  return true;
}

// Parses and answers every complete request in c.in; returns false to close.
bool serve(Conn& c, const bezier::api::Limits& limits) {
  for (;;) {
    const auto end = c.in.find("\r\n\r\n");
    if (end == std::string::npos) return c.in.size() < 65536;
    std::string_view head(c.in.data(), end);
    const auto line_end = head.find("\r\n");
    std::string_view request_line = head.substr(0, line_end);
    const auto sp1 = request_line.find(' ');
    const auto sp2 = request_line.find(' ', sp1 + 1);
    if (sp1 == std::string_view::npos || sp2 == std::string_view::npos) return false;
    const std::string_view method = request_line.substr(0, sp1);
    const std::string_view path = request_line.substr(sp1 + 1, sp2 - sp1 - 1);
    std::size_t length = 0;
    std::size_t pos = line_end + 2;
    while (pos < head.size()) {
      auto e = head.find("\r\n", pos);
      if (e == std::string_view::npos) e = head.size();
      const std::string_view h = head.substr(pos, e - pos);
      if (iequals_prefix(h, "content-length:")) {
        auto v = h.substr(15);
        while (!v.empty() && v.front() == ' ') v.remove_prefix(1);
        std::from_chars(v.data(), v.data() + v.size(), length);
      }
      pos = e + 2;
    }
    if (length > limits.max_body_bytes) return false;
    const std::size_t total = end + 4 + length;
    if (c.in.size() < total) return true;
    const std::string_view body(c.in.data() + end + 4, length);
    int status = 200;
    std::string content_type = "application/json";
    std::string payload;
    if (method == "POST" && bezier::api::is_post_route(path)) {
      auto reply = bezier::api::handle(path, body, limits);
      status = reply.status;
      content_type = reply.content_type;
      payload = std::move(reply.body);
    } else if (path == "/healthz") {
      payload = R"({"status":"ok"})";
    } else {
      status = 404;
      payload = R"({"status":404})";
    }
    char header[256];
    const int n = std::snprintf(header, sizeof header,
                                "HTTP/1.1 %d %s\r\nContent-Type: %s\r\nContent-Length: %zu\r\nKeep-Alive: timeout=5\r\n\r\n",
                                status, status == 200 ? "OK" : "Error", content_type.c_str(), payload.size());
    c.out.append(header, static_cast<std::size_t>(n));
    c.out += payload;
    c.in.erase(0, total);
  }
}

void loop(int lfd, const bezier::api::Limits& limits) {
  const int ep = epoll_create1(0);
  epoll_event ev{};
  ev.events = EPOLLIN;
  ev.data.fd = lfd;
  epoll_ctl(ep, EPOLL_CTL_ADD, lfd, &ev);
  std::unordered_map<int, Conn> conns;
  std::vector<epoll_event> events(256);
  char buf[65536];
  for (;;) {
    const int n = epoll_wait(ep, events.data(), static_cast<int>(events.size()), -1);
    for (int i = 0; i < n; ++i) {
      const int fd = events[static_cast<std::size_t>(i)].data.fd;
      if (fd == lfd) {
        for (;;) {
          const int cfd = accept4(lfd, nullptr, nullptr, SOCK_NONBLOCK);
          if (cfd < 0) break;
          int one = 1;
          setsockopt(cfd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
          epoll_event cev{};
          cev.events = EPOLLIN;
          cev.data.fd = cfd;
          epoll_ctl(ep, EPOLL_CTL_ADD, cfd, &cev);
          conns[cfd];
        }
        continue;
      }
      Conn& c = conns[fd];
      bool close_it = false;
      if (events[static_cast<std::size_t>(i)].events & (EPOLLIN | EPOLLHUP | EPOLLERR)) {
        const ssize_t r = recv(fd, buf, sizeof buf, 0);
        if (r <= 0) {
          close_it = r == 0 || (errno != EAGAIN && errno != EWOULDBLOCK);
        } else {
          c.in.append(buf, static_cast<std::size_t>(r));
          close_it = !serve(c, limits);
        }
      }
      if (!close_it && c.out_pos < c.out.size()) {
        const ssize_t w = send(fd, c.out.data() + c.out_pos, c.out.size() - c.out_pos, MSG_NOSIGNAL);
        if (w < 0 && errno != EAGAIN) close_it = true;
        if (w > 0) c.out_pos += static_cast<std::size_t>(w);
        if (c.out_pos == c.out.size()) {
          c.out.clear();
          c.out_pos = 0;
        }
        if (c.want_out == c.out.empty()) {  // only when the interest changes
          c.want_out = !c.out.empty();
          epoll_event cev{};
          cev.events = EPOLLIN | (c.want_out ? EPOLLOUT : 0u);
          cev.data.fd = fd;
          epoll_ctl(ep, EPOLL_CTL_MOD, fd, &cev);
        }
      }
      if (close_it) {
        epoll_ctl(ep, EPOLL_CTL_DEL, fd, nullptr);
        close(fd);
        conns.erase(fd);
      }
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  int port = 0, threads = 2;
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::string_view(argv[i]) == "--port") port = std::atoi(argv[i + 1]);
    if (std::string_view(argv[i]) == "--threads") threads = std::atoi(argv[i + 1]);
  }
  const bezier::api::Limits limits;
  std::vector<int> sockets;
  for (int i = 0; i < threads; ++i) sockets.push_back(listen_on(port));  // port 0: the first picks it
  std::vector<std::thread> workers;
  for (const int fd : sockets) workers.emplace_back([fd, &limits] { loop(fd, limits); });
  std::printf("listening on http://127.0.0.1:%d\n", port);
  std::fflush(stdout);
  for (auto& w : workers) w.join();
}
