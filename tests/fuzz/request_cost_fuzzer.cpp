// libFuzzer target: what a request may cost is bounded by its budget, for every POST route
// and for batches of them. Each input is one request; its CPU time (CLOCK_THREAD_CPUTIME_ID
// around api::handle) and its peak heap (the most bytes it held at once through operator
// new, beyond what was held before it) must stay below fixed multiples of what its budget
// allows, whatever the body.
//
// Input: byte 0 picks the route (0: /batch; k: the k-th compute route of
// api/route_table.hpp, modulo their number), byte 1 the work cap (Limits::max_work: the API
// default 22 000 000 units, or a tenth, a hundredth, a thousandth of it; the batch's cap ten
// times it, as the defaults are); the rest is the body as the service would pass it on.
//
// The budget of a request, in work units, is its route's cost model (api/route_cost.hpp:
// the per-request work cap for the routes whose kernels charge it, the sizes of the request
// for the others); a batch's is what it charges its items, at most its own cap. An input
// fails when
//   cpu  > kCpuMultiple * unit * (budget + kFixedUnits + kUnitsPerBodyByte * body bytes)
//   heap > kHeapMultiple * (kBytesPerUnit * budget + kBytesPerBodyByte * body bytes
//                           + answer bytes + kFixedBytes)
// where unit is the CPU time of a work unit measured at start-up (unit_cpu_time.hpp). The
// body's terms stand for parsing it (the parsed form of a JSON number or bracket is a JSON
// value, a few tens of bytes), the fixed ones for what every request costs whatever its
// budget (the phases bounded by the degrees, a first execution's page faults); the answer
// is what the route returns (the batch's answer cap bounds a batch's). A path whose CPU time
// or memory the budget does not bound exceeds them by orders of magnitude.
// Also checked: no 500.
//
// Build it without sanitizers, as work_bound_fuzzer (docs/FUZZING.md): ASan slows
// allocation-heavy code much more than arithmetic, and keeps freed memory in quarantine.

#include <malloc.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "api/batch_route.hpp"
#include "api/handler.hpp"
#include "api/limits.hpp"
#include "api/parse_json.hpp"
#include "api/route_table.hpp"
#include "tests/fuzz/fuzz_support.hpp"
#include "tests/fuzz/unit_cpu_time.hpp"

namespace {

// The heap the process holds through operator new, and the most it held since reset.
std::atomic<std::int64_t> held_bytes{0};
std::atomic<std::int64_t> peak_bytes{0};

[[gnu::noinline]] void* counted(void* p) {
  if (p == nullptr) throw std::bad_alloc();
  const std::int64_t now = held_bytes += static_cast<std::int64_t>(malloc_usable_size(p));
  std::int64_t peak = peak_bytes.load();
  while (now > peak && !peak_bytes.compare_exchange_weak(peak, now)) {
  }
  return p;
}

[[gnu::noinline]] void uncounted(void* p) noexcept {
  if (p == nullptr) return;
  held_bytes -= static_cast<std::int64_t>(malloc_usable_size(p));
  std::free(p);
}

}  // namespace

void* operator new(std::size_t size) { return counted(std::malloc(size == 0 ? 1 : size)); }
void* operator new[](std::size_t size) { return counted(std::malloc(size == 0 ? 1 : size)); }
void operator delete(void* p) noexcept { uncounted(p); }
void operator delete[](void* p) noexcept { uncounted(p); }
void operator delete(void* p, std::size_t) noexcept { uncounted(p); }
void operator delete[](void* p, std::size_t) noexcept { uncounted(p); }

namespace {

using Json = nlohmann::json;
using bezier::fuzz::check;

constexpr double kCpuMultiple = 3.0;
constexpr double kFixedUnits = 500000.0;
constexpr double kUnitsPerBodyByte = 16.0;
constexpr double kHeapMultiple = 3.0;
constexpr double kBytesPerUnit = 1.0;
constexpr double kBytesPerBodyByte = 64.0;
constexpr double kFixedBytes = 1 << 20;
constexpr std::array<std::int64_t, 4> kBudgets = {22000000, 2200000, 220000, 22000};

// The work units a request may spend by the cost models, as the batch charges them.
std::int64_t budget_of(std::string_view path, const Json& body, const bezier::api::Limits& limits) {
  if (!body.is_object()) return 0;
  if (path != bezier::api::kBatchPath) return bezier::api::find_compute_route(path)->work_bound(body, limits);
  const auto requests = body.find("requests");
  if (requests == body.end() || !requests->is_array()) return 0;
  std::int64_t work = 0;
  for (const Json& item : *requests) {
    if (!item.is_object()) continue;
    const auto item_path = item.find("path");
    const auto item_body = item.find("body");
    if (item_path == item.end() || !item_path->is_string() || item_body == item.end()) continue;
    if (const auto* route = bezier::api::find_compute_route(item_path->get_ref<const std::string&>())) {
      work += route->work_bound(*item_body, limits);
    }
  }
  return std::min(work, limits.max_batch_work);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const double unit = bezier::fuzz::seconds_per_unit("request_cost_fuzzer");
  if (size < 2) return -1;
  constexpr std::size_t kRoutes = bezier::api::kComputeRoutes.size();
  const std::size_t route = data[0] % (kRoutes + 1);
  const std::string path(route == 0 ? bezier::api::kBatchPath : bezier::api::kComputeRoutes[route - 1].path);
  bezier::api::Limits limits;
  limits.max_work = kBudgets[data[1] % kBudgets.size()];
  limits.max_batch_work = 10 * limits.max_work;
  const std::string body(reinterpret_cast<const char*>(data + 2), size - 2);
  if (bezier::fuzz::print_inputs()) {
    std::fprintf(stderr, "%s max_work %lld: %s\n", path.c_str(), static_cast<long long>(limits.max_work),
                 body.c_str());
  }

  const std::int64_t held_before = held_bytes.load();
  peak_bytes.store(held_before);
  const double start = bezier::fuzz::thread_cpu_seconds();
  const bezier::api::Reply reply = bezier::api::handle(path, body, limits);
  const double cpu = bezier::fuzz::thread_cpu_seconds() - start;
  const double heap = static_cast<double>(peak_bytes.load() - held_before);

  check(reply.status != 500, [&] { return "500 for " + path + " " + body.substr(0, 2000); });
  const bezier::api::ParsedJson parsed = bezier::api::parse_json(body);
  const double budget = static_cast<double>(parsed.ok ? budget_of(path, parsed.value, limits) : 0);
  const double bytes = static_cast<double>(body.size());
  const double cpu_limit = kCpuMultiple * unit * (budget + kFixedUnits + kUnitsPerBodyByte * bytes);
  check(cpu <= cpu_limit, [&] {
    char figures[200];
    std::snprintf(figures, sizeof figures, "%.4f s of CPU, over the %.4f s that %.0f units allow: ", cpu,
                  cpu_limit, budget);
    return std::string(figures) + path + " " + body.substr(0, 2000);
  });
  const double heap_limit =
      kHeapMultiple * (kBytesPerUnit * budget + kBytesPerBodyByte * bytes + static_cast<double>(reply.body.size()) +
                       kFixedBytes);
  check(heap <= heap_limit, [&] {
    char figures[200];
    std::snprintf(figures, sizeof figures, "%.0f bytes of heap at the peak, over the %.0f that %.0f units allow: ",
                  heap, heap_limit, budget);
    return std::string(figures) + path + " " + body.substr(0, 2000);
  });
  return 0;
}
