// POST /intersections at the handler level: answers (round-tripped kernel results, both
// forms), every validation rule with its JSON Pointer, the work cap, and the Python
// `bezier` fixtures (tests/fixtures/python-bezier, Apache-2.0, dhermes/bezier) end to end.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "api/write_json.hpp"
#include "api/handler.hpp"
#include "tests/support/route_answers.hpp"
#include "core/intersect/intersect.hpp"
#include "tests/core/intersect/python_bezier_fixtures.hpp"

namespace bezier::api {
namespace {

using nlohmann::json;

json call(const std::string& body, int expected_status, const Limits& limits = {}) {
  return test::route_answer("/intersections", body, expected_status, limits);
}

std::vector<std::string> errors_of(const std::string& body, const Limits& limits = Limits{}) {
  return test::error_pointers(call(body, 422, limits));
}

using Pointers = std::vector<std::string>;

constexpr const char* kCrossing =
    R"({"curves":[{"points":[[0,0],[2,2]]},{"points":[[0,2],[2,0]]}]})";

TEST(IntersectionsRoute, CrossingSegmentsAnswerIsTheKernelsRoundTripped) {
  const json r = call(kCrossing, 200);
  const core::IntersectionResult k =
      core::intersect(core::Curve({{0, 0}, {2, 2}}), core::Curve({{0, 2}, {2, 0}}));
  ASSERT_EQ(r["intersections"].size(), 1u);
  const json& x = r["intersections"][0];
  EXPECT_EQ(x["t"].get<double>(), 0.5);
  EXPECT_EQ(x["s"].get<double>(), 0.5);
  EXPECT_EQ(x["t_interval"][0].get<double>(), k.intersections[0].t_interval.lo);
  EXPECT_EQ(x["t_interval"][1].get<double>(), k.intersections[0].t_interval.hi);
  EXPECT_EQ(x["s_interval"][0].get<double>(), k.intersections[0].s_interval.lo);
  EXPECT_EQ(x["s_interval"][1].get<double>(), k.intersections[0].s_interval.hi);
  EXPECT_EQ(x["point"], json::array({1.0, 1.0}));
  EXPECT_EQ(x["kind"], "transversal");
  EXPECT_EQ(x["resolved"], true);
  EXPECT_TRUE(r["overlaps"].empty());
  EXPECT_EQ(r["tolerance"].get<double>(), 1e-12);
  EXPECT_EQ(r["stats"]["method"], "hybrid");
  EXPECT_EQ(r["stats"]["fat_curve_degree"], 3);
  for (const char* key : {"iterations", "work", "clipping_steps", "subdivisions", "candidate_boxes",
                          "compensated_steps", "newton_iterations", "max_depth"}) {
    EXPECT_TRUE(r["stats"][key].is_number_integer()) << key;
  }
}

TEST(IntersectionsRoute, MethodsToleranceAndFatCurveDegreeAreUsed) {
  for (const char* method : {"hybrid", "bezier-clipping", "subdivision"}) {
    const json r =
        call(std::string(
                 R"({"curves":[{"points":[[0,0],[1,2],[2,0]]},{"points":[[0,0.75],[2,0.75]]}],)") +
                 R"("method":")" + method + R"(","tolerance":1e-6,"fat_curve_degree":2})",
             200);
    EXPECT_EQ(r["stats"]["method"], method);
    EXPECT_EQ(r["stats"].contains("fat_curve_degree"), std::string(method) == "hybrid");
    EXPECT_EQ(r["tolerance"].get<double>(), 1e-6);
    ASSERT_EQ(r["intersections"].size(), 2u);
    // y = 2x - x^2 meets y = 3/4 at t = s = 1/4 and 3/4 (exact binary fractions).
    EXPECT_EQ(r["intersections"][0]["t"].get<double>(), 0.25);
    EXPECT_EQ(r["intersections"][1]["s"].get<double>(), 0.75);
    for (const json& x : r["intersections"]) {
      EXPECT_LT(x["t_interval"][1].get<double>() - x["t_interval"][0].get<double>(), 1e-6);
    }
  }
}

TEST(IntersectionsRoute, TangencyIsReportedOnce) {
  const json r =
      call(R"({"curves":[{"points":[[0,0],[1,2],[2,0]]},{"points":[[0,1],[2,1]]}]})", 200);
  ASSERT_EQ(r["intersections"].size(), 1u);
  EXPECT_EQ(r["intersections"][0]["kind"], "tangent");
  EXPECT_EQ(r["intersections"][0]["t"].get<double>(), 0.5);
}

TEST(IntersectionsRoute, HighOrderTangencyAnswersByEveryMethod) {
  // Issue 29: A(t) - B(t) = (2t - 1)^3 (1, -1) along A's tangent at 1/2, a contact of order
  // 5 at t = s = 1/2, the point (3.5, 3.5) (core/intersect/high_order_contact_test.cpp).
  const std::string curves =
      R"({"curves":[{"points":[[1,4],[4,5],[3,2],[6,3]]},{"points":[[2,3],[3,6],[4,1],[5,4]]}])";
  for (const std::string options :
       {R"("method":"hybrid","fat_curve_degree":3)", R"("method":"hybrid","fat_curve_degree":2)",
        R"("method":"bezier-clipping")", R"("method":"subdivision")"}) {
    SCOPED_TRACE(options);
    const json r = call(curves + "," + options + "}", 200);
    ASSERT_EQ(r["intersections"].size(), 1u);
    const json& x = r["intersections"][0];
    EXPECT_EQ(x["t"].get<double>(), 0.5);
    EXPECT_EQ(x["s"].get<double>(), 0.5);
    EXPECT_EQ(x["t_interval"], json::array({0.5, 0.5}));
    EXPECT_EQ(x["s_interval"], json::array({0.5, 0.5}));
    EXPECT_EQ(x["point"], json::array({3.5, 3.5}));
    EXPECT_EQ(x["kind"], "tangent");
    EXPECT_EQ(x["resolved"], true);
    EXPECT_LT(r["stats"]["work"].get<std::int64_t>(), Limits{}.max_work / 10);
  }
}

TEST(IntersectionsRoute, OverlapsAreIntervalPairs) {
  const json r = call(R"({"curves":[{"points":[[0,0],[2,0]]},{"points":[[1,0],[3,0]]}]})", 200);
  EXPECT_TRUE(r["intersections"].empty());
  ASSERT_EQ(r["overlaps"].size(), 1u);
  EXPECT_EQ(r["overlaps"][0]["t_interval"], json::array({0.5, 1.0}));
  EXPECT_EQ(r["overlaps"][0]["s_interval"], json::array({0.0, 0.5}));
  EXPECT_EQ(r["overlaps"][0]["reversed"], false);
  const json rev =
      call(R"({"curves":[{"points":[[0,0],[1,2],[2,0]]},{"points":[[2,0],[1,2],[0,0]]}]})", 200);
  ASSERT_EQ(rev["overlaps"].size(), 1u);
  EXPECT_EQ(rev["overlaps"][0]["reversed"], true);
  EXPECT_EQ(rev["overlaps"][0]["s_interval"], json::array({0.0, 1.0}));
}

TEST(IntersectionsRoute, OneCurveGivesItsSelfIntersectionsWithCertifiedIntervals) {
  // B(t) for (-9,0), (13,16), (-13,16), (9,0): x(1/4) = x(3/4) = 0 and y = 9 at both.
  const json r = call(R"({"curves":[{"points":[[-9,0],[13,16],[-13,16],[9,0]]}]})", 200);
  ASSERT_EQ(r["intersections"].size(), 1u);
  const json& x = r["intersections"][0];
  EXPECT_LT(x["t"].get<double>(), x["s"].get<double>());
  EXPECT_LE(x["t_interval"][0].get<double>(), 0.25);
  EXPECT_GE(x["t_interval"][1].get<double>(), 0.25);
  EXPECT_LE(x["s_interval"][0].get<double>(), 0.75);
  EXPECT_GE(x["s_interval"][1].get<double>(), 0.75);
  EXPECT_LT(x["t_interval"][1].get<double>() - x["t_interval"][0].get<double>(), 1e-12);
  EXPECT_EQ(x["resolved"], true);
  EXPECT_EQ(x["kind"], "transversal");
  EXPECT_NEAR(x["point"][1].get<double>(), 9.0, 1e-14);
  EXPECT_TRUE(r["stats"]["method"].is_string());
  // A straight curve doubling back retraces itself: B(t) = (4t(1 - t) + t^2, 0) (control
  // points 0, 2, 1 on the x axis) goes from 0 to 4/3 (t = 2/3) and back to 1, so B on
  // [1/3, 2/3] and B on [2/3, 1] are the same points, run in opposite directions.
  const json back = call(R"({"curves":[{"points":[[0,0],[2,0],[1,0]]}]})", 200);
  ASSERT_EQ(back["overlaps"].size(), 1u);
  EXPECT_NEAR(back["overlaps"][0]["t_interval"][0].get<double>(), 1.0 / 3, 1e-12);
  EXPECT_NEAR(back["overlaps"][0]["s_interval"][1].get<double>(), 1.0, 1e-12);
  EXPECT_EQ(back["overlaps"][0]["reversed"], true);
  // No self-intersection: empty.
  EXPECT_TRUE(call(R"({"curves":[{"points":[[0,0],[1,2],[2,0]]}]})", 200)["intersections"].empty());
}

TEST(IntersectionsRoute, ValidationErrorsPointAtTheField) {
  EXPECT_EQ(errors_of("{}"), (Pointers{"/curves"}));
  EXPECT_EQ(errors_of(R"({"curves":{}})"), (Pointers{"/curves"}));
  EXPECT_EQ(errors_of(R"({"curves":[]})"), (Pointers{"/curves"}));
  EXPECT_EQ(
      errors_of(
          R"({"curves":[{"points":[[0,0],[1,1]]},{"points":[[0,0],[1,1]]},{"points":[[0,0],[1,1]]}]})"),
      (Pointers{"/curves"}));
  EXPECT_EQ(errors_of(R"({"curves":[[[0,0],[1,1]]]})"), (Pointers{"/curves/0"}));
  EXPECT_EQ(errors_of(R"({"curves":[{"points":[[0,0],[1,1]]},{}]})"),
            (Pointers{"/curves/1/points"}));
  EXPECT_EQ(errors_of(R"({"curves":[{"points":[[0,0],[1,1]],"p":1}]})"), (Pointers{"/curves/0/p"}));
  EXPECT_EQ(errors_of(R"({"curves":[{"points":[[0,0],[1,1]]},{"points":[[0,0],[1,1],[2,"x"]]}]})"),
            (Pointers{"/curves/1/points/2/1"}));
  EXPECT_EQ(errors_of(R"({"curves":[{"points":[[0,0]]}]})"), (Pointers{"/curves/0/points"}));
  EXPECT_EQ(errors_of(R"({"curves":[{"points":[[0,0],[1,1]]}],"tolerance":"small"})"),
            (Pointers{"/tolerance"}));
  EXPECT_EQ(errors_of(R"({"curves":[{"points":[[0,0],[1,1]]}],"tolerance":1e-15})"),
            (Pointers{"/tolerance"}));
  EXPECT_EQ(errors_of(R"({"curves":[{"points":[[0,0],[1,1]]}],"tolerance":0})"),
            (Pointers{"/tolerance"}));
  EXPECT_EQ(errors_of(R"({"curves":[{"points":[[0,0],[1,1]]}],"tolerance":2})"),
            (Pointers{"/tolerance"}));
  EXPECT_EQ(errors_of(R"({"curves":[{"points":[[0,0],[1,1]]}],"method":"newton"})"),
            (Pointers{"/method"}));
  EXPECT_EQ(errors_of(R"({"curves":[{"points":[[0,0],[1,1]]}],"fat_curve_degree":4})"),
            (Pointers{"/fat_curve_degree"}));
  EXPECT_EQ(errors_of(R"({"curves":[{"points":[[0,0],[1,1]]}],"fat_curve_degree":2.5})"),
            (Pointers{"/fat_curve_degree"}));
  EXPECT_EQ(errors_of(R"({"curves":[{"points":[[0,0],[1,1]]}],"curve":1})"), (Pointers{"/curve"}));
  // All problems at once, in request order of the checks.
  EXPECT_EQ(
      errors_of(
          R"({"curves":[{"points":[[0,0]]}],"tolerance":-1,"method":1,"fat_curve_degree":"3"})"),
      (Pointers{"/curves/0/points", "/tolerance", "/method", "/fat_curve_degree"}));
  // The smallest tolerance accepted is 2^-46.
  EXPECT_EQ(
      call(std::string(
               R"({"curves":[{"points":[[0,0],[2,2]]},{"points":[[0,2],[2,0]]}],"tolerance":)") +
               json(core::kMinTolerance).dump() + "}",
           200)["intersections"]
          .size(),
      1u);
}

TEST(IntersectionsRoute, DegreeAboveTheLimitIsRejected) {
  Limits limits;
  limits.max_degree = 3;
  EXPECT_EQ(
      errors_of(
          R"({"curves":[{"points":[[0,0],[1,1],[2,0],[3,1],[4,0]]},{"points":[[0,0],[1,1]]}]})",
          limits),
      (Pointers{"/curves/0/points"}));
}

TEST(IntersectionsRoute, RetracedCurvesAnswerTheirOverlaps) {
  // g(s) = f(4s(1 - s)) runs along f and back (the spec's "retraced" example): f on [0, 1]
  // is g on [0, 1/2] and, reversed, g on [1/2, 1].
  const json r = call(
      R"({"curves":[{"points":[[0,0],[3,6],[6,0]]},{"points":[[0,0],[6,12],[8,-16],[6,12],[0,0]]}]})",
      200);
  EXPECT_TRUE(r["intersections"].empty());
  ASSERT_EQ(r["overlaps"].size(), 2u);
  EXPECT_EQ(r["overlaps"][0]["t_interval"], json::parse("[0.0, 1.0]"));
  EXPECT_EQ(r["overlaps"][0]["s_interval"], json::parse("[0.0, 0.5]"));
  EXPECT_EQ(r["overlaps"][0]["reversed"], false);
  EXPECT_EQ(r["overlaps"][1]["t_interval"], json::parse("[0.0, 1.0]"));
  EXPECT_EQ(r["overlaps"][1]["s_interval"], json::parse("[0.5, 1.0]"));
  EXPECT_EQ(r["overlaps"][1]["reversed"], true);
}

TEST(IntersectionsRoute, WorkCapAnswers422NotAHang) {
  // The retraced pair with g's middle control point moved by 4e-10: within about 1e-10 of
  // f all along without coinciding, which takes the hybrid search about a million units.
  const std::string near_retraced =
      R"({"curves":[{"points":[[0,0],[3,6],[6,0]]},{"points":[[0,0],[6,12],[8,-15.9999999996],[6,12],[0,0]]}])";
  Limits limits;
  limits.max_work = 5000;
  const json problem = call(near_retraced + "}", 422, limits);
  EXPECT_EQ(problem["type"], "urn:bezier-service:problem:work-cap");
  EXPECT_EQ(problem["status"], 422);
  const std::string detail = problem["detail"].get<std::string>();
  EXPECT_NE(detail.find("work cap of 5000 units"), std::string::npos) << detail;
  // Subdivision converges only linearly along it: the default cap stops it too.
  const json at_default = call(near_retraced + R"(,"method":"subdivision"})", 422);
  EXPECT_EQ(at_default["type"], "urn:bezier-service:problem:work-cap");
}

TEST(IntersectionsRoute, WorkSpentStaysWithinTheCap) {
  // Two cubics crossing: the answer reports the units spent, within the cap.
  Limits limits;
  const json r = call(
      R"({"curves":[{"points":[[0,0],[1,0.1],[2,-0.1],[3,0]]},{"points":[[1.5,-1],[1.6,0],[1.4,0.5],[1.5,1]]}]})",
      200, limits);
  EXPECT_GT(r["stats"]["work"].get<std::int64_t>(), r["stats"]["iterations"].get<std::int64_t>());
  EXPECT_LE(r["stats"]["work"].get<std::int64_t>(), limits.max_work);
}

TEST(IntersectionsRoute, ACurveRetracingPartOfItselfAnswersTheOverlap) {
  // B = C(4 (t - 1/4)^2), C quadratic: B(1/4 - x) = B(1/4 + x), so B on [0, 1/4] is B on
  // [1/4, 1/2] reversed.
  const json r = call(
      R"({"curves":[{"points":[[0.75,0.5625],[-0.75,-0.9375],[-0.25,1.5625],[2.25,-3.9375],[6.75,18.5625]]}]})",
      200);
  EXPECT_TRUE(r["intersections"].empty());
  EXPECT_EQ(r["overlaps"],
            json::parse(R"([{"reversed":true,"s_interval":[0.25,0.5],"t_interval":[0.0,0.25]}])"));
}

TEST(IntersectionsRoute, SelfIntersectionWorkCapAnswers422) {
  // The curve above with one coordinate moved by 1e-9: no longer retracing itself, but
  // within rounding of it along a whole piece, which needs more boxes than this cap buys.
  Limits limits;
  limits.max_work = 20000;
  const json problem = call(
      R"({"curves":[{"points":[[0.75,0.5625],[-0.75,-0.9375],[-0.25,1.562500001],[2.25,-3.9375],[6.75,18.5625]]}]})",
      422, limits);
  EXPECT_EQ(problem["type"], "urn:bezier-service:problem:work-cap");
  const std::string detail = problem["detail"].get<std::string>();
  EXPECT_NE(detail.find("self-intersection search spent"), std::string::npos) << detail;
  EXPECT_NE(detail.find("work cap of 20000 units"), std::string::npos) << detail;
}

TEST(IntersectionsRoute, PythonBezierFixturesEndToEnd) {
  const auto curves = test::python_bezier::curves();
  const auto points_json = [](const core::Curve& c) {
    json pts = json::array();
    for (const core::Point2 p : c.points()) pts.push_back({p.x, p.y});
    return pts;
  };
  int cases = 0;
  for (const auto& c : test::python_bezier::cases()) {
    SCOPED_TRACE("case " + std::to_string(c.id));
    const json body = {{"curves",
                        {{{"points", points_json(curves.at(c.curve1))}},
                         {{"points", points_json(curves.at(c.curve2))}}}}};
    const json r = call(body.dump(), 200);
    if (c.type == "no-intersection") {
      EXPECT_TRUE(r["intersections"].empty());
    } else if (c.type == "standard" || c.type == "tangent") {
      // Case 46's rounded input crosses twice where the exact curves touch (see
      // tests/core/intersect/intersect_hard_cases_test.cpp).
      EXPECT_EQ(r["intersections"].size(), c.t.size() + (c.id == 46 ? 1 : 0));
      for (std::size_t i = 0; i < c.t.size(); ++i) {
        bool found = false;
        for (const json& x : r["intersections"]) {
          found = found || (std::fabs(x["t"].get<double>() - c.t[i]) < 1e-6 &&
                            std::fabs(x["s"].get<double>() - c.s[i]) < 1e-6);
        }
        EXPECT_TRUE(found) << c.t[i] << " " << c.s[i];
      }
    } else {
      EXPECT_EQ(r["overlaps"].size() + r["intersections"].size(), c.id == 20 ? 1u : c.t.size());
    }
    ++cases;
  }
  EXPECT_EQ(cases, 53);
}

}  // namespace
}  // namespace bezier::api
