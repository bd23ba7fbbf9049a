// libFuzzer target: the whole request -> response path of the POST routes,
// bezier::api::handle(path, body, limits), on arbitrary bodies.
//
// Input: byte 0 picks the route (bits 0-2, modulo the five routes of api/openapi.yaml) and the
// limits (bit 3: the documented defaults, or tight ones, so that every limit is hit at
// small sizes); the remaining bytes are the body, as the service would pass it on.
// Every answer is checked by check_reply() (reply_checks.hpp).
//
// Run: see docs/FUZZING.md (with -dict=tests/fuzz/api_request_fuzzer.dict).

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "api/handler.hpp"
#include "api/limits.hpp"
#include "tests/fuzz/reply_checks.hpp"

namespace {

// The spec's POST routes, in a fixed order so that a corpus keeps its meaning when the
// route table grows; a route not registered (yet) rejects the input.
constexpr std::array<std::string_view, 5> kPaths = {"/evaluate", "/polar", "/loop-area",
                                                    "/intersections", "/classify"};

// The documented defaults, except a tenth of the work cap: under ASan and coverage a
// kernel step costs ten to fifty times what it does in a release build, and requests that
// exhaust 200000 steps (curves retracing themselves, high-order contacts) would take
// seconds each and starve the run. The cap's own path is the same at any value.
bezier::api::Limits default_limits() {
  bezier::api::Limits limits;
  limits.max_work = 20000;
  return limits;
}

bezier::api::Limits tight_limits() {
  bezier::api::Limits limits;
  limits.max_degree = 3;
  limits.max_t_values = 4;
  limits.max_body_bytes = 256;
  limits.max_work = 64;
  return limits;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return -1;
  const std::string_view path = kPaths[(data[0] & 7u) % kPaths.size()];
  if (!bezier::api::is_post_route(path)) return -1;
  const bezier::api::Limits limits = (data[0] & 8u) ? tight_limits() : default_limits();
  const std::string_view body(reinterpret_cast<const char*>(data + 1), size - 1);
  const bezier::api::Reply reply = bezier::api::handle(path, body, limits);
  bezier::fuzz::check_reply(body, reply);
  return 0;
}
