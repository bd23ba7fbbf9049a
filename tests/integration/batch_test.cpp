// POST /batch against the real binary: each item is, byte for byte, the status and body
// the route answers when that item's body is POSTed to it alone over HTTP; a batch beyond
// a limit is refused whole; the items are counted in /metrics by route and status.
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "api/limits.hpp"
#include "tests/support/batch_body.hpp"
#include "tests/support/raw_http.hpp"
#include "tests/support/service_suite.hpp"

namespace bezier::test {
namespace {

using nlohmann::json;

constexpr int kMaxItems = 40;
constexpr int kMaxBodyBytes = 65536;
constexpr std::int64_t kRoomForSizedItems = 4000000;

class BatchTest : public ServiceSuite<BatchTest> {
 public:
  static std::vector<std::string> service_args() {
    // The batch's work cap admits four items of work-capped routes at the default cap (each
    // charged the whole cap), and a few million units more for the items of the routes
    // bounded by their sizes (api/route_cost.hpp), far less than a fifth such item.
    const api::Limits defaults;
    return {"--max-batch-items", std::to_string(kMaxItems), "--max-body-bytes", std::to_string(kMaxBodyBytes),
            "--max-batch-work", std::to_string(4 * defaults.max_work + kRoomForSizedItems)};
  }
};

struct Answer {
  int status = 0;
  std::string content_type;
  std::string body;
};

Answer post(int port, const std::string& path, const std::string& body) {
  const std::string raw = raw_exchange(port, "POST " + path + " HTTP/1.1\r\nHost: x\r\nConnection: close\r\n" +
                                                 "Content-Type: application/json\r\nContent-Length: " +
                                                 std::to_string(body.size()) + "\r\n\r\n" + body);
  Answer answer;
  if (raw.size() < 12) return answer;
  answer.status = std::stoi(raw.substr(9, 3));
  answer.content_type = header_of(raw, "Content-Type").value;
  const auto end = raw.find("\r\n\r\n");
  if (end != std::string::npos) answer.body = raw.substr(end + 4);
  return answer;
}

using Item = BatchItem;

TEST_F(BatchTest, EveryItemIsTheRoutesHttpAnswerAloneByteForByte) {
  const std::vector<Item> items = {
      {"/classify", R"({"points":[[0,0],[1,1],[0,1],[1,0]]})"},
      {"/classify", R"({"points":[[0,0],[3,4],[1,1],[4,0]]})"},
      {"/classify", R"({"points":[[0,0],[1,"x"],[2,0],[3,1]],"unknown":true})"},
      {"/evaluate", R"({"points":[[0,0],[1,2],[3,3]],"t":[0,0.3,1],"derivatives":2,"frame":true})"},
      {"/evaluate", R"({"points":[[0,0],[1,2],[3,3]]})"},
      {"/polar", R"({"points":[[0,0],[1,2],[3,3],[4,0]],"t0":[0.25,0.5]})"},
      {"/intersections", R"({"curves":[{"points":[[0,0],[1,2],[2,-1],[3,1]]},{"points":[[0,1],[1,-1],[2,2],[3,0]]}]})"},
      {"/loop-area", R"({"points":[[0,0],[1,1],[0,1],[1,0]],"interval":[0.5,0.1]})"},
      {"/length", R"({"points":[[0,0],[1,2],[3,3]],"at_lengths":[1]})"},
      {"/bounds", R"({"points":[[0,0],[1,2],[2,-1],[3,1]],"interval":[0.25,0.75]})"},
      {"/nearest", R"({"points":[[0,0],[1,2],[2,-1],[3,1]],"targets":[[1,1],[3,"y"]]})"},
      {"/classify", "17"},
  };
  std::string expected = R"({"responses":[)";
  for (std::size_t i = 0; i < items.size(); ++i) {
    const Answer alone = post(port(), items[i].path, items[i].body);
    ASSERT_NE(alone.status, 0) << items[i].path;
    if (i > 0) expected += ',';
    expected += R"({"body":)" + alone.body + R"(,"status":)" + std::to_string(alone.status) + '}';
  }
  expected += "]}";
  const Answer batch = post(port(), "/batch", batch_body(items));
  EXPECT_EQ(batch.status, 200);
  EXPECT_EQ(batch.content_type, "application/json");
  EXPECT_EQ(batch.body, expected);
  // The answers include successes and problems of three statuses.
  std::vector<int> statuses;
  const json answer = json::parse(batch.body);
  for (const json& r : answer.at("responses")) statuses.push_back(r.at("status"));
  EXPECT_EQ(statuses, (std::vector<int>{200, 200, 422, 200, 422, 200, 200, 422, 200, 200, 422, 400}));
}

TEST_F(BatchTest, ABatchBeyondALimitIsRefusedWhole) {
  const Item classify{"/classify", R"({"points":[[0,0],[1,1],[0,1],[1,0]]})"};
  EXPECT_EQ(post(port(), "/batch", batch_body(std::vector<Item>(kMaxItems, classify))).status, 200);

  const Answer too_many = post(port(), "/batch", batch_body(std::vector<Item>(kMaxItems + 1, classify)));
  EXPECT_EQ(too_many.status, 422);
  EXPECT_EQ(too_many.content_type, "application/problem+json");
  const json problem = json::parse(too_many.body);
  EXPECT_EQ(problem.at("errors").at(0).at("pointer"), "/requests");

  const Item length{"/length", R"({"points":[[0,0],[3,4]]})"};
  EXPECT_EQ(post(port(), "/batch", batch_body(std::vector<Item>(4, length))).status, 200);
  const Answer too_much_work = post(port(), "/batch", batch_body(std::vector<Item>(5, length)));
  EXPECT_EQ(too_much_work.status, 422);
  EXPECT_EQ(json::parse(too_much_work.body).at("type"), "urn:bezier-service:problem:work-cap");

  // Beyond the body limit: 413 from the HTTP layer, before the body is read.
  const std::string big = batch_body({{"/classify", R"({"points":[[0,0],[1,1],[0,1],[1,0]],"pad":")" +
                                                        std::string(kMaxBodyBytes, 'x') + "\"}"}});
  EXPECT_EQ(post(port(), "/batch", big).status, 413);
}

TEST_F(BatchTest, OnlyPostIsAllowedOnBatch) {
  const std::string raw = raw_exchange(port(), "GET /batch HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n");
  EXPECT_EQ(raw.substr(9, 3), "405");
  EXPECT_EQ(header_of(raw, "Allow").value, "POST");
}

// The value of a sample line "name{labels} value" of the metrics text, 0 when absent.
double sample(const std::string& metrics, const std::string& series) {
  const auto at = metrics.find("\n" + series + " ");
  if (at == std::string::npos) return 0;
  return std::stod(metrics.substr(at + series.size() + 2));
}

TEST_F(BatchTest, ItemsAreCountedByRouteAndStatus) {
  const auto metrics = [] {
    const std::string raw = raw_exchange(port(), "GET /metrics HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n");
    return raw.substr(raw.find("\r\n\r\n") + 3);
  };
  const std::string classify_200 = R"(bezier_batch_items_total{route="/classify",status="200"})";
  const std::string classify_422 = R"(bezier_batch_items_total{route="/classify",status="422"})";
  const std::string bounds_200 = R"(bezier_batch_items_total{route="/bounds",status="200"})";
  const std::string other_404 = R"(bezier_batch_items_total{route="other",status="404"})";
  const std::string batches = R"(bezier_requests_total{route="/batch",status="200"})";
  const std::string before = metrics();
  const std::vector<Item> items = {
      {"/classify", R"({"points":[[0,0],[1,1],[0,1],[1,0]]})"},
      {"/classify", R"({"points":[[0,0],[1,1],[0,1],[1,0]]})"},
      {"/classify", R"({"points":[]})"},
      {"/bounds", R"({"points":[[0,0],[1,1]]})"},
      {"/nowhere", "{}"},
  };
  ASSERT_EQ(post(port(), "/batch", batch_body(items)).status, 200);
  const std::string after = metrics();
  EXPECT_EQ(sample(after, classify_200) - sample(before, classify_200), 2);
  EXPECT_EQ(sample(after, classify_422) - sample(before, classify_422), 1);
  EXPECT_EQ(sample(after, bounds_200) - sample(before, bounds_200), 1);
  EXPECT_EQ(sample(after, other_404) - sample(before, other_404), 1);
  EXPECT_EQ(sample(after, batches) - sample(before, batches), 1);
}

}  // namespace
}  // namespace bezier::test
