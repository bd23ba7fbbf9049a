#include "api/write_json.hpp"

#include <cassert>
#include <charconv>
#include <vector>

#include "api/utf8.hpp"

namespace bezier::api {

void append_json_string(std::string_view s, std::string& out) {
  static constexpr char kHex[] = "0123456789abcdef";
  out += '"';
  std::size_t i = 0;
  while (i < s.size()) {
    const std::size_t run = i;
    while (i < s.size()) {
      const auto c = static_cast<unsigned char>(s[i]);
      if (c == '"' || c == '\\' || c < 0x20 || c >= 0x80) break;
      ++i;
    }
    out.append(s.substr(run, i - run));
    if (i == s.size()) break;
    const auto c = static_cast<unsigned char>(s[i]);
    if (c >= 0x80) {
      if (const std::size_t n = utf8_sequence_length(s, i)) {
        out.append(s.substr(i, n));
        i += n;
      } else {
        out += "\xEF\xBF\xBD";
        ++i;
      }
      continue;
    }
    ++i;
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        out += "\\u00";
        out += kHex[c >> 4];
        out += kHex[c & 0xF];
    }
  }
  out += '"';
}

// nlohmann's layout (detail::dtoa_impl::format_buffer) of the shortest digits d1 d2 ... dk
// with value 0.d1...dk * 10^n: fixed notation for -4 < n <= 15, scientific otherwise.
void append_json_number(double v, std::string& out) {
  if (!std::isfinite(v)) {
    out += "null";
    return;
  }
  if (v == 0.0) {
    out += std::signbit(v) ? "-0.0" : "0.0";
    return;
  }
  char buffer[40];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::scientific);
  // buffer: [-]d[.ddd]e(+|-)xx
  const char* p = buffer;
  if (*p == '-') {
    out += '-';
    ++p;
  }
  char digits[20];
  int k = 0;
  const char* e = p;
  while (*e != 'e') {
    if (*e != '.') digits[k++] = *e;
    ++e;
  }
  int exponent = 0;
  std::from_chars(e + (e[1] == '+' ? 2 : 1), result.ptr, exponent);
  const int n = exponent + 1;  // the decimal point sits after n digits
  if (k <= n && n <= 15) {
    out.append(digits, static_cast<std::size_t>(k));
    out.append(static_cast<std::size_t>(n - k), '0');
    out += ".0";
  } else if (0 < n && n <= 15) {
    out.append(digits, static_cast<std::size_t>(n));
    out += '.';
    out.append(digits + n, static_cast<std::size_t>(k - n));
  } else if (-4 < n && n <= 0) {
    out += "0.";
    out.append(static_cast<std::size_t>(-n), '0');
    out.append(digits, static_cast<std::size_t>(k));
  } else {
    out += digits[0];
    if (k > 1) {
      out += '.';
      out.append(digits + 1, static_cast<std::size_t>(k - 1));
    }
    out += 'e';
    const int x = n - 1;
    out += x < 0 ? '-' : '+';
    const int magnitude = x < 0 ? -x : x;
    if (magnitude < 10) out += '0';
    out += std::to_string(magnitude);
  }
}

namespace {

template <class Integer>
void write_integer(Integer v, std::string& out) {
  char buffer[24];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
  out.append(buffer, result.ptr);
}

void write_value(const nlohmann::json& value, std::string& out) {
  using Type = nlohmann::json::value_t;
  switch (value.type()) {
    case Type::object: {
      out += '{';
      bool first = true;
      for (const auto& [key, member] : value.items()) {
        if (!first) out += ',';
        first = false;
        append_json_string(key, out);
        out += ':';
        write_value(member, out);
      }
      out += '}';
      return;
    }
    case Type::array: {
      out += '[';
      bool first = true;
      for (const auto& element : value) {
        if (!first) out += ',';
        first = false;
        write_value(element, out);
      }
      out += ']';
      return;
    }
    case Type::string: append_json_string(value.get_ref<const std::string&>(), out); return;
    case Type::boolean: out += value.get<bool>() ? "true" : "false"; return;
    case Type::number_integer: write_integer(value.get<std::int64_t>(), out); return;
    case Type::number_unsigned: write_integer(value.get<std::uint64_t>(), out); return;
    case Type::number_float: append_json_number(value.get<double>(), out); return;
    case Type::null:
    case Type::binary:  // never built by the api
    case Type::discarded: out += "null"; return;
  }
}

}  // namespace

std::string dump_json(const nlohmann::json& value) {
  std::string out;
  out.reserve(256);
  write_value(value, out);
  return out;
}

std::string JsonWriter::first_non_finite_pointer() const {
  assert(!all_finite());
  // The text up to the number (its separating comma included) is well-formed JSON with
  // its containers still open: each open bracket is a level of the path, an array's
  // commas count its index, and an object's last key before the number names its member.
  struct Level {
    bool object;
    std::size_t index;
    std::string_view key;
  };
  std::vector<Level> path;
  const std::string_view text(out_.data(), first_non_finite_);
  for (std::size_t i = 0; i < text.size(); ++i) {
    switch (text[i]) {
      case '"': {
        std::size_t end = i + 1;
        while (text[end] != '"') end += text[end] == '\\' ? 2 : 1;
        if (end + 1 < text.size() && text[end + 1] == ':') path.back().key = text.substr(i + 1, end - i - 1);
        i = end;
        break;
      }
      case '{':
        path.push_back({true, 0, {}});
        break;
      case '[':
        path.push_back({false, 0, {}});
        break;
      case '}':
      case ']':
        path.pop_back();
        break;
      case ',':
        if (!path.back().object) ++path.back().index;
        break;
      default:
        break;
    }
  }
  std::string pointer;
  for (const Level& level : path) {
    pointer += '/';
    pointer += level.object ? std::string(level.key) : std::to_string(level.index);
  }
  return pointer;
}

}  // namespace bezier::api
