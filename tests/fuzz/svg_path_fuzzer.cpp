// libFuzzer target: path::parse_svg_path_data (core/path/svg_path_data.hpp) on arbitrary
// bytes as path data.
//
// Checks (the header is the contract):
//  - an error lies within the data (offset <= size), has a message, and leaves no path;
//  - a parsed path keeps the invariants of path::Path: segments of degree 1 to 3 with finite
//    coordinates; subpaths listed in order, each non-empty, covering every segment once;
//    inside a subpath each segment starts exactly where the one before ends; `closed`
//    exactly when the last segment ends at the first one's start;
//  - round trip: the path written back as absolute M, L, Q, C and Z commands with every
//    double in full (%.17g reads back to the same double) parses to the same path;
//  - the segment limit: with a limit of one less than the path's segment count parsing
//    stops with too_many_segments, with the count itself it does not.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

#include "core/path/svg_path_data.hpp"
#include "tests/fuzz/fuzz_support.hpp"

namespace {

using bezier::fuzz::check;
using bezier::path::Path;
using bezier::path::PathDataErrorKind;
using bezier::path::PathDataParse;

/// A limit no input of the fuzzer reaches (it would need more bytes than it gets).
constexpr std::size_t kNoLimit = 1 << 20;

void append(std::string& out, double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, " %.17g", v);
  out += buf;
}

/// The path as absolute commands: one M per subpath, then each segment by its degree.
std::string write_back(const Path& path) {
  std::string out;
  for (const auto& sub : path.subpaths) {
    const auto& first = path.segments[sub.first_segment];
    out += "M";
    append(out, first.front().x);
    append(out, first.front().y);
    for (std::size_t k = 0; k < sub.segment_count; ++k) {
      const auto& segment = path.segments[sub.first_segment + k];
      out += segment.degree() == 1 ? " L" : segment.degree() == 2 ? " Q" : " C";
      for (int i = 1; i <= segment.degree(); ++i) {
        append(out, segment[i].x);
        append(out, segment[i].y);
      }
    }
    if (sub.closed) out += " Z ";
  }
  return out;
}

void check_invariants(const Path& path, std::string_view data) {
  const auto ctx = [&] { return " for data \"" + std::string(data) + "\""; };
  std::size_t next = 0;
  for (const auto& sub : path.subpaths) {
    check(sub.first_segment == next && sub.segment_count > 0,
          [&] { return "subpaths not in order or empty" + ctx(); });
    next += sub.segment_count;
    check(next <= path.segments.size(), [&] { return "subpath beyond the segments" + ctx(); });
    for (std::size_t k = 1; k < sub.segment_count; ++k) {
      check(path.segments[sub.first_segment + k].front() ==
                path.segments[sub.first_segment + k - 1].back(),
            [&] { return "segments of a subpath do not chain" + ctx(); });
    }
    const bool ends_at_start =
        path.segments[next - 1].back() == path.segments[sub.first_segment].front();
    check(sub.closed == ends_at_start, [&] { return "closed flag wrong" + ctx(); });
  }
  check(next == path.segments.size(), [&] { return "segments outside every subpath" + ctx(); });
  for (const auto& segment : path.segments) {
    check(segment.degree() >= 1 && segment.degree() <= 3,
          [&] { return "segment degree outside 1..3" + ctx(); });
    for (const auto p : segment.points()) {
      check(bezier::fuzz::is_finite(p), [&] { return "non-finite coordinate" + ctx(); });
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  const std::string_view data(reinterpret_cast<const char*>(bytes), size);
  const PathDataParse parse = bezier::path::parse_svg_path_data(data, kNoLimit);
  if (bezier::fuzz::print_inputs()) std::fprintf(stderr, "data: %.*s\n", int(size), data.data());
  if (parse.error) {
    check(parse.error->offset <= size && !parse.error->message.empty() &&
              parse.path.segments.empty() && parse.path.subpaths.empty(),
          "an error outside the data, without a message, or with a path");
    return 0;
  }
  check_invariants(parse.path, data);

  const std::string written = write_back(parse.path);
  const PathDataParse again = bezier::path::parse_svg_path_data(written, kNoLimit);
  check(!again.error && again.path.segments == parse.path.segments &&
            again.path.subpaths.size() == parse.path.subpaths.size(),
        [&] { return "round trip through \"" + written + "\" changed the path"; });
  for (std::size_t i = 0; i < parse.path.subpaths.size(); ++i) {
    check(again.path.subpaths[i].closed == parse.path.subpaths[i].closed &&
              again.path.subpaths[i].segment_count == parse.path.subpaths[i].segment_count,
          [&] { return "round trip through \"" + written + "\" changed a subpath"; });
  }

  const std::size_t count = parse.path.segments.size();
  if (count > 0) {
    const PathDataParse limited = bezier::path::parse_svg_path_data(data, count - 1);
    check(limited.error && limited.error->kind == PathDataErrorKind::too_many_segments,
          "a limit of one less than the segment count did not stop the parse");
    check(!bezier::path::parse_svg_path_data(data, count).error,
          "a limit of exactly the segment count refused the path");
  }
  return 0;
}
