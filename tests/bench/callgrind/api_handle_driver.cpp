// Instructions per api::handle call, for callgrind: 2000 calls on one of BM_ApiHandle's
// bodies (tests/bench/api_bench.cpp), so the count divided by 2000 is per request, steady
// where wall-clock time on a shared machine is not. Not part of the build:
//   g++ -std=c++20 -O2 -ffp-contract=off -I. tests/bench/callgrind/api_handle_driver.cpp
//       build/api/libbezier_api.a build/core/libbezier_core.a -o /tmp/api_handle_driver
//   valgrind --tool=callgrind /tmp/api_handle_driver intersections
// (or evaluate, classify, polar, loop-area, empty; polar is the first polar of evaluate's
// cubic at t0 = 0.5, evaluated at t = 0.25; loop-area a cubic made of the same numbers
// that has one loop).
#include <cstdio>
#include <string>
#include <string_view>

#include "api/handler.hpp"
#include "api/limits.hpp"

namespace {

constexpr std::string_view kCubic =
    R"([[0.62707394058816135,0.0027357211802154779],[0.52744703995995224,0.98105096747167408],)"
    R"([0.96837789821438491,0.28110350295901299],[0.61283886060118675,0.7207431411370635]])";
constexpr std::string_view kLoopCubic =
    R"([[0.62707394058816135,0.0027357211802154779],[0.96837789821438491,0.98105096747167408],)"
    R"([0.52744703995995224,0.98105096747167408],[0.96837789821438491,0.0027357211802154779]])";
constexpr std::string_view kPair =
    R"({"curves":[{"points":[[0.6575514690484852,0.5090645046439022],[0.5315440169069916,0.07611245918087661],)"
    R"([0.8079907614737749,0.8542386966291815],[0.2727865446358919,0.1642689702566713]]},)"
    R"({"points":[[0.30325650586746633,0.8939741610083729],[0.2899394116830081,0.14372913632541895],)"
    R"([0.6545765674673021,0.5490608897525817],[0.32461709063500166,0.12016563094221056]]}]})";

}  // namespace

int main(int argc, char** argv) {
  const std::string_view which = argc > 1 ? argv[1] : "evaluate";
  std::string path = "/evaluate", body = "{}";
  if (which == "evaluate") body = "{\"points\":" + std::string(kCubic) + ",\"t\":0.5}";
  if (which == "classify") path = "/classify", body = "{\"points\":" + std::string(kCubic) + "}";
  if (which == "intersections") path = "/intersections", body = std::string(kPair);
  if (which == "polar") path = "/polar", body = "{\"points\":" + std::string(kCubic) + ",\"t0\":0.5,\"t\":0.25}";
  if (which == "loop-area") path = "/loop-area", body = "{\"points\":" + std::string(kLoopCubic) + "}";
  const bezier::api::Limits limits;
  std::size_t bytes = 0;
  for (int i = 0; i < 2000; ++i) bytes += bezier::api::handle(path, body, limits).body.size();
  std::printf("%s: %zu answer bytes\n", which.data(), bytes);
}
