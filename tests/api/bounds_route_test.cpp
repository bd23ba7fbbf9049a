// Tests of POST /bounds at the handler level: the box of a curve (not of its control
// points) against closed forms, and the validation rules with their JSON Pointers.

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
  return test::route_answer("/bounds", body, expected_status, limits);
}

TEST(BoundsRoute, ArchBoxIsTheCurvesNotThePolygons) {
  // x = 2t, y = 4t(1 - t): the top is y = 1 at t = 1/2; the polygon reaches y = 2.
  const json r = call(R"({"points":[[0,0],[1,2],[2,0]]})", 200);
  EXPECT_EQ(r["degree"], 2);
  EXPECT_EQ(r["min"], json::parse("[0.0, 0.0]"));
  EXPECT_EQ(r["max"][0], 2.0);
  const double top = r["max"][1];
  EXPECT_GE(top, 1.0);
  EXPECT_LE(top, std::nextafter(std::nextafter(1.0, 2.0), 2.0));
  EXPECT_EQ(r["critical"], json::parse("[[], [0.5]]"));
  EXPECT_EQ(r["interval"], json::parse("[0.0, 1.0]"));
}

TEST(BoundsRoute, SpaceCurveAndInterval) {
  // z = 4t(1 - t) on [0, 1/4]: rising, no critical point inside.
  const json r = call(R"({"points":[[0,0,0],[1,1,2],[2,2,0]],"interval":[0,0.25]})", 200);
  ASSERT_EQ(r["critical"].size(), 3u);
  EXPECT_EQ(r["critical"][2], json::array());
  EXPECT_EQ(r["min"], json::parse("[0.0, 0.0, 0.0]"));
  EXPECT_GE(r["max"][2].get<double>(), 0.75);
  EXPECT_LE(r["max"][2].get<double>(), 0.75 + 4e-16);
}

TEST(BoundsRoute, Validation) {
  EXPECT_EQ(test::error_pointers(call(R"({"points":[[0,0],[1,1]],"interval":[1,0]})", 422)),
            std::vector<std::string>{"/interval"});
  EXPECT_EQ(test::error_pointers(call(R"({"points":[[0,0]]})", 422)), std::vector<std::string>{"/points"});
  EXPECT_EQ(test::error_pointers(call(R"({"points":[[0,0],[1,"a"]]})", 422)), std::vector<std::string>{"/points/1/1"});
  EXPECT_EQ(test::error_pointers(call(R"({"points":[[0,0],[1,1]],"t":0})", 422)), std::vector<std::string>{"/t"});
  EXPECT_EQ(call("[1,2]", 400)["status"], 400);
}

}  // namespace
}  // namespace bezier::api
