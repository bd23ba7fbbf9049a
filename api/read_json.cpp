#include "api/read_json.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "api/nearest_name.hpp"
#include "core/curve/evaluate.hpp"

namespace bezier::api {

namespace {

// A client that sends 100 000 bad points gets the first few errors, not a megabyte of them.
constexpr std::size_t kMaxRecordedErrors = 32;

const char* type_name(const Json& value) {
  switch (value.type()) {
    case Json::value_t::null:
      return "null";
    case Json::value_t::boolean:
      return "a boolean";
    case Json::value_t::string:
      return "a string";
    case Json::value_t::array:
      return "an array";
    case Json::value_t::object:
      return "an object";
    default:
      return "a number";
  }
}

std::string format_number(double v) {
  Json j = v;
  return j.dump();
}

}  // namespace

std::string pointer_to(const std::string& parent, std::string_view key) {
  std::string out = parent + "/";
  for (const char c : key) {
    if (c == '~') {
      out += "~0";
    } else if (c == '/') {
      out += "~1";
    } else {
      out += c;
    }
  }
  return out;
}

std::string pointer_to(const std::string& parent, std::size_t index) {
  return parent + "/" + std::to_string(index);
}

void RequestReader::fail(std::string pointer, std::string message) {
  if (errors_.size() < kMaxRecordedErrors) errors_.push_back({std::move(pointer), std::move(message)});
}

void RequestReader::fail_limit(std::string pointer, std::string message) {
  limit_reached_ = true;
  fail(std::move(pointer), std::move(message));
}

Reply RequestReader::refusal() {
  Reply reply = validation_reply(std::move(errors_));
  reply.limit_reached = limit_reached_;
  return reply;
}

namespace {

/// The routes that take SVG path data ("path"), named when a route that takes control
/// points only is sent one.
constexpr std::string_view kRoutesTakingPaths =
    "/intersections, /loop-area, /length, /bounds, /nearest, /contains, /boolean, /flatten, /offset "
    "and /segments";

}  // namespace

void RequestReader::reject_unknown_fields(const Json& object,
                                          std::initializer_list<std::string_view> known,
                                          const std::string& pointer) {
  const std::span<const std::string_view> names(known.begin(), known.size());
  const bool takes_points = std::find(names.begin(), names.end(), "points") != names.end();
  for (const auto& [key, value] : object.items()) {
    if (std::find(names.begin(), names.end(), key) != names.end()) continue;
    if (key == "path" && takes_points) {
      fail(pointer_to(pointer, key),
           "this route takes control points (\"points\"), not SVG path data; the routes that "
           "take \"path\" are " + std::string(kRoutesTakingPaths));
      continue;
    }
    fail(pointer_to(pointer, key), "unknown field" + did_you_mean(key, names));
  }
}

const Json* RequestReader::required(const Json& object, std::string_view key,
                                    const std::string& pointer) {
  const Json* value = optional(object, key);
  if (value == nullptr) fail(pointer_to(pointer, key), "required field is missing");
  return value;
}

const Json* RequestReader::optional(const Json& object, std::string_view key) {
  const auto it = object.find(key);
  if (it == object.end() || it->is_null()) return nullptr;
  return &*it;
}

namespace {

// A finite number, or nullopt: the common case, checked before any JSON Pointer is built.
std::optional<double> plain_number(const Json& value) {
  if (!value.is_number()) return std::nullopt;
  const double v = value.get<double>();
  if (!std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace

std::optional<double> RequestReader::number(const Json& value, const std::string& pointer) {
  if (const auto v = plain_number(value)) return v;
  if (!value.is_number()) {
    fail(pointer, std::string("expected a number, got ") + type_name(value));
  } else {
    // 1e999 parses to infinity: JSON has no infinities, and the kernel takes none.
    fail(pointer, "number is not finite (out of double range)");
  }
  return std::nullopt;
}

std::optional<double> RequestReader::number_in(const Json& value, const std::string& pointer,
                                               double lo, double hi) {
  const auto v = number(value, pointer);
  if (!v) return std::nullopt;
  if (!(lo <= *v && *v <= hi)) {
    fail(pointer, "must lie in [" + format_number(lo) + ", " + format_number(hi) + "]");
    return std::nullopt;
  }
  return v;
}

std::optional<int> RequestReader::integer(const Json& value, const std::string& pointer, int lo,
                                          int hi, Bound hi_is) {
  const auto v = number(value, pointer);
  if (!v) return std::nullopt;
  if (*v != std::floor(*v)) {
    fail(pointer, "expected an integer");
    return std::nullopt;
  }
  if (!(lo <= *v && *v <= hi)) {
    std::string message = "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    // Below lo too: the message names the limit.
    if (hi_is == Bound::limit) {
      fail_limit(pointer, std::move(message));
    } else {
      fail(pointer, std::move(message));
    }
    return std::nullopt;
  }
  return static_cast<int>(*v);
}

std::optional<std::vector<double>> RequestReader::numbers(const Json& value,
                                                          const std::string& pointer, double lo,
                                                          double hi) {
  if (!value.is_array()) {
    fail(pointer, std::string("expected an array of numbers, got ") + type_name(value));
    return std::nullopt;
  }
  if (value.empty()) {
    fail(pointer, "must not be empty");
    return std::nullopt;
  }
  if (value.size() > static_cast<std::size_t>(limits_.max_t_values)) {
    fail_limit(pointer, "at most " + std::to_string(limits_.max_t_values) + " values allowed, got " +
                      std::to_string(value.size()));
    return std::nullopt;
  }
  std::vector<double> out;
  out.reserve(value.size());
  bool all_ok = true;
  for (std::size_t i = 0; i < value.size(); ++i) {
    if (const auto v = plain_number(value[i]); v && lo <= *v && *v <= hi) {
      out.push_back(*v);
      continue;
    }
    const auto v = number_in(value[i], pointer_to(pointer, i), lo, hi);
    all_ok = all_ok && v.has_value();
    if (v) out.push_back(*v);
  }
  if (!all_ok) return std::nullopt;
  return out;
}

std::optional<std::vector<double>> RequestReader::number_or_numbers(const Json& value,
                                                                    const std::string& pointer,
                                                                    double lo, double hi) {
  if (value.is_array()) return numbers(value, pointer, lo, hi);
  const auto v = number_in(value, pointer, lo, hi);
  if (!v) return std::nullopt;
  return std::vector<double>{*v};
}

std::optional<std::string> RequestReader::one_of(const Json& value, const std::string& pointer,
                                                 std::initializer_list<std::string_view> allowed) {
  std::string list;
  for (const std::string_view a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
  if (value.is_string()) {
    const auto& s = value.get_ref<const std::string&>();
    for (const std::string_view a : allowed) {
      if (s == a) return s;
    }
  }
  fail(pointer, "must be one of: " + list);
  return std::nullopt;
}

std::vector<double> RequestReader::parameters(const Json& request, bool required) {
  constexpr double kAnyFinite = std::numeric_limits<double>::max();
  const Json* t = optional(request, "t");
  const Json* samples = optional(request, "samples");
  if (t != nullptr && samples != nullptr) {
    fail("/samples", "give either t or samples, not both");
  } else if (t != nullptr) {
    if (auto ts = number_or_numbers(*t, "/t", -kAnyFinite, kAnyFinite)) return std::move(*ts);
  } else if (samples != nullptr) {
    if (const auto n = integer(*samples, "/samples", 1, limits_.max_t_values, Bound::limit)) {
      return core::uniform_parameters(*n);
    }
  } else if (required) {
    fail("/t", "required: give t (a number or an array) or samples (a count)");
  }
  return {};
}

std::optional<std::variant<core::Curve, core::Curve3>> RequestReader::read_curve(
    const Json& value, const std::string& pointer, std::size_t dimension) {
  const std::size_t max_points = static_cast<std::size_t>(limits_.max_degree) + 1;
  if (!value.is_array()) {
    fail(pointer, std::string("expected an array of points, got ") + type_name(value));
    return std::nullopt;
  }
  if (value.size() < 2) {
    fail(pointer, "a curve needs at least 2 control points (degree >= 1), got " +
                      std::to_string(value.size()));
    return std::nullopt;
  }
  if (value.size() > max_points) {
    fail_limit(pointer, "degree " + std::to_string(value.size() - 1) + " is above the limit of " +
                      std::to_string(limits_.max_degree) + " (at most " +
                      std::to_string(max_points) + " control points)");
    return std::nullopt;
  }
  // The first well-formed point fixes the dimension when the route accepts 2 or 3.
  if (dimension == 0) {
    dimension = 2;
    for (const Json& p : value) {
      if (p.is_array() && (p.size() == 2 || p.size() == 3)) {
        dimension = p.size();
        break;
      }
    }
  }
  std::vector<double> coords;
  coords.reserve(value.size() * dimension);
  bool all_ok = true;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const Json& p = value[i];
    // Pointers are built only for what is rejected: one per coordinate cost more than
    // reading the whole curve.
    if (!p.is_array() || p.size() != dimension) {
      const std::string got =
          p.is_array() ? std::to_string(p.size()) + " coordinates" : std::string(type_name(p));
      fail(pointer_to(pointer, i),
           "expected a point of " + std::to_string(dimension) + " numbers like the first, got " + got);
      all_ok = false;
      continue;
    }
    for (std::size_t k = 0; k < dimension; ++k) {
      auto c = plain_number(p[k]);
      if (!c) c = number(p[k], pointer_to(pointer_to(pointer, i), k));
      all_ok = all_ok && c.has_value();
      coords.push_back(c.value_or(0.0));
    }
  }
  if (!all_ok) return std::nullopt;
  if (dimension == 2) {
    std::vector<core::Point2> pts;
    for (std::size_t i = 0; i < coords.size(); i += 2) pts.push_back({coords[i], coords[i + 1]});
    return core::Curve(std::move(pts));
  }
  std::vector<core::Point3> pts;
  for (std::size_t i = 0; i < coords.size(); i += 3) {
    pts.push_back({coords[i], coords[i + 1], coords[i + 2]});
  }
  return core::Curve3(std::move(pts));
}

std::optional<core::Curve> RequestReader::curve2(const Json& value, const std::string& pointer) {
  auto c = read_curve(value, pointer, 2);
  if (!c) return std::nullopt;
  return std::get<core::Curve>(std::move(*c));
}

std::optional<std::variant<core::Curve, core::Curve3>> RequestReader::curve(
    const Json& value, const std::string& pointer) {
  return read_curve(value, pointer, 0);
}

std::optional<std::variant<core::Curve, core::Curve3>> RequestReader::request_curve(const Json& request) {
  const Json* points = required(request, "points", "");
  if (points == nullptr) return std::nullopt;
  return curve(*points, "/points");
}

}  // namespace bezier::api
