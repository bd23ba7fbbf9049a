// The epoll HTTP engine over raw sockets (--http-engine epoll): what an HTTP client
// library would hide. Pipelining, chunked bodies, 100-continue, HEAD, HTTP/1.0, 413
// before the body is sent, malformed requests, the read and keep-alive timeouts,
// keep_alive_max_requests, max_connections, and shutdown with a request on the pool.
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/raw_http.hpp"
#include "tests/support/service_suite.hpp"

namespace bezier::test {
namespace {

constexpr std::string_view kEvaluate = R"({"points":[[0,0],[1,2],[3,3]],"t":0.5})";

std::string post(std::string_view path, std::string_view body, std::string_view extra_headers = "") {
  return post_request(path, body, extra_headers);
}

class EpollEngine : public ServiceSuite<EpollEngine> {
 public:
  static std::vector<std::string> service_args() {
    return {"--http-engine", "epoll", "--io-threads", "2", "--threads", "2", "--max-body-bytes", "100000",
            "--read-timeout", "1", "--keep-alive-timeout", "2", "--keep-alive-max-requests", "5"};
  }
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

TEST_F(EpollEngine, AbsoluteFormTargetIsServed) {
  // RFC 9112 §3.2.2: a server must accept the absolute form (what a client sends to a
  // proxy); the path routes, and the Host header still must be there on HTTP/1.1.
  Connection c(port());
  ASSERT_TRUE(c.send_all("GET http://localhost:8080/healthz HTTP/1.1\r\nHost: localhost:8080\r\n\r\n"
                         "POST HTTP://localhost/evaluate?x=1 HTTP/1.1\r\nHost: localhost\r\n"
                         "Content-Type: application/json\r\nContent-Length: " +
                         std::to_string(kEvaluate.size()) + "\r\n\r\n" + std::string(kEvaluate)));
  const auto answers = c.responses(2);
  ASSERT_EQ(answers.size(), 2u);
  EXPECT_EQ(status_of(answers[0]), 200) << answers[0];
  EXPECT_EQ(body_of(answers[0]), R"({"status":"ok"})");
  ASSERT_EQ(status_of(answers[1]), 200) << answers[1];
  EXPECT_EQ(nlohmann::json::parse(body_of(answers[1]))["results"][0]["point"], nlohmann::json::parse("[1.25,1.75]"));
}

TEST_F(EpollEngine, Http11RequestWithoutOrWithTwoHostsIs400) {
  // RFC 9112 §3.2: exactly one Host on HTTP/1.1 (HTTP/1.0 may leave it out).
  for (const std::string_view bad : {"GET /healthz HTTP/1.1\r\n\r\n",
                                     "GET /healthz HTTP/1.1\r\nHost: a\r\nHost: b\r\n\r\n"}) {
    Connection c(port());
    ASSERT_TRUE(c.send_all(bad));
    const auto answers = c.responses(1);
    ASSERT_EQ(answers.size(), 1u) << bad;
    expect_problem(answers[0], 400);
    EXPECT_TRUE(c.closed_by_peer()) << bad;
  }
  Connection c(port());
  ASSERT_TRUE(c.send_all("GET /healthz HTTP/1.0\r\n\r\n"));
  const auto answers = c.responses(1);
  ASSERT_EQ(answers.size(), 1u);
  EXPECT_EQ(status_of(answers[0]), 200);
}

TEST_F(EpollEngine, ContentEncodingOtherThanIdentityIs415) {
  // The body is read as sent: a coded one is refused (RFC 9110 §15.5.16, with the codings
  // that would do in Accept-Encoding), never parsed as if it were JSON.
  for (const std::string_view coding : {"gzip", "identity, gzip", "br"}) {
    const auto answer =
        round_trip(port(), post("/evaluate", kEvaluate, "Content-Encoding: " + std::string(coding) + "\r\n"));
    expect_problem(answer, 415);
    EXPECT_TRUE(has_header(answer, "Accept-Encoding: identity")) << answer;
    EXPECT_EQ(nlohmann::json::parse(body_of(answer))["type"], "urn:bezier-service:problem:unsupported-media-type");
  }
  for (const std::string_view coding : {"identity", "Identity"}) {
    const auto answer =
        round_trip(port(), post("/evaluate", kEvaluate, "Content-Encoding: " + std::string(coding) + "\r\n"));
    EXPECT_EQ(status_of(answer), 200) << answer;
  }
}

TEST_F(EpollEngine, ExpectContinueIsNotSentToARequestThatWillBeRefused) {
  // Each is refused on its head alone (route, method, media type): the final answer comes
  // instead of "100 Continue", and the connection closes without the body being asked for.
  const std::string expect = "Expect: 100-continue\r\nContent-Length: 60000\r\n\r\n";
  const std::pair<std::string, int> refused[] = {
      {"POST /nowhere HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n" + expect, 404},
      {"PUT /evaluate HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n" + expect, 405},
      {"POST /healthz HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n" + expect, 405},
      {"POST /evaluate HTTP/1.1\r\nHost: x\r\nContent-Type: text/plain\r\n" + expect, 415},
      {"POST /evaluate HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\nContent-Encoding: gzip\r\n" +
           expect, 415},
  };
  for (const auto& [head, status] : refused) {
    Connection c(port());
    ASSERT_TRUE(c.send_all(head));
    const auto answers = c.responses(1);
    ASSERT_EQ(answers.size(), 1u) << head;
    expect_problem(answers[0], status);
    EXPECT_TRUE(has_header(answers[0], "Connection: close")) << answers[0];
    EXPECT_TRUE(c.closed_by_peer()) << head;
  }
}

TEST(EpollEngineAuth, ExpectContinueIsNotSentWithoutTheToken) {
  // An unauthenticated client must not be invited to upload its body.
  ServiceProcess service({}, {"BEZIER_AUTH_TOKEN=s3cret-token-value"});
  Connection c(service.port());
  ASSERT_TRUE(c.send_all("POST /evaluate HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
                         "Expect: 100-continue\r\nContent-Length: 1048576\r\n\r\n"));
  const auto answers = c.responses(1);
  ASSERT_EQ(answers.size(), 1u);
  expect_problem(answers[0], 401);
  EXPECT_TRUE(has_header(answers[0], "WWW-Authenticate: Bearer"));
  EXPECT_TRUE(c.closed_by_peer());
  // With the token, the same head is invited.
  Connection invited(service.port());
  const std::string request =
      post("/evaluate", kEvaluate, "Authorization: Bearer s3cret-token-value\r\nExpect: 100-continue\r\n");
  ASSERT_TRUE(invited.send_all(request.substr(0, request.find("\r\n\r\n") + 4)));
  const std::string interim =
      invited.read_until([](const std::string& s) { return s.find("\r\n\r\n") != std::string::npos; });
  EXPECT_EQ(interim, "HTTP/1.1 100 Continue\r\n\r\n");
}

TEST(EpollEngineAuth, BearerSchemeNameIsCaseInsensitive) {
  // RFC 9110 §11.1: the authentication scheme is a case-insensitive token; one or more
  // spaces separate it from the credentials (§11.4).
  ServiceProcess service({}, {"BEZIER_AUTH_TOKEN=s3cret-token-value"});
  for (const std::string_view scheme : {"Bearer ", "bearer ", "BEARER ", "bEaReR ", "Bearer   "}) {
    const std::string authorization = "Authorization: " + std::string(scheme) + "s3cret-token-value\r\n";
    const auto answer = round_trip(service.port(), post("/evaluate", kEvaluate, authorization));
    EXPECT_EQ(status_of(answer), 200) << scheme << answer;
  }
  for (const std::string_view credentials : {"Basic s3cret-token-value", "Bearers3cret-token-value",
                                             "Bearer s3cret-token-valuE", "Bearer", "s3cret-token-value"}) {
    const std::string authorization = "Authorization: " + std::string(credentials) + "\r\n";
    const auto answer = round_trip(service.port(), post("/evaluate", kEvaluate, authorization));
    expect_problem(answer, 401);
  }
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
