// Tests of POST /nearest at the handler level: global minima and ties against closed
// forms, and the validation rules (targets, interval, dimensions, the work cap).

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "api/handler.hpp"
#include "tests/support/route_answers.hpp"
#include "api/write_json.hpp"

namespace bezier::api {
namespace {

using nlohmann::json;

json call(const std::string& body, int expected_status, const Limits& limits = {}) {
  return test::route_answer("/nearest", body, expected_status, limits);
}

TEST(NearestRoute, TiesAndGlobalMinimum) {
  // The parabola (2t - 1, (2t - 1)^2) from (0, 1): minima at x = ±sqrt(1/2), distance
  // sqrt(3)/2, t = (1 ∓ sqrt(1/2)) / 2. From (3, 2): the end (1, 1).
  const json r = call(R"({"points":[[-1,1],[0,-1],[1,1]],"targets":[[0,1],[3,2]]})", 200);
  ASSERT_EQ(r["results"].size(), 2u);
  const json& tied = r["results"][0];
  EXPECT_NEAR(tied["distance"].get<double>(), std::sqrt(3.0) / 2, 1e-15);
  EXPECT_NEAR(tied["t"].get<double>(), (1 - std::sqrt(0.5)) / 2, 1e-10);
  ASSERT_EQ(tied["ties"].size(), 1u);
  EXPECT_NEAR(tied["ties"][0].get<double>(), (1 + std::sqrt(0.5)) / 2, 1e-10);
  EXPECT_EQ(tied["target"], json::parse("[0.0, 1.0]"));
  const json& end = r["results"][1];
  EXPECT_EQ(end["t"], 1.0);
  EXPECT_EQ(end["point"], json::parse("[1.0, 1.0]"));
  EXPECT_EQ(end["ties"], json::array());
}

TEST(NearestRoute, SpaceCurveAndInterval) {
  const json r = call(R"({"points":[[0,0,0],[2,2,2]],"targets":[[1,1,1],[3,3,3]],"interval":[0,0.25]})", 200);
  EXPECT_EQ(r["results"][0]["t"], 0.25);
  EXPECT_EQ(r["results"][1]["t"], 0.25);
  EXPECT_EQ(r["interval"], json::parse("[0.0, 0.25]"));
}

TEST(NearestRoute, Validation) {
  const std::string points = R"("points":[[0,0],[1,1]])";
  EXPECT_EQ(test::error_pointers(call("{" + points + "}", 422)), std::vector<std::string>{"/targets"});
  EXPECT_EQ(test::error_pointers(call("{" + points + R"(,"targets":[]})", 422)), std::vector<std::string>{"/targets"});
  EXPECT_EQ(test::error_pointers(call("{" + points + R"(,"targets":[[0,0,0]]})", 422)),
            std::vector<std::string>{"/targets/0"});
  EXPECT_EQ(test::error_pointers(call("{" + points + R"(,"targets":[[0,0],[1,"x"]]})", 422)),
            std::vector<std::string>{"/targets/1/1"});
  EXPECT_EQ(test::error_pointers(call("{" + points + R"(,"targets":[[0,0]],"interval":[0.75,0.5]})", 422)),
            std::vector<std::string>{"/interval"});
  EXPECT_EQ(test::error_pointers(call(R"({"targets":[[0,0]]})", 422)), std::vector<std::string>{"/points"});
  Limits small;
  small.max_t_values = 1;
  const Reply many = handle("/nearest", "{" + points + R"(,"targets":[[0,0],[1,1]]})", small);
  EXPECT_EQ(many.status, 422);
  EXPECT_TRUE(many.limit_reached);
}

TEST(NearestRoute, WorkCap) {
  Limits tight;
  tight.max_work = 100;
  const Reply r = handle("/nearest", R"({"points":[[0,0],[1,1],[2,0]],"targets":[[0,0],[1,1]]})", tight);
  EXPECT_EQ(r.status, 422);
  EXPECT_TRUE(r.limit_reached);
  EXPECT_EQ(json::parse(r.body)["type"], "urn:bezier-service:problem:work-cap");
}

}  // namespace
}  // namespace bezier::api
