// The epoll HTTP engine over raw sockets (--http-engine epoll): what an HTTP client
// library would hide. Pipelining, chunked bodies, 100-continue, HEAD, HTTP/1.0, 413
// before the body is sent, malformed requests, the read and keep-alive timeouts,
// keep_alive_max_requests, max_connections, and shutdown with a request on the pool.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/service_process.hpp"

namespace bezier::test {
namespace {

constexpr std::string_view kEvaluate = R"({"points":[[0,0],[1,2],[3,3]],"t":0.5})";

std::string post(std::string_view path, std::string_view body, std::string_view extra_headers = "") {
  return "POST " + std::string(path) + " HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n" +
         std::string(extra_headers) + "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" +
         std::string(body);
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
  ~Connection() { close(fd_); }
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  [[nodiscard]] bool connected() const { return connected_; }

  bool send_all(std::string_view data) {
    while (!data.empty()) {
      const ssize_t n = ::send(fd_, data.data(), data.size(), MSG_NOSIGNAL);
      if (n <= 0) return false;
      data.remove_prefix(static_cast<std::size_t>(n));
    }
    return true;
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
  std::vector<std::string> responses(std::size_t count) {
    read_until([count](const std::string& s) { return split(s).size() >= count; });
    return split(received_);
  }

  /// Whether the service closed the connection (reads EOF within the deadline).
  bool closed_by_peer(int timeout_ms = 10000) {
    read_until([](const std::string&) { return false; }, timeout_ms);
    return closed_;
  }

  static std::vector<std::string> split(const std::string& stream) {
    std::vector<std::string> out;
    std::size_t at = 0;
    for (;;) {
      const std::size_t end = stream.find("\r\n\r\n", at);
      if (end == std::string::npos) return out;
      const std::string head = stream.substr(at, end + 4 - at);
      std::size_t length = 0;
      const std::size_t cl = head.find("Content-Length: ");
      if (cl != std::string::npos) length = std::stoul(head.substr(cl + 16));
      if (head.rfind("HTTP/1.1 100 ", 0) == 0) length = 0;
      if (stream.size() < end + 4 + length) return out;
      out.push_back(stream.substr(at, end + 4 + length - at));
      at = end + 4 + length;
    }
  }

 private:
  int fd_;
  bool connected_ = false;
  bool closed_ = false;
  std::string received_;
};

int status_of(const std::string& response) { return std::stoi(response.substr(9, 3)); }
std::string body_of(const std::string& response) { return response.substr(response.find("\r\n\r\n") + 4); }
bool has_header(const std::string& response, std::string_view line) {
  return response.substr(0, response.find("\r\n\r\n") + 2).find("\r\n" + std::string(line) + "\r\n") !=
         std::string::npos;
}
void expect_problem(const std::string& response, int status) {
  EXPECT_EQ(status_of(response), status) << response;
  EXPECT_TRUE(has_header(response, "Content-Type: application/problem+json")) << response;
  const auto body = nlohmann::json::parse(body_of(response), nullptr, false);
  ASSERT_TRUE(body.is_object()) << response;
  EXPECT_EQ(body["status"], status);
  EXPECT_TRUE(body["type"].is_string() && body["title"].is_string() && body["detail"].is_string());
}

class EpollEngine : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    service_ = new ServiceProcess({"--http-engine", "epoll", "--io-threads", "2", "--threads", "2",
                                   "--max-body-bytes", "100000", "--read-timeout", "1",
                                   "--keep-alive-timeout", "2", "--keep-alive-max-requests", "5"});
  }
  static void TearDownTestSuite() {
    delete service_;
    service_ = nullptr;
  }
  static int port() { return service_->port(); }
  static inline ServiceProcess* service_ = nullptr;
};

TEST_F(EpollEngine, PipelinedRequestsAreAnsweredInOrder) {
  Connection c(port());
  ASSERT_TRUE(c.connected());
  // A cheap GET, a POST computed inline, a POST that goes to the compute pool (degree 9
  // is above the inline try's degree), and a GET: sent in one write.
  const std::string pool = R"({"points":[[0,0],[1,0],[2,0],[3,0],[4,0],[5,0],[6,0],[7,0],[8,0],[9,0]],"t":0.5})";
  ASSERT_TRUE(c.send_all("GET /healthz HTTP/1.1\r\nHost: x\r\n\r\n" + post("/evaluate", kEvaluate) +
                         post("/evaluate", pool) + "GET /nope HTTP/1.1\r\nHost: x\r\n\r\n"));
  const auto answers = c.responses(4);
  ASSERT_EQ(answers.size(), 4u);
  EXPECT_EQ(status_of(answers[0]), 200);
  EXPECT_EQ(body_of(answers[0]), R"({"status":"ok"})");
  EXPECT_EQ(status_of(answers[1]), 200);
  EXPECT_EQ(nlohmann::json::parse(body_of(answers[1]))["results"][0]["point"], nlohmann::json::parse("[1.25,1.75]"));
  EXPECT_EQ(status_of(answers[2]), 200) << answers[2];
  // B(1/2) of P_i = (i, 0), i = 0..9: (4.5, 0), exact.
  EXPECT_EQ(nlohmann::json::parse(body_of(answers[2]))["results"][0]["point"], nlohmann::json::parse("[4.5,0.0]"));
  expect_problem(answers[3], 404);
}

TEST_F(EpollEngine, RequestsSplitIntoSingleBytesAreAnswered) {
  Connection c(port());
  const std::string request = post("/evaluate", kEvaluate);
  for (const char byte : request) ASSERT_TRUE(c.send_all(std::string_view(&byte, 1)));
  const auto answers = c.responses(1);
  ASSERT_EQ(answers.size(), 1u);
  EXPECT_EQ(status_of(answers[0]), 200);
}

TEST_F(EpollEngine, ChunkedBodyIsDecoded) {
  Connection c(port());
  const std::string_view body = kEvaluate;
  const std::string head = "POST /evaluate HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
                           "Transfer-Encoding: chunked\r\n\r\n";
  char size[16];
  std::snprintf(size, sizeof size, "%zx", body.size() - 10);
  ASSERT_TRUE(c.send_all(head + "a\r\n" + std::string(body.substr(0, 10)) + "\r\n" + size + "\r\n" +
                         std::string(body.substr(10)) + "\r\n0\r\n\r\n"));
  const auto answers = c.responses(1);
  ASSERT_EQ(answers.size(), 1u);
  EXPECT_EQ(status_of(answers[0]), 200) << answers[0];
}

TEST_F(EpollEngine, ExpectContinueIsAnsweredBeforeTheBody) {
  Connection c(port());
  const std::string request = post("/evaluate", kEvaluate, "Expect: 100-continue\r\n");
  const std::size_t head_end = request.find("\r\n\r\n") + 4;
  ASSERT_TRUE(c.send_all(request.substr(0, head_end)));
  const std::string interim = c.read_until([](const std::string& s) { return s.find("\r\n\r\n") != std::string::npos; });
  EXPECT_EQ(interim, "HTTP/1.1 100 Continue\r\n\r\n");
  ASSERT_TRUE(c.send_all(request.substr(head_end)));
  const auto answers = c.responses(2);
  ASSERT_EQ(answers.size(), 2u);
  EXPECT_EQ(status_of(answers[1]), 200);
}

TEST_F(EpollEngine, OversizedBodyIs413BeforeItIsSentThenClosed) {
  Connection c(port());
  // Only the head is sent: the answer cannot wait for the body.
  ASSERT_TRUE(c.send_all("POST /evaluate HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
                         "Content-Length: 1000000000\r\nX-Request-Id: big-1\r\n\r\n{"));
  const auto answers = c.responses(1);
  ASSERT_EQ(answers.size(), 1u);
  expect_problem(answers[0], 413);
  EXPECT_TRUE(has_header(answers[0], "Connection: close"));
  EXPECT_TRUE(has_header(answers[0], "X-Request-Id: big-1"));
  EXPECT_TRUE(c.closed_by_peer());
}

TEST_F(EpollEngine, MalformedRequestIs400ProblemThenClosed) {
  for (const std::string_view bad : {"GET /healthz HTTP/1.1\r\nNo colon here\r\n\r\n", "NOT A REQUEST\r\n\r\n",
                                     "GET /healthz HTTP/3.0\r\n\r\n"}) {
    Connection c(port());
    ASSERT_TRUE(c.send_all(bad));
    const auto answers = c.responses(1);
    ASSERT_EQ(answers.size(), 1u) << bad;
    expect_problem(answers[0], bad.find("HTTP/3.0") != std::string_view::npos ? 505 : 400);
    EXPECT_TRUE(c.closed_by_peer()) << bad;
  }
}

TEST_F(EpollEngine, HeadHasTheHeadersOfGetWithoutTheBody) {
  Connection c(port());
  ASSERT_TRUE(c.send_all("HEAD /healthz HTTP/1.1\r\nHost: x\r\n\r\nGET /healthz HTTP/1.1\r\nHost: x\r\n\r\n"));
  // The HEAD answer announces 15 bytes and sends none, so the GET answer follows it
  // directly; read both as they arrive.
  const std::string both = c.read_until([](const std::string& s) { return s.find("{\"status\":\"ok\"}") != std::string::npos; });
  EXPECT_EQ(both.rfind("HTTP/1.1 200 OK\r\n", 0), 0u);
  const std::size_t first_end = both.find("\r\n\r\n") + 4;
  EXPECT_NE(both.substr(0, first_end).find("Content-Length: 15\r\n"), std::string::npos);
  EXPECT_EQ(both.substr(first_end).rfind("HTTP/1.1 200 OK\r\n", 0), 0u);
}

TEST_F(EpollEngine, Http10ClosesUnlessKeepAliveIsAsked) {
  {
    Connection c(port());
    ASSERT_TRUE(c.send_all("GET /healthz HTTP/1.0\r\n\r\n"));
    const auto answers = c.responses(1);
    ASSERT_EQ(answers.size(), 1u);
    EXPECT_TRUE(has_header(answers[0], "Connection: close"));
    EXPECT_TRUE(c.closed_by_peer());
  }
  Connection c(port());
  ASSERT_TRUE(c.send_all("GET /healthz HTTP/1.0\r\nConnection: keep-alive\r\n\r\n"));
  auto answers = c.responses(1);
  ASSERT_EQ(answers.size(), 1u);
  EXPECT_TRUE(has_header(answers[0], "Connection: keep-alive"));
  ASSERT_TRUE(c.send_all("GET /healthz HTTP/1.0\r\nConnection: keep-alive\r\n\r\n"));
  answers = c.responses(2);
  EXPECT_EQ(answers.size(), 2u);
}

TEST_F(EpollEngine, IncompleteRequestIs408AtTheReadTimeout) {
  Connection c(port());
  ASSERT_TRUE(c.send_all("POST /evaluate HTTP/1.1\r\nHost: x\r\nContent-Length: 10\r\n\r\n{"));
  const auto answers = c.responses(1);
  ASSERT_EQ(answers.size(), 1u);
  expect_problem(answers[0], 408);
  EXPECT_TRUE(c.closed_by_peer());
}

TEST_F(EpollEngine, IdleKeepAliveConnectionIsClosedAtTheIdleTimeout) {
  Connection c(port());
  ASSERT_TRUE(c.send_all("GET /healthz HTTP/1.1\r\nHost: x\r\n\r\n"));
  ASSERT_EQ(c.responses(1).size(), 1u);
  EXPECT_TRUE(c.closed_by_peer());  // --keep-alive-timeout 2; the read deadline is 10 s
}

TEST_F(EpollEngine, TheLastRequestOfAConnectionSaysClose) {
  Connection c(port());
  std::string five;
  for (int i = 0; i < 5; ++i) five += "GET /healthz HTTP/1.1\r\nHost: x\r\n\r\n";
  ASSERT_TRUE(c.send_all(five));
  const auto answers = c.responses(5);
  ASSERT_EQ(answers.size(), 5u);
  EXPECT_FALSE(has_header(answers[3], "Connection: close"));
  EXPECT_TRUE(has_header(answers[4], "Connection: close"));  // --keep-alive-max-requests 5
  EXPECT_TRUE(c.closed_by_peer());
}

TEST(EpollEngineLimits, ConnectionsBeyondTheLimitGet503) {
  ServiceProcess service({"--http-engine", "epoll", "--max-connections", "2"});
  Connection a(service.port()), b(service.port());
  for (Connection* c : {&a, &b}) {
    ASSERT_TRUE(c->send_all("GET /healthz HTTP/1.1\r\nHost: x\r\n\r\n"));
    ASSERT_EQ(c->responses(1).size(), 1u);  // both accepted and served
  }
  Connection third(service.port());
  const auto answers = third.responses(1);
  ASSERT_EQ(answers.size(), 1u);
  expect_problem(answers[0], 503);
  EXPECT_TRUE(has_header(answers[0], "Retry-After: 1"));
}

TEST(EpollEngineShutdown, RequestOnTheComputePoolIsAnsweredBeforeExit) {
  ServiceProcess service({"--http-engine", "epoll"});
  Connection idle(service.port());
  ASSERT_TRUE(idle.send_all("GET /healthz HTTP/1.1\r\nHost: x\r\n\r\n"));
  ASSERT_EQ(idle.responses(1).size(), 1u);
  // Degree 9: above the inline try, so it runs on the pool. The connection sent nothing
  // else, so it may still be in the backlog when the signal comes: stopping takes the
  // backlog's connections too.
  Connection busy(service.port());
  ASSERT_TRUE(busy.send_all(post("/evaluate", R"({"points":[[0,0],[1,0],[2,0],[3,0],[4,0],[5,0],[6,0],[7,0],[8,0],[9,0]],"samples":2000,"derivatives":2})")));
  service.signal(SIGTERM);
  const auto answers = busy.responses(1);
  ASSERT_EQ(answers.size(), 1u);
  EXPECT_EQ(status_of(answers[0]), 200);
  EXPECT_TRUE(idle.closed_by_peer());  // idle keep-alive connections are closed
  EXPECT_EQ(service.wait_exit(), std::optional<int>(0));
}

}  // namespace
}  // namespace bezier::test
