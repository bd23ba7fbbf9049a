// Security headers on the wire, read from raw sockets: X-Content-Type-Options: nosniff
// on every kind of answer, and on HTML pages a Content-Security-Policy that admits only
// the service's own origin and no framing.
#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/raw_http.hpp"
#include "tests/support/service_suite.hpp"

namespace bezier::test {
namespace {

class SecurityHeadersTest : public ServiceSuite<SecurityHeadersTest> {
 public:
  static std::vector<std::string> service_args() { return {"--max-body-bytes", "4096"}; }

 protected:
  static std::string get(const std::string& path) {
    return raw_exchange(port(), "GET " + path + " HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n");
  }
  static std::string post(const std::string& path, const std::string& type, const std::string& body) {
    return raw_exchange(port(), "POST " + path + " HTTP/1.1\r\nHost: x\r\nConnection: close\r\n" +
                                              "Content-Type: " + type + "\r\nContent-Length: " +
                                              std::to_string(body.size()) + "\r\n\r\n" + body);
  }
};

std::string status_line(const std::string& answer) { return answer.substr(0, answer.find("\r\n")); }

// The directives of a Content-Security-Policy value, each as "name value...".
std::vector<std::string> directives(const std::string& policy) {
  std::vector<std::string> out;
  std::istringstream in(policy);
  for (std::string directive; std::getline(in, directive, ';');) {
    const auto first = directive.find_first_not_of(' ');
    const auto last = directive.find_last_not_of(' ');
    if (first != std::string::npos) out.push_back(directive.substr(first, last - first + 1));
  }
  return out;
}

TEST_F(SecurityHeadersTest, EveryKindOfAnswerSaysNoSniff) {
  const std::vector<std::pair<std::string, std::string>> answers = {
      {"200 JSON", post("/evaluate", "application/json", R"({"points":[[0,0],[1,1]],"t":0.5})")},
      {"422 problem", post("/evaluate", "application/json", R"({"points":[],"t":0.5})")},
      {"400 problem", post("/evaluate", "application/json", "{")},
      {"415 problem", post("/evaluate", "text/plain", "{}")},
      {"413 problem", post("/evaluate", "application/json", std::string(5000, ' '))},
      {"404 problem", get("/no-such-route")},
      {"405 problem", get("/evaluate")},
      {"health", get("/healthz")},
      {"metrics", get("/metrics")},
      {"spec", get("/openapi.yaml")},
      {"page", get("/")},
      {"script", get("/playground/app.js")},
      {"style", get("/playground/style.css")},
      {"malformed request line", raw_exchange(port(), "GARBAGE\r\n\r\n")},
  };
  const std::vector<std::string> statuses = {"200", "422", "400", "415", "413", "404", "405",
                                             "200", "200", "200", "200", "200", "200", "400"};
  for (std::size_t i = 0; i < answers.size(); ++i) {
    const auto& [what, answer] = answers[i];
    EXPECT_EQ(status_line(answer).substr(9, 3), statuses[i]) << what << ": " << status_line(answer);
    const HeaderValue nosniff = header_of(answer, "X-Content-Type-Options");
    EXPECT_TRUE(nosniff.found) << what << " has no X-Content-Type-Options:\n" << answer_head(answer);
    EXPECT_EQ(nosniff.value, "nosniff") << what;
  }
}

TEST_F(SecurityHeadersTest, PlaygroundPagesAdmitOnlyTheirOwnOriginAndNoFraming) {
  for (const std::string path : {"/", "/playground/index.html"}) {
    const std::string answer = get(path);
    ASSERT_EQ(status_line(answer), "HTTP/1.1 200 OK") << path;
    ASSERT_EQ(header_of(answer, "Content-Type").value.rfind("text/html", 0), 0u) << path;
    const HeaderValue policy = header_of(answer, "Content-Security-Policy");
    ASSERT_TRUE(policy.found) << path << " has no Content-Security-Policy:\n" << answer_head(answer);
    const std::vector<std::string> given = directives(policy.value);
    // Everything from the page's own origin only (no host, scheme or 'unsafe-*' source),
    // and no page may frame it.
    EXPECT_NE(std::find(given.begin(), given.end(), "default-src 'self'"), given.end()) << policy.value;
    EXPECT_NE(std::find(given.begin(), given.end(), "frame-ancestors 'none'"), given.end()) << policy.value;
    for (const std::string& directive : given) {
      const std::string sources = directive.substr(directive.find(' ') + 1);
      EXPECT_TRUE(sources == "'self'" || sources == "'none'") << "directive admits more: " << directive;
    }
  }
}

TEST_F(SecurityHeadersTest, HeadAnswersCarryTheSameHeaders) {
  const std::string answer =
      raw_exchange(port(), "HEAD / HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n");
  EXPECT_EQ(header_of(answer, "X-Content-Type-Options").value, "nosniff");
  EXPECT_TRUE(header_of(answer, "Content-Security-Policy").found);
}

}  // namespace
}  // namespace bezier::test
