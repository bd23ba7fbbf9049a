#pragma once

// What the route tests share: a POST route's answer as a document, checked for what every
// answer keeps, and the pointers of a validation problem.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "api/handler.hpp"
#include "api/write_json.hpp"

namespace bezier::test {

/// The answer of POST `route` to `body` under `limits` (bezier::api::handle), parsed.
/// Expects `expected_status` and the content type that goes with it; answers are written
/// as text (JsonWriter), members in key order, so a 200 answer must be exactly the text
/// its document dumps to.
inline nlohmann::json route_answer(std::string_view route, const std::string& body, int expected_status,
                                   const api::Limits& limits = {}) {
  const api::Reply reply = api::handle(route, body, limits);
  EXPECT_EQ(reply.status, expected_status) << route << " " << body << "\n" << reply.body;
  EXPECT_EQ(reply.content_type, expected_status == 200 ? "application/json" : "application/problem+json");
  if (reply.status == 200) {
    EXPECT_EQ(api::dump_json(nlohmann::json::parse(reply.body)), reply.body);
  }
  return nlohmann::json::parse(reply.body);
}

/// The pointers of a validation problem's errors, in order; expects a 422 validation
/// problem whose every error has a message.
inline std::vector<std::string> error_pointers(const nlohmann::json& problem) {
  EXPECT_EQ(problem.value("status", 0), 422) << problem.dump();
  EXPECT_EQ(problem.value("type", ""), "urn:bezier-service:problem:validation") << problem.dump();
  std::vector<std::string> pointers;
  for (const nlohmann::json& e : problem.at("errors")) {
    EXPECT_TRUE(e["message"].is_string()) << e.dump();
    pointers.push_back(e.at("pointer"));
  }
  return pointers;
}

}  // namespace bezier::test
