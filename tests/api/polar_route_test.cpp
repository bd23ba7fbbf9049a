#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "api/write_json.hpp"
#include "api/handler.hpp"
#include "tests/support/route_answers.hpp"

namespace bezier::api {
namespace {

using nlohmann::json;

json call(const std::string& body, int expected_status) {
  return test::route_answer("/polar", body, expected_status);
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

TEST(PolarRoute, AnswerMembersInKeyOrder) {
  // Every optional member at once is not possible (curve_point is a first polar's, blossom
  // a polar of all n arguments') except for a degree-1 curve: the exact bytes of both.
  const Reply first = handle("/polar", R"({"points":[[0,0],[4,8]],"t0":0.25,"t":[0,1]})", Limits{});
  EXPECT_EQ(first.body,
            R"({"blossom":[1.0,2.0],"control_points":[[1.0,2.0]],"curve_point":[1.0,2.0],"degree":0,)"
            R"("results":[{"point":[1.0,2.0],"t":0.0},{"point":[1.0,2.0],"t":1.0}]})");
  const Reply space = handle("/polar", R"({"points":[[0,0,0],[2,4,6],[4,0,2]],"t0":[0.5]})", Limits{});
  EXPECT_EQ(space.body, R"({"control_points":[[1.0,2.0,3.0],[3.0,2.0,4.0]],"degree":1,"results":[]})");
}

TEST(PolarRoute, ResultBeyondTheDoubleRangeNamesItsField) {
  // The first polar of the segment 0 -> 1e308 at t0 = 2 is 2e308, beyond the largest double.
  json r = call(R"({"points":[[0,0],[1e308,0]],"t0":2})", 422);
  EXPECT_EQ(r["type"], "urn:bezier-service:problem:result-overflow");
  EXPECT_FALSE(r.contains("errors"));
  EXPECT_EQ(r["detail"], "the result overflows the double range (answer field '/blossom/0')");
  // Finite polar control points, evaluated far outside [0, 1].
  r = call(R"({"points":[[0,0],[0,1],[1e308,2]],"t0":0.5,"t":[0.5,5]})", 422);
  EXPECT_EQ(r["detail"], "the result overflows the double range (answer field '/results/1/point/0')");
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
