// POST /stroke (api/openapi.yaml, DESIGN.md §9): the outline of a stroked curve or path, a
// region under the nonzero fill rule (core/outline/stroke.hpp).
//
// Request:  {"path": SVG path data} or {"points": [[x, y], ...]}, "width": w, "tolerance": ε,
//           optional "join", "miter_limit", "cap", "simplify", "arc_tolerance"
//   width        > 0, the coordinates' units.
//   join         "miter" (default), "round" or "bevel" (SVG 2's stroke-linejoin).
//   miter_limit  >= 1 (default 4, SVG 2's stroke-miterlimit): the largest miter length /
//                stroke width; a sharper miter join is drawn as a bevel.
//   cap          "butt" (default), "round" or "square" (SVG 2's stroke-linecap).
//   tolerance    > 0, absolute, at least 1e-9 of the scale (the largest absolute control-point
//                coordinate or the width, whichever is larger), refused at /tolerance below it.
//   simplify     false (default) or true: the outline's overlaps removed by the boolean
//                simplify of core/region (nonzero), as simple contours.
// Answer:   {"arc_tolerance"?, "path", "simplified"}
//   path        the outline as SVG path data, one closed subpath (M ... Z) per contour; with
//               round joins and caps its nonzero region holds every point closer than w/2
//               to the input and no point farther than w/2 + ε.
//   simplified  whether `simplify` was applied.
// Errors: 422 validation problems with JSON Pointers (unknown join or cap names with the
// nearest name); an outline of more than max_path_segments segments is refused at
// /tolerance as a limit before it is built or as soon as its count passes it; 422 work-cap
// when the stroke (and the simplify) need more than the per-request work cap.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "api/curve_or_path.hpp"
#include "api/nearest_name.hpp"
#include "api/read_json.hpp"
#include "api/read_tolerance.hpp"
#include "api/routes.hpp"
#include "api/write_json.hpp"
#include "core/outline/stroke.hpp"
#include "core/region/boolean.hpp"

namespace bezier::api {

namespace {

constexpr std::array<std::string_view, 3> kJoinNames = {"miter", "round", "bevel"};
constexpr std::array<std::string_view, 3> kCapNames = {"butt", "round", "square"};

/// The optional name member `key`: the index of its value in `names` (`fallback` when
/// absent); a refusal naming the allowed values and the nearest one otherwise.
std::size_t read_name(RequestReader& reader, const Json& request, std::string_view key,
                      std::span<const std::string_view> names, std::size_t fallback) {
  const Json* value = RequestReader::optional(request, key);
  if (value == nullptr) return fallback;
  std::string list;
  for (const std::string_view n : names) {
    if (!list.empty()) list += ", ";
    list += n;
  }
  std::string pointer = "/";
  pointer += key;
  if (!value->is_string()) {
    reader.fail(pointer, "must be a string, one of: " + list);
    return fallback;
  }
  const auto& s = value->get_ref<const std::string&>();
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (s == names[i]) return i;
  }
  reader.fail(pointer, "must be one of: " + list + did_you_mean(s, names));
  return fallback;
}

void append_point(core::Point2 p, std::string& out) {
  append_json_number(p.x, out);
  out += ' ';
  append_json_number(p.y, out);
}

/// Closed contours of segments of degree 1 to 3 as SVG path data: M, then L, Q or C per
/// segment, then Z.
class PathDataWriter {
 public:
  void contour_start(core::Point2 p) {
    if (!data_.empty()) data_ += ' ';
    data_ += 'M';
    append_point(p, data_);
  }
  void segment(const core::Curve& c) {
    data_ += c.degree() == 1 ? " L" : c.degree() == 2 ? " Q" : " C";
    for (int i = 1; i <= c.degree(); ++i) {
      if (i > 1) data_ += ' ';
      append_point(c[i], data_);
    }
  }
  void contour_end() { data_ += " Z"; }
  [[nodiscard]] std::string& data() { return data_; }

 private:
  std::string data_;
};

}  // namespace

Reply stroke_route(const nlohmann::json& request, const Limits& limits) {
  RequestReader reader(limits);
  reader.reject_unknown_fields(request,
                               {"points", "path", "arc_tolerance", "width", "join", "miter_limit",
                                "cap", "tolerance", "simplify"},
                               "");
  refuse_arc_tolerance_without_path(reader, request, has_path(request));
  std::optional<CurveOrPath> input =
      read_curve_or_path(reader, request, "", read_arc_tolerance(reader, request));
  outline::StrokeStyle style;
  if (const auto* value = reader.required(request, "width", "")) {
    const std::optional<double> width = reader.number(*value, "/width");
    if (width && !(*width > 0.0)) reader.fail("/width", "must be greater than 0");
    style.width = width.value_or(1.0);
  }
  style.join = static_cast<outline::LineJoin>(read_name(reader, request, "join", kJoinNames, 0));
  style.cap = static_cast<outline::LineCap>(read_name(reader, request, "cap", kCapNames, 0));
  if (const auto* value = RequestReader::optional(request, "miter_limit")) {
    style.miter_limit = reader
                            .number_in(*value, "/miter_limit", 1.0,
                                       std::numeric_limits<double>::max())
                            .value_or(4.0);
  }
  bool simplify = false;
  if (const auto* value = RequestReader::optional(request, "simplify")) {
    if (value->is_boolean()) {
      simplify = value->get<bool>();
    } else {
      reader.fail("/simplify", "must be true or false");
    }
  }
  const double tolerance = read_positive_tolerance(reader, request);
  if (!reader.ok() || !input) return reader.refusal();
  const path::Path p = as_path(std::move(*input));
  if (!tolerance_fits_scale(reader, tolerance, std::max(style.width, coordinate_scale(p)))) {
    return reader.refusal();
  }

  const auto max_segments = static_cast<std::size_t>(limits.max_path_segments);
  core::WorkBudget budget(limits.max_work);
  outline::StrokeOutline outline = outline::stroke(p, style, tolerance, budget, max_segments);
  if (outline.status == outline::StrokeStatus::work_cap_reached) {
    return problem_reply(ProblemKind::work_cap,
                         "stroking the path took more than the per-request work cap of " +
                             std::to_string(limits.max_work) +
                             " units: send a larger tolerance or a shorter path");
  }
  if (outline.status == outline::StrokeStatus::too_many_segments) {
    reader.fail_limit("/tolerance", "the outline needs more than " + std::to_string(max_segments) +
                                        " segments (max_path_segments): send a larger "
                                        "tolerance or a shorter path");
    return reader.refusal();
  }

  PathDataWriter writer;
  if (simplify) {
    path::Path boundary;
    for (outline::Contour& c : outline.contours) {
      boundary.subpaths.push_back({boundary.segments.size(), c.size(), true});
      for (core::Curve& s : c) boundary.segments.push_back(std::move(s));
    }
    const region::BooleanResult result =
        region::simplify(region::Region{std::move(boundary), region::FillRule::nonzero}, budget);
    if (budget.exhausted()) {
      return problem_reply(ProblemKind::work_cap,
                           "removing the outline's overlaps took more than the per-request work "
                           "cap of " +
                               std::to_string(limits.max_work) +
                               " units: send a larger tolerance, a shorter path or leave out "
                               "simplify");
    }
    if (result.status == region::BooleanStatus::unresolved) {
      return problem_reply(ProblemKind::validation,
                           "the outline's contours come so close to their vertices that no ray "
                           "could decide which side of an edge is inside",
                           {{"/simplify", "the overlaps of this outline could not be removed"}});
    }
    for (const region::ResultContour& c : result.contours) {
      writer.contour_start(result.segments[c.first_segment].curve.front());
      for (std::size_t k = c.first_segment; k < c.end_segment; ++k) {
        writer.segment(result.segments[k].curve);
      }
      writer.contour_end();
    }
  } else {
    for (const outline::Contour& c : outline.contours) {
      writer.contour_start(c.front().front());
      for (const core::Curve& s : c) writer.segment(s);
      writer.contour_end();
    }
  }

  // {"arc_tolerance"?, "path", "simplified"}, members in key order.
  JsonWriter w;
  w.begin_object();
  write_arc_tolerance(w, p.arc_tolerance);
  w.key("path").value(std::string_view(writer.data()));
  w.key("simplified").value(simplify);
  w.end_object();
  return json_reply(std::move(w));
}

}  // namespace bezier::api
