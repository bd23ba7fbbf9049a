#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "api/write_json.hpp"
#include "api/handler.hpp"
#include "tests/support/route_answers.hpp"
#include "core/curve/derivative.hpp"
#include "core/curve/evaluate.hpp"

namespace bezier::api {
namespace {

using nlohmann::json;

json call(const std::string& body, int expected_status, const Limits& limits = {}) {
  return test::route_answer("/evaluate", body, expected_status, limits);
}

TEST(EvaluateRoute, PointsAtSeveralT) {
  // Quadratic (0,0), (2,4), (4,0): B(t) = (4t, 8t(1-t)). Dyadic t gives exact values.
  const json r = call(R"({"points":[[0,0],[2,4],[4,0]],"t":[0,0.25,1]})", 200);
  EXPECT_EQ(r["degree"], 2);
  ASSERT_EQ(r["results"].size(), 3u);
  EXPECT_EQ(r["results"][0]["point"], json::parse("[0.0, 0.0]"));
  EXPECT_EQ(r["results"][1]["point"], json::parse("[1.0, 1.5]"));
  EXPECT_EQ(r["results"][2]["point"], json::parse("[4.0, 0.0]"));
  EXPECT_EQ(r["results"][1]["t"], 0.25);
  EXPECT_FALSE(r["results"][0].contains("derivatives"));
}

TEST(EvaluateRoute, DerivativesOfEveryOrder) {
  // B(t) = (4t, 8t - 8t^2): B' = (4, 8 - 16t), B'' = (0, -16), B''' = 0.
  const json r = call(R"({"points":[[0,0],[2,4],[4,0]],"t":0.25,"derivatives":3})", 200);
  const json& d = r["results"][0]["derivatives"];
  ASSERT_EQ(d.size(), 3u);
  EXPECT_EQ(d[0], json::parse("[4.0, 4.0]"));
  EXPECT_EQ(d[1], json::parse("[0.0, -16.0]"));
  EXPECT_EQ(d[2], json::parse("[0.0, 0.0]"));
}

TEST(EvaluateRoute, SamplesIncludeBothEnds) {
  const json r = call(R"({"points":[[0,0],[4,8]],"samples":5})", 200);
  ASSERT_EQ(r["results"].size(), 5u);
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(r["results"][i]["t"], i / 4.0);
    EXPECT_EQ(r["results"][i]["point"], json::array({i * 1.0, i * 2.0}));
  }
}

TEST(EvaluateRoute, SplitReturnsBothHalves) {
  const json r = call(R"({"points":[[0,0],[2,4],[4,0]],"t":0.5,"split":0.5})", 200);
  EXPECT_EQ(r["split"]["left"], json::parse("[[0.0,0.0],[1.0,2.0],[2.0,2.0]]"));
  EXPECT_EQ(r["split"]["right"], json::parse("[[2.0,2.0],[3.0,2.0],[4.0,0.0]]"));
}

TEST(EvaluateRoute, ThreeDimensionalPoints) {
  const json r = call(R"({"points":[[0,0,0],[2,4,8]],"t":0.5})", 200);
  EXPECT_EQ(r["results"][0]["point"], json::parse("[1.0, 2.0, 4.0]"));
}

TEST(EvaluateRoute, AnyFiniteTExtrapolates) {
  // The line from (0,0) to (1,2) at t = -3 and t = 5.
  const json r = call(R"({"points":[[0,0],[1,2]],"t":[-3,5]})", 200);
  EXPECT_EQ(r["results"][0]["point"], json::parse("[-3.0, -6.0]"));
  EXPECT_EQ(r["results"][1]["point"], json::parse("[5.0, 10.0]"));
}

TEST(EvaluateRoute, ResultBeyondTheDoubleRangeNamesItsField) {
  // B(2) of the segment 0 -> 1e308 and B' of -1e308 -> 1e308 are 2e308: finite input, a
  // result JSON cannot carry. The problem says so in its type and title (the request broke
  // no rule), and the detail names the first such number of the answer.
  json r = call(R"({"points":[[0,0],[1e308,0]],"t":[0.5,2]})", 422);
  EXPECT_EQ(r["type"], "urn:bezier-service:problem:result-overflow");
  EXPECT_EQ(r["title"], "The answer overflows the double range");
  EXPECT_FALSE(r.contains("errors"));
  EXPECT_EQ(r["detail"], "the result overflows the double range (answer field '/results/1/point/0')");
  r = call(R"({"points":[[-1e308,0],[1e308,0]],"t":0.5,"derivatives":1})", 422);
  EXPECT_EQ(r["detail"], "the result overflows the double range (answer field '/results/0/derivatives/0/0')");
}

TEST(EvaluateRoute, AnswersAreTheKernelsBitForBit) {
  // Degree 20, control points alternating around ±1000 (the issue-2 accuracy case): the
  // API must return exactly the compensated kernel's values (whose accuracy
  // tests/core/curve/derivative_test.cpp and evaluate_test.cpp prove), with no extra rounding
  // from hodographs computed separately or from number formatting.
  std::vector<core::Point2> pts;
  json points = json::array();
  for (int i = 0; i <= 20; ++i) {
    const core::Point2 p{(i % 2 ? -1000.0 : 1000.0) + i / 7.0, (i % 2 ? 1000.0 : -1000.0) - i / 3.0};
    pts.push_back(p);
    points.push_back({p.x, p.y});
  }
  const core::Curve curve(pts);
  const json ts = {0.1, 0.3, 0.5, 0.7, 0.9};
  const json r = call(json{{"points", points}, {"t", ts}, {"derivatives", 2}}.dump(), 200);
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const double t = ts[i];
    const core::Point2 p = core::evaluate(curve, t);
    const auto d = core::derivatives_at(curve, t, 2);
    const json& got = r["results"][i];
    EXPECT_EQ(got["point"][0].get<double>(), p.x);
    EXPECT_EQ(got["point"][1].get<double>(), p.y);
    for (std::size_t k = 0; k < 2; ++k) {
      EXPECT_EQ(got["derivatives"][k][0].get<double>(), d[k].x) << "t " << t << " order " << k + 1;
      EXPECT_EQ(got["derivatives"][k][1].get<double>(), d[k].y) << "t " << t << " order " << k + 1;
    }
  }
}

TEST(EvaluateRoute, MissingFields) {
  const json r = call(R"({})", 422);
  EXPECT_EQ(test::error_pointers(r), (std::vector<std::string>{"/points", "/t"}));
  EXPECT_EQ(r["type"], "urn:bezier-service:problem:validation");
}

TEST(EvaluateRoute, UnknownFieldIsRejected) {
  const json r = call(R"({"points":[[0,0],[1,1]],"t":0.5,"derivative":1})", 422);
  EXPECT_EQ(test::error_pointers(r), (std::vector<std::string>{"/derivative"}));
}

TEST(EvaluateRoute, WrongTypesPointAtTheField) {
  const json r = call(R"({"points":"abc","t":"x","derivatives":1.5,"split":[]})", 422);
  EXPECT_EQ(test::error_pointers(r), (std::vector<std::string>{"/points", "/t", "/derivatives", "/split"}));
}

TEST(EvaluateRoute, RaggedAndMixedDimensionPoints) {
  json r = call(R"({"points":[[0,0],[1],[2,2]],"t":0})", 422);
  EXPECT_EQ(test::error_pointers(r), (std::vector<std::string>{"/points/1"}));
  r = call(R"({"points":[[0,0,0],[1,1],[2,2,2]],"t":0})", 422);
  EXPECT_EQ(test::error_pointers(r), (std::vector<std::string>{"/points/1"}));
  r = call(R"({"points":[[0,0],[1,1,1,1]],"t":0})", 422);
  EXPECT_EQ(test::error_pointers(r), (std::vector<std::string>{"/points/1"}));
  r = call(R"({"points":[[0,0],[true,1]],"t":0})", 422);
  EXPECT_EQ(test::error_pointers(r), (std::vector<std::string>{"/points/1/0"}));
}

TEST(EvaluateRoute, TooFewPoints) {
  EXPECT_EQ(test::error_pointers(call(R"({"points":[[0,0]],"t":0})", 422)), (std::vector<std::string>{"/points"}));
  EXPECT_EQ(test::error_pointers(call(R"({"points":[],"t":0})", 422)), (std::vector<std::string>{"/points"}));
}

TEST(EvaluateRoute, DegreeLimit) {
  Limits limits;
  limits.max_degree = 3;
  call(R"({"points":[[0,0],[1,1],[2,2],[3,3]],"t":0})", 200, limits);
  const json r = call(R"({"points":[[0,0],[1,1],[2,2],[3,3],[4,4]],"t":0})", 422, limits);
  EXPECT_EQ(test::error_pointers(r), (std::vector<std::string>{"/points"}));
}

TEST(EvaluateRoute, TValueAndSampleLimits) {
  Limits limits;
  limits.max_t_values = 2;
  call(R"({"points":[[0,0],[1,1]],"t":[0,1]})", 200, limits);
  EXPECT_EQ(test::error_pointers(call(R"({"points":[[0,0],[1,1]],"t":[0,0.5,1]})", 422, limits)),
            (std::vector<std::string>{"/t"}));
  EXPECT_EQ(test::error_pointers(call(R"({"points":[[0,0],[1,1]],"samples":3})", 422, limits)),
            (std::vector<std::string>{"/samples"}));
  EXPECT_EQ(test::error_pointers(call(R"({"points":[[0,0],[1,1]],"samples":0})", 422)),
            (std::vector<std::string>{"/samples"}));
  EXPECT_EQ(test::error_pointers(call(R"({"points":[[0,0],[1,1]],"t":[]})", 422)), (std::vector<std::string>{"/t"}));
}

TEST(EvaluateRoute, AnswerPointsLimitCountsDerivatives) {
  Limits limits;
  limits.max_t_values = 6;
  // 2 t values x (2 derivatives + 1) = 6 points: at the limit.
  call(R"({"points":[[0,0],[1,1],[2,0]],"t":[0,1],"derivatives":2})", 200, limits);
  // 3 x 3 = 9 points: above it, reported at /derivatives.
  EXPECT_EQ(test::error_pointers(call(R"({"points":[[0,0],[1,1],[2,0]],"t":[0,0.5,1],"derivatives":2})", 422, limits)),
            (std::vector<std::string>{"/derivatives"}));
  EXPECT_EQ(test::error_pointers(call(R"({"points":[[0,0],[1,1],[2,0]],"samples":4,"derivatives":1})", 422, limits)),
            (std::vector<std::string>{"/derivatives"}));
}

TEST(EvaluateRoute, TAndSamplesAreExclusive) {
  EXPECT_EQ(test::error_pointers(call(R"({"points":[[0,0],[1,1]],"t":0,"samples":2})", 422)),
            (std::vector<std::string>{"/samples"}));
}

TEST(EvaluateRoute, DerivativeOrderLimit) {
  Limits limits;
  limits.max_degree = 4;
  call(R"({"points":[[0,0],[1,1]],"t":0,"derivatives":4})", 200, limits);
  EXPECT_EQ(test::error_pointers(call(R"({"points":[[0,0],[1,1]],"t":0,"derivatives":5})", 422, limits)),
            (std::vector<std::string>{"/derivatives"}));
  EXPECT_EQ(test::error_pointers(call(R"({"points":[[0,0],[1,1]],"t":0,"derivatives":-1})", 422)),
            (std::vector<std::string>{"/derivatives"}));
}

TEST(EvaluateRoute, NonFiniteNumbersPointAtTheField) {
  const json r = call(R"({"points":[[0,0],[1,-1e400]],"t":[0,1e999]})", 422);
  EXPECT_EQ(test::error_pointers(r), (std::vector<std::string>{"/points/1/1", "/t/1"}));
}

TEST(EvaluateRoute, MalformedAndNonObjectBodiesAre400) {
  for (const char* body : {"", "{", "nul", "[]", "3", "\"text\"", "null", "{\"a\":1}x", "{'a':1}"}) {
    const json r = call(body, 400);
    EXPECT_EQ(r["type"], "urn:bezier-service:problem:malformed-json") << body;
  }
}

// JSON nested beyond the parser's depth is valid JSON, so not a 400: a 422 on the body.
TEST(EvaluateRoute, BodiesNestedTooDeeplyAre422) {
  const std::string deep = R"({"points":)" + std::string(200, '[') + std::string(200, ']') + R"(,"t":0})";
  const json r = call(deep, 422);
  EXPECT_EQ(r["type"], "urn:bezier-service:problem:validation");
  EXPECT_EQ(test::error_pointers(r), (std::vector<std::string>{""}));
}

TEST(EvaluateRoute, ErrorListIsBounded) {
  std::string body = R"({"t":0,"points":[)";
  for (int i = 0; i < 20; ++i) body += std::string(i ? "," : "") + "[\"a\",\"b\"]";
  body += "]}";
  const json r = call(body, 422);
  EXPECT_LE(r["errors"].size(), 32u);
  EXPECT_EQ(r["errors"][0]["pointer"], "/points/0/0");
}

TEST(EvaluateRoute, FrameOfAParabola) {
  // B(t) = (t, t^2): at t = 0 tangent (1, 0), normal (0, 1), curvature 2; at t = 1/2 the
  // tangent (1, 1)/sqrt(2) and curvature 2 / 2^(3/2) = 1/sqrt(2).
  const json r = call(R"({"points":[[0,0],[0.5,0],[1,1]],"t":[0,0.5],"frame":true})", 200);
  const json& vertex = r["results"][0];
  EXPECT_EQ(vertex["tangent"], json::parse("[1.0, 0.0]"));
  EXPECT_EQ(dump_json(vertex["normal"]), "[0.0,1.0]");
  EXPECT_NEAR(vertex["curvature"].get<double>(), 2.0, 1e-15);
  const json& middle = r["results"][1];
  EXPECT_NEAR(middle["tangent"][0].get<double>(), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(middle["tangent"][1].get<double>(), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(middle["normal"][0].get<double>(), -std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(middle["curvature"].get<double>(), std::sqrt(0.5), 1e-15);
  // Clockwise: the reversed parabola's curvature is negative.
  const json back = call(R"({"points":[[1,1],[0.5,0],[0,0]],"t":1,"frame":true})", 200);
  EXPECT_NEAR(back["results"][0]["curvature"].get<double>(), -2.0, 1e-15);
  // Without frame (or frame false) the members are absent.
  const json plain = call(R"({"points":[[0,0],[0.5,0],[1,1]],"t":0,"frame":false})", 200);
  EXPECT_FALSE(plain["results"][0].contains("tangent"));
  EXPECT_FALSE(plain["results"][0].contains("curvature"));
}

TEST(EvaluateRoute, FrameIsNullAtACusp) {
  const json r = call(R"({"points":[[0,0],[1,1],[0,1],[1,0]],"t":[0.5,0.25],"frame":true})", 200);
  EXPECT_TRUE(r["results"][0]["tangent"].is_null());
  EXPECT_TRUE(r["results"][0]["normal"].is_null());
  EXPECT_TRUE(r["results"][0]["curvature"].is_null());
  EXPECT_TRUE(r["results"][1]["tangent"].is_array());
}

TEST(EvaluateRoute, FrameInSpace) {
  // (5t, 3t^2, 4t^2): the parabola of curvature 2/5 at its vertex, normal (0, 3/5, 4/5); a
  // straight space line has no principal normal.
  const json r = call(R"({"points":[[0,0,0],[2.5,0,0],[5,3,4]],"t":0,"frame":true,"derivatives":1})", 200);
  const json& f = r["results"][0];
  EXPECT_EQ(f["tangent"], json::parse("[1.0, 0.0, 0.0]"));
  EXPECT_NEAR(f["normal"][1].get<double>(), 0.6, 1e-15);
  EXPECT_NEAR(f["normal"][2].get<double>(), 0.8, 1e-15);
  EXPECT_NEAR(f["curvature"].get<double>(), 0.4, 1e-15);
  EXPECT_EQ(f["derivatives"][0], json::parse("[5.0, 0.0, 0.0]"));
  const json line = call(R"({"points":[[0,0,0],[1,2,2]],"t":0.5,"frame":true})", 200);
  EXPECT_TRUE(line["results"][0]["normal"].is_null());
  EXPECT_EQ(line["results"][0]["curvature"], 0.0);
}

TEST(EvaluateRoute, FrameMustBeABoolean) {
  EXPECT_EQ(test::error_pointers(call(R"({"points":[[0,0],[1,1]],"t":0,"frame":1})", 422)),
            std::vector<std::string>{"/frame"});
}

}  // namespace
}  // namespace bezier::api
