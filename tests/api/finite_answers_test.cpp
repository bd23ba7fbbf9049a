// Answers whose numbers would not be finite: a result beyond the double range is a 422,
// never a 200 with null in place of a number (JSON has no NaN or infinity).

#include <gtest/gtest.h>

#include <ctime>
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

}  // namespace
}  // namespace bezier::api
