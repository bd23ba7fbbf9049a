// Tests of POST /flatten at the handler level: the answer's shape and promises (vertices on
// the curve at their t, within the tolerance of the curve), paths, and the validation rules
// (tolerance, the vertex limit before building, unknown fields, the work cap).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "api/handler.hpp"
#include "core/curve/evaluate.hpp"
#include "core/measure/nearest.hpp"
#include "tests/support/route_answers.hpp"

namespace bezier::api {
namespace {

using nlohmann::json;

json call(const std::string& body, int expected_status, const Limits& limits = {}) {
  return test::route_answer("/flatten", body, expected_status, limits);
}

TEST(FlattenRoute, CurvePolylineIsOnTheCurveAndWithinTolerance) {
  const core::Curve curve({{0, 0}, {1, 2}, {2, -2}, {3, 0}});
  const double tolerance = 1e-3;
  const json r = call(R"({"points":[[0,0],[1,2],[2,-2],[3,0]],"tolerance":0.001})", 200);
  ASSERT_EQ(r["polylines"].size(), 1u);
  ASSERT_EQ(r["vertices"].size(), 1u);
  const json& points = r["polylines"][0];
  const json& vertices = r["vertices"][0];
  ASSERT_EQ(points.size(), vertices.size());
  EXPECT_EQ(r["count"].get<std::size_t>(), points.size());
  EXPECT_EQ(vertices.front()["t"], 0.0);
  EXPECT_EQ(vertices.back()["t"], 1.0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(vertices[i]["segment"], 0);
    const core::Point2 p{points[i][0].get<double>(), points[i][1].get<double>()};
    EXPECT_EQ(p, core::evaluate(curve, vertices[i]["t"].get<double>()));
    if (i > 0) {
      // The chord's middle is within the tolerance of the curve.
      const core::Point2 q{points[i - 1][0].get<double>(), points[i - 1][1].get<double>()};
      EXPECT_LE(core::nearest(curve, 0.5 * (p + q), 0, 1).distance, tolerance * (1 + 1e-9));
    }
  }
}

TEST(FlattenRoute, PathGivesOnePolylinePerSubpath) {
  const json r = call(R"({"path":"M0 0 Q1 2 2 0 Z M5 5 L6 6","tolerance":0.01})", 200);
  ASSERT_EQ(r["polylines"].size(), 2u);
  EXPECT_EQ(r["polylines"][0].front(), r["polylines"][0].back());  // closed
  EXPECT_EQ(r["vertices"][0].back()["segment"], 1);                // the closing line
  EXPECT_EQ(r["polylines"][1], json::parse("[[5.0,5.0],[6.0,6.0]]"));
  EXPECT_EQ(r["vertices"][1], json::parse(R"([{"segment":2,"t":0.0},{"segment":2,"t":1.0}])"));
  EXPECT_EQ(r["count"].get<std::size_t>(), r["polylines"][0].size() + 2);
}

TEST(FlattenRoute, ToleranceMustBePositiveAndAboveTheRoundingScale) {
  for (const char* body :
       {R"({"points":[[0,0],[1,1]],"tolerance":0})", R"({"points":[[0,0],[1,1]],"tolerance":-1})",
        R"({"points":[[0,0],[1,1]],"tolerance":"x"})", R"({"points":[[0,0],[1,1]]})",
        R"({"points":[[0,0],[1e6,1]],"tolerance":1e-4})"}) {
    EXPECT_EQ(test::error_pointers(call(body, 422)), std::vector<std::string>{"/tolerance"})
        << body;
  }
  // 1e-9 of the scale is accepted.
  call(R"({"points":[[0,0],[1e6,1]],"tolerance":1e-3})", 200);
}

TEST(FlattenRoute, UnknownFieldsAndMissingCurveAreRefused) {
  EXPECT_EQ(
      test::error_pointers(call(R"({"points":[[0,0],[1,1]],"tolerance":1,"tolerence":1})", 422)),
      std::vector<std::string>{"/tolerence"});
  call(R"({"tolerance":1})", 422);
}

TEST(FlattenRoute, TooManyVerticesIsRefusedAtTheTolerance) {
  Limits small;
  small.max_t_values = 50;
  const json problem =
      call(R"({"points":[[0,0],[1,2],[2,-2],[3,0]],"tolerance":1e-6})", 422, small);
  EXPECT_EQ(test::error_pointers(problem), std::vector<std::string>{"/tolerance"});
}

TEST(FlattenRoute, ExtremeScalesGiveTheSameParameters) {
  // Scaling by a power of two is exact, and the tolerance scales with the curve.
  const json unit = call(R"({"points":[[0,0],[1,2],[2,-2],[3,0]],"tolerance":0.001})", 200);
  for (const int e : {600, -600, 1022}) {  // at 2^1022 differences reach 2^1024, beyond the doubles
    const double s = std::ldexp(1.0, e);
    json request = {{"points", {{0, 0}, {s, 2 * s}, {2 * s, -2 * s}, {3 * s, 0}}},
                    {"tolerance", 0.001 * s}};
    const json scaled = call(request.dump(), 200);
    EXPECT_EQ(scaled["vertices"], unit["vertices"]) << e;
  }
}

TEST(FlattenRoute, WorkCapIsA422) {
  Limits tight;
  tight.max_work = 2000;
  const json problem =
      call(R"({"points":[[0,0],[1,2],[2,-2],[3,0]],"tolerance":1e-5})", 422, tight);
  EXPECT_NE(problem["detail"].get<std::string>().find("work cap"), std::string::npos);
}

}  // namespace
}  // namespace bezier::api
