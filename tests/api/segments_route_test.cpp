// Tests of POST /segments at the handler level: the segments and subpaths of path data
// against values written from the data by hand, the closing lines of Z, arcs and their
// tolerance, the empty case, and the refusals with their pointers.

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "api/handler.hpp"
#include "tests/support/route_answers.hpp"

namespace bezier::api {
namespace {

using nlohmann::json;

json call(const std::string& body, int expected_status, const Limits& limits = {}) {
  return test::route_answer("/segments", body, expected_status, limits);
}

json segment(bool closing, int degree, const char* points, int subpath) {
  return {{"closing", closing}, {"degree", degree}, {"points", json::parse(points)}, {"subpath", subpath}};
}

TEST(SegmentsRoute, EveryCommandFamilyWithAbsoluteAndRelativeCoordinates) {
  // M, h (relative), Q, T (reflecting Q's control point about (4, 0): (5, -2)), then a
  // second subpath after Z: m relative to the first subpath's start, c, s (reflecting
  // (2, 6) about (2, 5): (2, 4)), L.
  const json r = call(R"({"path":"M0 0 h2 Q3 2 4 0 T6 0 Z m1 5 c0 1 1 1 1 0 s2 -1 2 0 L1 5"})", 200);
  const json expected = json::parse(R"({
    "segment_count": 7,
    "segments": [],
    "subpaths": [{"closed": true, "first_segment": 0, "segment_count": 4},
                 {"closed": true, "first_segment": 4, "segment_count": 3}]})");
  EXPECT_EQ(r["segment_count"], expected["segment_count"]);
  EXPECT_EQ(r["subpaths"], expected["subpaths"]);
  ASSERT_EQ(r["segments"].size(), 7u);
  EXPECT_EQ(r["segments"][0], segment(false, 1, "[[0,0],[2,0]]", 0));
  EXPECT_EQ(r["segments"][1], segment(false, 2, "[[2,0],[3,2],[4,0]]", 0));
  EXPECT_EQ(r["segments"][2], segment(false, 2, "[[4,0],[5,-2],[6,0]]", 0));
  EXPECT_EQ(r["segments"][3], segment(true, 1, "[[6,0],[0,0]]", 0));
  EXPECT_EQ(r["segments"][4], segment(false, 3, "[[1,5],[1,6],[2,6],[2,5]]", 1));
  EXPECT_EQ(r["segments"][5], segment(false, 3, "[[2,5],[2,4],[4,4],[4,5]]", 1));
  EXPECT_EQ(r["segments"][6], segment(false, 1, "[[4,5],[1,5]]", 1));
  EXPECT_FALSE(r.contains("arc_tolerance"));
}

TEST(SegmentsRoute, AnExplicitLineBackIsNotAClosingLine) {
  const json r = call(R"({"path":"M0 0 L1 0 L0 1 L0 0 Z"})", 200);
  ASSERT_EQ(r["segments"].size(), 3u);
  for (const json& s : r["segments"]) EXPECT_EQ(s["closing"], false);
  EXPECT_EQ(r["subpaths"][0]["closed"], true);
}

TEST(SegmentsRoute, ArcsAreCubicsAndTheAnswerStatesTheirTolerance) {
  // A quarter of the unit circle from (1, 0) to (0, 1) in one cubic (0.01 allows it): the
  // handles are k = 4/3 tan(π/8) = 4/3 (√2 - 1) along the end tangents.
  const json r = call(R"({"path":"M1 0 A1 1 0 0 1 0 1","arc_tolerance":0.01})", 200);
  EXPECT_EQ(r["arc_tolerance"], 0.01);
  ASSERT_EQ(r["segment_count"], 1);
  const json& s = r["segments"][0];
  EXPECT_EQ(s["degree"], 3);
  const double k = 4.0 / 3.0 * (std::sqrt(2.0) - 1.0);
  const double expected[4][2] = {{1, 0}, {1, k}, {k, 1}, {0, 1}};
  for (int i = 0; i < 4; ++i) {
    for (int c = 0; c < 2; ++c) EXPECT_NEAR(s["points"][i][c].get<double>(), expected[i][c], 1e-15);
  }
  // The default is 1e-6 of the radius, in more cubics.
  const json fine = call(R"({"path":"M1 0 A1 1 0 0 1 0 1"})", 200);
  EXPECT_EQ(fine["arc_tolerance"], 1e-6);
  EXPECT_GT(fine["segment_count"].get<int>(), 1);
}

TEST(SegmentsRoute, DataThatDrawsNothingHasNoSegments) {
  for (const char* body : {R"({"path":""})", R"({"path":"M1 1"})", R"({"path":"M1 1 m2 2"})"}) {
    EXPECT_EQ(call(body, 200), json::parse(R"({"segment_count":0,"segments":[],"subpaths":[]})")) << body;
  }
}

TEST(SegmentsRoute, ZRightAfterAMovetoIsAZeroLengthClosingLine) {
  EXPECT_EQ(call(R"({"path":"M1 1 Z"})", 200),
            json::parse(R"({"segment_count":1,"segments":[{"closing":true,"degree":1,)"
                        R"("points":[[1.0,1.0],[1.0,1.0]],"subpath":0}],)"
                        R"("subpaths":[{"closed":true,"first_segment":0,"segment_count":1}]})"));
}

TEST(SegmentsRoute, RefusalsPointAtTheirField) {
  EXPECT_EQ(test::error_pointers(call(R"({})", 422)), std::vector<std::string>{"/path"});
  EXPECT_EQ(test::error_pointers(call(R"({"path":7})", 422)), std::vector<std::string>{"/path"});
  EXPECT_EQ(test::error_pointers(call(R"({"path":"M0 0 L1 1","points":[[0,0],[1,1]]})", 422)),
            std::vector<std::string>{"/points"});
  EXPECT_EQ(test::error_pointers(call(R"({"path":"M0 0 L1 1","arc_tolerance":0})", 422)),
            std::vector<std::string>{"/arc_tolerance"});
  const json syntax = call(R"({"path":"M0 0 L1 x"})", 422);
  EXPECT_EQ(syntax["errors"][0]["message"], "offset 8: expected a number, found 'x'");
  Limits limits;
  limits.max_path_segments = 2;
  EXPECT_EQ(test::error_pointers(call(R"({"path":"M0 0 L1 1 L2 2 L3 3"})", 422, limits)),
            std::vector<std::string>{"/path"});
}

}  // namespace
}  // namespace bezier::api
