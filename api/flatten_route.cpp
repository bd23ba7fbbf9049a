// POST /flatten (api/openapi.yaml): polylines within a tolerance of a curve or path, their
// vertices on it (core/outline/flatten.hpp).
//
// Request:  {"points": [[x, y], ...]} or {"path": SVG path data}, "tolerance": ε
//   tolerance  > 0, absolute (the coordinates' units), at least 1e-9 of the coordinates'
//              scale (the largest absolute control-point coordinate): below it the polyline
//              would be rounding noise, and it is refused at /tolerance.
// Answer:   {"count", "polylines": [[[x, y], ...], ...], "vertices": [[{"segment", "t"}, ...],
// ...]}
//   polylines  one per subpath (a curve is one), in drawing order; vertices aligned with
//              them. The Hausdorff distance of each polyline to its subpath is at most ε.
// Errors: 422 validation problems with JSON Pointers; a polyline estimated (before any vertex
// is placed) or found to have more than limits().max_t_values vertices in all is refused at
// /tolerance as a limit; 422 work-cap when the chord checks exceed the per-request work cap.

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "api/curve_or_path.hpp"
#include "api/read_json.hpp"
#include "api/read_tolerance.hpp"
#include "api/routes.hpp"
#include "api/write_json.hpp"
#include "core/outline/flatten.hpp"

namespace bezier::api {

Reply flatten_route(const nlohmann::json& request, const Limits& limits) {
  RequestReader reader(limits);
  reader.reject_unknown_fields(request, {"points", "path", "arc_tolerance", "tolerance"}, "");
  refuse_arc_tolerance_without_path(reader, request, has_path(request));
  std::optional<CurveOrPath> input = read_curve_or_path(reader, request, "", read_arc_tolerance(reader, request));
  const double tolerance = read_positive_tolerance(reader, request);
  if (!reader.ok() || !input) return reader.refusal();
  const path::Path p = as_path(std::move(*input));
  if (!tolerance_fits_scale(reader, tolerance, coordinate_scale(p))) return reader.refusal();

  outline::FlattenOptions options;
  options.tolerance = tolerance;
  options.max_vertices = static_cast<std::size_t>(limits.max_t_values);
  core::WorkBudget budget = request_budget(limits);
  const outline::Flattening flat = outline::flatten(p, options, budget);
  if (budget.exhausted()) {
    return problem_reply(
        ProblemKind::work_cap,
        "the chord checks of the polyline took more than the per-request work cap of " +
            std::to_string(limits.max_work) + " units: send a larger tolerance or a shorter path");
  }
  if (flat.status == outline::FlattenStatus::too_many_vertices) {
    const std::string size =
        flat.count > 0
            ? std::to_string(flat.count) + " or more"
            : "about " + std::to_string(static_cast<long long>(std::ceil(flat.estimated_count)));
    reader.fail_limit("/tolerance", "the polylines would have " + size +
                                        " vertices, more than the limit of " +
                                        std::to_string(limits.max_t_values) +
                                        " (max_t_values): send a larger tolerance");
    return reader.refusal();
  }

  // {"count", "polylines", "vertices"}, members in key order.
  JsonWriter w;
  w.begin_object();
  write_arc_tolerance(w, p.arc_tolerance);
  w.key("count").value(static_cast<std::int64_t>(flat.count));
  w.key("polylines").begin_array();
  for (const auto& polyline : flat.polylines) {
    w.begin_array();
    for (const outline::PolylineVertex& v : polyline) write_point(w, v.point);
    w.end_array();
  }
  w.end_array();
  w.key("vertices").begin_array();
  for (const auto& polyline : flat.polylines) {
    w.begin_array();
    for (const outline::PolylineVertex& v : polyline) {
      w.begin_object();
      w.key("segment").value(static_cast<std::int64_t>(v.segment));
      w.key("t").value(v.t);
      w.end_object();
    }
    w.end_array();
  }
  w.end_array();
  w.end_object();
  return json_reply(std::move(w));
}

}  // namespace bezier::api
