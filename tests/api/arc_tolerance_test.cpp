// Tests of elliptical arcs in path data at the handler level: every route taking a path
// accepts `arc_tolerance` and states the tolerance its arcs were drawn within, answers about
// a circle drawn by arcs agree with the circle's closed forms to that tolerance, and the
// field's refusals point at it.

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "api/handler.hpp"
#include "tests/support/route_answers.hpp"

namespace bezier::api {
namespace {

using nlohmann::json;

constexpr double kPi = std::numbers::pi;
/// The unit circle about the origin, counter-clockwise (in y-up axes), as two half arcs.
constexpr const char* kCircle = "M-1 0 A1 1 0 0 1 1 0 A1 1 0 0 1 -1 0 Z";

json call(const std::string& route, const std::string& body, int expected_status) {
  return test::route_answer(route, body, expected_status, Limits{});
}

std::string with_path(const char* path, const std::string& rest = "") {
  return std::string(R"({"path":")") + path + "\"" + rest + "}";
}

std::pair<std::string, std::string> only_error(const json& problem) {
  EXPECT_EQ(problem["type"], "urn:bezier-service:problem:validation") << problem.dump();
  EXPECT_EQ(problem["errors"].size(), 1u) << problem.dump();
  return {problem["errors"][0]["pointer"], problem["errors"][0]["message"]};
}

TEST(ArcTolerance, EveryPathRouteStatesTheDefault) {
  // 1e-6 of the larger radius, 2 here.
  const char* ellipse = "M-2 0 A2 1 0 0 1 2 0 A2 1 0 0 1 -2 0 Z";
  EXPECT_EQ(call("/length", with_path(ellipse), 200)["arc_tolerance"], 2e-6);
  EXPECT_EQ(call("/bounds", with_path(ellipse), 200)["arc_tolerance"], 2e-6);
  EXPECT_EQ(call("/loop-area", with_path(ellipse), 200)["arc_tolerance"], 2e-6);
  EXPECT_EQ(call("/nearest", with_path(ellipse, R"(,"targets":[[0,0]])"), 200)["arc_tolerance"], 2e-6);
  EXPECT_EQ(call("/intersections", std::string(R"({"curves":[{"path":")") + ellipse + "\"}]}", 200)
                ["arc_tolerance"],
            2e-6);
}

TEST(ArcTolerance, PathsWithoutArcsStateNone) {
  for (const char* route : {"/length", "/bounds", "/loop-area"}) {
    EXPECT_FALSE(call(route, with_path("M0 0 L1 1 Q2 0 3 1"), 200).contains("arc_tolerance")) << route;
  }
  EXPECT_FALSE(call("/length", with_path("M0 0 L1 1", R"(,"arc_tolerance":0.1)"), 200)
                   .contains("arc_tolerance"));
}

TEST(ArcTolerance, CircleAnswersAgreeWithItsClosedFormsWithinTheTolerance) {
  const double tolerance = 1e-9;
  const std::string rest = R"(,"arc_tolerance":1e-9)";
  // Every point of the cubics is within the tolerance of the circle and every point of the
  // circle within it of the cubics: the box is [-1, 1]² to within it, the enclosed area
  // differs from π by at most the band of that width along the circle, 2π (1 + tol) tol, and
  // the distance from (3, 0) is 2 to within it.
  const json box = call("/bounds", with_path(kCircle, rest), 200);
  EXPECT_EQ(box["arc_tolerance"], tolerance);
  for (const int axis : {0, 1}) {
    EXPECT_NEAR(box["min"][axis].get<double>(), -1.0, tolerance);
    EXPECT_NEAR(box["max"][axis].get<double>(), 1.0, tolerance);
  }
  const json area = call("/loop-area", with_path(kCircle, rest), 200);
  EXPECT_EQ(area["closed"], true);
  EXPECT_NEAR(area["closed_area"].get<double>(), kPi, 2 * kPi * (1 + tolerance) * tolerance);
  EXPECT_EQ(area["loops"], json::array());
  const json nearest = call("/nearest", with_path(kCircle, R"(,"targets":[[3,0]])" + rest), 200);
  EXPECT_NEAR(nearest["results"][0]["distance"].get<double>(), 2.0, tolerance);
  // The length of a curve within tol of the circle has no bound from tol alone; these
  // cubics' is within 1e-6 of 2π (the cubic of angle δ is longer by O(δ^6)).
  EXPECT_NEAR(call("/length", with_path(kCircle, rest), 200)["length"].get<double>(), 2 * kPi, 1e-6);
}

TEST(ArcTolerance, TwoCirclesMeetWhereTheCirclesDo) {
  // Unit circles about (0, 0) and (1, 0) meet at (1/2, ±√3/2).
  const json r = call("/intersections",
                      std::string(R"({"arc_tolerance":1e-10,"curves":[{"path":")") + kCircle +
                          R"("},{"path":"M0 0 A1 1 0 0 1 2 0 A1 1 0 0 1 0 0"}]})",
                      200);
  EXPECT_EQ(r["arc_tolerance"], 1e-10);
  ASSERT_EQ(r["intersections"].size(), 2u);
  for (const json& x : r["intersections"]) {
    EXPECT_NEAR(x["point"][0].get<double>(), 0.5, 1e-9);
    EXPECT_NEAR(std::abs(x["point"][1].get<double>()), std::sqrt(3.0) / 2, 1e-9);
  }
}

TEST(ArcTolerance, RefusalsPointAtTheField) {
  for (const char* bad : {"0", "-1", "\"fine\"", "[1]"}) {
    const json problem = call("/length", with_path(kCircle, std::string(R"(,"arc_tolerance":)") + bad), 422);
    EXPECT_EQ(only_error(problem).first, "/arc_tolerance") << bad;
  }
  const auto [pointer, message] =
      only_error(call("/bounds", R"({"points":[[0,0],[1,1]],"arc_tolerance":1e-3})", 422));
  EXPECT_EQ(pointer, "/arc_tolerance");
  EXPECT_NE(message.find("path"), std::string::npos) << message;
  EXPECT_EQ(only_error(call("/intersections",
                            R"({"arc_tolerance":1e-3,"curves":[{"points":[[0,0],[1,1]]}]})", 422))
                .first,
            "/arc_tolerance");
  EXPECT_EQ(only_error(call("/loop-area", R"({"points":[[0,0],[1,1],[0,1]],"arc_tolerance":1})", 422))
                .first,
            "/arc_tolerance");
  EXPECT_EQ(only_error(call("/nearest", R"({"points":[[0,0],[1,1]],"targets":[[0,0]],"arc_tolerance":1})", 422))
                .first,
            "/arc_tolerance");
}

TEST(ArcTolerance, AToleranceTooFineForTheSegmentLimitIsALimitsRefusal) {
  Limits limits;
  limits.max_path_segments = 50;
  const json problem = test::route_answer("/length", with_path(kCircle, R"(,"arc_tolerance":1e-15)"), 422, limits);
  const auto [pointer, message] = only_error(problem);
  EXPECT_EQ(pointer, "/path");
  EXPECT_NE(message.find("arc_tolerance"), std::string::npos) << message;
}

}  // namespace
}  // namespace bezier::api
