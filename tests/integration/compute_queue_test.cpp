// The compute queue has a deadline (--queue-deadline): a request that waited longer for a
// compute thread is answered 503 with Retry-After instead of computed, so a burst of
// costly requests sent and abandoned does not cost their whole CPU time, nor make every
// later request wait for all of them. The 503 comes when the deadline passes, while the
// pool's only thread is still busy with a long request. A request whose connection is gone
// (reset, or closed normally) while it waits is dropped unanswered and uncomputed. Both
// are counted in the metrics. The service's CPU time is read from /proc/<pid>/stat.
#include <chrono>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/integration/costly_request.hpp"
#include "tests/support/raw_http.hpp"
#include "tests/support/service_process.hpp"

namespace bezier::test {
namespace {

constexpr std::string_view kDepth = "bezier_compute_queue_depth";
constexpr std::string_view kInFlight = "bezier_requests_in_flight";

// Sends the costly request on a new connection and waits until a compute thread runs it:
// in flight (it and the metrics request) and not in the queue.
std::unique_ptr<Connection> start_costly_request(int port) {
  auto c = std::make_unique<Connection>(port);
  EXPECT_TRUE(c->send_all(post_request("/intersections", work_cap_bound_intersections())));
  await_metric(port, kInFlight, [](double v) { return v >= 2; });
  await_metric(port, kDepth, [](double v) { return v == 0; });
  return c;
}

TEST(ComputeQueue, RequestsPastTheDeadlineAre503InsteadOfComputed) {
  // One compute thread; a deadline far shorter than one costly request, so every request
  // that queues behind a running one is past it when its turn comes.
  ServiceProcess service({"--threads", "1", "--io-threads", "1", "--queue-deadline", "0.02"});
  const std::string costly = post_request("/intersections", work_cap_bound_intersections());

  // The CPU time of one costly request, alone.
  double before = cpu_seconds(service.pid());
  const std::string alone = round_trip(service.port(), costly);
  ASSERT_EQ(status_of(alone), 422) << alone;
  ASSERT_EQ(nlohmann::json::parse(body_of(alone))["type"], "urn:bezier-service:problem:work-cap");
  const double one_request = cpu_seconds(service.pid()) - before;

  // A burst of them, sent at once as an attacker would: every connection opened first, then
  // the requests written back to back, so that a loaded machine holding this process up
  // between two connects does not spread the burst out.
  constexpr int kBurst = 12;
  std::vector<std::unique_ptr<Connection>> burst;
  for (int i = 0; i < kBurst; ++i) burst.push_back(std::make_unique<Connection>(service.port()));
  before = cpu_seconds(service.pid());
  for (auto& c : burst) ASSERT_TRUE(c->send_all(costly));
  int computed = 0;
  int refused = 0;
  for (auto& c : burst) {
    const auto answers = c->responses(1, 60000);
    ASSERT_EQ(answers.size(), 1u);
    if (status_of(answers[0]) == 422) {
      ++computed;
      continue;
    }
    expect_problem(answers[0], 503);
    EXPECT_TRUE(has_header(answers[0], "Retry-After: 1")) << answers[0];
    EXPECT_EQ(nlohmann::json::parse(body_of(answers[0]))["type"], "urn:bezier-service:problem:overloaded");
    ++refused;
  }
  const double burst_cpu = cpu_seconds(service.pid()) - before;
  // The first is computed; the others wait behind it far longer than the deadline, unless
  // this process was held up between two of its sends for longer than a request takes.
  EXPECT_GE(computed, 1);
  EXPECT_LE(computed, kBurst / 3);
  EXPECT_LT(burst_cpu, kBurst / 2 * one_request)
      << computed << " computed, " << refused << " refused; one request " << one_request << " s of CPU";
  EXPECT_EQ(metric(service.port(), R"(bezier_overload_responses_total{reason="queue_deadline"})"), refused);
  EXPECT_EQ(metric(service.port(), kDepth), 0);

  // A request after the burst is computed as usual.
  EXPECT_EQ(status_of(round_trip(service.port(), post_request("/evaluate", R"({"points":[[0,0],[1,1]],"t":0.5})"))),
            200);
}

TEST(ComputeQueue, RequestOfAResetConnectionIsDroppedUncomputed) {
  // One compute thread, kept busy by a request ten times the default work cap (about a
  // second) while the others queue behind it and their clients reset the connection.
  ServiceProcess service({"--threads", "1", "--io-threads", "1", "--max-work", "220000000"});
  const auto running = start_costly_request(service.port());

  constexpr int kQueued = 3;
  std::vector<std::unique_ptr<Connection>> queued;
  for (int i = 0; i < kQueued; ++i) {
    queued.push_back(std::make_unique<Connection>(service.port()));
    ASSERT_TRUE(queued.back()->send_all(post_request("/intersections", work_cap_bound_intersections())));
  }
  ASSERT_EQ(await_metric(service.port(), kDepth, [](double v) { return v == kQueued; }), kQueued);
  const auto open_fds = [&] { return metric(service.port(), "process_open_fds").value_or(-1); };
  const double fds_before = open_fds();
  for (auto& c : queued) c->reset();
  // The service has seen the resets (their sockets are closed) while the running request
  // still runs: the order this test is about.
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (open_fds() > fds_before - kQueued && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_LE(open_fds(), fds_before - kQueued);
  ASSERT_FALSE(answer_arrived(*running)) << "the running request ended before the resets were seen";

  const auto answers = running->responses(1, 60000);
  ASSERT_EQ(answers.size(), 1u);
  EXPECT_EQ(status_of(answers[0]), 422);
  const double dropped = await_metric(service.port(), "bezier_requests_dropped_total",
                                      [](double v) { return v >= kQueued; });
  EXPECT_EQ(dropped, kQueued);
  // Only the running request was computed, and the gauges are back to rest.
  EXPECT_EQ(metric(service.port(), R"(bezier_requests_total{route="/intersections",status="422"})"), 1);
  EXPECT_EQ(metric(service.port(), "bezier_work_cap_hits_total"), 1);
  EXPECT_EQ(metric(service.port(), kDepth), 0);
  EXPECT_EQ(metric(service.port(), kInFlight), 1);  // the metrics request itself
}

TEST(ComputeQueue, DeadlineHoldsWhileTheOnlyThreadIsBusy) {
  // The only compute thread runs a request fifty times the default work cap (seconds of
  // CPU); the deadline is a tenth of a second. A request queued behind it gets
  // its 503 while that request still runs, not when the thread is free again.
  ServiceProcess service({"--threads", "1", "--io-threads", "1", "--max-work", "1100000000",
                          "--queue-deadline", "0.1"});
  const auto running = start_costly_request(service.port());
  Connection waiting(service.port());
  ASSERT_TRUE(waiting.send_all(post_request("/intersections", work_cap_bound_intersections())));
  const auto answers = waiting.responses(1, 60000);
  ASSERT_EQ(answers.size(), 1u);
  ASSERT_FALSE(answer_arrived(*running)) << "the 503 came only after the running request ended";
  expect_problem(answers[0], 503);
  EXPECT_TRUE(has_header(answers[0], "Retry-After: 1")) << answers[0];
  EXPECT_EQ(metric(service.port(), R"(bezier_overload_responses_total{reason="queue_deadline"})"), 1);
  EXPECT_EQ(metric(service.port(), kDepth), 0);
  running->reset();
}

TEST(ComputeQueue, RequestOfAConnectionClosedNormallyIsDroppedUncomputed) {
  // As for a reset, but the clients close their side normally (FIN) while their requests
  // wait behind a running one: the requests leave the queue at once, unanswered.
  ServiceProcess service({"--threads", "1", "--io-threads", "1", "--max-work", "1100000000"});
  const auto running = start_costly_request(service.port());
  constexpr int kQueued = 3;
  std::vector<std::unique_ptr<Connection>> queued;
  for (int i = 0; i < kQueued; ++i) {
    queued.push_back(std::make_unique<Connection>(service.port()));
    ASSERT_TRUE(queued.back()->send_all(post_request("/intersections", work_cap_bound_intersections())));
  }
  ASSERT_EQ(await_metric(service.port(), kDepth, [](double v) { return v == kQueued; }), kQueued);
  for (auto& c : queued) c->shutdown_write();
  EXPECT_EQ(await_metric(service.port(), "bezier_requests_dropped_total", [](double v) { return v >= kQueued; }),
            kQueued);
  EXPECT_EQ(metric(service.port(), kDepth), 0);
  ASSERT_FALSE(answer_arrived(*running)) << "the running request ended before the closes were seen";
  // Each closed connection ends without an answer.
  for (auto& c : queued) {
    EXPECT_TRUE(c->closed_by_peer(20000));
    EXPECT_TRUE(c->responses(1, 0).empty());
  }
  running->reset();
}

TEST(ComputeQueue, FullQueueIs503AndCounted) {
  ServiceProcess service({"--threads", "1", "--io-threads", "1", "--max-queued-requests", "1",
                          "--max-work", "220000000"});
  const auto running = start_costly_request(service.port());
  Connection waiting(service.port());
  ASSERT_TRUE(waiting.send_all(post_request("/intersections", work_cap_bound_intersections())));
  ASSERT_EQ(await_metric(service.port(), kDepth, [](double v) { return v == 1; }), 1);
  const std::string refused = round_trip(service.port(), post_request("/intersections", work_cap_bound_intersections()));
  ASSERT_FALSE(answer_arrived(*running)) << "the running request ended before the queue was full";
  expect_problem(refused, 503);
  EXPECT_TRUE(has_header(refused, "Retry-After: 1"));
  EXPECT_EQ(metric(service.port(), R"(bezier_overload_responses_total{reason="queue_full"})"), 1);
  EXPECT_EQ(metric(service.port(), R"(bezier_overload_responses_total{reason="queue_deadline"})"), 0);
}

}  // namespace
}  // namespace bezier::test
