#pragma once

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <string_view>

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

}  // namespace bezier::test
