// Tests of POST /offset at the handler level: the answer's shape (cubics with their source
// and parameters, the SVG path data), the promise checked on a closed form (a line's
// parallel is the line moved by d along its left normal; a parabola's parallel points are at
// distance |d| from it), and the validation rules.

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
  return test::route_answer("/offset", body, expected_status, limits);
}

TEST(OffsetRoute, LineMovesAlongItsLeftNormal) {
  const json r = call(R"({"points":[[0,0],[4,0]],"distance":1,"tolerance":1e-6})", 200);
  ASSERT_EQ(r["segments"].size(), 1u);
  const json& s = r["segments"][0];
  EXPECT_EQ(s["source_segment"], 0);
  EXPECT_EQ(s["t"], json::parse("[0.0, 1.0]"));
  EXPECT_EQ(s["points"][0], json::parse("[0.0, 1.0]"));
  EXPECT_EQ(s["points"][3], json::parse("[4.0, 1.0]"));
  EXPECT_EQ(r["path"].get<std::string>().substr(0, 7), "M0.0 1.");
  EXPECT_LE(r["error_bound"].get<double>(), 1e-6);
}

TEST(OffsetRoute, ParabolaPointsAreAtTheDistance) {
  // The convex side of y = x^2 (d < 0): every point of the parallel curve is |d| from the
  // parabola, its nearest point being the foot of the normal.
  const core::Curve parabola({{-1, 1}, {0, -1}, {1, 1}});
  const json r = call(R"({"points":[[-1,1],[0,-1],[1,1]],"distance":-0.5,"tolerance":1e-4})", 200);
  ASSERT_GE(r["segments"].size(), 1u);
  for (const json& s : r["segments"]) {
    std::vector<core::Point2> pts;
    for (const json& q : s["points"]) pts.push_back({q[0].get<double>(), q[1].get<double>()});
    const core::Curve cubic(pts);
    for (int j = 0; j <= 10; ++j) {
      const core::Point2 p = core::evaluate(cubic, j / 10.0);
      EXPECT_NEAR(core::nearest(parabola, p, 0, 1).distance, 0.5, 1e-4 * (1 + 1e-6));
    }
  }
}

TEST(OffsetRoute, PathSegmentsAreOffsetEachWithoutJoins) {
  const json r = call(R"({"path":"M0 0 L2 0 L2 2","distance":0.5,"tolerance":1e-6})", 200);
  ASSERT_EQ(r["segments"].size(), 2u);
  EXPECT_EQ(r["segments"][0]["source_segment"], 0);
  EXPECT_EQ(r["segments"][1]["source_segment"], 1);
  // The right angle is not joined: the second line starts a new subpath.
  EXPECT_EQ(r["segments"][1]["points"][0], json::parse("[1.5, 0.0]"));
  const std::string data = r["path"];
  EXPECT_EQ(std::count(data.begin(), data.end(), 'M'), 2);
}

TEST(OffsetRoute, CurvesThatTurnBackAlongTheirLineAnswer) {
  // Issue 31: where a collinear curve turns back (B' = 0) its parallel curve jumps to the
  // other side of the line: each run is its segment moved by d to its left, so every answer
  // point is on y = ±d within the curve's x range (within its control points'); and a cusp at a tolerance of
  // 1e-9 of its scale answers at the default limits.
  for (const char* path : {"M0 0 Q100 0 50 0", "M0 0 C100 0 -100 0 0 0", "M0 0 C100 0 100 0 50 0",
                           "M0 0 C100 0 -100 0 50 0"}) {
    SCOPED_TRACE(path);
    const json r = call(std::string(R"({"path":")") + path + R"(","distance":2,"tolerance":0.001})", 200);
    ASSERT_GE(r["segments"].size(), 2u);
    bool above = false, below = false;
    for (const json& s : r["segments"]) {
      for (const json& q : s["points"]) {
        EXPECT_NEAR(std::fabs(q[1].get<double>()), 2.0, 1e-12);
        EXPECT_GE(q[0].get<double>(), -100 - 1e-12);
        EXPECT_LE(q[0].get<double>(), 100 + 1e-12);
        (q[1].get<double>() > 0 ? above : below) = true;
      }
    }
    EXPECT_TRUE(above && below);
  }
  const json r = call(R"({"path":"M0 0 C10 10 0 10 10 0","distance":1,"tolerance":1e-8})", 200);
  EXPECT_LE(r["error_bound"].get<double>(), 1e-8);
}

TEST(OffsetRoute, ValidationPointers) {
  EXPECT_EQ(
      test::error_pointers(call(R"({"points":[[0,0],[1,1]],"distance":1,"tolerance":0})", 422)),
      std::vector<std::string>{"/tolerance"});
  EXPECT_EQ(
      test::error_pointers(call(R"({"points":[[0,0],[1,1]],"distance":"x","tolerance":1})", 422)),
      std::vector<std::string>{"/distance"});
  EXPECT_EQ(test::error_pointers(call(R"({"points":[[0,0],[1,1]],"tolerance":1})", 422)),
            std::vector<std::string>{"/distance"});
  EXPECT_EQ(test::error_pointers(
                call(R"({"points":[[0,0],[1,1]],"distance":1e6,"tolerance":1e-4})", 422)),
            std::vector<std::string>{"/tolerance"});
  EXPECT_EQ(test::error_pointers(
                call(R"({"points":[[0,0],[1,1]],"distance":1,"tolerance":1,"join":"round"})", 422)),
            std::vector<std::string>{"/join"});
}

TEST(OffsetRoute, TooManyCubicsAndWorkCap) {
  Limits small;
  small.max_t_values = 3;
  EXPECT_EQ(
      test::error_pointers(call(
          R"({"points":[[0,0],[1,2],[2,-2],[3,0]],"distance":0.2,"tolerance":1e-6})", 422, small)),
      std::vector<std::string>{"/tolerance"});
  Limits tight;
  tight.max_work = 1000;
  const json problem =
      call(R"({"points":[[0,0],[1,2],[2,-2],[3,0]],"distance":0.2,"tolerance":1e-6})", 422, tight);
  EXPECT_NE(problem["detail"].get<std::string>().find("work cap"), std::string::npos);
}

}  // namespace
}  // namespace bezier::api
