// Memory is a budget like work (issue 28 item 1): the path sweep's candidate pairs, and the
// copy a path's self-intersection search keeps, are charged as they are produced against
// --max-request-memory (api/limits.hpp), and a request that would pass it is refused with
// a memory-cap problem at the path before it stores more. Measured as the growth of the
// service's peak resident set (VmHWM in /proc/<pid>/status) over its level after a small
// request, for the two requests of the issue: 1 200 zero-length segments, and a circle
// traced 1 000 times, each meeting itself everywhere.
#include <cstdint>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "api/limits.hpp"
#include "tests/integration/costly_request.hpp"
#include "tests/support/raw_http.hpp"
#include "tests/support/service_process.hpp"

namespace bezier::test {
namespace {

std::string one_path(const std::string& path) {
  return nlohmann::json{{"curves", {{{"path", path}}}}}.dump();
}

// "M0 0" and 1 200 line segments to (-0, -0): every pair of their boxes meets.
std::string zero_length_segments() {
  std::string path = "M0 0";
  for (int i = 0; i < 1200; ++i) path += "-0-0";
  return one_path(path);
}

// The circle traced 1000 times (costly_request.hpp): every segment meets its 999 copies.
std::string circle_traced_1000_times() { return one_path(circle_traced_1000_times_path()); }

TEST(RequestMemory, APathThatMeetsItselfEverywhereIsRefusedWithinTheMemoryLimit) {
  ServiceProcess service({"--threads", "1", "--io-threads", "1"});
  ASSERT_EQ(status_of(round_trip(service.port(), post_request("/evaluate", R"({"points":[[0,0],[1,1]],"t":0.5})"))), 200);
  const std::int64_t before = peak_resident_bytes(service.pid());
  for (const std::string& body : {zero_length_segments(), circle_traced_1000_times()}) {
    const std::string response = round_trip(service.port(), post_request("/intersections", body));
    ASSERT_EQ(status_of(response), 422) << body_of(response);
    const auto problem = nlohmann::json::parse(body_of(response));
    EXPECT_EQ(problem["type"], "urn:bezier-service:problem:memory-cap");
    ASSERT_EQ(problem["errors"].size(), 1u);
    EXPECT_EQ(problem["errors"][0]["pointer"], "/curves/0");
  }
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "resident memory under AddressSanitizer is its allocator's";
#endif
  // The pairs' vector holds at most the limit; while it grows the old block and the new
  // one (twice the old) are both resident: one and a half times the limit at the most, and
  // the rest of a request (its body, its parsed form, a path of 4 000 segments) is well
  // under a megabyte. Without the limit the sweep stored pairs until the work cap (about
  // 13 MiB for the first request, 24 MiB for the second at their peak).
  const std::int64_t limit = api::Limits{}.max_request_memory;
  const std::int64_t peak = peak_resident_bytes(service.pid());
  EXPECT_LT(peak - before, 2 * limit + (std::int64_t{2} << 20)) << "before " << before << " peak " << peak;
}

TEST(RequestMemory, TheLimitIsAFlag) {
  // Above what the first request's 719 400 pairs take (11.5 MB), the memory limit no longer
  // decides it: zero-length segments add nothing (no intersection), or the work cap stops
  // the sweep first.
  ServiceProcess service({"--max-request-memory", std::to_string(std::int64_t{64} << 20)});
  const std::string response =
      round_trip(service.port(), post_request("/intersections", zero_length_segments()));
  const auto answer = nlohmann::json::parse(body_of(response));
  if (status_of(response) == 200) {
    EXPECT_EQ(answer["intersections"].size(), 0u);
  } else {
    ASSERT_EQ(status_of(response), 422);
    EXPECT_EQ(answer["type"], "urn:bezier-service:problem:work-cap");
  }
}

}  // namespace
}  // namespace bezier::test
