// Answers whose numbers would not be finite: a result beyond the double range is a 422,
// never a 200 with null in place of a number (JSON has no NaN or infinity).

#include <gtest/gtest.h>

#include <cmath>
#include <ctime>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "api/handler.hpp"

namespace bezier::api {
namespace {

using nlohmann::json;

// Whether a null sits inside an array of `value`: where nlohmann writes a NaN or an
// infinity (JSON has neither). No 200 answer documents a null inside an array.
bool has_null_in_array(const json& value, bool in_array = false) {
  if (value.is_null()) return in_array;
  if (value.is_array()) {
    for (const auto& e : value) {
      if (has_null_in_array(e, true)) return true;
    }
  } else if (value.is_object()) {
    for (const auto& [key, member] : value.items()) {
      if (has_null_in_array(member, false)) return true;
    }
  }
  return false;
}

// A result that overflows the double range must not be answered as a 200 with null in
// place of the number: either every number of the answer is finite, or the request gets
// a problem (422, like any other input whose answer cannot be computed).
void expect_no_overflowed_number(const std::string& path, const std::string& body) {
  const Reply reply = handle(path, body, Limits{});
  const json answer = json::parse(reply.body);
  if (reply.status == 200) {
    EXPECT_FALSE(has_null_in_array(answer)) << path << " " << body << "\n -> " << reply.body;
    for (const char* key : {"area", "signed_area"}) {
      if (answer.contains(key)) {
        EXPECT_TRUE(answer[key].is_number()) << path << " " << body << "\n -> " << reply.body;
      }
    }
  } else {
    EXPECT_EQ(reply.status, 422) << reply.body;
    EXPECT_EQ(reply.content_type, "application/problem+json");
  }
}

// Finite input, non-finite result. The exact
// results here are 2e308 (B(2) of the segment 0 -> 1e308), 2e308 (B' of -1e308 -> 1e308),
// 2e308 (the first polar at t0 = 2) and about 1e400 (the area of a loop 1e200 wide), all
// beyond the largest double (about 1.8e308).
TEST(FiniteAnswers, OverflowingEvaluationIsNotWrittenAsNull) {
  expect_no_overflowed_number("/evaluate", R"({"points":[[0,0],[1e308,0]],"t":2})");
}

TEST(FiniteAnswers, OverflowingDerivativeIsNotWrittenAsNull) {
  expect_no_overflowed_number("/evaluate",
                              R"({"points":[[-1e308,0],[1e308,0]],"t":0.5,"derivatives":1})");
}

TEST(FiniteAnswers, OverflowingPolarIsNotWrittenAsNull) {
  expect_no_overflowed_number("/polar", R"({"points":[[0,0],[1e308,0]],"t0":2})");
}

TEST(FiniteAnswers, OverflowingIntervalAreaIsNotWrittenAsNull) {
  expect_no_overflowed_number(
      "/loop-area", R"({"points":[[0,0],[1e200,1e200],[0,1e200],[1e200,0]],"interval":[0,1]})");
}

// Subnormal segments through the API: a NaN point would be written as null (or turn a
// valid request into a 422); the answer is the intersection at the origin.
TEST(FiniteAnswers, SubnormalSegmentsThroughTheApi) {
  const Reply reply = handle(
      "/intersections",
      R"({"curves":[{"points":[[1e-310,0],[0,0]]},{"points":[[0,0],[0,1e-310]]}]})", Limits{});
  ASSERT_EQ(reply.status, 200) << reply.body;
  const auto answer = nlohmann::json::parse(reply.body);
  ASSERT_EQ(answer["intersections"].size(), 1u) << reply.body;
  EXPECT_EQ(answer["intersections"][0]["point"], nlohmann::json::parse("[0.0, 0.0]")) << reply.body;
}

// Subnormal coordinates are ordinary input with representable answers: the measuring
// kernels scale the curve by a power of two (beyond 2^1023 for a subnormal largest
// coordinate) and the answers come back in the subnormal range.
TEST(FiniteAnswers, NearestOnASubnormalSegment) {
  const Reply reply = handle("/nearest", R"({"points":[[0,0],[1e-320,1e-320]],"targets":[[0,0],[1e-320,0]]})",
                             Limits{});
  ASSERT_EQ(reply.status, 200) << reply.body;
  const json answer = json::parse(reply.body);
  const double d = 1e-320;  // the segment from 0 to (d, d)
  const double ulp = std::numeric_limits<double>::denorm_min();
  // The origin is the segment's start.
  EXPECT_EQ(answer["results"][0]["t"], 0.0);
  EXPECT_EQ(answer["results"][0]["distance"], 0.0);
  EXPECT_EQ(answer["results"][0]["point"], json::parse("[0.0, 0.0]"));
  // (d, 0) projects onto the segment's midpoint (d/2, d/2), at distance d / sqrt(2).
  const json& far = answer["results"][1];
  EXPECT_NEAR(far["t"].get<double>(), 0.5, 1e-12) << reply.body;
  EXPECT_NEAR(far["point"][0].get<double>(), d / 2, ulp) << reply.body;
  EXPECT_NEAR(far["point"][1].get<double>(), d / 2, ulp) << reply.body;
  EXPECT_NEAR(far["distance"].get<double>(), d / std::sqrt(2.0), 2 * ulp) << reply.body;
}

TEST(FiniteAnswers, BoundsOfASubnormalPath) {
  // The quadratic (0,0), (x1, y1), (x2, 0): x rises from 0 to x2 (x1 < x2 and 2 x1 > 0), y
  // peaks at t = 1/2 at y1 / 2. Each face is the exact extreme or outside it by at most a
  // few ulps (here the smallest subnormal).
  const double x2 = 2e-310, y1 = 2e-310;
  const double ulp = std::numeric_limits<double>::denorm_min();
  for (const std::string body : {R"({"path":"M0 0 Q1e-310 2e-310 2e-310 0"})",
                                 R"({"points":[[0,0],[1e-310,2e-310],[2e-310,0]]})"}) {
    const Reply reply = handle("/bounds", body, Limits{});
    ASSERT_EQ(reply.status, 200) << body << " -> " << reply.body;
    const json answer = json::parse(reply.body);
    EXPECT_EQ(answer["min"], json::parse("[0.0, 0.0]")) << reply.body;
    EXPECT_EQ(answer["max"][0].get<double>(), x2) << reply.body;
    const double top = answer["max"][1].get<double>();
    EXPECT_GE(2 * top, y1) << reply.body;  // doubling a subnormal is exact
    EXPECT_LE(top, y1 / 2 + 4 * ulp) << reply.body;
  }
}

// A path request whose answer overflows: the problem is about the answer, and points at no
// request field (the request has no "points").
TEST(FiniteAnswers, OverflowOfAPathAnswerNamesTheAnswerField) {
  const Reply reply = handle("/length", R"({"path":"M-1.7e308 0 L1.7e308 0"})", Limits{});
  ASSERT_EQ(reply.status, 422) << reply.body;
  const json answer = json::parse(reply.body);
  EXPECT_EQ(answer["type"], "urn:bezier-service:problem:result-overflow") << reply.body;
  EXPECT_EQ(answer["title"], "The answer overflows the double range");
  EXPECT_FALSE(answer.contains("errors")) << reply.body;
  EXPECT_NE(answer["detail"].get<std::string>().find("(answer field '/"), std::string::npos) << reply.body;
}

}  // namespace
}  // namespace bezier::api
