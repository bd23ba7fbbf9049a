// CORS on the wire, read from raw sockets: off by default; with --cors-origin (repeatable)
// or BEZIER_CORS_ORIGIN (comma-separated), preflights from an allowed origin are answered
// 204 with the methods, headers and max age, and every answer to an allowed origin (errors
// and the engine's own refusals included) admits it, with "Vary: Origin"; an origin not
// on the list gets no CORS header at all; "*" admits every origin.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/child_process.hpp"
#include "tests/support/raw_http.hpp"
#include "tests/support/service_suite.hpp"

namespace bezier::test {
namespace {

constexpr const char* kAllowed = "https://app.example";
constexpr const char* kAllowedWithPort = "https://tools.example:8443";
constexpr const char* kCubic = R"({"points":[[0,0],[1,1],[0,1],[1,0]]})";

std::string status_of(const std::string& answer) { return answer.substr(9, 3); }

std::string request(const std::string& method, const std::string& path, const std::vector<std::string>& headers,
                    const std::string& body = "") {
  std::string text = method + " " + path + " HTTP/1.1\r\nHost: x\r\nConnection: close\r\n";
  for (const std::string& h : headers) text += h + "\r\n";
  if (method == "POST") text += "Content-Length: " + std::to_string(body.size()) + "\r\n";
  return text + "\r\n" + body;
}

std::string post(int port, const std::string& path, const std::string& origin, const std::string& body,
                 const std::string& type = "application/json") {
  std::vector<std::string> headers = {"Content-Type: " + type};
  if (!origin.empty()) headers.push_back("Origin: " + origin);
  return raw_exchange(port, request("POST", path, headers, body));
}

std::string preflight(int port, const std::string& path, const std::string& origin,
                      const std::string& method = "POST") {
  return raw_exchange(port, request("OPTIONS", path,
                                    {"Origin: " + origin, "Access-Control-Request-Method: " + method,
                                     "Access-Control-Request-Headers: content-type"}));
}

// Every header of the answer whose name starts with "Access-Control-".
std::vector<std::string> cors_headers(const std::string& answer) {
  std::vector<std::string> found;
  const std::string_view head = answer_head(answer);
  for (std::size_t at = head.find("\r\nAccess-Control-"); at != std::string_view::npos;
       at = head.find("\r\nAccess-Control-", at + 2)) {
    found.emplace_back(head.substr(at + 2, head.find("\r\n", at + 2) - at - 2));
  }
  return found;
}

TEST(CorsOff, NoAnswerCarriesCorsHeaders) {
  ServiceProcess service;
  const std::string answers[] = {
      preflight(service.port(), "/classify", kAllowed),
      post(service.port(), "/classify", kAllowed, kCubic),
      post(service.port(), "/classify", kAllowed, "{"),
  };
  EXPECT_EQ(status_of(answers[0]), "405");  // OPTIONS is not a method of the route
  EXPECT_EQ(status_of(answers[1]), "200");
  for (const std::string& answer : answers) {
    EXPECT_TRUE(cors_headers(answer).empty()) << answer_head(answer);
    EXPECT_FALSE(header_of(answer, "Vary").found) << answer_head(answer);
  }
}

class CorsListTest : public ServiceSuite<CorsListTest> {
 public:
  static std::vector<std::string> service_args() {
    return {"--cors-origin", kAllowed, "--cors-origin", kAllowedWithPort, "--max-body-bytes", "8192"};
  }
};

TEST_F(CorsListTest, APreflightFromAnAllowedOriginIsAnswered) {
  for (const char* origin : {kAllowed, kAllowedWithPort}) {
    const std::string answer = preflight(port(), "/classify", origin);
    EXPECT_EQ(status_of(answer), "204") << answer;
    EXPECT_EQ(header_of(answer, "Access-Control-Allow-Origin").value, origin);
    EXPECT_EQ(header_of(answer, "Access-Control-Allow-Methods").value, "POST");
    EXPECT_EQ(header_of(answer, "Access-Control-Allow-Headers").value, "Authorization, Content-Type, X-Request-Id");
    EXPECT_EQ(header_of(answer, "Access-Control-Max-Age").value, "600");
    EXPECT_EQ(header_of(answer, "Vary").value, "Origin");
    // RFC 9110 §8.6: no Content-Length on a 204, and no body.
    EXPECT_FALSE(header_of(answer, "Content-Length").found);
    EXPECT_EQ(answer.size(), answer_head(answer).size() + 4);
  }
  const std::string get_route = preflight(port(), "/healthz", kAllowed, "GET");
  EXPECT_EQ(status_of(get_route), "204");
  EXPECT_EQ(header_of(get_route, "Access-Control-Allow-Methods").value, "GET, HEAD");
  EXPECT_EQ(status_of(preflight(port(), "/batch", kAllowed)), "204");
}

TEST_F(CorsListTest, APreflightFromAnotherOriginGetsNoCorsHeader) {
  for (const char* origin : {"https://evil.example", "http://app.example", "https://app.example.evil",
                             "https://app.example:443", "HTTPS://APP.EXAMPLE", "null"}) {
    const std::string answer = preflight(port(), "/classify", origin);
    EXPECT_EQ(status_of(answer), "405") << origin;
    EXPECT_TRUE(cors_headers(answer).empty()) << origin << "\n" << answer_head(answer);
  }
}

TEST_F(CorsListTest, EveryAnswerToAnAllowedOriginAdmitsIt) {
  const std::string answers[] = {
      post(port(), "/classify", kAllowed, kCubic),                               // 200, inline
      post(port(), "/batch", kAllowed, R"({"requests":[{"path":"/classify","body":)" + std::string(kCubic) +
                                           "}]}"),                               // 200, compute pool
      post(port(), "/classify", kAllowed, R"({"points":[]})"),                   // 422
      post(port(), "/classify", kAllowed, "{"),                                  // 400
      post(port(), "/classify", kAllowed, kCubic, "text/plain"),                 // 415
      post(port(), "/classify", kAllowed, std::string(9000, ' ')),               // 413, the HTTP layer's
      post(port(), "/nowhere", kAllowed, kCubic),                                // 404
      raw_exchange(port(), request("GET", "/healthz", {std::string("Origin: ") + kAllowed})),
      raw_exchange(port(), request("GET", "/classify", {std::string("Origin: ") + kAllowed})),  // 405
  };
  const char* statuses[] = {"200", "200", "422", "400", "415", "413", "404", "200", "405"};
  for (std::size_t i = 0; i < std::size(answers); ++i) {
    const std::string& answer = answers[i];
    EXPECT_EQ(status_of(answer), statuses[i]) << i;
    EXPECT_EQ(header_of(answer, "Access-Control-Allow-Origin").value, kAllowed) << i << "\n" << answer_head(answer);
    EXPECT_EQ(header_of(answer, "Access-Control-Expose-Headers").value,
              "X-Request-Id, Retry-After, Allow, WWW-Authenticate")
        << i;
    EXPECT_EQ(header_of(answer, "Vary").value, "Origin") << i;
  }
}

TEST_F(CorsListTest, AnAnswerToAnotherOriginOrToNoneHasNoCorsHeaderButVaries) {
  const std::string answers[] = {
      post(port(), "/classify", "https://evil.example", kCubic),
      post(port(), "/classify", "https://evil.example", R"({"points":[]})"),
      post(port(), "/classify", "", kCubic),
  };
  for (const std::string& answer : answers) {
    EXPECT_TRUE(cors_headers(answer).empty()) << answer_head(answer);
    // The answer would differ for an allowed Origin: caches must key on it.
    EXPECT_EQ(header_of(answer, "Vary").value, "Origin");
  }
}

TEST(CorsAnyOrigin, StarAdmitsEveryOriginWithoutVary) {
  ServiceProcess service({}, {"BEZIER_CORS_ORIGIN=*"});
  for (const char* origin : {"https://anything.example", "http://localhost:3000"}) {
    const std::string answer = post(service.port(), "/classify", origin, kCubic);
    EXPECT_EQ(status_of(answer), "200");
    EXPECT_EQ(header_of(answer, "Access-Control-Allow-Origin").value, "*");
    EXPECT_FALSE(header_of(answer, "Vary").found);
    const std::string pre = preflight(service.port(), "/evaluate", origin);
    EXPECT_EQ(status_of(pre), "204");
    EXPECT_EQ(header_of(pre, "Access-Control-Allow-Origin").value, "*");
  }
  // The same answer without Origin: nothing to vary on.
  EXPECT_EQ(header_of(post(service.port(), "/classify", "", kCubic), "Access-Control-Allow-Origin").value, "*");
}

TEST(CorsEnvironment, ACommaSeparatedListAllowsEachOrigin) {
  ServiceProcess service({}, {"BEZIER_CORS_ORIGIN=https://a.example,https://b.example"});
  for (const char* origin : {"https://a.example", "https://b.example"}) {
    EXPECT_EQ(header_of(post(service.port(), "/classify", origin, kCubic), "Access-Control-Allow-Origin").value,
              origin);
  }
  EXPECT_TRUE(cors_headers(post(service.port(), "/classify", "https://c.example", kCubic)).empty());
}

TEST(CorsConfiguration, AValueThatIsNotAnOriginStopsStartUp) {
  for (const char* value : {"https://app.example/", "app.example", "https://app.example/path", "https://"}) {
    const ProgramRun run = run_program({BEZIER_SERVICE_BINARY, "--port", "0", "--cors-origin", value});
    EXPECT_NE(run.exit_code, std::optional<int>(0)) << value;
    EXPECT_NE(run.output.find("is not an origin"), std::string::npos) << value << ": " << run.output;
  }
}

}  // namespace
}  // namespace bezier::test
