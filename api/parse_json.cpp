#include "api/parse_json.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>

#include "api/utf8.hpp"

namespace bezier::api {

namespace {

class Parser {
 public:
  explicit Parser(std::string_view text) : text_(text) {}

  ParsedJson run() {
    ParsedJson out;
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = 3;
    skip_space();
    out.root_is_object = peek() == '{';
    if (value(out.value, 0)) {
      skip_space();
      if (pos_ == text_.size()) {
        out.ok = true;
        return out;
      }
      fail("end of input after the value");
    }
    out.value = nullptr;
    out.error_offset = pos_;
    out.error = error_;
    out.too_deep = too_deep_;
    return out;
  }

 private:
  bool fail(const char* expected) {
    if (error_.empty()) error_ = std::string("expected ") + expected;
    return false;
  }
  [[nodiscard]] bool at_end() const noexcept { return pos_ >= text_.size(); }
  [[nodiscard]] char peek() const noexcept { return at_end() ? '\0' : text_[pos_]; }

  void skip_space() noexcept {
    while (!at_end()) {
      const char c = text_[pos_];
      if (c != ' ' && c != '\t' && c != '\n' && c != '\r') return;
      ++pos_;
    }
  }

  bool literal(std::string_view word) {
    if (text_.substr(pos_, word.size()) != word) return fail("a value");
    pos_ += word.size();
    return true;
  }

  bool value(nlohmann::json& out, int depth) {
    switch (peek()) {
      case '{': return object(out, depth + 1);
      case '[': return array(out, depth + 1);
      case '"': {
        std::string s;
        if (!string(s)) return false;
        out = std::move(s);
        return true;
      }
      case 't': out = true; return literal("true");
      case 'f': out = false; return literal("false");
      case 'n': out = nullptr; return literal("null");
      default: return number(out);
    }
  }

  /// Past the opening bracket of a container at nesting level `depth` and the blanks after
  /// it; false (an error) when it nests deeper than kMaxJsonDepth.
  bool open(int depth) {
    if (depth > kMaxJsonDepth) {
      too_deep_ = true;
      return fail("nesting no deeper than 128 levels");
    }
    ++pos_;
    skip_space();
    return true;
  }

  /// Past `c` when it comes next.
  bool take(char c) noexcept {
    if (peek() != c) return false;
    ++pos_;
    return true;
  }

  /// The members or elements of a container, each read by `read_item`, separated by ','
  /// and ended by `close` (nothing but blanks before it in an empty container).
  template <class ReadItem>
  bool items(char close, const char* expected, const ReadItem& read_item) {
    if (take(close)) return true;
    while (true) {
      if (!read_item()) return false;
      skip_space();
      if (!take(',')) return take(close) || fail(expected);
      skip_space();
    }
  }

  bool object(nlohmann::json& out, int depth) {
    if (!open(depth)) return false;
    out = nlohmann::json::object();
    return items('}', "',' or '}' in an object", [&] {
      if (peek() != '"') return fail("a member name (a string)");
      std::string key;
      if (!string(key)) return false;
      skip_space();
      if (!take(':')) return fail("':' after a member name");
      skip_space();
      nlohmann::json member;
      if (!value(member, depth)) return false;
      out[std::move(key)] = std::move(member);
      return true;
    });
  }

  bool array(nlohmann::json& out, int depth) {
    if (!open(depth)) return false;
    out = nlohmann::json::array();
    return items(']', "',' or ']' in an array", [&] {
      nlohmann::json element;
      if (!value(element, depth)) return false;
      out.push_back(std::move(element));
      return true;
    });
  }

  static bool is_digit(char c) noexcept { return c >= '0' && c <= '9'; }

  // -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)? (RFC 8259 §6)
  bool number(nlohmann::json& out) {
    const std::size_t start = pos_;
    const bool negative = peek() == '-';
    if (negative) ++pos_;
    if (peek() == '0') {
      ++pos_;
    } else if (is_digit(peek())) {
      while (is_digit(peek())) ++pos_;
    } else {
      return fail("a value");
    }
    bool integral = true;
    if (peek() == '.') {
      integral = false;
      ++pos_;
      if (!is_digit(peek())) return fail("a digit after '.'");
      while (is_digit(peek())) ++pos_;
    }
    if (peek() == 'e' || peek() == 'E') {
      integral = false;
      ++pos_;
      if (peek() == '+' || peek() == '-') ++pos_;
      if (!is_digit(peek())) return fail("a digit in the exponent");
      while (is_digit(peek())) ++pos_;
    }
    const char* first = text_.data() + start;
    const char* last = text_.data() + pos_;
    if (integral) {
      // As nlohmann does: unsigned when non-negative, signed when negative, and a
      // double only when the integer does not fit 64 bits.
      if (negative) {
        std::int64_t i = 0;
        if (std::from_chars(first, last, i).ec == std::errc()) {
          out = i;
          return true;
        }
      } else {
        std::uint64_t u = 0;
        if (std::from_chars(first, last, u).ec == std::errc()) {
          out = u;
          return true;
        }
      }
    }
    double d = 0.0;
    const auto [end, ec] = std::from_chars(first, last, d);
    if (ec == std::errc::result_out_of_range) {
      // Beyond the double range (or below its smallest subnormal): strtod gives the
      // signed infinity or zero that the reader then reports or accepts.
      d = std::strtod(std::string(first, last).c_str(), nullptr);
    } else if (ec != std::errc() || end != last) {
      return fail("a number");
    }
    out = d;
    return true;
  }

  static int hex_digit(char c) noexcept {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
  }

  bool hex4(std::uint32_t& out) {
    if (pos_ + 4 > text_.size()) return fail("four hex digits after \\u");
    out = 0;
    for (int i = 0; i < 4; ++i) {
      const int h = hex_digit(text_[pos_ + static_cast<std::size_t>(i)]);
      if (h < 0) return fail("four hex digits after \\u");
      out = out * 16 + static_cast<std::uint32_t>(h);
    }
    pos_ += 4;
    return true;
  }

  static void append_utf8(std::string& s, std::uint32_t cp) {
    if (cp < 0x80) {
      s += static_cast<char>(cp);
    } else if (cp < 0x800) {
      s += static_cast<char>(0xC0 | (cp >> 6));
      s += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
      s += static_cast<char>(0xE0 | (cp >> 12));
      s += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      s += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
      s += static_cast<char>(0xF0 | (cp >> 18));
      s += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
      s += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      s += static_cast<char>(0x80 | (cp & 0x3F));
    }
  }

  bool escape(std::string& s) {
    ++pos_;  // the backslash
    if (at_end()) return fail("an escape after '\\'");
    const char c = text_[pos_++];
    switch (c) {
      case '"': s += '"'; return true;
      case '\\': s += '\\'; return true;
      case '/': s += '/'; return true;
      case 'b': s += '\b'; return true;
      case 'f': s += '\f'; return true;
      case 'n': s += '\n'; return true;
      case 'r': s += '\r'; return true;
      case 't': s += '\t'; return true;
      case 'u': break;
      default: --pos_; return fail("one of \\\" \\\\ \\/ \\b \\f \\n \\r \\t \\u");
    }
    std::uint32_t cp = 0;
    if (!hex4(cp)) return false;
    if (cp >= 0xDC00 && cp <= 0xDFFF) return fail("a high surrogate before a low one");
    if (cp >= 0xD800 && cp <= 0xDBFF) {
      std::uint32_t low = 0;
      if (text_.substr(pos_, 2) != "\\u") return fail("a low surrogate (\\uDC00-\\uDFFF) after a high one");
      pos_ += 2;
      if (!hex4(low)) return false;
      if (low < 0xDC00 || low > 0xDFFF) return fail("a low surrogate (\\uDC00-\\uDFFF) after a high one");
      cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
    }
    append_utf8(s, cp);
    return true;
  }

  bool utf8_sequence(std::string& s) {
    const std::size_t length = utf8_sequence_length(text_, pos_);
    if (length == 0) return fail("valid UTF-8 in a string");
    s.append(text_.data() + pos_, length);
    pos_ += length;
    return true;
  }

  bool string(std::string& s) {
    ++pos_;  // the opening quote
    while (true) {
      // The plain run up to the next quote, backslash, control or non-ASCII byte.
      const std::size_t run = pos_;
      while (!at_end()) {
        const auto c = static_cast<unsigned char>(text_[pos_]);
        if (c == '"' || c == '\\' || c < 0x20 || c >= 0x80) break;
        ++pos_;
      }
      s.append(text_.data() + run, pos_ - run);
      if (at_end()) return fail("'\"' to close the string");
      const auto c = static_cast<unsigned char>(text_[pos_]);
      if (c == '"') {
        ++pos_;
        return true;
      }
      if (c == '\\') {
        if (!escape(s)) return false;
      } else if (c < 0x20) {
        return fail("no control character in a string (escape it)");
      } else if (!utf8_sequence(s)) {
        return false;
      }
    }
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  std::string error_;
  bool too_deep_ = false;
};

}  // namespace

ParsedJson parse_json(std::string_view text) { return Parser(text).run(); }

}  // namespace bezier::api
