#pragma once

// Raw-socket HTTP/1.1 for the integration tests of the HTTP layer: what a client library
// would hide (pipelining, half-closed and reset connections, unread answers, requests no
// client would send, an answer's exact bytes), and what the tests read of the service
// process from /proc (resident memory, CPU time).

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/types.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace bezier::test {

/// Sends `bytes` as they are to 127.0.0.1:port on a fresh connection and returns
/// everything the server sends until it closes the connection (or `limit` passes): for
/// requests no HTTP client library would send, and to see an answer's exact bytes.
/// Empty if the connection could not be made.
inline std::string raw_exchange(int port, std::string_view bytes,
                                std::chrono::milliseconds limit = std::chrono::seconds(10)) {
  const int fd = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return {};
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
    close(fd);
    return {};
  }
  for (std::size_t sent = 0; sent < bytes.size();) {
    const ssize_t n = send(fd, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
    if (n <= 0) break;
    sent += static_cast<std::size_t>(n);
  }
  std::string answer;
  const auto deadline = std::chrono::steady_clock::now() + limit;
  char buffer[65536];
  while (std::chrono::steady_clock::now() < deadline) {
    pollfd p{fd, POLLIN, 0};
    if (poll(&p, 1, 50) <= 0) continue;
    const ssize_t n = recv(fd, buffer, sizeof buffer, 0);
    if (n <= 0) break;
    answer.append(buffer, static_cast<std::size_t>(n));
  }
  close(fd);
  return answer;
}

/// The head of an HTTP answer (status line and header lines, up to the blank line).
inline std::string_view answer_head(std::string_view answer) {
  return answer.substr(0, answer.find("\r\n\r\n"));
}

/// The value of header `name` in an answer's head (exact name as the service writes it),
/// or nullopt-like empty view with `found` false.
struct HeaderValue {
  bool found = false;
  std::string value;
};

inline HeaderValue header_of(std::string_view answer, std::string_view name) {
  const std::string_view head = answer_head(answer);
  const std::string needle = "\r\n" + std::string(name) + ": ";
  const auto start = head.find(needle);
  if (start == std::string_view::npos) return {};
  const auto value_start = start + needle.size();
  const auto end = head.find("\r\n", value_start);
  return {true, std::string(head.substr(value_start, end == std::string_view::npos ? head.npos : end - value_start))};
}


inline std::string post_request(std::string_view path, std::string_view body, std::string_view extra_headers = "") {
  return "POST " + std::string(path) + " HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n" +
         std::string(extra_headers) + "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" +
         std::string(body);
}

inline std::string get_request(std::string_view path) {
  return "GET " + std::string(path) + " HTTP/1.1\r\nHost: x\r\n\r\n";
}

/// A blocking TCP connection to the service with a receive deadline.
class Connection {
 public:
  explicit Connection(int port) : fd_(socket(AF_INET, SOCK_STREAM, 0)) {
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<std::uint16_t>(port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    connected_ = connect(fd_, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0;
  }
  ~Connection() {
    if (fd_ >= 0) close(fd_);
  }
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  [[nodiscard]] bool connected() const { return connected_; }
  [[nodiscard]] int fd() const { return fd_; }

  bool send_all(std::string_view data) {
    while (!data.empty()) {
      const ssize_t n = ::send(fd_, data.data(), data.size(), MSG_NOSIGNAL);
      if (n <= 0) return false;
      data.remove_prefix(static_cast<std::size_t>(n));
    }
    return true;
  }

  /// Sends FIN: the client has nothing more to send, and still reads.
  void shutdown_write() { ::shutdown(fd_, SHUT_WR); }

  /// Closes with a reset (SO_LINGER 0) instead of a FIN: the connection is gone in both
  /// directions at once.
  void reset() {
    const linger abort_on_close{1, 0};
    setsockopt(fd_, SOL_SOCKET, SO_LINGER, &abort_on_close, sizeof abort_on_close);
    close(fd_);
    fd_ = -1;
  }

  /// Reads until `until` returns true on what was read, the peer closes, or the
  /// deadline passes; returns everything read (also kept for later calls).
  template <class Until>
  std::string read_until(Until until, int timeout_ms = 10000) {
    char buffer[65536];
    while (!until(received_)) {
      pollfd p{fd_, POLLIN, 0};
      if (poll(&p, 1, timeout_ms) <= 0) break;
      const ssize_t n = ::recv(fd_, buffer, sizeof buffer, 0);
      if (n <= 0) {
        closed_ = true;
        break;
      }
      received_.append(buffer, static_cast<std::size_t>(n));
    }
    return received_;
  }

  /// Reads `count` complete responses (each head + Content-Length body).
  std::vector<std::string> responses(std::size_t count, int timeout_ms = 10000) {
    read_until([count](const std::string& s) { return split(s).size() >= count; }, timeout_ms);
    return split(received_);
  }

  /// Whether the service closed the connection (reads EOF within the deadline).
  bool closed_by_peer(int timeout_ms = 10000) {
    read_until([](const std::string&) { return false; }, timeout_ms);
    return closed_;
  }

  /// The length of the response at the start of `stream`, or nullopt while incomplete.
  static std::optional<std::size_t> response_length(std::string_view stream) {
    const std::size_t end = stream.find("\r\n\r\n");
    if (end == std::string_view::npos) return std::nullopt;
    const std::string_view head = stream.substr(0, end + 4);
    std::size_t length = 0;
    const std::size_t cl = head.find("Content-Length: ");
    if (cl != std::string_view::npos) length = std::stoul(std::string(head.substr(cl + 16, 20)));
    if (head.rfind("HTTP/1.1 100 ", 0) == 0) length = 0;
    if (stream.size() < end + 4 + length) return std::nullopt;
    return end + 4 + length;
  }

  static std::vector<std::string> split(const std::string& stream) {
    std::vector<std::string> out;
    std::size_t at = 0;
    while (const auto length = response_length(std::string_view(stream).substr(at))) {
      out.push_back(stream.substr(at, *length));
      at += *length;
    }
    return out;
  }

 private:
  int fd_;
  bool connected_ = false;
  bool closed_ = false;
  std::string received_;
};

inline int status_of(const std::string& response) { return std::stoi(response.substr(9, 3)); }
inline std::string body_of(const std::string& response) { return response.substr(response.find("\r\n\r\n") + 4); }
inline bool has_header(const std::string& response, std::string_view line) {
  return response.substr(0, response.find("\r\n\r\n") + 2).find("\r\n" + std::string(line) + "\r\n") !=
         std::string::npos;
}
inline void expect_problem(const std::string& response, int status) {
  EXPECT_EQ(status_of(response), status) << response;
  EXPECT_TRUE(has_header(response, "Content-Type: application/problem+json")) << response;
  const auto body = nlohmann::json::parse(body_of(response), nullptr, false);
  ASSERT_TRUE(body.is_object()) << response;
  EXPECT_EQ(body["status"], status);
  EXPECT_TRUE(body["type"].is_string() && body["title"].is_string() && body["detail"].is_string());
}

/// One exchange on a fresh connection: the answer to `request`, empty if none came.
inline std::string round_trip(int port, const std::string& request) {
  Connection c(port);
  if (!c.send_all(request)) return {};
  const auto answers = c.responses(1);
  return answers.empty() ? std::string() : answers.front();
}

/// The value of the sample `series` (name and labels exactly as rendered, e.g.
/// `bezier_requests_total{route="/evaluate",status="200"}`) on GET /metrics; nullopt when
/// absent.
inline std::optional<double> metric(int port, std::string_view series) {
  std::string text = "\n";
  text += body_of(round_trip(port, get_request("/metrics")));
  std::string prefix = "\n";
  prefix += series;
  prefix += ' ';
  const std::size_t at = text.find(prefix);
  if (at == std::string::npos) return std::nullopt;
  return std::strtod(text.c_str() + at + prefix.size(), nullptr);
}

/// Reads the metric `series` until `holds` is true of it (at most 20 s); its last value (-1
/// while absent).
template <class Holds>
double await_metric(int port, std::string_view series, Holds holds) {
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  double value = metric(port, series).value_or(-1);
  while (!holds(value) && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    value = metric(port, series).value_or(-1);
  }
  return value;
}

/// Whether an answer has arrived on `c` (without waiting for one).
inline bool answer_arrived(const Connection& c) {
  pollfd p{c.fd(), POLLIN, 0};
  return poll(&p, 1, 0) > 0;
}

/// VmRSS of a process from /proc/<pid>/status, in bytes.
inline std::int64_t resident_bytes(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmRSS:", 0) == 0) return std::stoll(line.substr(6)) * 1024;  // "VmRSS:  1234 kB"
  }
  return -1;
}

/// VmHWM of a process from /proc/<pid>/status (its peak resident set so far), in bytes.
inline std::int64_t peak_resident_bytes(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return std::stoll(line.substr(6)) * 1024;  // "VmHWM:  1234 kB"
  }
  return -1;
}

/// User plus system CPU time of a process (all its threads) from /proc/<pid>/stat, in
/// seconds.
inline double cpu_seconds(pid_t pid) {
  std::ifstream file("/proc/" + std::to_string(pid) + "/stat");
  std::string stat((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  std::istringstream fields(stat.substr(stat.rfind(')') + 2));  // after "pid (comm) "
  std::string field;
  double ticks = 0;
  for (int i = 3; i <= 15; ++i) {  // fields 14 and 15: utime, stime
    fields >> field;
    if (i >= 14) ticks += std::stod(field);
  }
  return ticks / static_cast<double>(sysconf(_SC_CLK_TCK));
}

}  // namespace bezier::test
