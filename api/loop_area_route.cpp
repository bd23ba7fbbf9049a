// POST /loop-area (api/openapi.yaml): every loop of a planar curve of any degree with its area,
// the closed curve's area, or the area enclosed by one parameter interval and its chord.
//
// Request:  {"points": [[x, y], ...], "interval": [t1, t2]}   (interval optional)
//   points    2 to max_degree + 1 planar points, finite.
//   interval  exactly two numbers with 0 <= t1 < t2 <= 1 (an empty or reversed interval is
//             rejected: the area of [t2, t1] is minus that of [t1, t2]).
// Answer without interval:
//   {"degree", "loops": [{"t": [t1, t2], "point", "area" (>= 0), "signed_area", "kind"}],
//    "area": Σ loop areas, "closed": P0 = Pn, "closed_area": number or null,
//    "overlaps": [{"t_interval", "s_interval"}] (pieces the curve retraces: collinear curves,
//                 palindromic control points P_i = P_{n-i}),
//    "stats": {"method", "work", "max_depth", "newton_iterations"}}
// Answer with interval (no loop search):
//   {"degree", "interval": [t1, t2], "area": |A|, "signed_area": A, "chord": [B(t1), B(t2)],
//    "closed", "closed_area"}
// With {"path": SVG path data} instead of points (no interval):
//   {"area": Σ loop areas, "closed": every subpath closed, "closed_area": the signed area
//    the closed subpaths enclose (Green's theorem, core/path/path_area.hpp) or null when
//    none is closed, "loops": [{"area", "kind", "point", "segments": [i, j],
//    "signed_area", "t": [t on segment i, s on segment j]}] (the path's self-intersection
//    loops, core/path/path_loops.hpp), "overlaps": [{"s_interval", "segments",
//    "t_interval"}], "segment_count", "stats": {"candidate_pairs", "work"}}
// A path's elliptical arcs are cubics within "arc_tolerance" (a request field, > 0; default
// 1e-6 of each arc's larger radius), and the answer then begins with "arc_tolerance": the
// distance they keep (api/curve_or_path.hpp).
// Errors: 422 validation problems with JSON Pointers (an area beyond the double range is
// reported at /points); 422 work-cap problem when the self-intersection search needs more
// than limits.max_work work units (its parameter boxes charged by the curve's degree,
// core/self_intersect/work_cost.hpp).

#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "api/curve_or_path.hpp"
#include "api/parameter_interval.hpp"
#include "api/read_json.hpp"
#include "api/routes.hpp"
#include "api/write_contacts.hpp"
#include "api/write_json.hpp"
#include "core/curve/area.hpp"
#include "core/curve/evaluate.hpp"
#include "core/loop/loop_area.hpp"
#include "core/path/path_area.hpp"
#include "core/path/path_intersections.hpp"
#include "core/path/path_loops.hpp"

namespace bezier::api {

namespace {

/// An area beyond the double range (the curve is finite, its area need not be: a loop
/// 1e200 wide) cannot be written as a JSON number: that request is answered with a problem.
Reply area_out_of_range(const char* pointer = "/points") {
  return validation_reply({{pointer,
                            "the area is beyond the double range (about 1.8e308): "
                            "the coordinates are too large"}});
}

/// A number, or null when there is none (closed_area of a curve that is not closed).
JsonWriter& write_optional(JsonWriter& w, const std::optional<double>& number) {
  return number ? w.value(*number) : w.null();
}

// {"area", "chord": [B(t1), B(t2)], "closed", "closed_area", "degree", "interval",
//  "signed_area"}, members in key order (the text a document of the answer would dump to).
Reply interval_answer(const core::Curve& curve, ParameterInterval interval) {
  const double t1 = interval.a, t2 = interval.b;
  const double signed_area = core::enclosed_area(curve, t1, t2);
  const auto closed = core::closed_area(curve);
  if (!std::isfinite(signed_area) || (closed && !std::isfinite(*closed))) {
    return area_out_of_range();
  }
  JsonWriter w;
  w.begin_object();
  w.key("area").value(std::fabs(signed_area));
  w.key("chord").begin_array();
  write_point(w, core::evaluate(curve, t1));
  write_point(w, core::evaluate(curve, t2));
  w.end_array();
  w.key("closed").value(core::is_closed(curve));
  write_optional(w.key("closed_area"), closed);
  w.key("degree").value(curve.degree());
  w.key("interval").pair(t1, t2);
  w.key("signed_area").value(signed_area);
  w.end_object();
  return json_reply(std::move(w));
}

Reply loops_answer(const core::Curve& curve, const Limits& limits) {
  core::WorkBudget budget = request_budget(limits);
  const core::LoopAreaResult result = core::loop_area(curve, core::SelfIntersectionOptions{}, budget);
  if (budget.exhausted()) return self_intersection_work_cap_reply(result.stats.work, limits.max_work);
  if (!std::isfinite(result.area) || (result.closed_area && !std::isfinite(*result.closed_area))) {
    return area_out_of_range();  // the total is infinite when any loop's area is
  }
  // {"area", "closed", "closed_area", "degree",
  //  "loops": [{"area", "kind", "point", "signed_area", "t"}], "overlaps": [{"s_interval",
  //  "t_interval"}], "stats": {"max_depth", "method", "newton_iterations", "work"}}, members
  // in key order (the text a document of the answer would dump to).
  JsonWriter w;
  w.begin_object();
  w.key("area").value(result.area);
  w.key("closed").value(result.closed);
  write_optional(w.key("closed_area"), result.closed_area);
  w.key("degree").value(curve.degree());
  w.key("loops").begin_array();
  for (const core::Loop& loop : result.loops) {
    w.begin_object();
    w.key("area").value(loop.area);
    w.key("kind").value(core::to_string(loop.kind));
    write_point(w.key("point"), loop.point);
    w.key("signed_area").value(loop.signed_area);
    w.key("t").pair(loop.t1, loop.t2);
    w.end_object();
  }
  w.end_array();
  w.key("overlaps").begin_array();
  for (const core::Overlap& o : result.overlaps) write_overlap(w, o, OverlapDirection::left_out);
  w.end_array();
  w.key("stats").begin_object();
  w.key("max_depth").value(result.stats.max_depth);
  w.key("method").value(core::to_string(result.stats.method));
  w.key("newton_iterations").value(result.stats.newton_iterations);
  w.key("work").value(result.stats.work);
  w.end_object();
  w.end_object();
  return json_reply(std::move(w));
}

Reply path_loops_answer(const path::Path& p, const Limits& limits) {
  core::IntersectOptions options;
  options.max_work = limits.max_work;
  const path::PathSelfIntersectionResult self = path::self_intersections(p, options);
  if (self.status == core::IntersectStatus::work_cap_reached) {
    return problem_reply(ProblemKind::work_cap,
                         "the path's self-intersection search spent " +
                             std::to_string(self.stats.work) + " work units on " +
                             std::to_string(self.stats.candidate_pairs) +
                             " segment pairs without finishing, beyond the per-request work cap of " +
                             std::to_string(limits.max_work) + " units");
  }
  const std::vector<path::PathLoop> loops = path::loops(p, self);
  double total = 0.0;
  for (const path::PathLoop& loop : loops) total += loop.area;
  const std::optional<double> closed_area = path::closed_area(p);
  if (!std::isfinite(total) || (closed_area && !std::isfinite(*closed_area))) {
    return area_out_of_range("/path");
  }
  bool closed = true;
  for (const path::Subpath& sub : p.subpaths) closed = closed && sub.closed;
  // {"arc_tolerance"?, "area", "closed", "closed_area", "loops": [{"area", "kind", "point", "segments",
  //  "signed_area", "t"}], "overlaps": [{"s_interval", "segments", "t_interval"}],
  //  "segment_count", "stats": {"candidate_pairs", "work"}}, members in key order.
  JsonWriter w;
  w.begin_object();
  write_arc_tolerance(w, p.arc_tolerance);
  w.key("area").value(total);
  w.key("closed").value(closed);
  write_optional(w.key("closed_area"), closed_area);
  w.key("loops").begin_array();
  for (const path::PathLoop& loop : loops) {
    w.begin_object();
    w.key("area").value(loop.area);
    w.key("kind").value(core::to_string(loop.kind));
    write_point(w.key("point"), loop.point);
    write_segments(w, SegmentPair{loop.segment_t, loop.segment_s});
    w.key("signed_area").value(loop.signed_area);
    w.key("t").pair(loop.t, loop.s);
    w.end_object();
  }
  w.end_array();
  w.key("overlaps").begin_array();
  write_path_overlaps(w, self.overlaps, self.within_segments, OverlapDirection::left_out);
  w.end_array();
  w.key("segment_count").value(static_cast<std::int64_t>(p.segments.size()));
  w.key("stats").begin_object();
  w.key("candidate_pairs").value(self.stats.candidate_pairs);
  w.key("work").value(self.stats.work);
  w.end_object();
  w.end_object();
  return json_reply(std::move(w));
}

}  // namespace

Reply loop_area_route(const nlohmann::json& request, const Limits& limits) {
  RequestReader reader(limits);
  reader.reject_unknown_fields(request, {"points", "path", "arc_tolerance", "interval"}, "");
  const std::optional<double> arc_tolerance = read_arc_tolerance(reader, request);
  refuse_arc_tolerance_without_path(reader, request, has_path(request));
  std::optional<CurveOrPath> input = read_curve_or_path(reader, request, "", arc_tolerance);
  std::optional<ParameterInterval> interval;
  if (const auto* value = RequestReader::optional(request, "interval")) {
    if (has_path(request)) {
      reader.fail("/interval", "applies to a curve given by \"points\", not to a path");
    } else {
      interval = read_interval(reader, *value, SinglePointInterval::refused);
    }
  }
  if (!reader.ok()) return reader.refusal();
  if (const auto* p = std::get_if<path::Path>(&*input)) return path_loops_answer(*p, limits);
  const core::Curve& curve = std::get<core::Curve>(*input);
  if (interval) return interval_answer(curve, *interval);
  return loops_answer(curve, limits);
}

}  // namespace bezier::api
