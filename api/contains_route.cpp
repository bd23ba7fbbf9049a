// POST /contains (api/openapi.yaml, DESIGN.md §8): for each target, whether a region holds
// it, whether it is on the region's boundary, and its exact winding number.
//
// Request:  {"path": "<SVG path data>" or "curves": [[[x, y], ...], ...],
//            "fill_rule": "nonzero" | "evenodd", "targets": [[x, y], ...], "arc_tolerance"}
//   path, curves, fill_rule  the region operand (api/read_region.hpp); every subpath is
//                            closed for filling.
//   targets                  1 to max_t_values points [x, y], finite.
//   arc_tolerance            optional, > 0, with "path" only: the distance within which the
//                            path's elliptical arcs become cubics (api/curve_or_path.hpp).
// Answer:   {"arc_tolerance"?, "fill_rule", "results": [{"boundary", "inside", "target", "winding"}]}
//   arc_tolerance when the path had elliptical arcs: the largest distance of their cubics
//   from them (the region decided is the cubics').
//   one result per target, in order (core/region/winding.hpp): boundary when the target is
//   within 8 u s of the path (u = 2^-53, s the largest |coordinate| of the region's control
//   points and the target), winding the exact winding number (null on the boundary),
//   inside when on the boundary or filled by the fill rule.
// Errors: 422 validation problems with JSON Pointers; 422 work-cap problem when the targets'
// tests (each segment's box, the subdivision near the path) exceed limits.max_work.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "api/curve_or_path.hpp"
#include "api/read_json.hpp"
#include "api/read_region.hpp"
#include "api/read_targets.hpp"
#include "api/routes.hpp"
#include "api/write_json.hpp"
#include "core/region/winding.hpp"

namespace bezier::api {

Reply contains_route(const Json& request, const Limits& limits) {
  RequestReader reader(limits);
  reader.reject_unknown_fields(
      request, {kRegionFields[0], kRegionFields[1], kRegionFields[2], "targets", "arc_tolerance"}, "");
  const std::optional<double> arc_tolerance = read_arc_tolerance(reader, request);
  refuse_arc_tolerance_without_path(reader, request, has_path(request));
  std::optional<region::Region> operand = read_region(reader, request, "", arc_tolerance);
  std::optional<std::vector<core::Point2>> targets;
  if (const Json* value = reader.required(request, "targets", "")) {
    targets = read_targets<core::Point2>(reader, *value, " [x, y]");
  }
  if (!reader.ok()) return reader.refusal();

  const region::RegionWinding prepared(*operand);
  core::WorkBudget budget(limits.max_work);
  JsonWriter w;
  w.begin_object();
  write_arc_tolerance(w, operand->path.arc_tolerance);
  w.key("fill_rule").value(to_string(operand->fill_rule));
  w.key("results").begin_array();
  for (const core::Point2 target : *targets) {
    const std::optional<region::Winding> found = prepared.at(target, budget);
    if (!found) {
      return problem_reply(ProblemKind::work_cap,
                           "deciding " + std::to_string(targets->size()) + " targets against " +
                               std::to_string(operand->path.segments.size()) +
                               " segments needs more than the cap of " +
                               std::to_string(limits.max_work) +
                               " work units: send fewer targets or segments per request");
    }
    w.begin_object();
    w.key("boundary").value(found->boundary);
    w.key("inside").value(region::inside(*found, operand->fill_rule));
    write_point(w.key("target"), target);
    if (found->boundary) {
      w.key("winding").null();
    } else {
      w.key("winding").value(static_cast<std::int64_t>(found->winding));
    }
    w.end_object();
  }
  w.end_array();
  w.end_object();
  return json_reply(std::move(w));
}

}  // namespace bezier::api
