// POST /batch (api/batch_route.hpp): each item's status and body are the bytes the route
// answers when the item's body is sent to it alone, and a batch beyond a limit is refused
// whole before any item is computed.

#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "api/handler.hpp"
#include "api/route_table.hpp"
#include "tests/support/batch_body.hpp"

namespace bezier::api {
namespace {

using nlohmann::json;

using Item = test::BatchItem;
using test::batch_body;

// The batch answer built from the answers of the items sent alone, byte for byte.
std::string expected_answer(const std::vector<Item>& items, const Limits& limits) {
  std::string text = R"({"responses":[)";
  for (std::size_t i = 0; i < items.size(); ++i) {
    const Reply alone = handle(items[i].path, items[i].body, limits);
    if (i > 0) text += ',';
    text += R"({"body":)" + alone.body + R"(,"status":)" + std::to_string(alone.status) + '}';
  }
  return text + "]}";
}

// Limits under which the mixed items fit one batch: ten of them are of routes the per-item
// work cap bounds, each charged the whole cap, and the others are charged too.
Limits roomy_batch_work() {
  Limits limits;
  limits.max_batch_work = 100 * limits.max_work;
  return limits;
}

const std::vector<Item>& mixed_items() {
  static const std::vector<Item> items = {
      {"/classify", R"({"points":[[0,0],[1,1],[0,1],[1,0]]})"},
      {"/classify", R"({"points":[[0,0],[1,"x"],[2,0],[3,1]]})"},
      {"/classify", R"({"points":[[0,0],[1,1],[2,0]]})"},
      {"/evaluate", R"({"points":[[0,0],[1,2],[3,3]],"t":[0,0.25,1],"derivatives":1})"},
      {"/evaluate", R"({"points":[[0,0],[1,2],[3,3]],"samples":0})"},
      {"/polar", R"({"points":[[0,0],[1,2],[3,3],[4,0]],"t0":0.5,"t":[0,1]})"},
      {"/intersections", R"({"curves":[{"points":[[0,0],[1,2],[2,-1],[3,1]]},{"points":[[0,1],[1,-1],[2,2],[3,0]]}]})"},
      {"/intersections", R"({"curves":[{"points":[[0,0],[1,1],[0,1],[1,0]]}]})"},
      {"/intersections", R"({"curves":[{"points":[[0,0],[1,1]]}],"method":"newton"})"},
      {"/loop-area", R"({"points":[[0,0],[1,1],[0,1],[1,0]]})"},
      {"/length", R"({"points":[[0,0],[3,4]],"at_lengths":[2.5]})"},
      {"/length", R"({"points":[[0,0],[3,4]],"at_lengths":[6]})"},
      {"/bounds", R"({"points":[[0,0],[1,2],[2,-1],[3,1]]})"},
      {"/nearest", R"({"points":[[0,0],[1,2],[2,-1],[3,1]],"targets":[[1,1],[2,0]]})"},
      {"/nearest", R"({"points":[[0,0],[1,2]],"targets":[]})"},
      {"/contains", R"({"path":"M0 0 H4 V4 H0 Z","fill_rule":"evenodd","targets":[[1,1],[4,2],[5,5]]})"},
      {"/contains", R"({"curves":[[[0,0],[1,0]]],"fill_rule":"odd","targets":[[0,0]]})"},
      // Bodies that are not objects get the route's 400.
      {"/classify", "[1,2]"},
      {"/bounds", "null"},
      {"/evaluate", R"("points")"},
      // Numbers beyond the double range and duplicate keys read as the route reads them.
      {"/classify", R"({"points":[[0,0],[1,1e999],[0,1],[1,0]]})"},
      {"/classify", R"({"points":[[9,9]],"points":[[0,0],[1,1],[0,1],[1,0]]})"},
  };
  return items;
}

TEST(Batch, EveryItemIsTheRoutesAnswerAloneByteForByte) {
  const Limits limits = roomy_batch_work();
  const std::vector<Item>& items = mixed_items();
  const Reply batch = handle("/batch", batch_body(items), limits);
  ASSERT_EQ(batch.status, 200) << batch.body;
  EXPECT_EQ(batch.content_type, "application/json");
  EXPECT_EQ(batch.body, expected_answer(items, limits));
  // The cases cover what they mean to: answers and problems of several kinds.
  const json answer = json::parse(batch.body);
  ASSERT_EQ(answer.at("responses").size(), items.size());
  std::vector<int> statuses;
  for (const json& r : answer.at("responses")) statuses.push_back(r.at("status").get<int>());
  EXPECT_EQ(statuses, (std::vector<int>{200, 422, 422, 200, 422, 200, 200, 200, 422, 200, 200, 422, 200, 200, 422,
                                        200, 422, 400, 400, 400, 422, 200}));
}

TEST(Batch, AFailedItemsPointersPointIntoItsOwnBody) {
  const std::vector<Item> items = {
      {"/classify", R"({"points":[[0,0],[1,1],[0,1],[1,0]]})"},
      {"/classify", R"({"points":[[0,0],[1,"x"],[2,0],[3,1]],"extra":1})"},
  };
  const json answer = json::parse(handle("/batch", batch_body(items), Limits{}).body);
  const json& problem = answer.at("responses").at(1).at("body");
  std::vector<std::string> pointers;
  for (const json& e : problem.at("errors")) pointers.push_back(e.at("pointer"));
  std::sort(pointers.begin(), pointers.end());
  EXPECT_EQ(pointers, (std::vector<std::string>{"/extra", "/points/1/1"}));
}

TEST(Batch, AnItemUnderThePerItemWorkCapIsItsAnswerAlone) {
  // Two degree-9 curves close to each other: their search needs more than 1000 units.
  Limits limits;
  limits.max_work = 1000;
  const Item heavy{"/intersections",
                   R"({"curves":[{"points":[[0,0],[1,3],[2,-3],[3,3],[4,-3],[5,3],[6,-3],[7,3],[8,-3],[9,0]]},)"
                   R"({"points":[[0,0.1],[1,-3],[2,3],[3,-3],[4,3],[5,-3],[6,3],[7,-3],[8,3],[9,0.1]]}]})"};
  const Reply alone = handle(heavy.path, heavy.body, limits);
  ASSERT_EQ(alone.status, 422) << alone.body;
  ASSERT_NE(alone.body.find("work-cap"), std::string::npos) << alone.body;
  const std::vector<Item> items = {heavy, {"/classify", R"({"points":[[0,0],[1,1],[0,1],[1,0]]})"}};
  const Reply batch = handle("/batch", batch_body(items), limits);
  EXPECT_EQ(batch.status, 200);
  EXPECT_EQ(batch.body, expected_answer(items, limits));
  EXPECT_TRUE(batch.limit_reached);  // the cap decided an item's answer
}

TEST(Batch, PathsThatAreNotComputeRoutesAre404ItemsAndTheOthersAreAnswered) {
  const std::vector<Item> items = {
      {"/nowhere", "{}"},
      {"/batch", R"({"requests":[]})"},
      {"/healthz", "{}"},
      {"/classify?x=1", R"({"points":[[0,0],[1,1],[0,1],[1,0]]})"},
      {"/classify", R"({"points":[[0,0],[1,1],[0,1],[1,0]]})"},
  };
  const json answer = json::parse(handle("/batch", batch_body(items), Limits{}).body);
  const json& responses = answer.at("responses");
  ASSERT_EQ(responses.size(), items.size());
  for (std::size_t i = 0; i + 1 < items.size(); ++i) {
    EXPECT_EQ(responses[i].at("status"), 404) << items[i].path;
    EXPECT_EQ(responses[i].at("body").at("type"), "urn:bezier-service:problem:not-found");
    EXPECT_NE(responses[i].at("body").at("detail").get<std::string>().find(items[i].path), std::string::npos);
  }
  EXPECT_EQ(responses.back().at("status"), 200);
  EXPECT_EQ(responses.back().at("body"), json::parse(handle("/classify", items.back().body, Limits{}).body));
}

TEST(Batch, AnEmptyBatchIsAnEmptyAnswer) {
  const Reply reply = handle("/batch", R"({"requests":[]})", Limits{});
  EXPECT_EQ(reply.status, 200);
  EXPECT_EQ(reply.body, R"({"responses":[]})");
}

// What the observer saw: (path, status) of each computed item.
struct Seen {
  std::vector<std::pair<std::string, int>> items;
  BatchItemObserver observer() {
    return [this](std::string_view path, const Reply& reply) { items.emplace_back(std::string(path), reply.status); };
  }
};

TEST(Batch, TheObserverSeesEveryItemInOrder) {
  const std::vector<Item>& items = mixed_items();
  Seen seen;
  const Reply batch = handle("/batch", batch_body(items), roomy_batch_work(), seen.observer());
  ASSERT_EQ(batch.status, 200);
  ASSERT_EQ(seen.items.size(), items.size());
  const json answer = json::parse(batch.body);
  for (std::size_t i = 0; i < items.size(); ++i) {
    EXPECT_EQ(seen.items[i].first, items[i].path);
    EXPECT_EQ(seen.items[i].second, answer.at("responses")[i].at("status"));
  }
}

std::vector<std::string> pointers_of(const Reply& reply) {
  std::vector<std::string> pointers;
  for (const json& e : json::parse(reply.body).value("errors", json::array())) pointers.push_back(e.at("pointer"));
  return pointers;
}

std::vector<Item> classify_items(std::size_t n) {
  return std::vector<Item>(n, Item{"/classify", R"({"points":[[0,0],[1,1],[0,1],[1,0]]})"});
}

TEST(BatchLimits, MoreItemsThanTheLimitAreRefusedWholeBeforeAnyWork) {
  Limits limits;
  limits.max_batch_items = 5;
  Seen seen;
  EXPECT_EQ(handle("/batch", batch_body(classify_items(5)), limits, seen.observer()).status, 200);
  EXPECT_EQ(seen.items.size(), 5u);
  seen.items.clear();
  const Reply refused = handle("/batch", batch_body(classify_items(6)), limits, seen.observer());
  EXPECT_EQ(refused.status, 422);
  EXPECT_EQ(refused.content_type, "application/problem+json");
  EXPECT_TRUE(refused.limit_reached);
  EXPECT_EQ(pointers_of(refused), std::vector<std::string>{"/requests"});
  EXPECT_NE(refused.body.find("at most 5 items"), std::string::npos) << refused.body;
  EXPECT_TRUE(seen.items.empty());
}

// What the batch charges an item: its route's cost model (api/route_table.hpp).
std::int64_t charge(const Item& item, const Limits& limits) {
  return find_compute_route(item.path)->work_bound(json::parse(item.body), limits);
}

TEST(BatchLimits, TheBatchWorkCapChargesEveryItemItsRoutesCostModel) {
  Limits limits;
  limits.max_work = 100000;
  const Item pair{"/intersections", R"({"curves":[{"points":[[0,0],[1,2],[2,-1],[3,1]]},{"points":[[0,1],[3,0]]}]})"};
  const Item length{"/length", R"({"points":[[0,0],[3,4]]})"};
  std::vector<Item> items = classify_items(5);
  items.push_back(pair);
  items.push_back(length);
  items.push_back(pair);
  items.push_back({"/evaluate", R"({"points":[[0,0],[1,1]],"t":0.5})"});
  items.push_back({"/bounds", R"({"points":[[0,0],[1,1]]})"});
  items.push_back({"/polar", R"({"points":[[0,0],[1,1]],"t0":0.5})"});
  items.push_back({"/segments", R"({"path":"M0 0 L1 1"})"});
  std::int64_t total = 0;
  for (const Item& item : items) {
    EXPECT_GT(charge(item, limits), 0) << item.path;
    total += charge(item, limits);
  }
  // An item of a route the per-item cap bounds is charged that cap: the most it may spend.
  EXPECT_EQ(charge(pair, limits), limits.max_work);
  EXPECT_EQ(charge(length, limits), limits.max_work);
  // Charges that add up to the batch's cap fit.
  limits.max_batch_work = total;
  Seen seen;
  const Reply fits = handle("/batch", batch_body(items), limits, seen.observer());
  EXPECT_EQ(fits.status, 200);
  EXPECT_EQ(fits.body, expected_answer(items, limits));
  // One unit less, and the batch is refused whole, before any item is computed.
  limits.max_batch_work = total - 1;
  seen.items.clear();
  const Reply refused = handle("/batch", batch_body(items), limits, seen.observer());
  EXPECT_EQ(refused.status, 422);
  EXPECT_NE(refused.body.find("\"urn:bezier-service:problem:work-cap\""), std::string::npos) << refused.body;
  EXPECT_TRUE(refused.limit_reached);
  EXPECT_TRUE(pointers_of(refused).empty());
  EXPECT_NE(refused.body.find("up to " + std::to_string(total) + " work units"), std::string::npos) << refused.body;
  EXPECT_TRUE(seen.items.empty());
}

// Items cheap one by one but large (what the per-item limits admit) add up: charged by their
// sizes, not only by the per-item work cap, so a batch of them is refused at the defaults.
TEST(BatchLimits, ItemsOfRoutesBoundedByTheirSizesAreChargedByTheirSizes) {
  const Limits defaults;
  std::string points = "[";
  for (int i = 0; i <= 20; ++i) points += (i > 0 ? ",[" : "[") + std::to_string(i) + ",1]";
  points += "]";
  const Item one_t{"/evaluate", R"({"points":)" + points + R"(,"t":0.5})"};
  const Item all_t{"/evaluate", R"({"points":)" + points + R"(,"samples":10000})"};
  const Item all_t_derivatives{"/evaluate", R"({"points":)" + points + R"(,"samples":500,"derivatives":19})"};
  // More t values, more derivatives, a frame, a higher degree: each costs more.
  EXPECT_LT(charge(one_t, defaults), charge(all_t, defaults));
  EXPECT_LT(charge({"/evaluate", R"({"points":[[0,0],[1,1]],"samples":10000})"}, defaults), charge(all_t, defaults));
  EXPECT_LT(charge(all_t, defaults),
            charge({"/evaluate", R"({"points":)" + points + R"(,"samples":10000,"frame":true})"}, defaults));
  EXPECT_LT(charge({"/evaluate", R"({"points":)" + points + R"(,"samples":500})"}, defaults),
            charge(all_t_derivatives, defaults));
  // The route refuses more t values than the limit before computing any: charged at the limit.
  EXPECT_EQ(charge({"/evaluate", R"({"points":)" + points + R"(,"samples":1e9})"}, defaults), charge(all_t, defaults));
  EXPECT_LT(charge({"/segments", R"({"path":"M0 0 L1 1"})"}, defaults),
            charge({"/segments", R"({"path":"M0 0 L1 1 2 2 3 3 4 4"})"}, defaults));
  EXPECT_EQ(charge({"/segments", R"({"path":"M0 0 A1 1 0 0 1 2 0"})"}, defaults),
            charge({"/segments", R"({"path":")" + std::string(defaults.max_path_segments, 'L') + R"("})"}, defaults));
  // With room for their answers, as many as their charges fit are computed, one more is
  // refused by its work alone, before any item runs.
  const std::size_t fit = static_cast<std::size_t>(defaults.max_batch_work / charge(all_t_derivatives, defaults));
  ASSERT_GE(fit, 1u);
  ASSERT_LT(fit, 100u);
  Limits roomy_answers = defaults;
  roomy_answers.max_batch_answer_bytes = std::size_t{1} << 32;
  EXPECT_EQ(handle("/batch", batch_body(std::vector<Item>(fit, all_t_derivatives)), roomy_answers).status, 200);
  Seen seen;
  const Reply refused =
      handle("/batch", batch_body(std::vector<Item>(fit + 1, all_t_derivatives)), roomy_answers, seen.observer());
  EXPECT_EQ(refused.status, 422);
  EXPECT_NE(refused.body.find("work-cap"), std::string::npos) << refused.body;
  EXPECT_TRUE(seen.items.empty());
}

TEST(BatchLimits, AnswersBeyondTheBatchAnswerCapRefuseTheBatchAtTheItemThatCrossesIt) {
  const std::vector<Item> items = classify_items(10);
  const Limits defaults;
  const std::string whole = expected_answer(items, defaults);
  // The answer of k items: "{"responses":[", k entries and k - 1 commas, then "]}".
  const std::string item_text = R"({"body":)" + handle("/classify", items[0].body, defaults).body + R"(,"status":200})";
  const std::size_t prefix = std::string(R"({"responses":[)").size();
  ASSERT_EQ(whole.size(), prefix + 10 * item_text.size() + 9 + 2);
  Limits limits;
  // Room for exactly 6 items: the seventh crosses the cap.
  limits.max_batch_answer_bytes = prefix + 6 * item_text.size() + 5 + 2;
  const Reply refused = handle("/batch", batch_body(items), limits);
  EXPECT_EQ(refused.status, 422);
  EXPECT_TRUE(refused.limit_reached);
  EXPECT_EQ(pointers_of(refused), std::vector<std::string>{"/requests/6"});
  limits.max_batch_answer_bytes = whole.size();
  EXPECT_EQ(handle("/batch", batch_body(items), limits).body, whole);
}

// 70 items of a degree-20 space curve at 10000 samples: a 21 KB request whose answer is
// tens of megabytes. Each result takes at least {"point":[x,y,z],"t":t} (23 bytes), so the
// items' answers certainly exceed the default cap, and the batch is refused before any item
// is built, at the item where those least sizes cross it.
TEST(BatchLimits, AnswersThatCertainlyExceedTheCapAreRefusedBeforeAnyItemIsComputed) {
  std::string points = "[";
  for (int i = 0; i <= 20; ++i) points += (i > 0 ? ",[" : "[") + std::to_string(i) + ",1,-1]";
  points += "]";
  const std::vector<Item> items(70, Item{"/evaluate", R"({"points":)" + points + R"(,"samples":10000})"});
  const Limits defaults;
  // The batch's work cap, which refuses these items first at the defaults, set aside.
  Limits roomy_work = defaults;
  roomy_work.max_batch_work = std::int64_t{1} << 50;
  EXPECT_NE(handle("/batch", batch_body(items), defaults).body.find("work-cap"), std::string::npos);
  Seen seen;
  const Reply refused = handle("/batch", batch_body(items), roomy_work, seen.observer());
  EXPECT_EQ(refused.status, 422);
  EXPECT_TRUE(refused.limit_reached);
  EXPECT_TRUE(seen.items.empty());
  const std::size_t least = 10000 * (17 + 2 * 3);
  const std::size_t crossing = defaults.max_batch_answer_bytes / least;  // items 0..crossing
  EXPECT_EQ(pointers_of(refused), std::vector<std::string>{"/requests/" + std::to_string(crossing)});
  // As many as fit by that bound are computed, and the real answer decides.
  Limits roomy;
  roomy.max_batch_answer_bytes = std::size_t{1} << 30;
  const std::vector<Item> two(items.begin(), items.begin() + 2);
  EXPECT_EQ(handle("/batch", batch_body(two), defaults).body, expected_answer(two, roomy));
  // A body the route refuses is not counted: its answer is a short problem.
  const std::vector<Item> refused_items(70, Item{"/evaluate", R"({"points":)" + points + R"(,"samples":10000,"x":1})"});
  EXPECT_EQ(handle("/batch", batch_body(refused_items), roomy_work).status, 200);
}

// The cap is on the whole answer, its closing "]}" included: an answer one or two bytes
// longer than the cap is refused at its last item, not sent.
TEST(BatchLimits, AnAnswerLongerThanTheCapByItsClosingBytesIsRefusedAtItsLastItem) {
  const std::vector<Item> items = classify_items(3);
  const std::string whole = expected_answer(items, Limits{});
  Limits limits;
  limits.max_batch_answer_bytes = whole.size();
  const Reply sent = handle("/batch", batch_body(items), limits);
  EXPECT_EQ(sent.status, 200);
  EXPECT_EQ(sent.body, whole);
  for (const std::size_t shorter : {1, 2}) {
    limits.max_batch_answer_bytes = whole.size() - shorter;
    const Reply refused = handle("/batch", batch_body(items), limits);
    EXPECT_EQ(refused.status, 422) << shorter;
    EXPECT_TRUE(refused.limit_reached);
    EXPECT_EQ(pointers_of(refused), std::vector<std::string>{"/requests/2"}) << shorter;
    EXPECT_NE(refused.body.find("take " + std::to_string(whole.size()) + " bytes"), std::string::npos) << refused.body;
  }
}

TEST(BatchLimits, AMalformedBatchIsRefusedWholeWithPointersIntoIt) {
  Seen seen;
  const std::string body =
      R"({"requests":[{"path":"/classify","body":{"points":[[0,0],[1,1],[0,1],[1,0]]}},)"
      R"(7,{"body":{}},{"path":3,"body":{}},{"path":"/classify"},{"path":"/classify","body":{},"method":"POST"}],)"
      R"("extra":true})";
  const Reply refused = handle("/batch", body, Limits{}, seen.observer());
  EXPECT_EQ(refused.status, 422);
  EXPECT_FALSE(refused.limit_reached);
  std::vector<std::string> pointers = pointers_of(refused);
  std::sort(pointers.begin(), pointers.end());
  EXPECT_EQ(pointers, (std::vector<std::string>{"/extra", "/requests/1", "/requests/2/path", "/requests/3/path",
                                                "/requests/4/body", "/requests/5/method"}));
  EXPECT_TRUE(seen.items.empty());

  EXPECT_EQ(pointers_of(handle("/batch", "{}", Limits{})), std::vector<std::string>{"/requests"});
  EXPECT_EQ(pointers_of(handle("/batch", R"({"requests":{}})", Limits{})), std::vector<std::string>{"/requests"});
  EXPECT_EQ(handle("/batch", "[]", Limits{}).status, 400);
  EXPECT_EQ(handle("/batch", R"({"requests":[)", Limits{}).status, 400);
}

TEST(BatchRoutes, ItemRoutesAreThePostRoutesButBatch) {
  const auto post = post_routes();
  const auto items = batch_item_routes();
  ASSERT_EQ(items.size() + 1, post.size());
  for (std::size_t i = 0; i < items.size(); ++i) EXPECT_EQ(items[i], post[i]);
  EXPECT_EQ(post.back(), "/batch");
  EXPECT_TRUE(is_post_route("/batch"));
}

}  // namespace
}  // namespace bezier::api
