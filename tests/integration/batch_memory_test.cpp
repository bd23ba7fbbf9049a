// What a batch may cost in memory, read from the service's /proc/<pid>/status: a batch
// whose answers would exceed --max-batch-answer-bytes is refused before its items are
// built, so a 21 KB request cannot make the service hold tens of megabytes.
#include <cstdint>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/batch_body.hpp"
#include "tests/support/raw_http.hpp"
#include "tests/support/service_process.hpp"

namespace bezier::test {
namespace {

// 70 /evaluate items of a degree-20 space curve at 10000 samples each: 21 KB of request,
// about 50 MB of answer if it were built.
std::string large_answer_batch() {
  std::string points = "[";
  for (int i = 0; i <= 20; ++i) points += (i > 0 ? ",[" : "[") + std::to_string(i) + ".125,1.5,-1.25]";
  points += "]";
  return batch_body(std::vector<BatchItem>(70, BatchItem{"/evaluate", R"({"points":)" + points + R"(,"samples":10000})"}));
}

TEST(BatchMemory, ABatchWhoseAnswerExceedsTheCapIsRefusedWithoutBuildingIt) {
  ServiceProcess service({"--threads", "1", "--io-threads", "1"});
  const std::string request = post_request("/batch", large_answer_batch());
  // Settle the allocator with one small request first.
  ASSERT_EQ(status_of(round_trip(service.port(), post_request("/evaluate", R"({"points":[[0,0],[1,1]],"t":0.5})"))), 200);
  const std::int64_t before = resident_bytes(service.pid());
  const std::string answer = round_trip(service.port(), request);
  EXPECT_EQ(status_of(answer), 422) << answer.substr(0, 400);
  const std::int64_t peak = peak_resident_bytes(service.pid());
  ASSERT_GT(before, 0);
#if defined(__SANITIZE_ADDRESS__)
  // AddressSanitizer's shadow memory and quarantine grow resident memory on their own.
  static_cast<void>(peak);
#else
  // The body, its parsed form and a problem: a few megabytes at most. Building the answers
  // would take tens of megabytes; 16 MiB leaves a wide margin either way.
  EXPECT_LT(peak - before, std::int64_t{16} << 20) << "peak " << peak << " before " << before;
#endif
}

}  // namespace
}  // namespace bezier::test
