// POST /bounds (api/openapi.yaml): the tight axis-aligned box of a planar or space curve of any
// degree on a parameter interval, and the parameters where its coordinates turn.
//
// Request:  {"points": [[x, y], ...] or [[x, y, z], ...], "interval": [a, b]}
//   interval  optional, 0 <= a <= b <= 1, default [0, 1].
// Answer:   {"critical": [[t, ...] per axis], "degree", "interval": [a, b], "max", "min"}
//   min, max   the box of the curve itself (not of its control points), each face the
//              exact extreme rounded outward (core/measure/bounds.hpp).
//   critical   per axis, increasing: the t in (a, b) where that coordinate's derivative
//              vanishes, a double root once.
// With {"path": SVG path data} instead of points (no interval): the box of the
// whole path, the union of its segments' tight boxes,
//   {"critical": [[{"segment", "t"}, ...] per axis], "max", "min", "segment_count"}
//   critical   per axis, by segment then t: each segment's critical t in (0, 1).
// A path's elliptical arcs are cubics within "arc_tolerance" (a request field, > 0; default
// 1e-6 of each arc's larger radius), and the answer then begins with "arc_tolerance": the
// distance they keep (api/curve_or_path.hpp).
// Errors: 422 validation problems with JSON Pointers.

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

#include "api/curve_or_path.hpp"
#include "api/parameter_interval.hpp"
#include "api/read_json.hpp"
#include "api/routes.hpp"
#include "api/write_json.hpp"
#include "core/measure/bounds.hpp"

namespace bezier::api {

namespace {

// {"critical", "degree", "interval", "max", "min"}, members in key order (the text a
// document of the answer would dump to).
template <class P>
Reply bounds_answer(const core::BasicCurve<P>& curve, ParameterInterval interval) {
  const core::Bounds<P> box = core::bounds(curve, interval.a, interval.b);
  JsonWriter w;
  w.begin_object();
  w.key("critical").begin_array();
  for (const auto& ts : box.critical) {
    w.begin_array();
    for (const double t : ts) w.value(t);
    w.end_array();
  }
  w.end_array();
  w.key("degree").value(curve.degree());
  w.key("interval").pair(interval.a, interval.b);
  write_point(w.key("max"), box.max);
  write_point(w.key("min"), box.min);
  w.end_object();
  return json_reply(std::move(w));
}

// {"arc_tolerance"?, "critical", "max", "min", "segment_count"}, members in key order.
Reply path_bounds_answer(const path::Path& p) {
  core::Bounds<core::Point2> box = core::bounds(p.segments[0], 0.0, 1.0);
  std::array<std::vector<std::pair<std::size_t, double>>, 2> critical;
  for (std::size_t k = 0; k < p.segments.size(); ++k) {
    const core::Bounds<core::Point2> b = k == 0 ? box : core::bounds(p.segments[k], 0.0, 1.0);
    box.min = {std::min(box.min.x, b.min.x), std::min(box.min.y, b.min.y)};
    box.max = {std::max(box.max.x, b.max.x), std::max(box.max.y, b.max.y)};
    for (std::size_t axis = 0; axis < 2; ++axis) {
      for (const double t : b.critical[axis]) critical[axis].emplace_back(k, t);
    }
  }
  JsonWriter w;
  w.begin_object();
  write_arc_tolerance(w, p.arc_tolerance);
  w.key("critical").begin_array();
  for (const auto& axis : critical) {
    w.begin_array();
    for (const auto& [segment, t] : axis) {
      w.begin_object();
      w.key("segment").value(static_cast<std::int64_t>(segment));
      w.key("t").value(t);
      w.end_object();
    }
    w.end_array();
  }
  w.end_array();
  write_point(w.key("max"), box.max);
  write_point(w.key("min"), box.min);
  w.key("segment_count").value(static_cast<std::int64_t>(p.segments.size()));
  w.end_object();
  return json_reply(std::move(w));
}

}  // namespace

Reply bounds_route(const nlohmann::json& request, const Limits& limits) {
  RequestReader reader(limits);
  reader.reject_unknown_fields(request, {"points", "path", "arc_tolerance", "interval"}, "");
  if (has_path(request)) {
    const std::optional<path::Path> p = read_request_path(reader, request);
    if (!reader.ok()) return reader.refusal();
    return path_bounds_answer(*p);
  }
  refuse_arc_tolerance_without_path(reader, request, false);
  const auto curve = reader.request_curve(request);
  const auto interval = read_parameter_interval(reader, request);
  if (!reader.ok()) return reader.refusal();
  return std::visit([&](const auto& c) { return bounds_answer(c, *interval); }, *curve);
}

}  // namespace bezier::api
