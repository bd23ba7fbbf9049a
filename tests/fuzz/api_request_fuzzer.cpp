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
#include "tests/fuzz/api_limits.hpp"
#include "tests/fuzz/reply_checks.hpp"

namespace {

using bezier::fuzz::default_limits;
using bezier::fuzz::tight_limits;
constexpr const auto& kPaths = bezier::fuzz::kApiPaths;

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
