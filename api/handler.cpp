#include "api/handler.hpp"

#include <array>
#include <cmath>
#include <cstdlib>
#include <optional>

#include "api/read_json.hpp"
#include "api/routes.hpp"

namespace bezier::api {

namespace {

using RouteFunction = Reply (*)(const nlohmann::json&, const Limits&);

struct Route {
  std::string_view path;
  RouteFunction function;
};

constexpr std::array kRoutes = {
    Route{"/evaluate", &evaluate_route},
    Route{"/polar", &polar_route},
    Route{"/classify", &classify_route},
    Route{"/loop-area", &loop_area_route},
    Route{"/intersections", &intersections_route},
};

constexpr std::array<std::string_view, kRoutes.size()> kPaths = [] {
  std::array<std::string_view, kRoutes.size()> paths{};
  for (std::size_t i = 0; i < kRoutes.size(); ++i) paths[i] = kRoutes[i].path;
  return paths;
}();

// JSON numbers too large for a double (1e999) make nlohmann's parser fail as a whole,
// yet they are a field-level mistake: 422 with the field's pointer, like any other
// non-finite number. Such literals are replaced by a marker string, the body is parsed
// again, and the markers' pointers become the errors. Only runs on that failure path.
constexpr std::string_view kOverflowMarker = "\\u0000number-overflow";  // JSON text of the marker

std::optional<std::string> mark_overflowing_numbers(std::string_view body) {
  std::string marked;
  bool found = false;
  bool in_string = false;
  for (std::size_t i = 0; i < body.size();) {
    const char c = body[i];
    if (in_string) {
      marked += c;
      if (c == '\\' && i + 1 < body.size()) {
        marked += body[i + 1];
        i += 2;
        continue;
      }
      in_string = c != '"';
      ++i;
    } else if (c == '"') {
      in_string = true;
      marked += c;
      ++i;
    } else if (c == '-' || (c >= '0' && c <= '9')) {
      std::size_t end = i + 1;
      while (end < body.size() && std::string_view("0123456789.eE+-").find(body[end]) != std::string_view::npos) ++end;
      const std::string literal(body.substr(i, end - i));
      if (std::isinf(std::strtod(literal.c_str(), nullptr))) {
        marked += '"';
        marked += kOverflowMarker;
        marked += '"';
        found = true;
      } else {
        marked += literal;
      }
      i = end;
    } else {
      marked += c;
      ++i;
    }
  }
  if (!found) return std::nullopt;
  return marked;
}

void collect_markers(const nlohmann::json& value, const std::string& pointer,
                     std::vector<FieldError>& errors) {
  static constexpr std::string_view kDecodedMarker{"\0number-overflow", 16};
  if (value.is_string() && value.get_ref<const std::string&>() == kDecodedMarker) {
    errors.push_back({pointer, "number is not finite (out of double range)"});
  } else if (value.is_array()) {
    for (std::size_t i = 0; i < value.size() && errors.size() < 32; ++i) {
      collect_markers(value[i], pointer_to(pointer, i), errors);
    }
  } else if (value.is_object()) {
    for (const auto& [key, member] : value.items()) collect_markers(member, pointer_to(pointer, key), errors);
  }
}

Reply malformed(const nlohmann::json::exception& e) {
  return problem_reply(ProblemKind::malformed_json, std::string("body is not valid JSON: ") + e.what());
}

}  // namespace

std::span<const std::string_view> post_routes() noexcept { return kPaths; }

bool is_post_route(std::string_view path) noexcept {
  for (const Route& r : kRoutes) {
    if (r.path == path) return true;
  }
  return false;
}

Reply handle(std::string_view path, std::string_view body, const Limits& limits) {
  nlohmann::json request;
  try {
    request = nlohmann::json::parse(body);
  } catch (const nlohmann::json::out_of_range& e) {
    const auto marked = mark_overflowing_numbers(body);
    if (!marked) return malformed(e);
    nlohmann::json reparsed = nlohmann::json::parse(*marked, nullptr, /*allow_exceptions=*/false);
    if (reparsed.is_discarded()) return malformed(e);
    if (!reparsed.is_object()) return problem_reply(ProblemKind::malformed_json, "body must be a JSON object");
    std::vector<FieldError> errors;
    collect_markers(reparsed, "", errors);
    return validation_reply(std::move(errors));
  } catch (const nlohmann::json::exception& e) {
    return malformed(e);
  }
  if (!request.is_object()) {
    return problem_reply(ProblemKind::malformed_json, "body must be a JSON object");
  }
  for (const Route& r : kRoutes) {
    if (r.path == path) return r.function(request, limits);
  }
  return problem_reply(ProblemKind::not_found, "no route " + std::string(path));
}

}  // namespace bezier::api
