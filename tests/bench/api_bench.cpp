// The request -> answer path without sockets (issue 9, item 4): api::handle on the bodies
// that tests/bench/http/compare_peer.sh sends with wrk, so the HTTP figures can be split
// into what the socket layer costs and what parsing, the kernel and the JSON answer cost.
//
//   ninja -C build bezier_bench && build/tests/bezier_bench --benchmark_filter=ApiHandle
//
// The bodies are byte for byte those of ../shared/tools/peer-service/wrk/*.lua (the peer's
// own benchmark bodies: one cubic with t = 0.5, the first intersecting random cubic pair of
// the peer's generator, one cubic to classify), plus /healthz-sized work for reference:
// parsing an empty object.

#include <benchmark/benchmark.h>

#include <string_view>

#include "api/handler.hpp"

namespace {

constexpr std::string_view kEvaluate =
    R"({"points":[[0.62707394058816135,0.0027357211802154779],[0.52744703995995224,0.98105096747167408],[0.96837789821438491,0.28110350295901299],[0.61283886060118675,0.7207431411370635]],"t":0.5})";
constexpr std::string_view kClassify =
    R"({"points":[[0.62707394058816135,0.0027357211802154779],[0.52744703995995224,0.98105096747167408],[0.96837789821438491,0.28110350295901299],[0.61283886060118675,0.7207431411370635]]})";
constexpr std::string_view kIntersections =
    R"({"curves":[{"points":[[0.6575514690484852,0.5090645046439022],[0.5315440169069916,0.07611245918087661],[0.8079907614737749,0.8542386966291815],[0.2727865446358919,0.1642689702566713]]},{"points":[[0.30325650586746633,0.8939741610083729],[0.2899394116830081,0.14372913632541895],[0.6545765674673021,0.5490608897525817],[0.32461709063500166,0.12016563094221056]]}]})";

void run(benchmark::State& state, std::string_view path, std::string_view body) {
  const bezier::api::Limits limits;
  int status = 0;
  for (auto _ : state) {
    const bezier::api::Reply reply = bezier::api::handle(path, body, limits);
    status = reply.status;
    benchmark::DoNotOptimize(reply.body.data());
  }
  state.counters["status"] = status;
}

void BM_ApiHandle_Evaluate(benchmark::State& state) { run(state, "/evaluate", kEvaluate); }
void BM_ApiHandle_Intersections(benchmark::State& state) { run(state, "/intersections", kIntersections); }
void BM_ApiHandle_Classify(benchmark::State& state) { run(state, "/classify", kClassify); }
// A body every route rejects after parsing (422, missing fields): parsing and the problem
// answer alone.
void BM_ApiHandle_EmptyObject(benchmark::State& state) { run(state, "/evaluate", "{}"); }
BENCHMARK(BM_ApiHandle_Evaluate);
BENCHMARK(BM_ApiHandle_Intersections);
BENCHMARK(BM_ApiHandle_Classify);
BENCHMARK(BM_ApiHandle_EmptyObject);

}  // namespace
