// Tests that refusals say what to do: the nearest known field or route for a misspelt one,
// the routes that take paths for `path` sent to a route of control points, an empty body
// named as such, and the knobs a work-cap problem leaves to the client.

#include <gtest/gtest.h>

#include <array>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "api/handler.hpp"
#include "api/nearest_name.hpp"
#include "tests/support/route_answers.hpp"

namespace bezier::api {
namespace {

using nlohmann::json;

TEST(ErrorAdvice, EditDistanceOfTheClassicExamples) {
  // Levenshtein's textbook pair: kitten -> sitten -> sittin -> sitting.
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("flaw", "lawn"), 2u);
  EXPECT_EQ(edit_distance("Points", "points"), 0u);  // case aside
}

TEST(ErrorAdvice, NearestNameOnlyForLikelyMisspellings) {
  const std::array<std::string_view, 4> names = {"points", "t", "samples", "derivatives"};
  EXPECT_EQ(nearest_name("pionts", names), "points");
  EXPECT_EQ(nearest_name("derivative", names), "derivatives");
  EXPECT_EQ(nearest_name("sample", names), "samples");
  EXPECT_FALSE(nearest_name("x", names));        // one edit from "t", but x is a name of its own
  EXPECT_FALSE(nearest_name("colour", names));
  EXPECT_FALSE(nearest_name(std::string(100, 'p'), names));
}

std::string first_message(const json& problem) { return problem["errors"][0]["message"]; }

TEST(ErrorAdvice, UnknownFieldSuggestsTheNearestKnownOne) {
  const json r = test::route_answer("/classify", R"({"pionts":[[0,0],[1,1],[2,0],[3,1]]})", 422);
  ASSERT_EQ(r["errors"].size(), 2u) << r.dump();  // the typo, and the missing points
  EXPECT_EQ(r["errors"][0]["pointer"], "/pionts");
  EXPECT_EQ(first_message(r), "unknown field (did you mean `points`?)");
  const json far = test::route_answer("/classify", R"({"points":[[0,0],[1,1],[2,0],[3,1]],"colour":1})", 422);
  EXPECT_EQ(first_message(far), "unknown field");
}

TEST(ErrorAdvice, PathOnARouteOfControlPointsNamesTheRoutesThatTakePaths) {
  for (const char* route : {"/evaluate", "/polar", "/classify"}) {
    const json r = test::route_answer(route, R"({"path":"M0 0 L1 1"})", 422);
    EXPECT_EQ(r["errors"][0]["pointer"], "/path") << route;
    const std::string message = first_message(r);
    for (const char* path_route : {"/intersections", "/loop-area", "/length", "/bounds", "/nearest", "/segments"}) {
      EXPECT_NE(message.find(path_route), std::string::npos) << route << ": " << message;
    }
  }
}

TEST(ErrorAdvice, AnEmptyBodySaysItIsEmpty) {
  for (const std::string_view body : {std::string_view(""), std::string_view(" \r\n")}) {
    const Reply reply = handle("/evaluate", body, Limits{});
    EXPECT_EQ(reply.status, 400);
    const json r = json::parse(reply.body);
    EXPECT_EQ(r["detail"].get<std::string>().rfind(body.empty() ? "the body is empty" : "the body is only whitespace", 0), 0u)
        << r.dump();
  }
}

TEST(ErrorAdvice, UnknownRouteSuggestsTheNearestRoute) {
  const json r = test::route_answer("/evalute", R"({"points":[[0,0],[1,1]],"t":0.5})", 404);
  EXPECT_EQ(r["detail"], "no route /evalute (did you mean `/evaluate`?)");
  const json far = test::route_answer("/teapot", "{}", 404);
  EXPECT_EQ(far["detail"], "no route /teapot");
}

TEST(ErrorAdvice, AWorkCapProblemSaysWhatTheClientCanChange) {
  Limits limits;
  limits.max_work = 1;
  const json r = test::route_answer("/length", R"({"path":"M0 0 C1 2 2 2 3 0"})", 422, limits);
  EXPECT_EQ(r["type"], "urn:bezier-service:problem:work-cap");
  const std::string detail = r["detail"];
  for (const char* knob : {"`tolerance`", "`method`", "shorter path", "--max-work"}) {
    EXPECT_NE(detail.find(knob), std::string::npos) << knob << ": " << detail;
  }
}

}  // namespace
}  // namespace bezier::api
