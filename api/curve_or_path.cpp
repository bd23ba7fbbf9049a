#include "api/curve_or_path.hpp"

#include <utility>

#include "core/path/svg_path_data.hpp"

namespace bezier::api {

namespace {

/// The member `path` of `object`, null included (a null path is refused, not ignored, so
/// that it is never taken for a missing one and the request read as a curve's).
const Json* path_member(const Json& object) {
  const auto it = object.find("path");
  return it == object.end() ? nullptr : &*it;
}

}  // namespace

std::optional<double> read_arc_tolerance(RequestReader& reader, const Json& request) {
  const Json* value = RequestReader::optional(request, "arc_tolerance");
  if (value == nullptr) return std::nullopt;
  const std::optional<double> v = reader.number(*value, "/arc_tolerance");
  if (!v) return std::nullopt;
  if (!(*v > 0.0)) {
    reader.fail("/arc_tolerance",
                "must be above 0: the distance within which an elliptical arc's cubics follow it");
    return std::nullopt;
  }
  return v;
}

void refuse_arc_tolerance_without_path(RequestReader& reader, const Json& request, bool any_path) {
  if (!any_path && RequestReader::optional(request, "arc_tolerance") != nullptr) {
    reader.fail("/arc_tolerance",
                "applies to SVG path data (\"path\"), which this request does not have");
  }
}

void write_arc_tolerance(JsonWriter& w, const std::optional<double>& arc_tolerance) {
  if (arc_tolerance) w.key("arc_tolerance").value(*arc_tolerance);
}

std::optional<path::Path> read_path(RequestReader& reader, const Json& value,
                                    const std::string& pointer,
                                    std::optional<double> arc_tolerance) {
  auto parse = read_parsed_path(reader, value, pointer, arc_tolerance, EmptyPath::refused);
  if (!parse) return std::nullopt;
  return std::move(parse->path);
}

std::optional<path::PathDataParse> read_parsed_path(RequestReader& reader, const Json& value,
                                                    const std::string& pointer,
                                                    std::optional<double> arc_tolerance,
                                                    EmptyPath empty) {
  if (!value.is_string()) {
    reader.fail(pointer, "expected a string of SVG path data, e.g. \"M0 0 C1 1 2 1 3 0\"");
    return std::nullopt;
  }
  const auto& data = value.get_ref<const std::string&>();
  const auto max_segments = static_cast<std::size_t>(reader.limits().max_path_segments);
  path::PathDataParse parse = path::parse_svg_path_data(data, max_segments, arc_tolerance);
  if (parse.error) {
    std::string message =
        "offset " + std::to_string(parse.error->offset) + ": " + parse.error->message;
    if (parse.error->kind == path::PathDataErrorKind::too_many_segments) {
      reader.fail_limit(pointer, message + " (the max_path_segments limit)");
    } else {
      reader.fail(pointer, std::move(message));
    }
    return std::nullopt;
  }
  if (parse.path.segments.empty() && empty == EmptyPath::refused) {
    reader.fail(pointer, "the path draws no segment (it needs a moveto and a drawing command)");
    return std::nullopt;
  }
  for (std::size_t k = 0; k < parse.path.segments.size(); ++k) {
    const int degree = parse.path.segments[k].degree();
    if (degree > reader.limits().max_degree) {
      reader.fail_limit(pointer, "segment " + std::to_string(k) + " has degree " +
                                     std::to_string(degree) + ", above the max_degree limit " +
                                     std::to_string(reader.limits().max_degree));
      return std::nullopt;
    }
  }
  return parse;
}

std::optional<CurveOrPath> read_curve_or_path(RequestReader& reader, const Json& object,
                                              const std::string& pointer,
                                              std::optional<double> arc_tolerance) {
  const Json* points = RequestReader::optional(object, "points");
  const Json* path = path_member(object);
  if (points != nullptr && path != nullptr) {
    reader.fail(pointer, "give either \"points\" or \"path\", not both");
    return std::nullopt;
  }
  if (path != nullptr) {
    auto read = read_path(reader, *path, pointer_to(pointer, "path"), arc_tolerance);
    if (!read) return std::nullopt;
    return std::optional<CurveOrPath>(std::in_place, std::in_place_type<path::Path>,
                                      std::move(*read));
  }
  if (points == nullptr) {
    reader.fail(pointer_to(pointer, "points"),
                "required field is missing (or give \"path\": SVG path data)");
    return std::nullopt;
  }
  auto curve = reader.curve2(*points, pointer_to(pointer, "points"));
  if (!curve) return std::nullopt;
  return std::optional<CurveOrPath>(std::in_place, std::in_place_type<core::Curve>,
                                    std::move(*curve));
}

std::optional<path::Path> read_request_path(RequestReader& reader, const Json& request) {
  if (RequestReader::optional(request, "points") != nullptr) {
    reader.fail("/points", "give either \"points\" or \"path\", not both");
  }
  if (RequestReader::optional(request, "interval") != nullptr) {
    reader.fail("/interval", "applies to a curve given by \"points\", not to a path");
  }
  const std::optional<double> arc_tolerance = read_arc_tolerance(reader, request);
  const Json* value = path_member(request);
  if (value == nullptr) return std::nullopt;
  return read_path(reader, *value, "/path", arc_tolerance);
}

bool has_path(const Json& object) { return path_member(object) != nullptr; }

path::Path as_path(CurveOrPath input) {
  if (auto* p = std::get_if<path::Path>(&input)) return std::move(*p);
  path::Path out;
  out.segments.push_back(std::move(std::get<core::Curve>(input)));
  out.subpaths.push_back({0, 1, out.segments[0].back() == out.segments[0].front()});
  return out;
}

}  // namespace bezier::api
