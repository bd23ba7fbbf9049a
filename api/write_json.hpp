#pragma once

// JSON text out: every byte the api sends is written here. Answers on the hot path are
// written straight to text by JsonWriter; the problem details, built as documents, go
// through dump_json. Both write strings and numbers by the same two functions, so an
// answer's text is the text dump_json gives the document it parses to (the route tests
// check that for every answer).

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "core/base/point.hpp"

namespace bezier::api {

/// `text` as a JSON string, appended to `out`: control characters escaped (\b \f \n \r \t
/// by name, the others as \u00XX), '"' and '\' escaped, valid UTF-8 copied as it is, and
/// each byte of an invalid UTF-8 sequence replaced by U+FFFD. Runs of plain ASCII are
/// copied whole, not decoded byte by byte as nlohmann's dump does.
void append_json_string(std::string_view text, std::string& out);

/// `value` as the shortest text that reads back to the same double (std::to_chars), laid
/// out by nlohmann's rules ("1.0", "0.001", "1e-05", "1.5e+20"); NaN and infinities as
/// null (JSON has neither).
void append_json_number(double value, std::string& out);

/// `value` as compact JSON text, as nlohmann's dump() with invalid UTF-8 replaced writes
/// it: members in key order, strings and numbers as the two functions above write them.
[[nodiscard]] std::string dump_json(const nlohmann::json& value);

/// Writes an answer straight to JSON text, for the answers on the hot path: building a
/// document first and writing it after costs more than the intersection search of a
/// cubic pair (every member a map node, every number a heap value, all of it freed again;
/// BENCHMARKS.md, "JSON reading and writing"). Members come out in the order they are
/// written (write them in key order for the text dump_json would give). Separators are
/// implicit: a value or key after a value gets its comma.
class JsonWriter {
 public:
  JsonWriter& begin_object() { return open('{'); }
  JsonWriter& end_object() { return close('}'); }
  JsonWriter& begin_array() { return open('['); }
  JsonWriter& end_array() { return close(']'); }

  /// A member name; the next call writes its value.
  JsonWriter& key(std::string_view name) {
    separate();
    append_json_string(name, out_);
    out_ += ':';
    after_value_ = false;
    return *this;
  }

  JsonWriter& value(double number) {
    separate();
    if (!std::isfinite(number) && first_non_finite_ == kNone) first_non_finite_ = out_.size();
    append_json_number(number, out_);
    after_value_ = true;
    return *this;
  }
  JsonWriter& value(std::int64_t number) {
    separate();
    out_ += std::to_string(number);
    after_value_ = true;
    return *this;
  }
  JsonWriter& value(int number) { return value(static_cast<std::int64_t>(number)); }
  JsonWriter& value(bool flag) {
    separate();
    out_ += flag ? "true" : "false";
    after_value_ = true;
    return *this;
  }
  JsonWriter& value(std::string_view text) {
    separate();
    append_json_string(text, out_);
    after_value_ = true;
    return *this;
  }
  JsonWriter& value(const char* text) { return value(std::string_view(text)); }
  JsonWriter& null() {
    separate();
    out_ += "null";
    after_value_ = true;
    return *this;
  }

  /// [a, b]: an interval or a 2-D point.
  JsonWriter& pair(double a, double b) { return begin_array().value(a).value(b).end_array(); }

  /// False once a NaN or an infinity was written (as null, like dump_json): JSON has
  /// neither, so such an answer is not sent.
  [[nodiscard]] bool all_finite() const noexcept { return first_non_finite_ == kNone; }
  /// The JSON Pointer (RFC 6901) of the first NaN or infinity written, "" for a bare
  /// number; precondition: !all_finite(). Only an answer that is refused needs it, so the
  /// writer keeps no path while it writes: the pointer is read back from the text before
  /// the number. Member names are used as written (the answers' names need no escaping).
  [[nodiscard]] std::string first_non_finite_pointer() const;
  [[nodiscard]] std::string take() && { return std::move(out_); }

 private:
  void separate() {
    if (after_value_) out_ += ',';
  }
  JsonWriter& open(char bracket) {
    separate();
    out_ += bracket;
    after_value_ = false;
    return *this;
  }
  JsonWriter& close(char bracket) {
    out_ += bracket;
    after_value_ = true;
    return *this;
  }

  static constexpr std::size_t kNone = std::string::npos;

  std::string out_;
  bool after_value_ = false;
  std::size_t first_non_finite_ = kNone;  ///< where its text begins in out_
};

/// The answers' geometric pieces.

/// [x, y]
inline JsonWriter& write_point(JsonWriter& w, core::Point2 p) { return w.pair(p.x, p.y); }
/// [x, y, z]
inline JsonWriter& write_point(JsonWriter& w, core::Point3 p) {
  return w.begin_array().value(p.x).value(p.y).value(p.z).end_array();
}
/// [[x, y], ...] or [[x, y, z], ...]
template <class P>
JsonWriter& write_points(JsonWriter& w, std::span<const P> points) {
  w.begin_array();
  for (const P& p : points) write_point(w, p);
  return w.end_array();
}

}  // namespace bezier::api
