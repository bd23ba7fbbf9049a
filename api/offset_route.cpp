// POST /offset (api/openapi.yaml): the parallel curve of a curve or of each segment of a path,
// as cubics within a tolerance of it both ways (core/outline/offset.hpp).
//
// Request:  {"points": [[x, y], ...]} or {"path": SVG path data}, "distance": d, "tolerance": ε
//   distance   signed, the coordinates' units: positive to the left of the direction of
//              travel (y up).
//   tolerance  > 0, absolute, at least 1e-9 of the scale (the largest absolute control-point
//              coordinate or |d|, whichever is larger), refused at /tolerance below it.
// Answer:   {"error_bound", "path", "segments": [{"points", "source_segment", "t": [t0, t1]}]}
//   segments     the cubics in order, each standing for the parallel curve of its source
//                segment on [t0, t1]; the cusps of the parallel curve are ends of cubics.
//   path         the cubics as SVG path data: a new subpath (M) wherever a cubic does not
//                start exactly where the one before it ends (a new source segment, since the
//                joints are not joined, or a zero of B', where the parallel curve jumps).
//   error_bound  the largest certified bound of a cubic's Hausdorff distance to its piece.
// Errors: 422 validation problems with JSON Pointers; more cubics than max_t_values is
// refused at /tolerance as a limit, as soon as the count passes it (none are answered);
// 422 work-cap when the fits and their bounds exceed the per-request work cap.

#include <algorithm>
#include <cmath>
#include <string>

#include "api/curve_or_path.hpp"
#include "api/read_json.hpp"
#include "api/read_tolerance.hpp"
#include "api/routes.hpp"
#include "api/write_json.hpp"
#include "core/outline/offset.hpp"

namespace bezier::api {

namespace {

struct SourcedCubic {
  std::size_t source_segment = 0;
  outline::OffsetCubic cubic;
};

}  // namespace

Reply offset_route(const nlohmann::json& request, const Limits& limits) {
  RequestReader reader(limits);
  reader.reject_unknown_fields(request, {"points", "path", "arc_tolerance", "distance", "tolerance"}, "");
  refuse_arc_tolerance_without_path(reader, request, has_path(request));
  std::optional<CurveOrPath> input = read_curve_or_path(reader, request, "", read_arc_tolerance(reader, request));
  double distance = 0.0;
  if (const auto* value = reader.required(request, "distance", "")) {
    distance = reader.number(*value, "/distance").value_or(0.0);
  }
  const double tolerance = read_positive_tolerance(reader, request);
  if (!reader.ok() || !input) return reader.refusal();
  const path::Path p = as_path(std::move(*input));
  if (!tolerance_fits_scale(reader, tolerance, std::max(std::fabs(distance), coordinate_scale(p)))) {
    return reader.refusal();
  }

  std::vector<SourcedCubic> cubics;
  double error_bound = 0.0;
  core::WorkBudget budget = request_budget(limits);
  for (std::size_t k = 0; k < p.segments.size(); ++k) {
    const outline::CurveOffset offset =
        outline::offset_curve(p.segments[k], distance, tolerance, budget);
    if (budget.exhausted()) {
      return problem_reply(ProblemKind::work_cap,
                           "fitting the parallel curve of segment " + std::to_string(k) +
                               " took more than the per-request work cap of " +
                               std::to_string(limits.max_work) +
                               " units: send a larger tolerance or a shorter path");
    }
    for (const outline::OffsetCubic& c : offset.cubics) {
      cubics.push_back({k, c});
      error_bound = std::max(error_bound, c.error_bound);
    }
    if (cubics.size() > static_cast<std::size_t>(limits.max_t_values)) {
      reader.fail_limit("/tolerance", "the parallel curve needs more than " +
                                          std::to_string(limits.max_t_values) +
                                          " cubics (max_t_values): send a larger tolerance");
      return reader.refusal();
    }
  }

  std::string data;
  for (std::size_t i = 0; i < cubics.size(); ++i) {
    const auto& points = cubics[i].cubic.points;
    if (i == 0 || !(points[0] == cubics[i - 1].cubic.points[3])) {
      if (!data.empty()) data += ' ';
      data += 'M';
      append_json_number(points[0].x, data);
      data += ' ';
      append_json_number(points[0].y, data);
    }
    data += " C";
    for (int j = 1; j <= 3; ++j) {
      if (j > 1) data += ' ';
      append_json_number(points[static_cast<std::size_t>(j)].x, data);
      data += ' ';
      append_json_number(points[static_cast<std::size_t>(j)].y, data);
    }
  }

  // {"arc_tolerance"?, "error_bound", "path", "segments"}, members in key order.
  JsonWriter w;
  w.begin_object();
  write_arc_tolerance(w, p.arc_tolerance);
  w.key("error_bound").value(error_bound);
  w.key("path").value(std::string_view(data));
  w.key("segments").begin_array();
  for (const SourcedCubic& c : cubics) {
    w.begin_object();
    w.key("points").begin_array();
    for (const core::Point2 q : c.cubic.points) write_point(w, q);
    w.end_array();
    w.key("source_segment").value(static_cast<std::int64_t>(c.source_segment));
    w.key("t").pair(c.cubic.t0, c.cubic.t1);
    w.end_object();
  }
  w.end_array();
  w.end_object();
  return json_reply(std::move(w));
}

}  // namespace bezier::api
