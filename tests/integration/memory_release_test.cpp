// Memory goes back to the system after a burst (service/memory_release.hpp): eight costly
// path requests at once make the service's resident set grow by tens of megabytes (the
// sweep's candidate pairs, freed when each request ends); once they are answered it is
// back near where it was. Read from /proc/<pid>/status (VmRSS, VmHWM).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/integration/costly_request.hpp"
#include "tests/support/raw_http.hpp"
#include "tests/support/service_process.hpp"

namespace bezier::test {
namespace {

// The circle traced 1000 times (costly_request.hpp) against itself.
std::string circle_traced_1000_times() {
  return nlohmann::json{{"curves", {{{"path", circle_traced_1000_times_path()}}}}}.dump();
}

TEST(MemoryRelease, ResidentSetReturnsNearItsLevelAfterABurst) {
#if defined(__SANITIZE_ADDRESS__)
  // AddressSanitizer's allocator replaces glibc's (no malloc_trim) and keeps freed memory
  // in quarantine: resident memory says nothing about the service's release there.
  GTEST_SKIP() << "resident memory under AddressSanitizer is its allocator's";
#endif
  // The per-request memory limit (request_memory_test.cpp) would cap each sweep at a few
  // MiB, leaving a burst too small to tell release from the pool threads' own arenas: it is
  // raised here, so that each request holds what its work cap allows.
  ServiceProcess service({"--threads", "8", "--io-threads", "1", "--max-request-memory", "268435456"});
  const std::string request = post_request("/intersections", circle_traced_1000_times());
  ASSERT_EQ(status_of(round_trip(service.port(), post_request("/evaluate", R"({"points":[[0,0],[1,1]],"t":0.5})"))), 200);
  const std::int64_t before = resident_bytes(service.pid());
  std::vector<std::unique_ptr<Connection>> burst;
  for (int i = 0; i < 8; ++i) {
    burst.push_back(std::make_unique<Connection>(service.port()));
    ASSERT_TRUE(burst.back()->send_all(request));
  }
  for (auto& c : burst) {
    const auto answers = c->responses(1, 120000);
    ASSERT_EQ(answers.size(), 1u);
    EXPECT_EQ(status_of(answers[0]), 422);  // the work cap stops each sweep
  }
  const std::int64_t peak = peak_resident_bytes(service.pid());
  const std::int64_t after = resident_bytes(service.pid());
  // The burst did cost memory (else this test would show nothing)...
  ASSERT_GT(peak - before, std::int64_t{16} << 20) << "peak " << peak << " before " << before;
  // ...and nearly all of it is returned: what stays is under a tenth of the burst's growth
  // (glibc's defaults keep a sixth of it or more, for good).
  EXPECT_LT(after - before, (peak - before) / 10) << "before " << before << " peak " << peak << " after " << after;
}

}  // namespace
}  // namespace bezier::test
