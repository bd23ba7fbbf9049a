// Tests of POST /contains at the handler level: winding numbers, boundary and inside under
// both fill rules for path and curves operands against hand-counted answers, and the
// validation rules (the operand, fill_rule, targets, chains of curves, the limits).

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "api/handler.hpp"
#include "tests/support/route_answers.hpp"

namespace bezier::api {
namespace {

using nlohmann::json;

json call(const std::string& body, int expected_status, const Limits& limits = {}) {
  return test::route_answer("/contains", body, expected_status, limits);
}

json result(bool boundary, bool inside, double x, double y, json winding) {
  return json{{"boundary", boundary}, {"inside", inside}, {"target", {x, y}}, {"winding", winding}};
}

TEST(ContainsRoute, NestedSquaresUnderBothFillRules) {
  // Two counter-clockwise squares (y up), one inside the other: winding 2 in the middle.
  const std::string path = R"("path":"M0 0 H10 V10 H0 Z M3 3 H7 V7 H3 Z")";
  const std::string targets = R"("targets":[[5,5],[1,5],[11,5],[10,5],[3,3]])";
  const json nonzero = call("{" + path + "," + targets + "}", 200);
  EXPECT_EQ(nonzero["fill_rule"], "nonzero");
  EXPECT_EQ(nonzero["results"],
            json::array({result(false, true, 5, 5, 2), result(false, true, 1, 5, 1),
                         result(false, false, 11, 5, 0), result(true, true, 10, 5, nullptr),
                         result(true, true, 3, 3, nullptr)}));
  const json evenodd = call("{" + path + R"(,"fill_rule":"evenodd",)" + targets + "}", 200);
  EXPECT_EQ(evenodd["fill_rule"], "evenodd");
  EXPECT_EQ(evenodd["results"][0], result(false, false, 5, 5, 2));
  EXPECT_EQ(evenodd["results"][1], result(false, true, 1, 5, 1));
}

TEST(ContainsRoute, AnOpenSubpathIsClosedForFilling) {
  // The triangle (0,0) (4,0) (0,4) drawn without Z, clockwise on the SVG screen, counter-
  // clockwise with y up; the closing line from (0, 4) to (0, 0) is its boundary.
  const json r = call(R"({"path":"M0 0 L4 0 L0 4","targets":[[1,1],[0,2],[3,3]]})", 200);
  EXPECT_EQ(r["results"],
            json::array({result(false, true, 1, 1, 1), result(true, true, 0, 2, nullptr),
                         result(false, false, 3, 3, 0)}));
}

TEST(ContainsRoute, ArcsFollowTheirToleranceAndTheAnswerSaysIt) {
  // The unit circle as two half-turn arcs, cut by the tolerance asked for: within 1e-3 of
  // it, a point 0.01 inside or outside the circle is decided as the circle decides it, and
  // the answer states a distance no larger than the one asked for.
  const json r = call(R"({"path":"M-1 0 A1 1 0 0 0 1 0 A1 1 0 0 0 -1 0 Z","arc_tolerance":1e-3,)"
                      R"("targets":[[0,0.99],[0,-0.99],[0.7,0.7],[0,1.01],[0.72,0.72]]})",
                      200);
  ASSERT_TRUE(r.contains("arc_tolerance"));
  EXPECT_GT(r["arc_tolerance"].get<double>(), 0.0);
  EXPECT_LE(r["arc_tolerance"].get<double>(), 1e-3);
  std::vector<bool> inside;
  for (const json& x : r["results"]) inside.push_back(x["inside"].get<bool>());
  EXPECT_EQ(inside, (std::vector<bool>{true, true, true, false, false}));
  // Without arcs there is nothing to state; with curves there is nothing to apply it to.
  EXPECT_FALSE(call(R"({"path":"M0 0 H1 V1 Z","targets":[[0.5,0.2]]})", 200).contains("arc_tolerance"));
  const json refused = call(R"({"curves":[[[0,0],[1,0]],[[1,0],[0,1]],[[0,1],[0,0]]],)"
                            R"("arc_tolerance":1e-3,"targets":[[0.2,0.2]]})",
                            422);
  EXPECT_EQ(refused["errors"][0]["pointer"], "/arc_tolerance");
  EXPECT_EQ(call(R"({"path":"M0 0 H1 V1 Z","arc_tolerance":0,"targets":[[0.5,0.2]]})", 422)["errors"][0]["pointer"],
            "/arc_tolerance");
}

TEST(ContainsRoute, CurvesOfAnyDegreeInChains) {
  // Chain 1: a degree-5 arch over [0, 5] closed by a line back (clockwise with y up: the
  // arch goes left to right above the base line); chain 2: a triangle far to the right.
  const json r =
      call(R"({"curves":[[[0,0],[1,2],[2,2],[3,2],[4,2],[5,0]],[[5,0],[0,0]],)"
           R"([[20,0],[30,0]],[[30,0],[20,10]]],"targets":[[2.5,1],[2.5,0],[22,2],[2.5,3]]})",
           200);
  EXPECT_EQ(r["results"],
            json::array({result(false, true, 2.5, 1, -1), result(true, true, 2.5, 0, nullptr),
                         result(false, true, 22, 2, 1), result(false, false, 2.5, 3, 0)}));
}

TEST(ContainsRoute, AnEmptyRegionHoldsNothing) {
  EXPECT_EQ(call(R"({"path":"","targets":[[0,0]]})", 200)["results"][0],
            result(false, false, 0, 0, 0));
  EXPECT_EQ(call(R"({"curves":[],"targets":[[0,0]]})", 200)["results"][0],
            result(false, false, 0, 0, 0));
}

TEST(ContainsRoute, Validation) {
  const auto pointers = [](const std::string& body) {
    return test::error_pointers(call(body, 422));
  };
  using V = std::vector<std::string>;
  EXPECT_EQ(pointers(R"({"path":"M0 0 H1 V1 Z"})"), V{"/targets"});
  EXPECT_EQ(pointers(R"({"path":"M0 0 H1 V1 Z","targets":[]})"), V{"/targets"});
  EXPECT_EQ(pointers(R"({"path":"M0 0 H1 V1 Z","targets":[[0,0,0],[1,"x"]]})"),
            (V{"/targets/0", "/targets/1/1"}));
  EXPECT_EQ(pointers(R"({"path":"M0 0 H1 V1 Z","fill_rule":"winding","targets":[[0,0]]})"),
            V{"/fill_rule"});
  EXPECT_EQ(pointers(R"({"path":"M0 0 H1 V1 Z","fill_rule":1,"targets":[[0,0]]})"),
            V{"/fill_rule"});
  EXPECT_EQ(pointers(R"({"targets":[[0,0]]})"), V{"/path"});
  EXPECT_EQ(pointers(R"({"path":"M0 0 H1 V1 Z","curves":[],"targets":[[0,0]]})"), V{""});
  EXPECT_EQ(pointers(R"({"path":"M0 0 X","targets":[[0,0]]})"), V{"/path"});
  EXPECT_EQ(pointers(R"({"path":null,"targets":[[0,0]]})"), V{"/path"});
  EXPECT_EQ(pointers(R"({"curves":null,"targets":[[0,0]]})"), V{"/curves"});
  EXPECT_EQ(pointers(R"({"path":"M0 0 H1 V1 Z","fill_rule":null,"targets":[[0,0]]})"),
            V{"/fill_rule"});
  EXPECT_EQ(pointers(R"({"path":"M0 0 H1 V1 Z","targets":[[0,0]],"point":[1,1]})"), V{"/point"});
  EXPECT_EQ(pointers(R"({"curves":{},"targets":[[0,0]]})"), V{"/curves"});
  EXPECT_EQ(pointers(R"({"curves":[[[0,0],[1,0]],[[1,0]]],"targets":[[0,0]]})"), V{"/curves/1"});
  EXPECT_EQ(pointers(R"({"curves":[[[0,0],[1,0]],[[1,0],["a",1]]],"targets":[[0,0]]})"),
            V{"/curves/1/1/0"});
  // Curve 2 starts neither at the end of curve 1 nor after a closed chain.
  EXPECT_EQ(pointers(R"({"curves":[[[0,0],[1,0]],[[1,0],[1,1]],[[1,2],[0,0]]],"targets":[[0,0]]})"),
            V{"/curves/2/0"});
  // After a closed chain a curve may start anywhere.
  call(R"({"curves":[[[0,0],[1,0],[0,1],[0,0]],[[5,5],[6,5]]],"targets":[[0,0]]})", 200);
}

TEST(ContainsRoute, Limits) {
  Limits small;
  small.max_t_values = 1;
  const Reply many =
      handle("/contains", R"({"path":"M0 0 H1 V1 Z","targets":[[0,0],[1,1]]})", small);
  EXPECT_EQ(many.status, 422);
  EXPECT_TRUE(many.limit_reached);
  small = {};
  small.max_path_segments = 2;
  const Reply segments =
      handle("/contains",
             R"({"curves":[[[0,0],[1,0]],[[1,0],[1,1]],[[1,1],[0,0]]],"targets":[[0,0]]})", small);
  EXPECT_EQ(segments.status, 422);
  EXPECT_TRUE(segments.limit_reached);
  small = {};
  small.max_degree = 3;
  const Reply degree = handle(
      "/contains", R"({"curves":[[[0,0],[1,0],[1,1],[0,1],[0,0]]],"targets":[[0,0]]})", small);
  EXPECT_EQ(degree.status, 422);
  EXPECT_TRUE(degree.limit_reached);
}

TEST(ContainsRoute, WorkCap) {
  // A target on the closing line: both segments' boxes hold it, so both are subdivided in
  // double-double (a cubic piece costs 14 (3 + 1)^2 = 224 units) to show it is on the
  // boundary.
  Limits tight;
  tight.max_work = 100;
  const Reply r =
      handle("/contains", R"({"path":"M0 0 C0 4 4 4 4 0 Z","targets":[[0.1,0]]})", tight);
  EXPECT_EQ(r.status, 422);
  EXPECT_TRUE(r.limit_reached);
  EXPECT_EQ(json::parse(r.body)["type"], "urn:bezier-service:problem:work-cap");
  EXPECT_EQ(call(R"({"path":"M0 0 C0 4 4 4 4 0 Z","targets":[[0.1,0]]})", 200)["results"][0],
            result(true, true, 0.1, 0, nullptr));
}

}  // namespace
}  // namespace bezier::api
