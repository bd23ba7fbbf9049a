#include "api/route_cost.hpp"

#include <algorithm>
#include <string>

namespace bezier::api {

namespace {

using Json = nlohmann::json;

// Coordinates per point: a curve is planar or in space, and the model charges space.
constexpr std::int64_t kDimensions = 3;

const Json* member(const Json& body, const char* name) {
  if (!body.is_object()) return nullptr;
  const auto found = body.find(name);
  return found == body.end() ? nullptr : &*found;
}

// A count member (samples, derivatives) as the route would read it, within [0, most].
std::int64_t count_of(const Json* value, std::int64_t most) {
  if (value == nullptr || !value->is_number()) return 0;
  const double v = value->get<double>();
  if (!(v > 0)) return 0;
  return v >= static_cast<double>(most) ? most : static_cast<std::int64_t>(v);
}

// The degree of the curve of `points` (an array of control points), within the limit.
std::int64_t degree_of(const Json& body, const Limits& limits) {
  const Json* points = member(body, "points");
  if (points == nullptr || !points->is_array() || points->empty()) return 0;
  return std::min<std::int64_t>(static_cast<std::int64_t>(points->size()) - 1, limits.max_degree);
}

// The t values of `t` (a number or an array) or `samples`, within the limit.
std::int64_t t_values_of(const Json& body, const Limits& limits) {
  std::int64_t count = count_of(member(body, "samples"), limits.max_t_values);
  if (const Json* t = member(body, "t")) count = std::max<std::int64_t>(count, t->is_array() ? t->size() : 1);
  return std::min<std::int64_t>(count, limits.max_t_values);
}

// One de Casteljau run of a degree-n curve, its coordinates written.
std::int64_t point_units(std::int64_t n) { return kDimensions * ((n + 1) * (n + 1) + kNumberUnits); }

void add_path_segments(const Json& value, const Limits& limits, std::int64_t& total) {
  if (value.is_object()) {
    for (auto it = value.begin(); it != value.end(); ++it) {
      if (it.key() == "path" && it->is_string()) {
        const std::string& data = it->get_ref<const std::string&>();
        const bool arcs = data.find_first_of("Aa") != std::string::npos;
        const std::int64_t most = limits.max_path_segments;
        total += arcs ? most : std::min<std::int64_t>(static_cast<std::int64_t>(data.size()), most);
      } else {
        add_path_segments(*it, limits, total);
      }
    }
  } else if (value.is_array()) {
    for (const Json& element : value) add_path_segments(element, limits, total);
  }
}

}  // namespace

std::int64_t path_segments_at_most(const Json& body, const Limits& limits) {
  std::int64_t total = 0;
  add_path_segments(body, limits, total);
  return total;
}

std::int64_t work_capped_cost(const Json& body, const Limits& limits) {
  return limits.max_work + path_segments_at_most(body, limits) * kPathSegmentUnits;
}

std::int64_t evaluate_cost(const Json& body, const Limits& limits) {
  const std::int64_t n = degree_of(body, limits);
  const std::int64_t derivatives = count_of(member(body, "derivatives"), limits.max_degree);
  const Json* frame = member(body, "frame");
  const std::int64_t frame_points = frame != nullptr && frame->is_boolean() && frame->get<bool>() ? 3 : 0;
  const std::int64_t ts = t_values_of(body, limits);
  // The route refuses more than max_t_values points and derivatives in all.
  const std::int64_t points = std::min<std::int64_t>(ts * (1 + derivatives), limits.max_t_values);
  const std::int64_t split = member(body, "split") != nullptr ? 2 * (n + 1) * point_units(n) : 0;
  return kRequestUnits + (points + ts * frame_points) * point_units(n) + split;
}

std::int64_t polar_cost(const Json& body, const Limits& limits) {
  const std::int64_t n = degree_of(body, limits);
  return kRequestUnits + std::max<std::int64_t>(1, t_values_of(body, limits)) * 2 * point_units(n);
}

std::int64_t classify_cost(const Json&, const Limits&) { return kRequestUnits + kClassifyUnits; }

std::int64_t bounds_cost(const Json& body, const Limits& limits) {
  const std::int64_t n = degree_of(body, limits);
  constexpr std::int64_t kCubic = 4 * 4 * 4;
  const std::int64_t curve = kDimensions * kRootUnits * (n + 1) * (n + 1) * (n + 1) + 2 * point_units(n);
  const std::int64_t segment = kDimensions * kRootUnits * kCubic + 2 * point_units(3) + kPathSegmentUnits;
  return kRequestUnits + curve + path_segments_at_most(body, limits) * segment;
}

std::int64_t segments_cost(const Json& body, const Limits& limits) {
  return kRequestUnits + path_segments_at_most(body, limits) * (kPathSegmentUnits + 4 * point_units(0));
}

}  // namespace bezier::api
