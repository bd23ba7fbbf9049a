#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "api/dump_json.hpp"

namespace bezier::api {

/// Writes an answer straight to JSON text, for the answers on the hot path: building a
/// document first and writing it after cost more than the intersection search of a cubic
/// pair (every member a map node, every number a heap value, all of it freed again).
/// Strings and numbers come out as dump_json writes them; members come out in the order
/// they are written (write them in key order for the text dump_json would give).
/// Separators are implicit: a value or key after a value gets its comma.
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

}  // namespace bezier::api
