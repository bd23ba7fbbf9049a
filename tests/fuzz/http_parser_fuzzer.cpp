// libFuzzer target: the epoll engine's HTTP/1.1 request parser
// (service/http_request_parser.hpp) on an arbitrary byte stream, read as pipelined
// requests.
//
// Input: byte 0 picks the piece size the stream is fed in (1 to 256 bytes, or all at
// once) and byte 1 the limits (the defaults, or tight ones: 64-byte heads, 16-byte
// bodies); the rest is the stream. Checks on every execution:
//  - the same stream fed whole and fed in pieces gives the same sequence of requests
//    (method, target, path, version, headers, body, keep-alive, 100-continue) and the
//    same final error status: where the bytes are split never matters;
//  - `used` never exceeds the input, and need_more always uses all of it;
//  - a completed request: its head within max_head_bytes and ending in a blank line,
//    its body within max_body_bytes, a path that starts with '/' (or the OPTIONS '*')
//    and is the target up to '?', HTTP/1.0 or 1.1;
//  - an error: a status of 400, 413, 414, 431, 501 or 505 with a detail; nothing more
//    is taken after it.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "service/http_request_parser.hpp"
#include "tests/fuzz/fuzz_support.hpp"

namespace {

using bezier::fuzz::check;
using bezier::service::HttpRequest;
using bezier::service::HttpRequestParser;
using bezier::service::ParserLimits;
using State = HttpRequestParser::State;

// One parsed request, copied out of the parser (its fields are views into it).
struct Seen {
  std::string method, target, path, headers, body;
  int minor_version;
  bool keep_alive, expect_continue;
  bool operator==(const Seen&) const = default;
};

struct Outcome {
  std::vector<Seen> requests;
  int error_status = 0;  // 0: the stream ended (need_more) without an error
  bool operator==(const Outcome&) const = default;
};

Seen copy(const HttpRequest& r) {
  std::string headers;
  for (const auto& h : r.headers) {
    headers.append(h.name).append(":").append(h.value).append("\n");
  }
  return {std::string(r.method), std::string(r.target), std::string(r.path), headers, r.body,
          r.minor_version, r.keep_alive, r.expect_continue};
}

void check_request(const HttpRequest& r, const ParserLimits& limits) {
  check(r.head.size() <= limits.max_head_bytes, "head over the limit");
  check(r.head.size() >= 4 && r.head.compare(r.head.size() - 4, 4, "\r\n\r\n") == 0, "head without its blank line");
  check(r.body.size() <= limits.max_body_bytes, "body over the limit");
  check(!r.path.empty() && (r.path.front() == '/' || r.target == "*"), "path does not start with '/'");
  check(r.target.substr(0, r.path.size()) == r.path, "path is not a prefix of the target");
  check(r.minor_version == 0 || r.minor_version == 1, "version other than 1.0 or 1.1");
  check(!r.method.empty(), "empty method");
}

Outcome run(std::string_view stream, std::size_t piece, const ParserLimits& limits) {
  HttpRequestParser parser(limits);
  Outcome outcome;
  std::size_t at = 0;
  while (at < stream.size()) {
    const std::string_view part = stream.substr(at, std::min(piece, stream.size() - at));
    const auto progress = parser.feed(part);
    check(progress.used <= part.size(), "used more than the input");
    at += progress.used;
    if (progress.state == State::need_more) {
      check(progress.used == part.size(), "need_more left bytes unused");
      continue;
    }
    if (progress.state == State::error) {
      const int s = parser.error().status;
      check(s == 400 || s == 413 || s == 414 || s == 431 || s == 501 || s == 505, "unexpected error status");
      check(!parser.error().detail.empty(), "error without a detail");
      check(parser.feed(stream.substr(at)).used == 0, "bytes taken after an error");
      outcome.error_status = s;
      return outcome;
    }
    check_request(parser.request(), limits);
    outcome.requests.push_back(copy(parser.request()));
    parser.reset();
  }
  return outcome;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const std::size_t piece = data[0] == 0 ? size : data[0];
  const ParserLimits limits = (data[1] & 1) != 0 ? ParserLimits{64, 16} : ParserLimits{};
  const std::string_view stream(reinterpret_cast<const char*>(data + 2), size - 2);
  const Outcome whole = run(stream, stream.size() + 1, limits);
  const Outcome pieces = run(stream, piece, limits);
  check(whole == pieces, "the split of the stream changed the requests");
  return 0;
}
