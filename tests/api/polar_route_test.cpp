#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "api/handler.hpp"

namespace bezier::api {
namespace {

using nlohmann::json;

json call(const std::string& body, int expected_status) {
  const Reply reply = handle("/polar", body, Limits{});
  EXPECT_EQ(reply.status, expected_status) << reply.body;
  return json::parse(reply.body);
}

TEST(PolarRoute, FirstPolarControlPointsAndCurvePoint) {
  // Cubic (0,0), (4,8), (8,0), (12,8) at t0 = 1/4: b_i = 3/4 P_i + 1/4 P_{i+1}.
  const json r = call(R"({"points":[[0,0],[4,8],[8,0],[12,8]],"t0":0.25,"t":[0.25]})", 200);
  EXPECT_EQ(r["degree"], 2);
  EXPECT_EQ(r["control_points"], json::parse("[[1.0,2.0],[5.0,6.0],[9.0,2.0]]"));
  // The polar at t = t0 is B(t0); both computed in exact binary fractions here:
  // B(1/4) = (27*P0 + 27*P1 + 9*P2 + P3)/64 = (3, (216 + 8)/64) = (3, 3.5).
  EXPECT_EQ(r["curve_point"], json::parse("[3.0, 3.5]"));
  EXPECT_EQ(r["results"][0]["point"], json::parse("[3.0, 3.5]"));
}

TEST(PolarRoute, KthPolarAndBlossom) {
  // The blossom of all n arguments: b(0, 1) of a quadratic is P1.
  json r = call(R"({"points":[[0,0],[2,4],[4,0]],"t0":[0,1]})", 200);
  EXPECT_EQ(r["degree"], 0);
  EXPECT_EQ(r["blossom"], json::parse("[2.0, 4.0]"));
  EXPECT_FALSE(r.contains("curve_point"));
  r = call(R"({"points":[[0,0,0],[2,4,6],[4,0,2],[8,8,8]],"t0":[1,0]})", 200);
  EXPECT_EQ(r["degree"], 1);
  // b(1, 0, t): control points b(1,0,0) = P1 and b(1,0,1) = P2.
  EXPECT_EQ(r["control_points"], json::parse("[[2.0,4.0,6.0],[4.0,0.0,2.0]]"));
}

TEST(PolarRoute, SamplesOfThePolarCurve) {
  const json r = call(R"({"points":[[0,0],[2,4],[4,0]],"t0":0.5,"samples":3})", 200);
  ASSERT_EQ(r["results"].size(), 3u);
  EXPECT_EQ(r["results"][0]["point"], json::parse("[1.0, 2.0]"));
  EXPECT_EQ(r["results"][2]["point"], json::parse("[3.0, 2.0]"));
}

TEST(PolarRoute, T0OutsideTheUnitIntervalIsAllowed) {
  const json r = call(R"({"points":[[0,0],[2,4],[4,0]],"t0":2})", 200);
  // b_i = -P_i + 2 P_{i+1}
  EXPECT_EQ(r["control_points"], json::parse("[[4.0,8.0],[6.0,-4.0]]"));
}

TEST(PolarRoute, Errors) {
  json r = call(R"({"points":[[0,0],[2,4],[4,0]]})", 422);
  EXPECT_EQ(r["errors"][0]["pointer"], "/t0");
  r = call(R"({"points":[[0,0],[2,4],[4,0]],"t0":[0.1,0.2,0.3]})", 422);
  EXPECT_EQ(r["errors"][0]["pointer"], "/t0");
  r = call(R"({"points":[[0,0],[2,4],[4,0]],"t0":[]})", 422);
  EXPECT_EQ(r["errors"][0]["pointer"], "/t0");
  r = call(R"({"points":[[0,0],[2,4],[4,0]],"t0":"half"})", 422);
  EXPECT_EQ(r["errors"][0]["pointer"], "/t0");
  r = call(R"({"points":[[0,0],[2,4],[4,0]],"t0":[0.5, null]})", 422);
  EXPECT_EQ(r["errors"][0]["pointer"], "/t0/1");
  r = call(R"({"points":[[0,0],[2,4],[4,0]],"t0":0.5,"t":0.1,"samples":2})", 422);
  EXPECT_EQ(r["errors"][0]["pointer"], "/samples");
}

}  // namespace
}  // namespace bezier::api
