// The epoll engine's inline try (service/inline_policy.hpp): a POST is computed on the
// I/O thread under small limits and computed again on the pool under the full ones only
// when a limit decided the inline answer (api::Reply::limit_reached). Checked here as the
// engine does it (service/event_loop.cpp: InlinePolicy::is_final of the answer under
// InlinePolicy::limits), with api::handle as Router::compute calls it: a plain validation
// error is answered inline, a limit's refusal is not, and wherever a request runs its
// answer is the same.
#include "service/inline_policy.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "api/handler.hpp"
#include "service/router.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::service {
namespace {

/// The answer and the decision of the inline try, and the answer on the pool.
struct Tried {
  Response inline_answer;
  bool final = false;
  Response pool_answer;
};

Tried try_inline(std::string_view path, std::string_view body, const api::Limits& full = {}) {
  Tried t;
  t.inline_answer = to_response(api::handle(path, body, InlinePolicy::limits(full)));
  t.final = InlinePolicy::is_final(t.inline_answer);
  t.pool_answer = to_response(api::handle(path, body, full));
  return t;
}

bool same(const Response& a, const Response& b) {
  return a.status == b.status && a.content_type == b.content_type && a.body == b.body;
}

TEST(InlinePolicy, IsFinalUnlessALimitDecided) {
  Response answer;
  answer.status = 422;
  EXPECT_TRUE(InlinePolicy::is_final(answer));  // a validation error
  answer.limit_reached = true;
  EXPECT_FALSE(InlinePolicy::is_final(answer));
  answer.status = 200;  // an answer the work cap cut short
  EXPECT_FALSE(InlinePolicy::is_final(answer));
  answer.limit_reached = false;
  EXPECT_TRUE(InlinePolicy::is_final(answer));
}

TEST(InlinePolicy, SmallBodiesAreTriedInlineButNeverABatch) {
  EXPECT_TRUE(InlinePolicy::may_try("/classify", InlinePolicy::kMaxBodyBytes));
  EXPECT_FALSE(InlinePolicy::may_try("/classify", InlinePolicy::kMaxBodyBytes + 1));
  // A batch's items are each bounded, their sum only by the batch's own limits.
  EXPECT_FALSE(InlinePolicy::may_try("/batch", 16));
}

TEST(InlinePolicy, LimitsOnlyShrink) {
  const api::Limits full;
  const api::Limits small = InlinePolicy::limits(full);
  EXPECT_EQ(small.max_degree, InlinePolicy::kMaxDegree);
  EXPECT_EQ(small.max_t_values, InlinePolicy::kMaxTValues);
  EXPECT_EQ(small.max_work, full.max_work / InlinePolicy::kWorkDivisor);
  EXPECT_EQ(small.max_body_bytes, full.max_body_bytes);
  api::Limits tiny;
  tiny.max_degree = 3;
  tiny.max_t_values = 5;
  tiny.max_work = 1;
  const api::Limits inline_tiny = InlinePolicy::limits(tiny);
  EXPECT_EQ(inline_tiny.max_degree, 3);
  EXPECT_EQ(inline_tiny.max_t_values, 5);
  EXPECT_EQ(inline_tiny.max_work, 1);
}

TEST(InlinePolicy, ValidationErrorsAreAnsweredInline) {
  for (const auto& [path, body] : std::initializer_list<std::pair<std::string_view, std::string_view>>{
           {"/evaluate", R"({"points":[[0,0],[1,1]],"t":"half"})"},
           {"/evaluate", R"({"points":[[0,0],[1,1]],"t":0,"derivative":1})"},
           {"/evaluate", R"({"points":[[0,0],[1,"y"]],"t":0,"derivatives":1.5})"},
           {"/evaluate", "{}"},
           {"/polar", R"({"points":[[0,0],[1,1]],"t0":[0.1,0.2]})"},
           {"/loop-area", R"({"points":[[0,0],[1,1],[2,0]],"interval":[0.7,0.2]})"},
           {"/classify", R"({"points":[[0,0],[1,1],[2,0]]})"},
           {"/intersections", R"({"curves":[{"points":[[0,0],[1,1]]}],"tolerance":0})"},
           {"/evaluate", R"({"points":[[0,0],[1e308,0]],"t":2})"},  // the result overflows
       }) {
    const Tried t = try_inline(path, body);
    EXPECT_EQ(t.inline_answer.status, 422) << body;
    EXPECT_TRUE(t.final) << body << " -> " << t.inline_answer.body;
    EXPECT_TRUE(same(t.inline_answer, t.pool_answer)) << body;
  }
}

TEST(InlinePolicy, RefusalsByAShrunkLimitRunAgain) {
  std::string t33 = "[0";
  for (int i = 1; i < 33; ++i) {
    t33 += ',';
    t33 += std::to_string(i / 32.0);
  }
  t33 += "]";
  const std::string degree8 = "[[0,0],[1,1],[2,0],[3,1],[4,0],[5,1],[6,0],[7,1],[8,0]]";
  for (const auto& [path, body] : std::initializer_list<std::pair<std::string_view, std::string>>{
           {"/evaluate", "{\"points\":" + degree8 + ",\"t\":0.5}"},
           {"/polar", "{\"points\":" + degree8 + ",\"t0\":0.5}"},
           {"/loop-area", "{\"points\":" + degree8 + "}"},
           {"/intersections", "{\"curves\":[{\"points\":" + degree8 + "}]}"},
           {"/evaluate", R"({"points":[[0,0],[1,1]],"t":)" + t33 + "}"},
           {"/evaluate", R"({"points":[[0,0],[1,1]],"samples":33})"},
           {"/polar", R"({"points":[[0,0],[1,1],[2,0]],"t0":0.5,"samples":33})"},
           {"/evaluate", R"({"points":[[0,0],[1,1]],"t":0,"derivatives":8})"},
           {"/evaluate", R"({"points":[[0,0],[1,1],[2,0]],"samples":11,"derivatives":2})"},
           // Below the range, but the message names it: "an integer in [0, 7]" inline.
           {"/evaluate", R"({"points":[[0,0],[1,1]],"t":0,"derivatives":-1})"},
           {"/evaluate", R"({"points":[[0,0],[1,1]],"samples":0})"},
           // With a validation error too: the full limits read the curve and find more.
           {"/polar", "{\"points\":" + degree8 + ",\"t0\":[0,1,2,3,4,5,6,7,8,9],\"extra\":1}"},
       }) {
    const Tried t = try_inline(path, body);
    EXPECT_FALSE(t.final) << body << " -> " << t.inline_answer.body;
    EXPECT_FALSE(same(t.inline_answer, t.pool_answer)) << body;
  }
}

TEST(InlinePolicy, WorkCapRunsAgain) {
  // The degree-7 loop of tests/api/loop_area_route_test.cpp needs `work` work units: a full
  // cap kWorkDivisor times one unit short of them leaves the inline try short of them.
  const std::string body = R"({"points":[[0,0],[1,1],[2,3],[1,4],[0,4],[-1,3],[0,1],[1,0]]})";
  const std::int64_t work =
      nlohmann::json::parse(api::handle("/loop-area", body, {}).body)["stats"]["work"].get<std::int64_t>();
  api::Limits full;
  full.max_work = InlinePolicy::kWorkDivisor * (work - 1);
  const Tried t = try_inline("/loop-area", body, full);
  EXPECT_EQ(t.inline_answer.status, 422) << t.inline_answer.body;
  EXPECT_FALSE(t.final);
  EXPECT_EQ(t.pool_answer.status, 200) << t.pool_answer.body;
  // A curve within 1e-10 of retracing another, by subdivision (the spec's near-retraced
  // example), exhausts the full cap too: the pool's 422 names it.
  const Tried retrace = try_inline(
      "/intersections",
      R"({"curves":[{"points":[[0,0],[3,6],[6,0]]},{"points":[[0,0],[6,12],[8,-15.9999999996],[6,12],[0,0]]}],"method":"subdivision"})");
  EXPECT_FALSE(retrace.final);
  EXPECT_EQ(retrace.pool_answer.status, 422);
  EXPECT_NE(retrace.pool_answer.body.find("work cap of 22000000 units"), std::string::npos)
      << retrace.pool_answer.body;
}

// Random requests of every route, within and beyond the inline limits (degree up to 9, up
// to 40 t values or samples, derivatives -1 to 9), some with a bad field: whenever the
// inline answer is final it is byte for byte the pool's.
TEST(InlinePolicy, WhereARequestRunsNeverChangesItsAnswer) {
  test::Mulberry32 rng(20240607);
  const auto pick = [&rng](int n) { return static_cast<int>(rng.next() * n); };
  const auto number = [&rng] {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", rng.next());
    return std::string(text);
  };
  const auto points = [&](int degree) {
    std::string s = "[";
    for (int i = 0; i <= degree; ++i) s += (i ? ",[" : "[") + number() + "," + number() + "]";
    return s + "]";
  };
  const auto ts = [&](int count) {
    std::string s = "[";
    for (int i = 0; i < count; ++i) s += (i ? "," : "") + number();
    return s + "]";
  };
  int final_refusals = 0, final_answers = 0, run_again = 0;
  for (int i = 0; i < 4000; ++i) {
    const int degree = 1 + pick(9);
    std::string path, body;
    switch (pick(6)) {
      case 0:
        path = "/evaluate";
        body = "{\"points\":" + points(degree) +
               (pick(2) ? ",\"t\":" + ts(1 + pick(40)) : ",\"samples\":" + std::to_string(pick(41))) +
               (pick(2) ? ",\"derivatives\":" + std::to_string(pick(11) - 1) : "");
        break;
      case 1:
        path = "/polar";
        body = "{\"points\":" + points(degree) + ",\"t0\":" + (pick(2) ? number() : ts(1 + pick(degree + 1))) +
               (pick(2) ? ",\"samples\":" + std::to_string(1 + pick(40)) : "");
        break;
      case 2:
        path = "/loop-area";
        body = "{\"points\":" + points(degree) + (pick(3) == 0 ? ",\"interval\":" + ts(pick(4)) : "");
        break;
      case 3:
        path = "/classify";
        body = "{\"points\":" + points(pick(4) == 0 ? degree : 3);
        break;
      default:
        path = "/intersections";
        body = "{\"curves\":[{\"points\":" + points(degree) + "}" +
               (pick(2) ? ",{\"points\":" + points(1 + pick(9)) + "}" : "") + "]" +
               (pick(3) == 0 ? ",\"method\":\"subdivision\"" : "");
        break;
    }
    // A bad field now and then: a wrong type or an unknown member.
    if (pick(8) == 0) body += pick(2) ? ",\"t\":\"x\"" : ",\"extra\":true";
    body += "}";
    const Tried t = try_inline(path, body);
    if (!t.final) {
      ++run_again;
      continue;
    }
    ++(t.inline_answer.status == 200 ? final_answers : final_refusals);
    EXPECT_TRUE(same(t.inline_answer, t.pool_answer))
        << path << " " << body << "\n inline: " << t.inline_answer.body << "\n pool: " << t.pool_answer.body;
  }
  // Each kind occurs often: the test checks answers given inline, refusals given inline
  // (validation errors) and requests sent to the pool.
  EXPECT_GT(final_answers, 1000);
  EXPECT_GT(final_refusals, 300);
  EXPECT_GT(run_again, 300);
}

}  // namespace
}  // namespace bezier::service
