// POST /intersections (api/openapi.yaml): every intersection of two planar curves of any degree,
// as guaranteed parameter intervals, or, with one curve, its self-intersections.
//
// Request:  {"curves": [{"points": [[x, y], ...]}, {"points": ...}],
//            "tolerance": 1e-12, "method": "hybrid", "fat_curve_degree": 2}
//   curves            1 or 2 objects {"points"}: 2 to max_degree + 1 finite points each, or
//                     {"path": SVG path data} (api/curve_or_path.hpp).
//   tolerance         optional, default 1e-12: every reported interval is narrower than
//                     this; at least 2^-46 (about 1.42e-14, what doubles can guarantee) and at
//                     most 1.
//   method            optional: "hybrid" (default), "bezier-clipping", "subdivision".
//   fat_curve_degree  optional, 2 or 3 (default): the hybrid method's fat curves.
// Answer (two curves):
//   {"intersections": [{"t", "s", "t_interval": [lo, hi], "s_interval": [lo, hi],
//                       "point": [x, y], "kind": "transversal" | "tangent" | "degenerate",
//                       "resolved": bool}],          sorted by t, then s
//    "overlaps": [{"t_interval", "s_interval", "reversed"}],
//    "tolerance": the tolerance used,
//    "stats": {"method", "fat_curve_degree" (hybrid), "iterations", "work", "clipping_steps",
//              "subdivisions", "candidate_boxes", "compensated_steps", "newton_iterations",
//              "max_depth"}}
// Answer (one curve): the same shape with t < s for every pair (the curve's
// self-intersections, never the trivial pair (0, 1) of a closed curve), retraced pieces
// of a collinear curve as "overlaps", and "stats": {"method" (the self-intersection
// search: "closed-form-cubic", "subdivision" or "collinear"), "work" (the search's and the
// certification's work units, core/self_intersect/work_cost.hpp), "max_depth",
// "newton_iterations", "certification_iterations"}; `method` and `fat_curve_degree` do not
// apply there and are ignored.
// A path's elliptical arcs are cubics within "arc_tolerance" (a request field, > 0; default
// 1e-6 of each arc's larger radius), and the answer then begins with "arc_tolerance": the
// distance they keep (api/curve_or_path.hpp).
// With a path among the curves (a curve then counts as a path of one segment, segment 0):
// the same answers over the paths' segments (core/path/path_intersections.hpp), each
// intersection and overlap with "segments": [i, j], the segment of the first curve or path
// that holds t and that of the second (or of the same path) that holds s; sorted by i, t,
// j, s. Two: every crossing, tangency and overlap of a segment of one with a segment of
// the other, a contact at a joint once. One path: its self-intersections between
// different segments (not the joints consecutive segments share, nor a closed subpath's
// start meeting its end) and within segments (certified as for one curve). "stats" then
// sums the pair searches' stats and adds "candidate_pairs" (segment pairs whose boxes
// meet) and, for one path, "certification_iterations"; "work" counts every phase.
// Errors: 422 validation problems with JSON Pointers (tolerance out of range included);
// 422 work-cap problem when the search needs more than limits.max_work work units (steps
// charged by their cost, core/intersect/work_cost.hpp and core/self_intersect/work_cost.hpp).

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <variant>

#include "api/curve_or_path.hpp"
#include "api/read_json.hpp"
#include "api/routes.hpp"
#include "api/write_contacts.hpp"
#include "api/write_json.hpp"
#include "core/intersect/intersect.hpp"
#include "core/path/path_intersections.hpp"
#include "core/path/segment_boxes.hpp"
#include "core/self_intersect/certify.hpp"
#include "core/self_intersect/self_intersection.hpp"

namespace bezier::api {

namespace {

struct IntersectionsRequest {
  std::vector<CurveOrPath> inputs;
  core::IntersectOptions options;
  /// Whether any input is a path: then the answers locate points by segment.
  [[nodiscard]] bool has_path() const {
    for (const CurveOrPath& input : inputs) {
      if (std::holds_alternative<path::Path>(input)) return true;
    }
    return false;
  }
  [[nodiscard]] const core::Curve& curve(std::size_t i) const {
    return std::get<core::Curve>(inputs[i]);
  }
};

/// An intersection {"kind", "point", "resolved", "s", "s_interval", "segments"?, "t",
/// "t_interval"}, members in key order (the text a document of the same answer would dump
/// to); `segments` for a path's.
void write_intersection(JsonWriter& w, const core::Intersection& x,
                        std::optional<SegmentPair> segments = std::nullopt) {
  w.begin_object();
  w.key("kind").value(core::to_string(x.kind));
  w.key("point").pair(x.point.x, x.point.y);
  w.key("resolved").value(x.resolved);
  w.key("s").value(x.s);
  w.key("s_interval").pair(x.s_interval.lo, x.s_interval.hi);
  if (segments) write_segments(w, *segments);
  w.key("t").value(x.t);
  w.key("t_interval").pair(x.t_interval.lo, x.t_interval.hi);
  w.end_object();
}

void write_path_intersection(JsonWriter& w, const path::PathContact& c) {
  write_intersection(w, c.intersection, SegmentPair{c.segment_t, c.segment_s});
}

/// `stats` of a two-curve search, or of a path's pair searches summed (`stats`), with
/// `work` every unit spent; for paths the segment pairs searched, and for one path the
/// Newton steps that certified its segments' own self-intersections.
void write_search_stats(JsonWriter& w, const core::IntersectStats& stats,
                        const core::IntersectOptions& options, std::int64_t work,
                        std::optional<std::int64_t> candidate_pairs = std::nullopt,
                        std::optional<std::int64_t> certification_iterations = std::nullopt) {
  w.key("stats").begin_object();
  w.key("candidate_boxes").value(stats.candidate_boxes);
  if (candidate_pairs) w.key("candidate_pairs").value(*candidate_pairs);
  if (certification_iterations) w.key("certification_iterations").value(*certification_iterations);
  w.key("clipping_steps").value(stats.clipping_steps);
  w.key("compensated_steps").value(stats.compensated_steps);
  if (options.method == core::IntersectMethod::hybrid) {
    w.key("fat_curve_degree").value(options.fat_curve_degree);
  }
  w.key("iterations").value(stats.iterations);
  w.key("max_depth").value(stats.max_depth);
  w.key("method").value(core::to_string(options.method));
  w.key("newton_iterations").value(stats.newton_iterations);
  w.key("subdivisions").value(stats.subdivisions);
  w.key("work").value(work);
  w.end_object();
}

Reply tolerance_too_small_reply() {
  return validation_reply({{"/tolerance", "below what doubles can guarantee"}});
}

Reply work_cap_reply(std::int64_t steps, const Limits& limits) {
  return problem_reply(ProblemKind::work_cap,
                       "the intersection search took " + std::to_string(steps) +
                           " steps without finishing and ran out of the per-request work cap of " +
                           std::to_string(limits.max_work) +
                           " units (curves that come within rounding of each other along an "
                           "arc without coinciding, or touch to a high order, need work that "
                           "grows without bound as they get closer)");
}

Reply two_curves_answer(const IntersectionsRequest& request, const Limits& limits) {
  core::WorkBudget budget = request_budget(limits);
  const core::IntersectionResult r =
      core::intersect(request.curve(0), request.curve(1), request.options, budget);
  if (budget.exhausted()) return work_cap_reply(r.stats.iterations, limits);
  if (r.status == core::IntersectStatus::tolerance_too_small) {
    return tolerance_too_small_reply();
  }
  JsonWriter w;
  w.begin_object();
  w.key("intersections").begin_array();
  for (const core::Intersection& x : r.intersections) write_intersection(w, x);
  w.end_array();
  w.key("overlaps").begin_array();
  for (const core::Overlap& o : r.overlaps) write_overlap(w, o, OverlapDirection::written);
  w.end_array();
  write_search_stats(w, r.stats, request.options, r.stats.work);
  w.key("tolerance").value(request.options.tolerance);
  w.end_object();
  return json_reply(std::move(w));
}

Reply one_curve_answer(const IntersectionsRequest& request, const Limits& limits) {
  // The certification shares what the self-intersection search left of the budget; a pair
  // it cannot certify within it is reported as found, unresolved.
  core::WorkBudget budget = request_budget(limits);
  const core::CertifiedSelfIntersectionResult c =
      core::certified_self_intersections(request.curve(0), request.options, budget);
  const core::SelfIntersectionResult& r = c.found;
  const core::CertifiedSelfIntersections& certified = c.certified;
  if (budget.exhausted()) return self_intersection_work_cap_reply(r.stats.work, limits.max_work);
  JsonWriter w;
  w.begin_object();
  w.key("intersections").begin_array();
  for (const core::Intersection& x : certified.intersections) write_intersection(w, x);
  w.end_array();
  w.key("overlaps").begin_array();
  for (const core::Overlap& o : r.overlaps) write_overlap(w, o, OverlapDirection::written);
  w.end_array();
  w.key("stats").begin_object();
  w.key("certification_iterations").value(certified.steps);
  w.key("max_depth").value(r.stats.max_depth);
  w.key("method").value(core::to_string(r.stats.method));
  w.key("newton_iterations").value(r.stats.newton_iterations);
  w.key("work").value(budget.spent());  // the search and the certification
  w.end_object();
  w.key("tolerance").value(request.options.tolerance);
  w.end_object();
  Reply reply = json_reply(std::move(w));
  // A pair left unresolved for want of work units is an answer the cap decided.
  reply.limit_reached = certified.uncertified > 0;
  reply.decided_by_work_cap = certified.uncertified > 0;
  return reply;
}

/// The problem of a path search whose budget ran out: work-cap, or memory-cap at `input`
/// (the JSON Pointer of the path whose segment pairs passed the memory limit).
Reply path_budget_reply(const core::WorkBudget& budget, const path::PathSearchStats& stats,
                        const Limits& limits, const std::string& input) {
  if (budget.exhaustion() == core::Exhaustion::memory) {
    return memory_cap_reply(input,
                            "the segment pairs whose boxes meet need more than the per-request "
                            "memory limit of " +
                                std::to_string(limits.max_request_memory) + " bytes (" +
                                std::to_string(path::kStoredPairBytes) + " bytes a pair)");
  }
  return problem_reply(ProblemKind::work_cap,
                       "the path intersection search spent " + std::to_string(stats.work) +
                           " work units on " + std::to_string(stats.candidate_pairs) +
                           " segment pairs without finishing, beyond the per-request work cap of " +
                           std::to_string(limits.max_work) +
                           " units (it covers the whole path request: every segment pair whose "
                           "boxes meet, and each segment's own search)");
}

Reply two_paths_answer(const IntersectionsRequest& request, const Limits& limits) {
  const path::Path a = as_path(request.inputs[0]);
  const path::Path b = as_path(request.inputs[1]);
  core::WorkBudget budget = request_budget(limits);
  const path::PathIntersectionResult r = path::intersect(a, b, request.options, budget);
  std::optional<double> arc_tolerance = a.arc_tolerance;
  if (b.arc_tolerance) arc_tolerance = std::max(arc_tolerance.value_or(0.0), *b.arc_tolerance);
  if (budget.exhausted()) return path_budget_reply(budget, r.stats, limits, "/curves");
  if (r.status == core::IntersectStatus::tolerance_too_small) {
    return tolerance_too_small_reply();
  }
  JsonWriter w;
  w.begin_object();
  write_arc_tolerance(w, arc_tolerance);
  w.key("intersections").begin_array();
  for (const path::PathContact& c : r.intersections) write_path_intersection(w, c);
  w.end_array();
  w.key("overlaps").begin_array();
  write_path_overlaps(w, r.overlaps, {}, OverlapDirection::written);
  w.end_array();
  write_search_stats(w, r.stats.pairs, request.options, r.stats.work, r.stats.candidate_pairs);
  w.key("tolerance").value(request.options.tolerance);
  w.end_object();
  return json_reply(std::move(w));
}

Reply one_path_answer(const IntersectionsRequest& request, const Limits& limits) {
  const path::Path p = as_path(request.inputs[0]);
  core::WorkBudget budget = request_budget(limits);
  const path::PathSelfIntersectionResult r =
      path::certified_self_intersections(p, request.options, budget);
  if (budget.exhausted()) return path_budget_reply(budget, r.stats, limits, "/curves/0");
  if (r.status == core::IntersectStatus::tolerance_too_small) {
    return tolerance_too_small_reply();
  }
  JsonWriter w;
  w.begin_object();
  write_arc_tolerance(w, p.arc_tolerance);
  w.key("intersections").begin_array();
  for (const path::PathContact& c : r.intersections) write_path_intersection(w, c);
  w.end_array();
  w.key("overlaps").begin_array();
  write_path_overlaps(w, r.overlaps, r.within_segments, OverlapDirection::written);
  w.end_array();
  write_search_stats(w, r.stats.pairs, request.options, r.stats.work, r.stats.candidate_pairs,
                     r.stats.certification_steps);
  w.key("tolerance").value(request.options.tolerance);
  w.end_object();
  Reply reply = json_reply(std::move(w));
  reply.limit_reached = r.uncertified_pairs > 0;
  reply.decided_by_work_cap = r.uncertified_pairs > 0;
  return reply;
}

}  // namespace

Reply intersections_route(const nlohmann::json& request, const Limits& limits) {
  RequestReader reader(limits);
  reader.reject_unknown_fields(
      request, {"curves", "arc_tolerance", "tolerance", "method", "fat_curve_degree"}, "");
  IntersectionsRequest parsed;
  const std::optional<double> arc_tolerance = read_arc_tolerance(reader, request);
  bool any_path = false;
  if (const auto* curves = reader.required(request, "curves", "")) {
    if (!curves->is_array() || curves->empty() || curves->size() > 2) {
      reader.fail("/curves", "expected an array of 1 or 2 curves {\"points\": [[x, y], ...]} "
                             "or paths {\"path\": \"M0 0 C1 1 2 1 3 0\"}");
    } else {
      for (std::size_t i = 0; i < curves->size(); ++i) {
        const std::string at = pointer_to("/curves", i);
        const Json& c = (*curves)[i];
        if (!c.is_object()) {
          reader.fail(at, "expected an object {\"points\": [[x, y], ...]} or {\"path\": \"...\"}");
          continue;
        }
        reader.reject_unknown_fields(c, {"points", "path"}, at);
        any_path = any_path || has_path(c);
        if (auto input = read_curve_or_path(reader, c, at, arc_tolerance)) {
          parsed.inputs.push_back(std::move(*input));
        }
      }
    }
  }
  refuse_arc_tolerance_without_path(reader, request, any_path);
  if (const auto* tolerance = RequestReader::optional(request, "tolerance")) {
    if (const auto v = reader.number(*tolerance, "/tolerance")) {
      if (!(core::kMinTolerance <= *v && *v <= 1.0)) {
        Json lo = core::kMinTolerance;
        reader.fail("/tolerance", "must lie in [" + lo.dump() + ", 1]: intervals narrower than " +
                                      lo.dump() + " cannot be guaranteed in double precision");
      } else {
        parsed.options.tolerance = *v;
      }
    }
  }
  if (const auto* method = RequestReader::optional(request, "method")) {
    if (const auto m =
            reader.one_of(*method, "/method", {"hybrid", "bezier-clipping", "subdivision"})) {
      parsed.options.method = *m == "hybrid"            ? core::IntersectMethod::hybrid
                              : *m == "bezier-clipping" ? core::IntersectMethod::bezier_clipping
                                                        : core::IntersectMethod::subdivision;
    }
  }
  if (const auto* k = RequestReader::optional(request, "fat_curve_degree")) {
    if (const auto v = reader.integer(*k, "/fat_curve_degree", 2, 3))
      parsed.options.fat_curve_degree = *v;
  }
  if (!reader.ok()) return reader.refusal();
  if (parsed.has_path()) {
    return parsed.inputs.size() == 1 ? one_path_answer(parsed, limits)
                                     : two_paths_answer(parsed, limits);
  }
  return parsed.inputs.size() == 1 ? one_curve_answer(parsed, limits)
                                    : two_curves_answer(parsed, limits);
}

}  // namespace bezier::api
