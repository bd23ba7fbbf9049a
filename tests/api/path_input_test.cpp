// Tests of SVG path data where the API lets a path stand for a curve (/intersections,
// /loop-area, /length, /bounds, /nearest) at the handler level: answers located by segment
// against exact values, the refusals with their pointers and offsets, and the limits.

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

json call(const std::string& route, const std::string& body, int expected_status,
          const Limits& limits = {}) {
  return test::route_answer(route, body, expected_status, limits);
}

/// The single error of a 422: its pointer and message.
std::pair<std::string, std::string> only_error(const json& problem) {
  EXPECT_EQ(problem["type"], "urn:bezier-service:problem:validation") << problem.dump();
  EXPECT_EQ(problem["errors"].size(), 1u) << problem.dump();
  return {problem["errors"][0]["pointer"], problem["errors"][0]["message"]};
}

TEST(PathInput, TwoSquaresCrossTwiceBySegment) {
  const json r = call("/intersections",
                      R"({"curves":[{"path":"M0 0 H2 V2 H0 Z"},{"path":"M1 1 H3 V3 H1 Z"}]})", 200);
  ASSERT_EQ(r["intersections"].size(), 2u);
  EXPECT_EQ(r["intersections"][0]["segments"], json::parse("[1, 0]"));
  EXPECT_EQ(r["intersections"][1]["segments"], json::parse("[2, 3]"));
  EXPECT_EQ(r["intersections"][0]["point"], json::parse("[2.0, 1.0]"));
  EXPECT_EQ(r["intersections"][1]["point"], json::parse("[1.0, 2.0]"));
  EXPECT_NEAR(r["intersections"][0]["t"].get<double>(), 0.5, 1e-12);
  EXPECT_EQ(r["overlaps"], json::array());
  EXPECT_GE(r["stats"]["candidate_pairs"].get<int>(), 2);
}

TEST(PathInput, CurveAgainstPathIsSegmentZero) {
  const json r = call("/intersections",
                      R"({"curves":[{"points":[[1,-1],[1,3]]},{"path":"M0 0 H2 V2 H0 Z"}]})", 200);
  ASSERT_EQ(r["intersections"].size(), 2u);
  EXPECT_EQ(r["intersections"][0]["segments"], json::parse("[0, 0]"));
  EXPECT_EQ(r["intersections"][1]["segments"], json::parse("[0, 2]"));
  EXPECT_NEAR(r["intersections"][0]["t"].get<double>(), 0.25, 1e-12);
  EXPECT_NEAR(r["intersections"][1]["t"].get<double>(), 0.75, 1e-12);
}

TEST(PathInput, CurvesAloneAnswerWithoutSegments) {
  const json r = call("/intersections", R"({"curves":[{"points":[[0,0],[2,2]]},{"points":[[0,2],[2,0]]}]})", 200);
  ASSERT_EQ(r["intersections"].size(), 1u);
  EXPECT_FALSE(r["intersections"][0].contains("segments"));
  EXPECT_FALSE(r["stats"].contains("candidate_pairs"));
}

TEST(PathInput, OnePathSelfIntersectionsLeaveItsJointsOut) {
  const json bow = call("/intersections", R"({"curves":[{"path":"M0 0 L2 2 L2 0 L0 2 Z"}]})", 200);
  ASSERT_EQ(bow["intersections"].size(), 1u);
  EXPECT_EQ(bow["intersections"][0]["segments"], json::parse("[0, 2]"));
  EXPECT_EQ(bow["intersections"][0]["point"], json::parse("[1.0, 1.0]"));
  const json square = call("/intersections", R"({"curves":[{"path":"M0 0 H2 V2 H0 Z"}]})", 200);
  EXPECT_EQ(square["intersections"], json::array());
}

TEST(PathInput, OnePathWithALoopInsideASegment) {
  // The cubic (0,0) (3,3) (-1,3) (2,0) is the mirror image of itself about x = 1
  // (B(1 - t) is B(t) mirrored), so its double point is on x = 1 with s = 1 - t:
  // x(t) - 1 = 14 t^3 - 21 t^2 + 9 t - 1 = (2t - 1)(7 t^2 - 7 t + 1), so t (1 - t) = 1/7.
  const json r = call("/intersections", R"({"curves":[{"path":"M0 0 C3 3 -1 3 2 0 L0 0"}]})", 200);
  ASSERT_GE(r["intersections"].size(), 1u);
  const json& loop = r["intersections"][0];
  EXPECT_EQ(loop["segments"], json::parse("[0, 0]"));
  const double t = (1 - std::sqrt(3.0 / 7)) / 2;
  EXPECT_NEAR(loop["t"].get<double>(), t, 1e-12);
  EXPECT_NEAR(loop["s"].get<double>(), 1 - t, 1e-12);
}

TEST(PathInput, LoopAreaOfAPathIsItsClosedSubpathsArea) {
  const json r = call("/loop-area", R"({"path":"M0 0 H4 V4 H0 Z M1 1 V3 H3 V1 Z"})", 200);
  EXPECT_EQ(r["closed_area"], 12.0);
  EXPECT_EQ(r["closed"], true);
  EXPECT_EQ(r["loops"], json::array());
  EXPECT_EQ(r["segment_count"], 8);
  const json open = call("/loop-area", R"({"path":"M0 0 L1 0 L1 1"})", 200);
  EXPECT_TRUE(open["closed_area"].is_null());
  EXPECT_EQ(open["closed"], false);
  // The bow tie: one loop, the triangle (1,1) (2,2) (2,0), clockwise, area 1.
  const json bow = call("/loop-area", R"({"path":"M0 0 L2 2 L2 0 L0 2 Z"})", 200);
  ASSERT_EQ(bow["loops"].size(), 1u);
  EXPECT_EQ(bow["loops"][0]["segments"], json::parse("[0, 2]"));
  EXPECT_NEAR(bow["loops"][0]["signed_area"].get<double>(), -1.0, 1e-15);
  EXPECT_NEAR(bow["area"].get<double>(), 1.0, 1e-15);
}

TEST(PathInput, LengthBoundsAndNearestOverTheWholePath) {
  // An L of two lines, lengths 3 and 4.
  const json length = call("/length", R"({"path":"M0 0 h3 v4","at_lengths":[1.5,5]})", 200);
  EXPECT_NEAR(length["length"].get<double>(), 7.0, 7e-12);
  EXPECT_EQ(length["segment_count"], 2);
  ASSERT_EQ(length["parameters"].size(), 2u);
  EXPECT_EQ(length["parameters"][0]["segment"], 0);
  EXPECT_NEAR(length["parameters"][0]["t"].get<double>(), 0.5, 1e-12);
  EXPECT_EQ(length["parameters"][1]["segment"], 1);
  EXPECT_NEAR(length["parameters"][1]["t"].get<double>(), 0.5, 1e-12);

  // The parabola from (0,0) to (2,0) with control (1,2) peaks at (1,1): x in [0, 3] with
  // the line to (3, -1), y in [-1, 1], y' = 0 at t = 1/2 of segment 0.
  const json box = call("/bounds", R"({"path":"M0 0 Q1 2 2 0 L3 -1"})", 200);
  EXPECT_EQ(box["min"], json::parse("[0.0, -1.0]"));
  EXPECT_EQ(box["max"][0], 3.0);
  EXPECT_NEAR(box["max"][1].get<double>(), 1.0, 4e-16);
  ASSERT_EQ(box["critical"][1].size(), 1u);
  EXPECT_EQ(box["critical"][1][0]["segment"], 0);
  EXPECT_EQ(box["critical"][1][0]["t"], 0.5);

  // Nearest to (3, 1) on the square [0,2]^2: the right side x = 2 at (2, 1), segment 1,
  // t = 1/2, distance 1. Nearest to (3, 3): the corner (2, 2), the joint of segments 1 and
  // 2, reported once, on segment 1 at t = 1.
  const json near = call("/nearest", R"({"path":"M0 0 H2 V2 H0 Z","targets":[[3,1],[3,3]]})", 200);
  EXPECT_EQ(near["results"][0]["segment"], 1);
  EXPECT_NEAR(near["results"][0]["t"].get<double>(), 0.5, 1e-12);
  EXPECT_NEAR(near["results"][0]["distance"].get<double>(), 1.0, 1e-15);
  EXPECT_EQ(near["results"][1]["segment"], 1);
  EXPECT_EQ(near["results"][1]["t"], 1.0);
  EXPECT_EQ(near["results"][1]["ties"], json::array());
  // The centre is at distance 1 from all four sides: three ties.
  const json centre = call("/nearest", R"({"path":"M0 0 H2 V2 H0 Z","targets":[[1,1]]})", 200);
  EXPECT_EQ(centre["results"][0]["segment"], 0);
  EXPECT_EQ(centre["results"][0]["ties"].size(), 3u);
}

TEST(PathInput, SyntaxErrorsPointAtThePathStringWithTheOffset) {
  const auto [pointer, message] =
      only_error(call("/intersections", R"({"curves":[{"path":"M0 0 L1"},{"path":"M0 0 L1 1"}]})", 422));
  EXPECT_EQ(pointer, "/curves/0/path");
  EXPECT_EQ(message, "offset 7: expected a number, found the end of the data");
  const auto [arc_pointer, arc_message] = only_error(call("/length", R"({"path":"M0 0 A1 1 0 2 1 2 2"})", 422));
  EXPECT_EQ(arc_pointer, "/path");
  EXPECT_EQ(arc_message, "offset 12: expected a flag (0 or 1), found '2'");
}

TEST(PathInput, RefusalsOfTheShape) {
  EXPECT_EQ(only_error(call("/bounds", R"({"path":"M1 1"})", 422)).first, "/path");
  EXPECT_EQ(only_error(call("/bounds", R"({"path":7})", 422)).first, "/path");
  // A null path is refused as a path, not read as a missing one (then a curve's).
  EXPECT_EQ(only_error(call("/bounds", R"({"path":null})", 422)).first, "/path");
  EXPECT_EQ(only_error(call("/loop-area", R"({"path":null})", 422)).first, "/path");
  EXPECT_EQ(only_error(call("/intersections", R"({"curves":[{"path":null}]})", 422)).first,
            "/curves/0/path");
  EXPECT_EQ(only_error(call("/bounds", R"({"path":"M0 0 L1 1","points":[[0,0],[1,1]]})", 422)).first,
            "/points");
  EXPECT_EQ(only_error(call("/nearest", R"({"path":"M0 0 L1 1","targets":[[0,0]],"interval":[0,1]})", 422)).first,
            "/interval");
  EXPECT_EQ(only_error(call("/loop-area", R"({"path":"M0 0 L1 1 L0 1 Z","interval":[0,1]})", 422)).first,
            "/interval");
  EXPECT_EQ(only_error(call("/intersections", R"({"curves":[{"path":"M0 0 L1 1","points":[[0,0],[1,1]]}]})", 422)).first,
            "/curves/0");
  EXPECT_EQ(only_error(call("/intersections", R"({"curves":[{}]})", 422)).first, "/curves/0/points");
}

TEST(PathInput, SegmentLimitIsALimitsRefusal) {
  Limits limits;
  limits.max_path_segments = 3;
  const Reply reply = handle("/bounds", R"({"path":"M0 0 L1 1 2 2 3 3 4 4"})", limits);
  EXPECT_EQ(reply.status, 422);
  EXPECT_TRUE(reply.limit_reached);
  const json problem = json::parse(reply.body);
  EXPECT_EQ(problem["errors"][0]["pointer"], "/path");
  EXPECT_NE(problem["errors"][0]["message"].get<std::string>().find("max_path_segments"),
            std::string::npos);
  EXPECT_EQ(handle("/bounds", R"({"path":"M0 0 L1 1 2 2 3 3"})", limits).status, 200);
}

TEST(PathInput, WorkCapCoversTheWholePathRequest) {
  // Two zigzags of 200 lines crossing 400 times: fine at the default cap, refused with a
  // work-cap problem (limit_reached) at a cap below what the pairs need.
  std::string a = "M0 0", b = "M0 1";
  for (int k = 1; k <= 200; ++k) {
    a += " L";
    a += std::to_string(k);
    a += k % 2 ? " 2" : " 0";
    b += " L";
    b += std::to_string(k);
    b += k % 2 ? " -1" : " 3";
  }
  std::string body = R"({"curves":[{"path":")";
  body += a;
  body += R"("},{"path":")";
  body += b;
  body += R"("}]})";
  const json full = call("/intersections", body, 200);
  EXPECT_GE(full["intersections"].size(), 200u);
  Limits limits;
  limits.max_work = full["stats"]["work"].get<std::int64_t>() / 2;
  const Reply capped = handle("/intersections", body, limits);
  EXPECT_EQ(capped.status, 422);
  EXPECT_TRUE(capped.limit_reached);
  EXPECT_EQ(json::parse(capped.body)["type"], "urn:bezier-service:problem:work-cap");
}

TEST(PathInput, LengthOfAPathIsChargedToTheWorkCap) {
  // 100 cubic arches: each quadrature is charged by its pieces, at least 15 points of a
  // degree-4 polynomial (10 updates each): at least 15000 units in all.
  std::string body = R"({"path":"M0 0)";
  for (int k = 0; k < 100; ++k) body += " c1 1 2 1 3 0";
  body += R"("})";
  EXPECT_EQ(handle("/length", body, Limits{}).status, 200);
  Limits limits;
  limits.max_work = 14999;
  const Reply capped = handle("/length", body, limits);
  EXPECT_EQ(capped.status, 422);
  EXPECT_TRUE(capped.limit_reached);
  EXPECT_EQ(json::parse(capped.body)["type"], "urn:bezier-service:problem:work-cap");
}

}  // namespace
}  // namespace bezier::api
