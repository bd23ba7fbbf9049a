#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "api/write_json.hpp"
#include "api/handler.hpp"
#include "tests/support/route_answers.hpp"
#include "core/loop/loop_area.hpp"
#include "core/self_intersect/work_cost.hpp"

namespace bezier::api {
namespace {

using nlohmann::json;

constexpr const char* kDegree7 = R"([[0,0],[1,1],[2,3],[1,4],[0,4],[-1,3],[0,1],[1,0]])";

Reply post(const std::string& body, const Limits& limits = Limits{}) {
  return handle("/loop-area", body, limits);
}

json call(const std::string& body, int expected_status, const Limits& limits = {}) {
  return test::route_answer("/loop-area", body, expected_status, limits);
}

std::vector<std::string> errors_of(const std::string& body, const Limits& limits = Limits{}) {
  return test::error_pointers(call(body, 422, limits));
}

using Pointers = std::vector<std::string>;

TEST(LoopAreaRoute, Degree7ExampleIsTheKernelsAnswerRoundTripped) {
  const json r = call(std::string(R"({"points":)") + kDegree7 + "}", 200);
  const core::LoopAreaResult k = core::loop_area(
      core::Curve({{0, 0}, {1, 1}, {2, 3}, {1, 4}, {0, 4}, {-1, 3}, {0, 1}, {1, 0}}));
  ASSERT_EQ(k.loops.size(), 1u);
  EXPECT_EQ(r["degree"], 7);
  ASSERT_EQ(r["loops"].size(), 1u);
  const json& loop = r["loops"][0];
  // Full double precision on the wire: every number reads back to the same double.
  EXPECT_EQ(loop["t"][0].get<double>(), k.loops[0].t1);
  EXPECT_EQ(loop["t"][1].get<double>(), k.loops[0].t2);
  EXPECT_EQ(loop["point"][0].get<double>(), k.loops[0].point.x);
  EXPECT_EQ(loop["point"][1].get<double>(), k.loops[0].point.y);
  EXPECT_EQ(loop["signed_area"].get<double>(), k.loops[0].signed_area);
  EXPECT_EQ(loop["area"].get<double>(), k.loops[0].area);
  EXPECT_EQ(loop["kind"], "transversal");
  EXPECT_EQ(r["area"].get<double>(), k.area);
  // The issue's values (t1 + t2 = 1 by symmetry, area ~2.2537) to the precision the core
  // tests establish against exact arithmetic.
  EXPECT_NEAR(loop["t"][0].get<double>(), 0.07506435058866631, 1e-15);
  EXPECT_NEAR(loop["signed_area"].get<double>(), 2.2537095301725511, 1e-14);
  EXPECT_EQ(r["closed"], false);
  EXPECT_TRUE(r["closed_area"].is_null());
  EXPECT_EQ(r["overlaps"], json::array());
  EXPECT_EQ(r["stats"]["method"], "subdivision");
  EXPECT_GT(r["stats"]["work"].get<std::int64_t>(), 0);
  EXPECT_EQ(r["stats"]["work"].get<std::int64_t>(), k.stats.work);
}

TEST(LoopAreaRoute, StatsWorkIsInTheUnitsOfTheWorkCap) {
  // The cap that the answer says it spent is enough, one unit less is not: stats.work and
  // --max-work count the same units.
  const std::string body = std::string(R"({"points":)") + kDegree7 + "}";
  const std::int64_t work = call(body, 200)["stats"]["work"].get<std::int64_t>();
  Limits limits;
  limits.max_work = work;
  EXPECT_EQ(call(body, 200, limits)["stats"]["work"].get<std::int64_t>(), work);
  limits.max_work = work - 1;
  const json refused = call(body, 422, limits);
  EXPECT_EQ(refused["type"], "urn:bezier-service:problem:work-cap");
}

TEST(LoopAreaRoute, CubicUsesTheClosedForm) {
  // B(t) = t (a t^2 + b t + c) with B(3/4) = B(0) = (0, 0): the loop closes at the start.
  const json r = call(R"({"points":[[0,0],[-0.375,-2.8125],[-1.75,-2.625],[1.875,3.5625]]})", 200);
  ASSERT_EQ(r["loops"].size(), 1u);
  EXPECT_EQ(r["loops"][0]["t"][0], 0.0);
  EXPECT_NEAR(r["loops"][0]["t"][1].get<double>(), 0.75, 1e-15);
  EXPECT_EQ(r["loops"][0]["point"], json::parse("[0.0, 0.0]"));
  EXPECT_EQ(r["stats"]["method"], "closed-form-cubic");
}

TEST(LoopAreaRoute, ClosedCurveHasItsAreaAndNoTrivialLoop) {
  // A closed cubic, P0 = P3 = 0: x = 6t(1-t)^2, y = 6t^2(1-t), and
  // 1/2 ∫ (x y' - x' y) dt = 1/2 ∫ 36 t^2 (1-t)^2 dt = 18 B(3,3) = 18 / 30 = 3/5.
  const json r = call(R"({"points":[[0,0],[2,0],[0,2],[0,0]]})", 200);
  EXPECT_EQ(r["closed"], true);
  EXPECT_EQ(r["loops"], json::array());
  EXPECT_EQ(r["area"], 0.0);
  EXPECT_NEAR(r["closed_area"].get<double>(), 0.6, 1e-15);
}

TEST(LoopAreaRoute, IntervalAreaWithItsChord) {
  // Archimedes: the parabolic segment is 2/3 of the triangle (0,0), (1,2), (2,0): 4/3,
  // clockwise. On [1/4, 3/4] the piece is again a parabola, control points (0.5, 0.75),
  // (1, 1.25), (1.5, 0.75) (blossoms b(1/4,1/4), b(1/4,3/4), b(3/4,3/4)): 2/3 of that
  // triangle (base 1, height 1/2), 1/6.
  json r = call(R"({"points":[[0,0],[1,2],[2,0]],"interval":[0,1]})", 200);
  EXPECT_EQ(r["degree"], 2);
  EXPECT_EQ(r["interval"], json::parse("[0.0, 1.0]"));
  EXPECT_EQ(r["signed_area"], -4.0 / 3.0);
  EXPECT_EQ(r["area"], 4.0 / 3.0);
  EXPECT_EQ(r["chord"], json::parse("[[0.0, 0.0], [2.0, 0.0]]"));
  EXPECT_FALSE(r.contains("loops"));
  EXPECT_EQ(r["closed"], false);
  EXPECT_TRUE(r["closed_area"].is_null());
  r = call(R"({"points":[[0,0],[1,2],[2,0]],"interval":[0.25,0.75]})", 200);
  EXPECT_NEAR(r["signed_area"].get<double>(), -1.0 / 6.0, 1e-15);
  EXPECT_EQ(r["chord"], json::parse("[[0.5, 0.75], [1.5, 0.75]]"));
  // A null interval is an absent one.
  r = call(R"({"points":[[0,0],[1,2],[2,0]],"interval":null})", 200);
  EXPECT_TRUE(r.contains("loops"));
}

TEST(LoopAreaRoute, CollinearCurveListsOverlaps) {
  const json r = call(R"({"points":[[0,0],[2,2],[0,0]]})", 200);
  EXPECT_EQ(r["loops"], json::array());
  EXPECT_EQ(r["area"], 0.0);
  ASSERT_EQ(r["overlaps"].size(), 1u);
  EXPECT_EQ(r["overlaps"][0]["t_interval"][0], 0.0);
  EXPECT_NEAR(r["overlaps"][0]["t_interval"][1].get<double>(), 0.5, 1e-12);
  EXPECT_EQ(r["overlaps"][0]["s_interval"][1], 1.0);
  EXPECT_EQ(r["stats"]["method"], "collinear");
  EXPECT_EQ(r["closed"], true);
  EXPECT_EQ(r["closed_area"], 0.0);
}

TEST(LoopAreaRoute, ValidationErrorsPointAtTheField) {
  EXPECT_EQ(errors_of(R"({})"), (Pointers{"/points"}));
  EXPECT_EQ(errors_of(R"({"points":"abc"})"), (Pointers{"/points"}));
  EXPECT_EQ(errors_of(R"({"points":[[0,0]]})"), (Pointers{"/points"}));
  EXPECT_EQ(errors_of(R"({"points":[[0,0],[1]]})"), (Pointers{"/points/1"}));
  EXPECT_EQ(errors_of(R"({"points":[[0,0],[1,1,1]]})"), (Pointers{"/points/1"}));
  EXPECT_EQ(errors_of(R"({"points":[[0,0,0],[1,1,1]]})"), (Pointers{"/points/0", "/points/1"}));
  EXPECT_EQ(errors_of(R"({"points":[[0,0],[1e999,1]]})"), (Pointers{"/points/1/0"}));
  EXPECT_EQ(errors_of(R"({"points":[[0,"a"],[1,1]]})"), (Pointers{"/points/0/1"}));
  EXPECT_EQ(errors_of(R"({"points":[[0,0],[1,1]],"intervals":[0,1]})"), (Pointers{"/intervals"}));
  EXPECT_EQ(errors_of(R"({"points":[[0,0],[1,1]],"interval":0.5})"), (Pointers{"/interval"}));
  EXPECT_EQ(errors_of(R"({"points":[[0,0],[1,1]],"interval":[]})"), (Pointers{"/interval"}));
  EXPECT_EQ(errors_of(R"({"points":[[0,0],[1,1]],"interval":[0.5]})"), (Pointers{"/interval"}));
  EXPECT_EQ(errors_of(R"({"points":[[0,0],[1,1]],"interval":[0.1,0.2,0.3]})"),
            (Pointers{"/interval"}));
  EXPECT_EQ(errors_of(R"({"points":[[0,0],[1,1]],"interval":[-0.1,0.5]})"),
            (Pointers{"/interval/0"}));
  EXPECT_EQ(errors_of(R"({"points":[[0,0],[1,1]],"interval":[0.2,1.5]})"),
            (Pointers{"/interval/1"}));
  EXPECT_EQ(errors_of(R"({"points":[[0,0],[1,1]],"interval":["a",0.5]})"),
            (Pointers{"/interval/0"}));
  EXPECT_EQ(errors_of(R"({"points":[[0,0],[1,1]],"interval":[0.5,0.5]})"), (Pointers{"/interval"}));
  EXPECT_EQ(errors_of(R"({"points":[[0,0],[1,1]],"interval":[0.7,0.2]})"), (Pointers{"/interval"}));
  // Every problem at once.
  EXPECT_EQ(errors_of(R"({"interval":[2,0.5],"extra":1})"),
            (Pointers{"/extra", "/points", "/interval/0"}));
}

TEST(LoopAreaRoute, AreaBeyondTheDoubleRangeIsAProblemNotANull) {
  // A curve 1e200 wide has a finite description and an area of order 1e400.
  EXPECT_EQ(test::error_pointers(call(
                R"({"points":[[0,0],[1e200,1e200],[0,1e200],[1e200,0]],"interval":[0,1]})", 422)),
            (Pointers{"/points"}));
  // A loop that size too (the cubic (0,0), (1,1), (-1/2,1), (1/2,0) crosses itself).
  EXPECT_EQ(test::error_pointers(call(R"({"points":[[0,0],[1e200,1e200],[-5e199,1e200],[5e199,0]]})", 422)),
            (Pointers{"/points"}));
  // 1e150 is fine: areas of order 1e300.
  const json r =
      call(R"({"points":[[0,0],[1e150,1e150],[0,1e150],[1e150,0]],"interval":[0,1]})", 200);
  EXPECT_TRUE(r["area"].is_number());
}

TEST(LoopAreaRoute, DegreeAboveTheLimit) {
  Limits limits;
  limits.max_degree = 6;
  const json r = call(std::string(R"({"points":)") + kDegree7 + "}", 422, limits);
  EXPECT_EQ(test::error_pointers(r), (Pointers{"/points"}));
}

TEST(LoopAreaRoute, WorkCapIsA422Problem) {
  // Parameter boxes are charged at the degree's price: five boxes' worth here, spent whole
  // (no Newton run among the first boxes, which lie next to the diagonal).
  Limits limits;
  limits.max_work = 5 * core::self_intersection_box_cost(7);
  const json r = call(std::string(R"({"points":)") + kDegree7 + "}", 422, limits);
  EXPECT_EQ(r["type"], "urn:bezier-service:problem:work-cap");
  EXPECT_EQ(r["status"], 422);
  const std::string detail = r["detail"].get<std::string>();
  EXPECT_NE(detail.find("spent " + std::to_string(limits.max_work) + " work units"),
            std::string::npos)
      << detail;
  EXPECT_NE(detail.find("work cap of " + std::to_string(limits.max_work) + " units"),
            std::string::npos)
      << detail;
  EXPECT_FALSE(r.contains("errors"));
  // The interval form does no search and is not capped.
  limits.max_work = 1;
  call(std::string(R"({"points":)") + kDegree7 + R"(,"interval":[0.1,0.9]})", 200, limits);
  // A curve within rounding of retracing part of itself (B = C(4 (t - 1/4)^2), C quadratic,
  // with one coordinate moved by 1e-9) needs far more boxes than this cap buys.
  limits.max_work = 100000;
  const json cap = call(
      R"({"points":[[0.75,0.5625],[-0.75,-0.9375],[-0.25,1.562500001],[2.25,-3.9375],[6.75,18.5625]]})",
      422, limits);
  EXPECT_EQ(cap["type"], "urn:bezier-service:problem:work-cap");
}

TEST(LoopAreaRoute, ACurveRetracingPartOfItselfHasAnOverlapAndNoLoop) {
  // The same curve exactly: B(1/4 - x) = B(1/4 + x), B on [0, 1/4] is B on [1/4, 1/2].
  const json r = call(
      R"({"points":[[0.75,0.5625],[-0.75,-0.9375],[-0.25,1.5625],[2.25,-3.9375],[6.75,18.5625]]})",
      200);
  EXPECT_EQ(r["loops"], json::array());
  EXPECT_EQ(r["overlaps"], json::parse(R"([{"t_interval":[0.0,0.25],"s_interval":[0.25,0.5]}])"));
}

TEST(LoopAreaRoute, PalindromicCurveRetracesItself) {
  // P_i = P_{4-i}: B(1 - t) = B(t), out along a parabola and back.
  const json r = call(R"({"points":[[0,0],[3,1.5],[4,5],[3,1.5],[0,0]]})", 200);
  EXPECT_EQ(r["loops"], json::array());
  EXPECT_EQ(r["overlaps"], json::parse(R"([{"t_interval":[0.0,0.5],"s_interval":[0.5,1.0]}])"));
  EXPECT_EQ(r["closed"], true);
}

TEST(LoopAreaRoute, MalformedBodies) {
  EXPECT_EQ(post("not json").status, 400);
  EXPECT_EQ(post("[1,2]").status, 400);
  EXPECT_EQ(post("[1,2]").content_type, "application/problem+json");
}

}  // namespace
}  // namespace bezier::api
