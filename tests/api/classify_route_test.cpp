#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "api/write_json.hpp"
#include "api/handler.hpp"
#include "tests/support/route_answers.hpp"
#include "core/cubic/classify.hpp"

namespace bezier::api {
namespace {

using nlohmann::json;

json call(const std::string& body, int expected_status) {
  return test::route_answer("/classify", body, expected_status);
}

// The cubic with P0, P1, P2 = (0,0), (0,1), (1,1) has canonical point P3 itself; its
// inflection polynomial is I(t) ∝ −1 + (3 − x) t + (x + y − 3) t² (Stone & DeRose).
std::string canonical_body(double x, double y) {
  return "{\"points\":[[0,0],[0,1],[1,1],[" + json(x).dump() + "," + json(y).dump() + "]]}";
}

TEST(ClassifyRoute, SingleInflection) {
  // (0, 2): I ∝ −1 + 3t − t², roots (3 ± √5)/2, one in [0,1].
  const json r = call(canonical_body(0, 2), 200);
  EXPECT_EQ(r["type"], "single-inflection");
  EXPECT_EQ(r["canonical_point"], json::parse("[0.0, 2.0]"));
  ASSERT_EQ(r["inflections"].size(), 1u);
  EXPECT_NEAR(r["inflections"][0].get<double>(), (3 - std::sqrt(5.0)) / 2, 1e-15);
  EXPECT_TRUE(r["cusp"].is_null());
  EXPECT_TRUE(r["self_intersection"].is_null());
  EXPECT_EQ(r["loop_blinn"], "serpentine");
}

TEST(ClassifyRoute, DoubleInflectionWithOneExactlyAtTheEnd) {
  // (0, 1): I ∝ −1 + 3t − 2t² = −(2t − 1)(t − 1).
  const json r = call(canonical_body(0, 1), 200);
  EXPECT_EQ(r["type"], "double-inflection");
  EXPECT_EQ(r["inflections"], json::parse("[0.5, 1.0]"));
  EXPECT_EQ(r["loop_blinn"], "serpentine");
}

TEST(ClassifyRoute, Cusp) {
  // (−1, 0) lies on the cusp edge y = (−x² + 2x + 3)/4; B'(t) = 0 at t = 2/(3 − x) = 1/2.
  const json r = call(canonical_body(-1, 0), 200);
  EXPECT_EQ(r["type"], "cusp");
  EXPECT_EQ(r["cusp"], 0.5);
  EXPECT_EQ(r["inflections"], json::array());
  EXPECT_EQ(r["loop_blinn"], "cusp");
}

TEST(ClassifyRoute, LoopClosingAtEitherEnd) {
  // (−3, −6) lies on y = (−x² + 3x)/3: B(0) = B(1/2).
  json r = call(canonical_body(-3, -6), 200);
  EXPECT_EQ(r["type"], "loop-at-start");
  EXPECT_EQ(r["self_intersection"]["t"], json::parse("[0.0, 0.5]"));
  EXPECT_EQ(r["self_intersection"]["point"], json::parse("[0.0, 0.0]"));
  EXPECT_EQ(r["loop_blinn"], "loop");
  // The same curve reversed: B(1/2) = B(1).
  r = call(R"({"points":[[-3,-6],[1,1],[0,1],[0,0]]})", 200);
  EXPECT_EQ(r["type"], "loop-at-end");
  EXPECT_EQ(r["self_intersection"]["t"], json::parse("[0.5, 1.0]"));
  EXPECT_EQ(r["self_intersection"]["point"], json::parse("[0.0, 0.0]"));
}

TEST(ClassifyRoute, Loop) {
  // (−1, −0.5): s + t = (3 − x)/(3 − x − y) = 8/9, st = 10/81: t = (4 ∓ √6)/9.
  const json r = call(canonical_body(-1, -0.5), 200);
  EXPECT_EQ(r["type"], "loop");
  const json& si = r["self_intersection"];
  EXPECT_NEAR(si["t"][0].get<double>(), (4 - std::sqrt(6.0)) / 9, 1e-15);
  EXPECT_NEAR(si["t"][1].get<double>(), (4 + std::sqrt(6.0)) / 9, 1e-15);
  // B(t) = (3t² + (x − 3)t³, 3t − 3t² + y t³) at either parameter.
  const double t = si["t"][0].get<double>();
  EXPECT_NEAR(si["point"][0].get<double>(), 3 * t * t - 4 * t * t * t, 1e-14);
  EXPECT_NEAR(si["point"][1].get<double>(), 3 * t - 3 * t * t - 0.5 * t * t * t, 1e-14);
}

TEST(ClassifyRoute, ArchWithAHorizontalFirstLeg) {
  // P1.y = P0.y: u = (1,0), v = (1,1), w = (0,1) give the canonical point (1, 0), below
  // the cusp edge (a loop of the unbounded curve) but under the loop-at-end edge.
  const json r = call(R"({"points":[[0,0],[1,0],[1,1],[0,1]]})", 200);
  EXPECT_EQ(r["type"], "arch");
  EXPECT_EQ(r["canonical_point"], json::parse("[1.0, 0.0]"));
  EXPECT_EQ(r["loop_blinn"], "loop");
  EXPECT_TRUE(r["self_intersection"].is_null());
}

TEST(ClassifyRoute, DegenerateCubics) {
  json r = call(R"({"points":[[1,2],[1,2],[1,2],[1,2]]})", 200);
  EXPECT_EQ(r["type"], "point");
  EXPECT_EQ(r["loop_blinn"], "point");
  EXPECT_TRUE(r["canonical_point"].is_null());
  r = call(R"({"points":[[0,0],[2,2],[-1,-1],[1,1]]})", 200);
  EXPECT_EQ(r["type"], "line");
  EXPECT_EQ(r["loop_blinn"], "line");
  EXPECT_TRUE(r["canonical_point"].is_null());
  // The degree elevation of the parabola (0,0), (3,6), (6,0).
  r = call(R"({"points":[[0,0],[2,4],[4,4],[6,0]]})", 200);
  EXPECT_EQ(r["type"], "quadratic");
  EXPECT_EQ(r["loop_blinn"], "quadratic");
  EXPECT_EQ(r["canonical_point"], json::parse("[3.0, 0.0]"));
  // P0 = P1: a cusp at t = 0, and P0, P1, P2 collinear so no canonical point.
  r = call(R"({"points":[[0,0],[0,0],[1,1],[2,0]]})", 200);
  EXPECT_EQ(r["type"], "cusp");
  EXPECT_EQ(r["cusp"], 0.0);
  EXPECT_TRUE(r["canonical_point"].is_null());
}

TEST(ClassifyRoute, NumbersRoundTrip) {
  const std::string body = R"({"points":[[0.1,0.2],[1.3,2.7],[3.3,-0.7],[0.4,1.9]]})";
  const json r = call(body, 200);
  const core::CubicClassification c =
      core::classify(core::Curve({{0.1, 0.2}, {1.3, 2.7}, {3.3, -0.7}, {0.4, 1.9}}));
  EXPECT_EQ(r["type"], std::string(core::to_string(c.type)));
  ASSERT_TRUE(c.canonical_point.has_value());
  EXPECT_EQ(r["canonical_point"][0].get<double>(), c.canonical_point->x);
  EXPECT_EQ(r["canonical_point"][1].get<double>(), c.canonical_point->y);
  ASSERT_EQ(r["inflections"].size(), static_cast<std::size_t>(c.inflections.count));
  for (int i = 0; i < c.inflections.count; ++i) {
    EXPECT_EQ(r["inflections"][static_cast<std::size_t>(i)].get<double>(),
              c.inflections.t[static_cast<std::size_t>(i)]);
  }
}

TEST(ClassifyRoute, ValidationErrorsCarryPointers) {
  json r = call("{}", 422);
  EXPECT_EQ(test::error_pointers(r), std::vector<std::string>{"/points"});
  r = call(R"({"points":"cubic"})", 422);
  EXPECT_EQ(test::error_pointers(r), std::vector<std::string>{"/points"});
  // Not a cubic: the route says exactly 4 points, whatever the count.
  for (const std::string pts :
       {"[]", "[[0,0],[1,1]]", "[[0,0],[1,1],[2,0]]", "[[0,0],[1,1],[2,0],[3,3],[4,0]]"}) {
    r = call("{\"points\":" + pts + "}", 422);
    EXPECT_EQ(test::error_pointers(r), std::vector<std::string>{"/points"}) << pts;
    EXPECT_NE(r["errors"][0]["message"].get<std::string>().find("exactly 4"), std::string::npos);
  }
  // Space points: classification is planar.
  r = call(R"({"points":[[0,0,0],[1,1,1],[2,0,2],[3,3,3]]})", 422);
  EXPECT_EQ(test::error_pointers(r),
            (std::vector<std::string>{"/points/0", "/points/1", "/points/2", "/points/3"}));
  // A ragged point and a string coordinate, both reported.
  r = call(R"({"points":[[0,0],[1],[2,"0"],[3,1]]})", 422);
  EXPECT_EQ(test::error_pointers(r), (std::vector<std::string>{"/points/1", "/points/2/1"}));
  // A number beyond double range.
  r = call(R"({"points":[[0,0],[1,1],[2,0],[3,1e999]]})", 422);
  EXPECT_EQ(test::error_pointers(r), std::vector<std::string>{"/points/3/1"});
  // Null coordinates are not numbers.
  r = call(R"({"points":[[0,0],[1,1],[2,0],[null,3]]})", 422);
  EXPECT_EQ(test::error_pointers(r), std::vector<std::string>{"/points/3/0"});
  // Unknown fields are rejected next to the other problems, all reported at once.
  r = call(R"({"points":[[0,0],[1,1],[2,0]],"t":0.5})", 422);
  EXPECT_EQ(test::error_pointers(r), (std::vector<std::string>{"/t", "/points"}));
  EXPECT_EQ(r["status"], 422);
}

TEST(ClassifyRoute, MalformedBodies) {
  EXPECT_EQ(call("not json", 400)["status"], 400);
  EXPECT_EQ(call("[[0,0],[0,1],[1,1],[1,0]]", 400)["status"], 400);
}

}  // namespace
}  // namespace bezier::api
