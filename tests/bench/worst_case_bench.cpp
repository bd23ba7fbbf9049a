// The costliest requests at the default limits (api/limits.hpp), timed through
// api::handle: JSON parsing, validation, the kernel and the JSON answer, no sockets. The
// requests and the curves they use are described in worst_case_inputs.hpp.
//
//   ninja -C build bezier_bench
//   build/tests/bezier_bench --benchmark_filter=WorstCase --benchmark_min_time=0.2
//
// Counters: status (200, or 422 when a work cap answered), reply_bytes, work (the units the
// answer's stats report; 0 for a 422). BENCHMARKS.md, "Worst requests at the default limits", has
// the figures. BEZIER_BENCH_MAX_WORK=<units> replaces Limits::max_work, to measure what another
// default would cost and which requests it would turn into 422s.

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <string>

#include <nlohmann/json.hpp>

#include "api/handler.hpp"
#include "tests/bench/worst_case_inputs.hpp"

namespace {

bezier::api::Limits bench_limits() {
  bezier::api::Limits limits;
  if (const char* v = std::getenv("BEZIER_BENCH_MAX_WORK")) limits.max_work = std::strtoll(v, nullptr, 10);
  return limits;
}

void run(benchmark::State& state, const bezier::test::worst_case::Request& request) {
  const bezier::api::Limits limits = bench_limits();
  int status = 0;
  std::size_t bytes = 0;
  double work = 0;
  for (auto _ : state) {
    const bezier::api::Reply reply = bezier::api::handle(request.path, request.body, limits);
    status = reply.status;
    bytes = reply.body.size();
    benchmark::DoNotOptimize(reply.body.data());
  }
  if (status == 200) {  // once more, untimed, for the units spent
    const auto json = nlohmann::json::parse(bezier::api::handle(request.path, request.body, limits).body);
    if (json.contains("stats") && json["stats"].contains("work")) work = json["stats"]["work"].get<double>();
  }
  state.counters["status"] = status;
  state.counters["reply_bytes"] = static_cast<double>(bytes);
  state.counters["max_work"] = static_cast<double>(limits.max_work);
  state.counters["work"] = work;
}

// Registered at start-up, one benchmark per request.
const bool registered = [] {
  for (const auto& request : bezier::test::worst_case::requests()) {
    benchmark::RegisterBenchmark(("BM_WorstCase/" + request.name).c_str(),
                                 [request](benchmark::State& state) { run(state, request); })
        ->Unit(benchmark::kMillisecond);
  }
  return true;
}();

}  // namespace
