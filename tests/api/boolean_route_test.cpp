#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "api/handler.hpp"
#include "core/curve/polar.hpp"
#include "core/path/svg_path_data.hpp"
#include "tests/support/route_answers.hpp"

namespace bezier::api {
namespace {

using nlohmann::json;

json call(const std::string& body, int expected_status, const Limits& limits = {}) {
  return test::route_answer("/boolean", body, expected_status, limits);
}

std::vector<std::string> errors_of(const std::string& body) {
  return test::error_pointers(call(body, 422));
}

using Pointers = std::vector<std::string>;

/// The answer's promises that the wire shows: `path` parses back to exactly the segments'
/// points, contours cover the segments in order and their areas sum to `area`.
void expect_consistent(const json& r) {
  double total = 0.0;
  std::size_t next = 0;
  for (const json& c : r["contours"]) {
    EXPECT_EQ(c["segments"][0].get<std::size_t>(), next);
    next = c["segments"][1].get<std::size_t>();
    total += c["area"].get<double>();
    EXPECT_EQ(c["orientation"], c["area"].get<double>() > 0 ? "ccw" : "cw");
  }
  EXPECT_EQ(next, r["segments"].size());
  EXPECT_NEAR(total, r["area"].get<double>(), 1e-12);
  if (r["path"].is_null()) return;
  const path::PathDataParse parsed = path::parse_svg_path_data(r["path"].get<std::string>(), 10000);
  ASSERT_FALSE(parsed.error);
  ASSERT_EQ(parsed.path.segments.size(), r["segments"].size());
  for (std::size_t k = 0; k < parsed.path.segments.size(); ++k) {
    const json& points = r["segments"][k]["points"];
    const core::Curve& s = parsed.path.segments[k];
    ASSERT_EQ(static_cast<std::size_t>(s.degree() + 1), points.size());
    for (int i = 0; i <= s.degree(); ++i) {
      EXPECT_EQ(s[i].x, points[static_cast<std::size_t>(i)][0].get<double>());
      EXPECT_EQ(s[i].y, points[static_cast<std::size_t>(i)][1].get<double>());
    }
  }
}

TEST(BooleanRoute, UnionOfOverlappingSquares) {
  const json r = call(R"({"op":"union","a":{"path":"M0 0 H2 V2 H0 Z"},"b":{"path":"M1 1 H3 V3 H1 Z"}})", 200);
  EXPECT_EQ(r["area"].get<double>(), 7.0);
  ASSERT_EQ(r["contours"].size(), 1u);
  EXPECT_EQ(r["contours"][0]["orientation"], "ccw");
  // Eight sides: each square's two outer sides whole and its two others up to the crossing.
  EXPECT_EQ(r["segments"].size(), 8u);
  for (const json& s : r["segments"]) {
    EXPECT_EQ(s["degree"], 1);
    const double t0 = s["t"][0].get<double>(), t1 = s["t"][1].get<double>();
    EXPECT_TRUE((t0 == 0.0 || t0 == 0.5 || t0 == 1.0) && (t1 == 0.0 || t1 == 0.5 || t1 == 1.0));
  }
  expect_consistent(r);
}

TEST(BooleanRoute, DifferenceWithAHoleAndEveryOperation) {
  const std::string a = R"({"path":"M0 0 H4 V4 H0 Z"})", b = R"({"path":"M1 1 H2 V2 H1 Z"})";
  const auto body = [&](const char* op) { return std::string(R"({"op":")") + op + R"(","a":)" + a + R"(,"b":)" + b + "}"; };
  const json d = call(body("difference"), 200);
  EXPECT_EQ(d["area"].get<double>(), 15.0);
  ASSERT_EQ(d["contours"].size(), 2u);
  EXPECT_EQ(d["contours"][0]["orientation"], "ccw");
  EXPECT_EQ(d["contours"][1]["orientation"], "cw");
  EXPECT_EQ(d["contours"][1]["area"].get<double>(), -1.0);
  expect_consistent(d);
  EXPECT_EQ(call(body("union"), 200)["area"].get<double>(), 16.0);
  EXPECT_EQ(call(body("intersection"), 200)["area"].get<double>(), 1.0);
  EXPECT_EQ(call(body("xor"), 200)["area"].get<double>(), 15.0);
}

TEST(BooleanRoute, EmptyResultIsAnAnswer) {
  const json r = call(R"({"op":"intersection","a":{"path":"M0 0 H1 V1 H0 Z"},"b":{"path":"M2 0 H3 V1 H2 Z"}})", 200);
  EXPECT_EQ(r["path"], "");
  EXPECT_EQ(r["area"].get<double>(), 0.0);
  EXPECT_EQ(r["contours"], json::array());
  EXPECT_EQ(r["segments"], json::array());
  // An empty operand.
  const json e = call(R"({"op":"union","a":{"path":""},"b":{"path":"M2 0 H3 V1 H2 Z"}})", 200);
  EXPECT_EQ(e["area"].get<double>(), 1.0);
  for (const json& s : e["segments"]) EXPECT_EQ(s["source"], "b");
}

TEST(BooleanRoute, SimplifyFigureEightUnderEitherRule) {
  for (const char* rule : {"nonzero", "evenodd"}) {
    const json r = call(std::string(R"({"op":"simplify","a":{"path":"M0 0 L2 2 L2 0 L0 2 Z","fill_rule":")") + rule + R"("}})", 200);
    EXPECT_EQ(r["area"].get<double>(), 2.0);
    ASSERT_EQ(r["contours"].size(), 2u);
    for (const json& c : r["contours"]) EXPECT_EQ(c["orientation"], "ccw");
    expect_consistent(r);
  }
}

TEST(BooleanRoute, CubicsStayCubicsAndSegmentsArePiecesOfTheirSource) {
  const std::string a = "M0 0 C1 -1 3 -1 4 0 C5 1 5 3 4 4 C3 5 1 5 0 4 C-1 3 -1 1 0 0 Z";
  const json r = call(R"({"op":"union","a":{"path":")" + a + R"("},"b":{"path":"M2 2 H6 V6 H2 Z"}})", 200);
  expect_consistent(r);
  const path::Path source = path::parse_svg_path_data(a, 100).path;
  int cubics = 0;
  for (const json& s : r["segments"]) {
    if (s["source"] != "a") continue;
    ++cubics;
    EXPECT_EQ(s["degree"], 3);
    const core::Curve piece = core::portion(source.segments[s["segment"].get<std::size_t>()],
                                            s["t"][0].get<double>(), s["t"][1].get<double>());
    for (int i = 1; i < 3; ++i) {
      EXPECT_EQ(piece[i].x, s["points"][static_cast<std::size_t>(i)][0].get<double>());
      EXPECT_EQ(piece[i].y, s["points"][static_cast<std::size_t>(i)][1].get<double>());
    }
  }
  EXPECT_GT(cubics, 0);
}

TEST(BooleanRoute, DegreeFiveCurvesGiveNullPath) {
  const json r = call(R"({"op":"simplify","a":{"curves":[[[0,0],[1,-2],[1.5,-3],[2.5,-3],[3,-2],[4,0]],[[4,0],[0,0]]]}})", 200);
  EXPECT_TRUE(r["path"].is_null());
  ASSERT_EQ(r["segments"].size(), 2u);
  EXPECT_GT(r["area"].get<double>(), 0.0);
  expect_consistent(r);
}

TEST(BooleanRoute, ArcsFollowTheirToleranceAndTheAnswerSaysIt) {
  // The unit circle (two half-turn arcs) and the square [0, 2]^2 meet in a quarter disc of
  // area pi/4; the cubics are within the stated distance d of the arc, so the area is within
  // d times the quarter circle's length pi/2 of it (plus rounding).
  constexpr double kPi = 3.141592653589793;
  const json r = call(R"({"op":"intersection","arc_tolerance":1e-4,)"
                      R"("a":{"path":"M-1 0 A1 1 0 0 0 1 0 A1 1 0 0 0 -1 0 Z"},)"
                      R"("b":{"curves":[[[0,0],[2,0]],[[2,0],[2,2]],[[2,2],[0,2]],[[0,2],[0,0]]]}})",
                      200);
  ASSERT_TRUE(r.contains("arc_tolerance"));
  const double d = r["arc_tolerance"].get<double>();
  EXPECT_GT(d, 0.0);
  EXPECT_LE(d, 1e-4);
  EXPECT_NEAR(r["area"].get<double>(), kPi / 4, d * kPi / 2 + 1e-12);
  // No arcs, nothing stated; no path, nothing to apply it to.
  EXPECT_FALSE(call(R"({"op":"simplify","a":{"path":"M0 0 H1 V1 Z"}})", 200).contains("arc_tolerance"));
  const json refused = call(R"({"op":"simplify","arc_tolerance":1e-3,)"
                            R"("a":{"curves":[[[0,0],[1,0]],[[1,0],[0,1]],[[0,1],[0,0]]]}})",
                            422);
  EXPECT_EQ(refused["errors"][0]["pointer"], "/arc_tolerance");
}

TEST(BooleanRoute, RefusesBadRequests) {
  EXPECT_EQ(errors_of(R"({"a":{"path":"M0 0 H1 V1 Z"}})"), (Pointers{"/op"}));
  EXPECT_EQ(errors_of(R"({"op":"merge","a":{"path":"M0 0 H1 V1 Z"}})"), (Pointers{"/op"}));
  EXPECT_EQ(errors_of(R"({"op":"union","a":{"path":"M0 0 H1 V1 Z"}})"), (Pointers{"/b"}));
  EXPECT_EQ(errors_of(R"({"op":"simplify","a":{"path":"M0 0 H1 V1 Z"},"b":{"path":""}})"), (Pointers{"/b"}));
  EXPECT_EQ(errors_of(R"({"op":"union","a":{"path":"M0 0 X"},"b":{"path":""}})"), (Pointers{"/a/path"}));
  EXPECT_EQ(errors_of(R"({"op":"union","a":{"path":"M0 0 H1 V1 Z","fill_rule":"odd"},"b":{"path":""}})"), (Pointers{"/a/fill_rule"}));
  EXPECT_EQ(errors_of(R"({"op":"union","a":{"path":"M0 0 H1 V1 Z","extra":1},"b":{"path":""}})"), (Pointers{"/a/extra"}));
  EXPECT_EQ(errors_of(R"({"op":"union","a":{"path":""},"b":{"curves":[[[0,0],[1,0]],[[2,0],[1,1]]]}})"), (Pointers{"/b/curves/1/0"}));
}

TEST(BooleanRoute, WorkCapIsA422) {
  Limits limits;
  limits.max_work = 200;
  const json r = call(R"({"op":"union","a":{"path":"M0 0 C1 -1 3 -1 4 0 C5 1 5 3 4 4 C3 5 1 5 0 4 C-1 3 -1 1 0 0 Z"},"b":{"path":"M2 2 C3 1 5 1 6 2 C7 3 7 5 6 6 C5 7 3 7 2 6 C1 5 1 3 2 2 Z"}})", 422, limits);
  EXPECT_EQ(r["type"], "urn:bezier-service:problem:work-cap");
}

}  // namespace
}  // namespace bezier::api
