// Tests of POST /length at the handler level: answers against closed forms, and every
// validation rule (interval, at_lengths, dimensions) with its JSON Pointer.

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "api/handler.hpp"
#include "core/measure/arc_length.hpp"
#include "tests/support/route_answers.hpp"
#include "api/write_json.hpp"

namespace bezier::api {
namespace {

using nlohmann::json;

json call(const std::string& body, int expected_status, const Limits& limits = {}) {
  return test::route_answer("/length", body, expected_status, limits);
}

TEST(LengthRoute, LineAndCuspClosedForms) {
  const json line = call(R"({"points":[[0,0],[3,4]]})", 200);
  EXPECT_EQ(line["degree"], 1);
  EXPECT_NEAR(line["length"].get<double>(), 5.0, 5e-12);
  EXPECT_EQ(line["interval"], json::parse("[0.0, 1.0]"));
  EXPECT_FALSE(line.contains("parameters"));
  // The cusp cubic: 2 sqrt(2) - 1, with the bound it met.
  const json cusp = call(R"({"points":[[0,0],[1,1],[0,1],[1,0]]})", 200);
  const double exact = 2 * std::sqrt(2.0) - 1;
  EXPECT_NEAR(cusp["length"].get<double>(), exact, 1e-12 * exact);
  EXPECT_LE(cusp["error_bound"].get<double>(), 1e-12 * exact);
  EXPECT_GE(cusp["error_bound"].get<double>(), 0.0);
}

TEST(LengthRoute, IntervalAndSpaceCurve) {
  const json half = call(R"({"points":[[0,0],[6,8]],"interval":[0.25,0.75]})", 200);
  EXPECT_NEAR(half["length"].get<double>(), 5.0, 5e-12);
  const json space = call(R"({"points":[[0,0,0],[1,2,2]],"interval":[0.5,0.5]})", 200);
  EXPECT_EQ(space["length"], 0.0);
  const json line3 = call(R"({"points":[[0,0,0],[1,2,2]]})", 200);
  EXPECT_NEAR(line3["length"].get<double>(), 3.0, 3e-12);
}

TEST(LengthRoute, ParametersAtLengths) {
  // x = 3t^2, y = 4t^2: length 5 t^2, so length l is at t = sqrt(l / 5).
  const json r = call(R"({"points":[[0,0],[0,0],[3,4]],"at_lengths":[0,1.25,5]})", 200);
  ASSERT_EQ(r["parameters"].size(), 3u);
  EXPECT_EQ(r["parameters"][0]["t"], 0.0);
  EXPECT_EQ(r["parameters"][0]["length"], 0.0);
  EXPECT_NEAR(r["parameters"][1]["t"].get<double>(), 0.5, 1e-12);
  EXPECT_NEAR(r["parameters"][1]["point"][0].get<double>(), 0.75, 1e-12);
  EXPECT_EQ(r["parameters"][2]["t"], 1.0);
  EXPECT_EQ(r["parameters"][2]["point"], json::parse("[3.0, 4.0]"));
}

TEST(LengthRoute, AtLengthsBeyondTheLengthOrNegative) {
  EXPECT_EQ(test::error_pointers(call(R"({"points":[[0,0],[3,4]],"at_lengths":[1,6,2]})", 422)),
            std::vector<std::string>{"/at_lengths/1"});
  EXPECT_EQ(test::error_pointers(call(R"({"points":[[0,0],[3,4]],"at_lengths":[-1]})", 422)),
            std::vector<std::string>{"/at_lengths/0"});
  EXPECT_EQ(test::error_pointers(call(R"({"points":[[0,0],[3,4]],"at_lengths":[]})", 422)),
            std::vector<std::string>{"/at_lengths"});
  // The length itself, sent back, is accepted.
  const json r = call(R"({"points":[[0,0],[1,1],[0,1],[1,0]]})", 200);
  const std::string again = R"({"points":[[0,0],[1,1],[0,1],[1,0]],"at_lengths":[)" +
                            dump_json(r["length"]) + "]}";
  EXPECT_EQ(call(again, 200)["parameters"][0]["t"], 1.0);
}

TEST(LengthRoute, BadIntervals) {
  const std::string points = R"("points":[[0,0],[3,4]])";
  EXPECT_EQ(test::error_pointers(call("{" + points + R"(,"interval":[0.5,0.25]})", 422)),
            std::vector<std::string>{"/interval"});
  EXPECT_EQ(test::error_pointers(call("{" + points + R"(,"interval":[-0.5,0.25]})", 422)),
            std::vector<std::string>{"/interval/0"});
  EXPECT_EQ(test::error_pointers(call("{" + points + R"(,"interval":[0,1.5]})", 422)),
            std::vector<std::string>{"/interval/1"});
  EXPECT_EQ(test::error_pointers(call("{" + points + R"(,"interval":[0.5]})", 422)),
            std::vector<std::string>{"/interval"});
  EXPECT_EQ(test::error_pointers(call("{" + points + R"(,"interval":"all"})", 422)),
            std::vector<std::string>{"/interval"});
}

TEST(LengthRoute, PointsAndFieldsValidated) {
  EXPECT_EQ(test::error_pointers(call(R"({"interval":[0,1]})", 422)), std::vector<std::string>{"/points"});
  EXPECT_EQ(test::error_pointers(call(R"({"points":[[0,0],[1,1,1]]})", 422)), std::vector<std::string>{"/points/1"});
  EXPECT_EQ(test::error_pointers(call(R"({"points":[[0,0],[1,1]],"lenght":1})", 422)), std::vector<std::string>{"/lenght"});
  Limits small;
  small.max_degree = 2;
  const json r = call(R"({"points":[[0,0],[1,1],[2,0],[3,3]]})", 422, small);
  EXPECT_EQ(test::error_pointers(r), std::vector<std::string>{"/points"});
  small.max_t_values = 2;
  EXPECT_EQ(test::error_pointers(call(R"({"points":[[0,0],[1,1]],"at_lengths":[0,0,0]})", 422, small)),
            std::vector<std::string>{"/at_lengths"});
}

TEST(LengthRoute, TheQuadratureChargesTheWorkCap) {
  // The cusp cubic needs several halvings toward t = 1/2: a cap of 400 units pays for the
  // first rules (2 pieces, 7 evaluations of 10 units each, and their extensions) and not
  // for a halving (30 evaluations): 422 work-cap, naming the cap.
  Limits limits;
  limits.max_work = 400;
  const json capped = call(R"({"points":[[0,0],[1,1],[0,1],[1,0]]})", 422, limits);
  EXPECT_EQ(capped["type"], "urn:bezier-service:problem:work-cap");
  const std::string detail = capped["detail"].get<std::string>();
  EXPECT_NE(detail.find("within the per-request work cap of 400 units"), std::string::npos) << detail;
  // The same cusp twice in a path shares one cap: one and a half times what one cusp needs
  // alone is not enough for two.
  core::WorkBudget one;
  (void)core::arc_length(core::Curve({{0, 0}, {1, 1}, {0, 1}, {1, 0}}), 0, 1, {}, one);
  limits.max_work = one.spent() + one.spent() / 2;
  call(R"({"points":[[0,0],[1,1],[0,1],[1,0]]})", 200, limits);
  const json path = call(R"({"path":"M0 0 C1 1 0 1 1 0 C2 1 1 1 2 0"})", 422, limits);
  EXPECT_EQ(path["type"], "urn:bezier-service:problem:work-cap");
  // With the default cap both answer, each cusp 2 sqrt(2) - 1.
  const json both = call(R"({"path":"M0 0 C1 1 0 1 1 0 C2 1 1 1 2 0"})", 200);
  EXPECT_NEAR(both["length"].get<double>(), 2 * (2 * std::sqrt(2.0) - 1), 1e-11);
}

}  // namespace
}  // namespace bezier::api
