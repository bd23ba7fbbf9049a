// Starts the built bezier-service on a free port and talks HTTP to it. Every exchange
// of the fixture is also checked against api/openapi.yaml (expect_conforms).
#include "tests/support/openapi_validator.hpp"  // first: see there

#include <httplib.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/child_process.hpp"
#include "tests/support/service_suite.hpp"

namespace bezier::test {
namespace {

using nlohmann::json;

class ServiceTest : public ServiceSuite<ServiceTest> {
 public:
  static std::vector<std::string> service_args() { return {"--threads", "2", "--max-body-bytes", "1000000"}; }

 protected:
  static httplib::Client client() {
    httplib::Client c("127.0.0.1", port());
    c.set_read_timeout(10, 0);
    return c;
  }

  static httplib::Result post(const std::string& path, const std::string& body,
                              const std::string& type = "application/json") {
    auto r = client().Post(path.c_str(), body, type.c_str());
    expect_conforms("POST", path, type, body, r);
    return r;
  }

  static httplib::Result get(const std::string& path, const httplib::Headers& headers = {}) {
    auto r = client().Get(path.c_str(), headers);
    expect_conforms("GET", path, "", "", r);
    return r;
  }

  // Every error is problem+json with the RFC 9457 members and the status repeated.
  static json expect_problem(const httplib::Result& r, int status) {
    EXPECT_TRUE(r) << "no answer";
    if (!r) return {};
    EXPECT_EQ(r->status, status) << r->body;
    EXPECT_EQ(r->get_header_value("Content-Type"), "application/problem+json");
    const json body = json::parse(r->body);
    EXPECT_EQ(body.at("status"), status);
    EXPECT_TRUE(body.at("type").is_string());
    EXPECT_TRUE(body.at("title").is_string());
    EXPECT_TRUE(body.at("detail").is_string());
    return body;
  }
};

TEST_F(ServiceTest, EvaluateAnswersExactDyadicValues) {
  // B(1/2) of (0,0), (1,2), (3,3) is (0 + 2*1 + 3)/4, (0 + 2*2 + 3)/4 = (1.25, 1.75): exact.
  const auto r = post("/evaluate", R"({"points":[[0,0],[1,2],[3,3]],"t":0.5,"derivatives":1})");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_EQ(r->get_header_value("Content-Type"), "application/json");
  const json body = json::parse(r->body);
  EXPECT_EQ(body["degree"], 2);
  EXPECT_EQ(body["results"][0]["point"], json::parse("[1.25, 1.75]"));
  // B'(t) = 2[(1-t)(P1-P0) + t(P2-P1)] = (1,2) + (2,1) = (3, 3) at t = 1/2.
  EXPECT_EQ(body["results"][0]["derivatives"][0], json::parse("[3.0, 3.0]"));
}

TEST_F(ServiceTest, PolarAnswers) {
  const auto r = post("/polar", R"({"points":[[0,0],[1,2],[3,3]],"t0":0.5})");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  const json body = json::parse(r->body);
  // b_i = (P_i + P_{i+1}) / 2
  EXPECT_EQ(body["control_points"], json::parse("[[0.5, 1.0], [2.0, 2.5]]"));
  EXPECT_EQ(body["curve_point"], json::parse("[1.25, 1.75]"));
}

TEST_F(ServiceTest, NumbersRoundTrip) {
  const double third = 1.0 / 3.0;
  json request = {{"points", {{0.0, 0.0}, {third, 0.1}}}, {"t", 1.0}};
  const auto r = post("/evaluate", request.dump());
  ASSERT_TRUE(r);
  const json body = json::parse(r->body);
  EXPECT_EQ(body["results"][0]["point"][0].get<double>(), third);
  EXPECT_EQ(body["results"][0]["point"][1].get<double>(), 0.1);
}

TEST_F(ServiceTest, MalformedBodiesAre400) {
  expect_problem(post("/evaluate", "{\"points\": [[0,0],"), 400);
  expect_problem(post("/evaluate", ""), 400);
  expect_problem(post("/evaluate", "[1, 2]"), 400);
  expect_problem(post("/evaluate", "{\"t\": NaN}"), 400);
  // 100 000 levels of nesting: valid JSON, not an object, and no stack overflow.
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  expect_problem(post("/evaluate", deep), 400);
}

TEST_F(ServiceTest, ValidationErrorsAre422WithPointers) {
  auto body = expect_problem(post("/evaluate", R"({"points":[[0,0],[1,"x"]],"t":0.5})"), 422);
  EXPECT_EQ(body["errors"][0]["pointer"], "/points/1/1");
  body = expect_problem(post("/evaluate", R"({"points":[[0,0],[1,1e999]],"t":0.5})"), 422);
  EXPECT_EQ(body["errors"][0]["pointer"], "/points/1/1");
  body = expect_problem(post("/evaluate", R"({"points":[[0,0],[1,1,1]],"t":0.5})"), 422);
  EXPECT_EQ(body["errors"][0]["pointer"], "/points/1");
  body = expect_problem(post("/evaluate", R"({"points":[[0,0]],"t":0.5})"), 422);
  EXPECT_EQ(body["errors"][0]["pointer"], "/points");
}

TEST_F(ServiceTest, BodiesOverTheLimitAre413) {
  const std::string huge = R"({"t":0.5,"points":[[0,0],[1,1]],"pad":")" + std::string(1000000, 'x') + "\"}";
  expect_problem(post("/evaluate", huge), 413);
  // The service keeps serving.
  const auto r = get("/healthz");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
}

TEST_F(ServiceTest, HundredThousandPointsUnderTheBodyLimitAre422) {
  std::string many = R"({"t":0.5,"points":[)";
  for (int i = 0; i < 100000; ++i) many += i == 0 ? "[0,0]" : ",[0,0]";
  many += "]}";
  ASSERT_LT(many.size(), 1000000u);
  const auto body = expect_problem(post("/evaluate", many), 422);
  EXPECT_EQ(body["errors"][0]["pointer"], "/points");
}

TEST_F(ServiceTest, WrongContentTypeIs415) {
  expect_problem(post("/evaluate", R"({"points":[[0,0],[1,1]],"t":0.5})", "text/plain"), 415);
}

TEST_F(ServiceTest, WrongMethodIs405WithAllow) {
  const auto r = get("/evaluate");
  expect_problem(r, 405);
  EXPECT_EQ(r->get_header_value("Allow"), "POST");
  const auto put = client().Put("/polar", "{}", "application/json");
  expect_conforms("PUT", "/polar", "application/json", "{}", put);
  expect_problem(put, 405);
  const auto post_health = post("/healthz", "{}");
  expect_problem(post_health, 405);
  EXPECT_EQ(post_health->get_header_value("Allow"), "GET, HEAD");
}

TEST_F(ServiceTest, UnknownRouteIs404) {
  expect_problem(get("/nope"), 404);
  expect_problem(post("/nope", "{}"), 404);
}

TEST_F(ServiceTest, HealthReadinessAndSpec) {
  auto r = get("/healthz");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  r = get("/readyz");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  r = get("/openapi.yaml");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  std::ifstream file(std::string(BEZIER_SOURCE_DIR) + "/api/openapi.yaml", std::ios::binary);
  std::stringstream text;
  text << file.rdbuf();
  EXPECT_EQ(r->body, text.str());
}

TEST_F(ServiceTest, MetricsCountRequestsByRouteAndStatus) {
  ASSERT_TRUE(post("/evaluate", R"({"points":[[0,0],[1,1]],"t":0.5})"));
  ASSERT_TRUE(post("/evaluate", R"({"points":[[0,0],[1,1]]})"));
  const auto r = get("/metrics");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_NE(r->body.find(R"(bezier_requests_total{route="/evaluate",status="200"})"), std::string::npos);
  EXPECT_NE(r->body.find(R"(bezier_requests_total{route="/evaluate",status="422"})"), std::string::npos);
  EXPECT_NE(r->body.find(R"(bezier_request_duration_seconds_bucket{route="/evaluate",le="+Inf"})"),
            std::string::npos);
  // At least this request is in flight (earlier ones may still be finishing their
  // access line, which is written after the answer).
  const auto gauge = r->body.find("\nbezier_requests_in_flight ");
  ASSERT_NE(gauge, std::string::npos);
  EXPECT_GE(std::stoi(r->body.substr(gauge + 27)), 1);
}

TEST_F(ServiceTest, RequestIdIsEchoedAndLogged) {
  httplib::Headers headers = {{"X-Request-Id", "test-id-42"}};
  const auto r = get("/healthz", headers);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->get_header_value("X-Request-Id"), "test-id-42");
  // The access line is written after the answer; give the log a moment to arrive.
  std::string log;
  for (int i = 0; i < 500 && log.find("test-id-42") == std::string::npos; ++i) {
    usleep(10000);
    log = service().output();
  }
  EXPECT_NE(log.find("GET /healthz 200"), std::string::npos);
  EXPECT_NE(log.find("id=test-id-42"), std::string::npos);
}

TEST_F(ServiceTest, IdleKeepAliveConnectionsBeyondThePoolDoNotStallOthers) {
  // Ten times the 2 worker threads of this instance, each holding an idle keep-alive
  // connection after one request.
  std::vector<std::unique_ptr<httplib::Client>> idle;
  for (int i = 0; i < 20; ++i) {
    auto c = std::make_unique<httplib::Client>("127.0.0.1", port());
    c->set_keep_alive(true);
    ASSERT_TRUE(c->Get("/healthz"));
    idle.push_back(std::move(c));
  }
  auto c = client();
  c.set_read_timeout(2, 0);  // the service's keep-alive timeout is 5 s: a stall would hit this
  const auto r = c.Get("/healthz");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
}

TEST(ServiceShutdown, SigtermDrainsThenExitsZero) {
  ServiceProcess service({"--drain-seconds", "1"});
  httplib::Client c("127.0.0.1", service.port());
  ASSERT_EQ(c.Get("/readyz")->status, 200);
  service.signal(SIGTERM);
  // During the drain the service still answers, but is no longer ready.
  int readyz = 0;
  for (int i = 0; i < 50 && readyz != 503; ++i) {
    const auto r = c.Get("/readyz");
    readyz = r ? r->status : -1;
    usleep(10000);
  }
  EXPECT_EQ(readyz, 503);
  const auto health = c.Get("/healthz");
  ASSERT_TRUE(health);
  EXPECT_EQ(health->status, 200);
  EXPECT_EQ(service.wait_exit(), std::optional<int>(0));
}

TEST(ServiceShutdown, SigintExitsZero) {
  ServiceProcess service;
  service.signal(SIGINT);
  EXPECT_EQ(service.wait_exit(), std::optional<int>(0));
}

}  // namespace
}  // namespace bezier::test

namespace bezier::test {
namespace {

using nlohmann::json;

TEST(ServiceLogs, JsonFormatWritesOneJsonObjectPerLine) {
  ServiceProcess service({"--log-format", "json"});
  httplib::Client c("127.0.0.1", service.port());
  ASSERT_TRUE(c.Post("/evaluate", R"({"points":[[0,0],[1,1]],"t":0.5})", "application/json"));
  ASSERT_TRUE(c.Get("/nope"));
  service.signal(SIGTERM);
  ASSERT_EQ(service.wait_exit(), std::optional<int>(0));
  std::istringstream lines(service.output());
  int access_lines = 0;
  int lines_read = 0;
  for (std::string line; std::getline(lines, line);) {
    ++lines_read;
    const json entry = json::parse(line, nullptr, /*allow_exceptions=*/false);
    ASSERT_TRUE(entry.is_object()) << line;
    EXPECT_TRUE(entry.contains("time") && entry.contains("level") && entry.contains("msg")) << line;
    if (entry["msg"] == "access") {
      ++access_lines;
      EXPECT_TRUE(entry.contains("status") && entry.contains("request_id") && entry.contains("duration_ms"));
    }
  }
  EXPECT_GE(lines_read, 4);  // start, two access lines, the signal, stopped
  EXPECT_EQ(access_lines, 2);
}

}  // namespace
}  // namespace bezier::test

namespace bezier::test {
namespace {

TEST(ServiceStartup, AnHttpEngineOtherThanEpollStopsStartUpWithAReason) {
  const ProgramRun by_flag =
      run_program({BEZIER_SERVICE_BINARY, "--port", "0", "--http-engine", "httplib"});
  ASSERT_TRUE(by_flag.exit_code.has_value()) << by_flag.output;
  EXPECT_NE(*by_flag.exit_code, 0);
  EXPECT_NE(by_flag.output.find("unknown HTTP engine 'httplib': the only engine is epoll"), std::string::npos)
      << by_flag.output;
  EXPECT_EQ(by_flag.output.find("listening on"), std::string::npos) << by_flag.output;

  const ProgramRun by_environment =
      run_program({BEZIER_SERVICE_BINARY, "--port", "0"}, {"BEZIER_HTTP_ENGINE=httplib"});
  ASSERT_TRUE(by_environment.exit_code.has_value()) << by_environment.output;
  EXPECT_NE(*by_environment.exit_code, 0);
  EXPECT_NE(by_environment.output.find("the only engine is epoll"), std::string::npos) << by_environment.output;
}

// Every BEZIER_* variable of README's configuration table, in the order of the table.
std::vector<std::string> readme_environment_variables() {
  std::ifstream readme(std::string(BEZIER_SOURCE_DIR) + "/README.md");
  std::vector<std::string> names;
  for (std::string line; std::getline(readme, line);) {
    if (line.rfind("| ", 0) != 0) continue;
    const auto start = line.find("`BEZIER_");
    if (start == std::string::npos) continue;
    const auto end = line.find('`', start + 1);
    names.push_back(line.substr(start + 1, end - start - 1));
  }
  return names;
}

TEST(ServiceStartup, HelpNamesEveryEnvironmentVariableOfTheReadme) {
  const ProgramRun help = run_program({BEZIER_SERVICE_BINARY, "--help"});
  ASSERT_EQ(help.exit_code, std::optional<int>(0)) << help.output;
  const std::vector<std::string> names = readme_environment_variables();
  EXPECT_GE(names.size(), 20u);  // the table was found
  EXPECT_NE(std::find(names.begin(), names.end(), "BEZIER_AUTH_TOKEN"), names.end());
  for (const std::string& name : names) {
    EXPECT_NE(help.output.find("(Env:" + name + ")"), std::string::npos) << name << " missing from --help";
  }
}

}  // namespace
}  // namespace bezier::test
