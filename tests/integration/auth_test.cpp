// The optional bearer token: off by default; when BEZIER_AUTH_TOKEN is set, POST routes
// need it, health and metrics stay open, and the token never reaches the log.
#include <httplib.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/service_process.hpp"

namespace bezier::test {
namespace {

constexpr const char* kBody = R"({"points":[[0,0],[1,1]],"t":0.5})";
constexpr const char* kToken = "s3cret-token-value";

TEST(Auth, OffByDefault) {
  ServiceProcess service;
  httplib::Client c("127.0.0.1", service.port());
  const auto r = c.Post("/evaluate", kBody, "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
}

TEST(Auth, TokenRequiredWhenConfigured) {
  ServiceProcess service({}, {std::string("BEZIER_AUTH_TOKEN=") + kToken});
  httplib::Client c("127.0.0.1", service.port());

  auto r = c.Post("/evaluate", kBody, "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 401);
  EXPECT_EQ(r->get_header_value("Content-Type"), "application/problem+json");
  EXPECT_EQ(r->get_header_value("WWW-Authenticate"), "Bearer");
  EXPECT_EQ(nlohmann::json::parse(r->body)["status"], 401);

  r = c.Post("/evaluate", {{"Authorization", "Bearer wrong-token-value!"}}, kBody, "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 401);

  r = c.Post("/evaluate", {{"Authorization", std::string("Bearer ") + kToken}}, kBody,
             "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);

  for (const char* open_route : {"/healthz", "/readyz", "/metrics"}) {
    r = c.Get(open_route);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200) << open_route;
  }

  service.signal(SIGTERM);
  EXPECT_EQ(service.wait_exit(), std::optional<int>(0));
  EXPECT_EQ(service.output().find(kToken), std::string::npos) << "token leaked into the log";
}

}  // namespace
}  // namespace bezier::test
