// Memory per connection is bounded: a client that pipelines requests and never reads the
// answers makes the service hold at most its limit of unsent output (1 MiB, README
// "Threads and keep-alive") plus one answer per connection, whatever the number of
// requests; the remaining requests wait unread until the client reads, and then every
// answer arrives, in order and intact (the same as a single request's). The service's resident memory is read from
// /proc/<pid>/status.
#include <algorithm>
#include <chrono>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/raw_http.hpp"
#include "tests/support/service_process.hpp"

namespace bezier::test {
namespace {

constexpr std::int64_t kMiB = 1 << 20;
// The service's limit of unsent output per connection.
constexpr std::int64_t kOutputLimit = kMiB;
// What a stalled connection may hold beyond its limit: one more answer (80 KiB here), and
// the string holding them growing by doubling, so up to twice the bytes it holds.
constexpr std::int64_t kAllowancePerConnection = 4 * kMiB;
// Allocator slack (per-thread arenas, freed memory kept for reuse) and measurement noise.
constexpr std::int64_t kMargin = 32 * kMiB;

constexpr int kRequestsPerConnection = 1000;

std::string_view series() { return R"(bezier_requests_total{route="/openapi.yaml",status="200"})"; }

// Waits until the service has stopped answering: the count of answered /openapi.yaml
// requests is the same over several reads a fraction of a second apart.
double settled_answer_count(int port) {
  double last = -1;
  int unchanged = 0;
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (unchanged < 4 && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
    const double now = metric(port, series()).value_or(0);
    unchanged = now == last ? unchanged + 1 : 0;
    last = now;
  }
  return last;
}

// Reads `count` answers from `c` as they come, each checked against `expected` and
// dropped once checked (the whole stream is too large to keep); the number that were a
// 200 with exactly the expected body.
int read_and_check_answers(Connection& c, int count, const std::string& expected) {
  std::string buffer;
  std::size_t at = 0;
  int intact = 0;
  char chunk[1 << 16];
  for (int answered = 0; answered < count;) {
    const std::string_view rest = std::string_view(buffer).substr(at);
    if (const auto length = Connection::response_length(rest)) {
      const std::string_view response = rest.substr(0, *length);
      const std::size_t head_end = response.find("\r\n\r\n") + 4;
      if (response.rfind("HTTP/1.1 200 ", 0) == 0 && response.substr(head_end) == expected) ++intact;
      at += *length;
      ++answered;
      continue;
    }
    buffer.erase(0, at);
    at = 0;
    pollfd p{c.fd(), POLLIN, 0};
    if (poll(&p, 1, 20000) <= 0) break;
    const ssize_t n = ::recv(c.fd(), chunk, sizeof chunk, 0);
    if (n <= 0) break;
    buffer.append(chunk, static_cast<std::size_t>(n));
  }
  return intact;
}

void expect_unread_answers_bounded(int connections) {
  // Connections wait unread while the test reads the others' answers one connection after
  // another (slow under the sanitizers): a write timeout longer than that reading keeps them.
  ServiceProcess service({"--io-threads", "2", "--write-timeout", "600"});
  // One answer first: the text every later answer must repeat, and what every answer
  // needs once (the loops' buffers) is in the baseline.
  const std::string first = round_trip(service.port(), get_request("/openapi.yaml"));
  ASSERT_EQ(status_of(first), 200);
  const std::string expected = body_of(first);
  ASSERT_TRUE(expected.rfind("openapi: ", 0) == 0 && expected.size() > 10000) << expected.substr(0, 100);
  const std::int64_t baseline = resident_bytes(service.pid());
  ASSERT_GT(baseline, 0);

  std::string pipeline;
  for (int i = 0; i < kRequestsPerConnection; ++i) pipeline += get_request("/openapi.yaml");
  std::vector<std::unique_ptr<Connection>> clients;
  for (int i = 0; i < connections; ++i) {
    clients.push_back(std::make_unique<Connection>(service.port()));
    ASSERT_TRUE(clients.back()->send_all(pipeline));
  }
  const double answered = settled_answer_count(service.port());
  const std::int64_t growth = resident_bytes(service.pid()) - baseline;
  // The answers the kernel's socket buffers took are answered too: the service may well
  // answer more than the limit's worth, but not all of them.
  EXPECT_LT(answered, 1 + connections * kRequestsPerConnection);
#if defined(__SANITIZE_ADDRESS__)
  // AddressSanitizer keeps freed memory in quarantine (256 MiB by default) and adds its
  // own: resident memory says nothing about the service's buffers there.
  static_cast<void>(growth);
#else
  EXPECT_LT(growth, connections * (kOutputLimit + kAllowancePerConnection) + kMargin)
      << "grew by " << growth / kMiB << " MiB for " << connections << " connection(s) of "
      << kRequestsPerConnection << " unread answers of " << expected.size() << " bytes";
#endif

  for (auto& c : clients) {
    EXPECT_EQ(read_and_check_answers(*c, kRequestsPerConnection, expected), kRequestsPerConnection);
  }
}

TEST(Backpressure, OneConnectionThatNeverReadsHoldsAboutTheLimit) { expect_unread_answers_bounded(1); }

TEST(Backpressure, TenConnectionsThatNeverReadHoldAboutTheLimitEach) { expect_unread_answers_bounded(10); }

}  // namespace
}  // namespace bezier::test
