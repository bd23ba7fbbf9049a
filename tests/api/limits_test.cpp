// Reply::limit_reached: set on every answer a limit of Limits decided (a refusal by a
// degree, count or work limit, or a self-intersection left unresolved for want of work
// units), never on a plain validation error or an ordinary answer. The epoll engine
// computes a request again under the full limits exactly when it is set
// (tests/service/inline_policy_test.cpp), so a missing flag would change an answer and a
// spurious one would compute a validation error twice.

#include <gtest/gtest.h>

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "api/handler.hpp"
#include "core/self_intersect/self_intersection.hpp"
#include "core/self_intersect/work_cost.hpp"

namespace bezier::api {
namespace {

constexpr const char* kCubic = R"([[0,0],[1,1],[2,-1],[3,0]])";

std::string with_points(const std::string& points, const std::string& rest = "") {
  return "{\"points\":" + points + rest + "}";
}

struct Case {
  const char* path;
  std::string body;
};

TEST(LimitReached, RefusalsByALimitSaySo) {
  Limits limits;
  limits.max_degree = 3;
  limits.max_t_values = 4;
  const Case cases[] = {
      // A degree above max_degree, on every route that reads a curve.
      {"/evaluate", with_points("[[0,0],[1,1],[2,2],[3,3],[4,4]]", ",\"t\":0")},
      {"/polar", with_points("[[0,0],[1,1],[2,2],[3,3],[4,4]]", ",\"t0\":0.5")},
      {"/loop-area", with_points("[[0,0],[1,1],[2,2],[3,3],[4,4]]")},
      {"/intersections", R"({"curves":[{"points":[[0,0],[1,1],[2,2],[3,3],[4,4]]}]})"},
      // More t values or samples than max_t_values; an interval array that long.
      {"/evaluate", with_points(kCubic, ",\"t\":[0,0.2,0.4,0.6,0.8]")},
      {"/evaluate", with_points(kCubic, ",\"samples\":5")},
      {"/polar", with_points(kCubic, ",\"t0\":0.5,\"samples\":5")},
      {"/polar", with_points(kCubic, ",\"t0\":[0.1,0.2,0.3,0.4,0.5]")},
      {"/loop-area", with_points(kCubic, ",\"interval\":[0,0.1,0.2,0.3,0.4]")},
      // Derivatives above max_degree; t values x (derivatives + 1) above max_t_values.
      {"/evaluate", with_points(kCubic, ",\"t\":0,\"derivatives\":4")},
      {"/evaluate", with_points(kCubic, ",\"t\":[0,1],\"derivatives\":2")},
  };
  for (const Case& c : cases) {
    const Reply reply = handle(c.path, c.body, limits);
    EXPECT_EQ(reply.status, 422) << c.path << " " << c.body << " -> " << reply.body;
    EXPECT_TRUE(reply.limit_reached) << c.path << " " << c.body << " -> " << reply.body;
    // The same requests are answered under the default limits.
    EXPECT_FALSE(handle(c.path, c.body, Limits{}).limit_reached) << c.path << " " << c.body;
  }
  // Below the range of a limit: refused under any limits, but the message names the limit
  // ("an integer in [0, 20]"), so the answer depends on it all the same.
  for (const char* rest : {",\"t\":0,\"derivatives\":-1", ",\"samples\":0"}) {
    const Reply reply = handle("/evaluate", with_points(kCubic, rest), Limits{});
    EXPECT_EQ(reply.status, 422) << reply.body;
    EXPECT_TRUE(reply.limit_reached) << rest;
  }
}

TEST(LimitReached, ValidationErrorsAndAnswersDoNot) {
  const Case cases[] = {
      {"/evaluate", with_points(kCubic, ",\"t\":\"half\"")},
      {"/evaluate", with_points(kCubic, ",\"t\":0,\"derivatives\":1.5")},
      {"/evaluate", with_points("[[0,0]]", ",\"t\":0")},
      {"/evaluate", with_points("[[0,0],[1,1e999]]", ",\"t\":0")},
      {"/evaluate", with_points(kCubic, ",\"t\":0,\"derivative\":1")},
      {"/evaluate", with_points("[[0,0],[1e308,0]]", ",\"t\":2")},  // the result overflows
      {"/polar", with_points("[[0,0],[1,1]]", ",\"t0\":[0.1,0.2]")},
      {"/loop-area", with_points(kCubic, ",\"interval\":[0.7,0.2]")},
      {"/classify", with_points("[[0,0],[1,1],[2,2]]")},
      {"/intersections", R"({"curves":[],"tolerance":0})"},
      {"/intersections", R"({"curves":[{"points":[[0,0],[1,1]]}],"method":"newton"})"},
      {"/evaluate", "{}"},
      {"/evaluate", "not json"},
      {"/evaluate", with_points(kCubic, ",\"t\":[0,0.5,1],\"derivatives\":3")},
      {"/classify", with_points(kCubic)},
      {"/loop-area", with_points(kCubic)},
      {"/intersections", R"({"curves":[{"points":[[0,0],[1,1]]},{"points":[[0,1],[1,0]]}]})"},
  };
  for (const Case& c : cases) {
    const Reply reply = handle(c.path, c.body, Limits{});
    EXPECT_FALSE(reply.limit_reached) << c.path << " " << c.body << " -> " << reply.body;
  }
}

TEST(LimitReached, WithOtherErrorsAndBeyondTheRecordedOnes) {
  Limits limits;
  limits.max_degree = 3;
  // A limit's refusal among validation errors still marks the answer: under the full
  // limits the curve would be read, and its errors or the polar's check would differ.
  EXPECT_TRUE(handle("/polar", R"({"points":[[0,0],[1,1],[2,2],[3,3],[4,4]],"t0":"x","extra":1})", limits)
                  .limit_reached);
  // Only the first 32 errors are listed; a limit's refusal after them still counts.
  std::string body = R"({"points":[)";
  for (int i = 0; i < 20; ++i) body += std::string(i ? "," : "") + "[\"a\",\"b\"]";
  body += R"(],"t":[0,0.25,0.5,0.75,1]})";
  limits = Limits{};
  limits.max_t_values = 4;
  const Reply refused = handle("/evaluate", body, limits);
  ASSERT_EQ(refused.status, 422);
  EXPECT_EQ(refused.body.find("\"/t\""), std::string::npos) << refused.body;  // not listed
  EXPECT_TRUE(refused.limit_reached);
  limits.max_t_values = 5;
  EXPECT_FALSE(handle("/evaluate", body, limits).limit_reached);
}

TEST(LimitReached, WorkCapSaysSo) {
  Limits limits;
  limits.max_work = 5 * core::self_intersection_box_cost(7);
  const std::string degree7 = R"([[0,0],[1,1],[2,3],[1,4],[0,4],[-1,3],[0,1],[1,0]])";
  Reply reply = handle("/loop-area", with_points(degree7), limits);
  EXPECT_EQ(reply.status, 422);
  EXPECT_TRUE(reply.limit_reached);
  reply = handle("/intersections", "{\"curves\":[{\"points\":" + degree7 + "}]}", limits);
  EXPECT_EQ(reply.status, 422);
  EXPECT_TRUE(reply.limit_reached);
  limits.max_work = 10;
  reply = handle("/intersections",
                 R"({"curves":[{"points":[[0,0],[1,2],[2,-1],[3,1]]},{"points":[[0,1],[1,-2],[2,2],[3,0]]}]})",
                 limits);
  EXPECT_EQ(reply.status, 422);
  EXPECT_TRUE(reply.limit_reached);
}

TEST(LimitReached, CertificationCutShortSaysSo) {
  // A degree-6 curve with two self-intersections. The certification searches get what the
  // self-intersection search left of the work cap; with one unit left they cannot certify
  // a pair, and the answer is a 200 with both pairs unresolved. (Under the epoll engine's
  // inline cap, 11 000 units, the same happened to 22 % of random one-curve requests
  // with "method": "subdivision" (degree 1-7, coordinates in [0, 1]) and to 0.1 % by the
  // default method, and that 200 was sent as the answer.)
  const std::string body =
      R"({"curves":[{"points":[[0.8398483560886234,0.28188969613984227],[0.32242265297099948,0.64435609616339207],)"
      R"([0.10673692845739424,0.094773779390379786],[0.69343192339874804,0.98840014287270606],)"
      R"([0.51793862972408533,0.25776530359871686],[0.51596170966513455,0.07079578354023397],)"
      R"([0.77919900021515787,0.42648506630212069]]}],"method":"subdivision"})";
  const Reply full = handle("/intersections", body, Limits{});
  ASSERT_EQ(full.status, 200);
  EXPECT_EQ(full.body.find("\"resolved\":false"), std::string::npos) << full.body;
  EXPECT_FALSE(full.limit_reached);
  // What the search alone charges (the answer's stats.work adds the certification's).
  const nlohmann::json request = nlohmann::json::parse(body);
  std::vector<core::Point2> points;
  for (const auto& p : request["curves"][0]["points"]) points.push_back({p[0].get<double>(), p[1].get<double>()});
  const std::int64_t search = core::self_intersections(core::Curve(points)).stats.work;
  Limits small;
  small.max_work = search + 1;
  const Reply cut = handle("/intersections", body, small);
  ASSERT_EQ(cut.status, 200) << cut.body;
  EXPECT_NE(cut.body.find("\"resolved\":false"), std::string::npos) << cut.body;
  EXPECT_TRUE(cut.limit_reached);
}

}  // namespace
}  // namespace bezier::api
