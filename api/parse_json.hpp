#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace bezier::api {

/// The outcome of parsing a request body: the document, or where and why it is not JSON.
struct ParsedJson {
  nlohmann::json value;
  bool ok = false;
  std::size_t error_offset = 0;  ///< byte offset of the first offending byte
  std::string error;             ///< what was expected there
  bool too_deep = false;         ///< valid JSON, maybe, but nested beyond kMaxJsonDepth
  bool root_is_object = false;   ///< the text starts with '{' (after blanks): known even then
};

/// Parses RFC 8259 JSON text into nlohmann's document model, the same document
/// nlohmann::json::parse builds (numbers without fraction or exponent as unsigned or
/// signed integers when they fit, the last of duplicate keys kept, a leading UTF-8 BOM
/// skipped), with two differences a service needs: numbers are converted in place by
/// std::from_chars (correctly rounded), and a literal beyond the double range becomes
/// ±infinity (or ±0 below it) instead of failing the whole body, so the field that holds
/// it can be reported. Strings must be valid UTF-8; nesting deeper than kMaxJsonDepth is
/// refused with `too_deep` set (no valid request nests more than a few levels, and the
/// parser recurses once per level), which the handler answers as a request it will not
/// take, not as text that is not JSON.
///
/// Why a parser of its own and not a library's: nlohmann's parser, through its SAX
/// interface as much as its DOM, lexes every number with strtod and every string into a
/// buffer byte by byte, which costs more than this whole parser does building the same
/// document, and it refuses a literal beyond the double range as a whole body. simdjson's
/// On-Demand parser costs about what this one does on the api's bodies, but it reports
/// an error as a class (one message for any misplaced comma, brace or key; invalid UTF-8
/// with no position at all) where a client here gets the byte and what was expected
/// there, and it refuses out-of-range literals too. Figures and commands: BENCHMARKS.md,
/// "JSON reading and writing".
[[nodiscard]] ParsedJson parse_json(std::string_view text);

inline constexpr int kMaxJsonDepth = 128;

}  // namespace bezier::api
