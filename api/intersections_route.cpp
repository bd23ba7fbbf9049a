// POST /intersections (DESIGN §3): every intersection of two planar curves of any degree,
// as guaranteed parameter intervals, or, with one curve, its self-intersections.
//
// Request:  {"curves": [{"points": [[x, y], ...]}, {"points": ...}],
//            "tolerance": 1e-12, "method": "hybrid", "fat_curve_degree": 2}
//   curves            1 or 2 objects {"points"}: 2 to max_degree + 1 finite points each.
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
// search: "closed-form-cubic", "subdivision" or "collinear"), "work", "max_depth",
// "newton_iterations", "certification_iterations"}; `method` and `fat_curve_degree` do not
// apply there and are ignored.
// Errors: 422 validation problems with JSON Pointers (tolerance out of range included);
// 422 work-cap problem when the search needs more than limits.max_work work units (steps
// charged by their cost, core/intersect/work_cost.hpp).

#include <algorithm>
#include <cmath>
#include <string>

#include "api/read_json.hpp"
#include "api/routes.hpp"
#include "api/write_json.hpp"
#include "core/curve/evaluate.hpp"
#include "core/intersect/intersect.hpp"
#include "core/self_intersect/self_intersection.hpp"
#include "core/self_intersect/work_cost.hpp"

namespace bezier::api {

namespace {

struct IntersectionsRequest {
  std::vector<core::Curve> curves;
  core::IntersectOptions options;
};

// Members in key order, so the text is what a document of the same answer would dump to.
void write_intersection(JsonWriter& w, const core::Intersection& x) {
  w.begin_object();
  w.key("kind").value(core::to_string(x.kind));
  w.key("point").pair(x.point.x, x.point.y);
  w.key("resolved").value(x.resolved);
  w.key("s").value(x.s);
  w.key("s_interval").pair(x.s_interval.lo, x.s_interval.hi);
  w.key("t").value(x.t);
  w.key("t_interval").pair(x.t_interval.lo, x.t_interval.hi);
  w.end_object();
}

void write_overlap(JsonWriter& w, bool reversed, double s_lo, double s_hi, double t_lo, double t_hi) {
  w.begin_object();
  w.key("reversed").value(reversed);
  w.key("s_interval").pair(s_lo, s_hi);
  w.key("t_interval").pair(t_lo, t_hi);
  w.end_object();
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
  const core::IntersectionResult r =
      core::intersect(request.curves[0], request.curves[1], request.options);
  if (r.status == core::IntersectStatus::work_cap_reached)
    return work_cap_reply(r.stats.iterations, limits);
  if (r.status == core::IntersectStatus::tolerance_too_small) {
    return validation_reply({{"/tolerance", "below what doubles can guarantee"}});
  }
  JsonWriter w;
  w.begin_object();
  w.key("intersections").begin_array();
  for (const core::Intersection& x : r.intersections) write_intersection(w, x);
  w.end_array();
  w.key("overlaps").begin_array();
  for (const core::Overlap& o : r.overlaps) {
    write_overlap(w, o.reversed, o.s_interval.lo, o.s_interval.hi, o.t_interval.lo, o.t_interval.hi);
  }
  w.end_array();
  const core::IntersectStats& stats = r.stats;
  w.key("stats").begin_object();
  w.key("candidate_boxes").value(stats.candidate_boxes);
  w.key("clipping_steps").value(stats.clipping_steps);
  w.key("compensated_steps").value(stats.compensated_steps);
  if (stats.method == core::IntersectMethod::hybrid) w.key("fat_curve_degree").value(request.options.fat_curve_degree);
  w.key("iterations").value(stats.iterations);
  w.key("max_depth").value(stats.max_depth);
  w.key("method").value(core::to_string(stats.method));
  w.key("newton_iterations").value(stats.newton_iterations);
  w.key("subdivisions").value(stats.subdivisions);
  w.key("work").value(stats.work);
  w.end_object();
  w.key("tolerance").value(request.options.tolerance);
  w.end_object();
  return json_reply(std::move(w));
}

core::IntersectionKind kind_of(core::SelfIntersectionKind kind) {
  switch (kind) {
    case core::SelfIntersectionKind::tangent:
      return core::IntersectionKind::tangent;
    case core::SelfIntersectionKind::degenerate:
      return core::IntersectionKind::degenerate;
    case core::SelfIntersectionKind::transversal:
      break;
  }
  return core::IntersectionKind::transversal;
}

/// A self-intersection (t, s) with guaranteed intervals: the curve against itself, searched
/// in a box around (t, s) that stays away from the diagonal t = s (where every point is a
/// trivial solution). When the box holds exactly one contact, its intervals and estimate
/// are used; otherwise the pair is reported as found, with point intervals, unresolved.
struct CertifiedPair {
  core::Intersection intersection;
  std::int64_t work = 0;   ///< work units spent
  std::int64_t steps = 0;  ///< search steps taken
  /// Left unresolved for want of work units (none left, or the search hit its budget):
  /// with a larger work cap it might have been certified.
  bool out_of_work = false;
};

CertifiedPair certified_pair(const core::Curve& curve, const core::SelfIntersection& pair,
                             const core::IntersectOptions& options, std::int64_t budget) {
  core::Intersection x;
  x.t = pair.t;
  x.s = pair.s;
  x.t_interval = {pair.t, pair.t};
  x.s_interval = {pair.s, pair.s};
  x.point = pair.point;
  x.kind = kind_of(pair.kind);
  x.resolved = false;
  const double w = std::min(0x1p-20, (pair.s - pair.t) / 4);
  if (!(w > 0)) return {x, 0, 0, false};
  if (budget <= 0) return {x, 0, 0, true};
  core::IntersectOptions local = options;
  local.max_work = budget;
  const core::IntersectionResult r =
      core::intersect_in(curve, curve, {std::max(0.0, pair.t - w), std::min(1.0, pair.t + w)},
                         {std::max(0.0, pair.s - w), std::min(1.0, pair.s + w)}, local);
  if (r.status != core::IntersectStatus::ok || r.intersections.size() != 1)
    return {x, r.stats.work, r.stats.iterations, r.status == core::IntersectStatus::work_cap_reached};
  return {r.intersections.front(), r.stats.work, r.stats.iterations, false};
}

Reply one_curve_answer(const IntersectionsRequest& request, const Limits& limits) {
  const core::Curve& curve = request.curves[0];
  core::SelfIntersectionOptions options;
  options.max_work = core::self_intersection_box_budget(limits.max_work, curve.degree());
  const core::SelfIntersectionResult r = core::self_intersections(curve, options);
  if (r.status == core::SelfIntersectionStatus::work_cap_reached)
    return self_intersection_work_cap_reply(r.stats.work, limits.max_work);
  // The certification searches share what the self-intersection search left of the budget;
  // a pair they cannot certify within it is reported as found, unresolved.
  const std::int64_t search_units = r.stats.work * core::self_intersection_box_cost(curve.degree());
  std::int64_t certification_work = 0, certification_steps = 0;
  bool out_of_work = false;
  JsonWriter w;
  w.begin_object();
  w.key("intersections").begin_array();
  for (const core::SelfIntersection& pair : r.pairs) {
    const CertifiedPair c = certified_pair(curve, pair, request.options,
                                           limits.max_work - search_units - certification_work);
    certification_work += c.work;
    certification_steps += c.steps;
    out_of_work = out_of_work || c.out_of_work;
    write_intersection(w, c.intersection);
  }
  w.end_array();
  w.key("overlaps").begin_array();
  for (const core::SelfOverlap& o : r.overlaps) {
    // The pieces run the same way when B(t_lo) is B(s_lo), backwards when it is B(s_hi).
    const core::Point2 a = core::evaluate(curve, o.t_lo);
    const double same = core::length(a - core::evaluate(curve, o.s_lo));
    const double opposite = core::length(a - core::evaluate(curve, o.s_hi));
    write_overlap(w, opposite < same, o.s_lo, o.s_hi, o.t_lo, o.t_hi);
  }
  w.end_array();
  w.key("stats").begin_object();
  w.key("certification_iterations").value(certification_steps);
  w.key("max_depth").value(r.stats.max_depth);
  w.key("method").value(core::method_name(r.stats.method));
  w.key("newton_iterations").value(r.stats.newton_iterations);
  w.key("work").value(r.stats.work);
  w.end_object();
  w.key("tolerance").value(request.options.tolerance);
  w.end_object();
  Reply reply = json_reply(std::move(w));
  // A pair left unresolved for want of work units is an answer the cap decided.
  reply.limit_reached = out_of_work;
  return reply;
}

}  // namespace

Reply intersections_route(const nlohmann::json& request, const Limits& limits) {
  RequestReader reader(limits);
  reader.reject_unknown_fields(request, {"curves", "tolerance", "method", "fat_curve_degree"}, "");
  IntersectionsRequest parsed;
  parsed.options.max_work = limits.max_work;
  if (const auto* curves = reader.required(request, "curves", "")) {
    if (!curves->is_array() || curves->empty() || curves->size() > 2) {
      reader.fail("/curves", "expected an array of 1 or 2 curves {\"points\": [[x, y], ...]}");
    } else {
      for (std::size_t i = 0; i < curves->size(); ++i) {
        const std::string at = pointer_to("/curves", i);
        const Json& c = (*curves)[i];
        if (!c.is_object()) {
          reader.fail(at, "expected an object {\"points\": [[x, y], ...]}");
          continue;
        }
        reader.reject_unknown_fields(c, {"points"}, at);
        if (const auto* points = reader.required(c, "points", at)) {
          if (auto curve = reader.curve2(*points, pointer_to(at, "points")))
            parsed.curves.push_back(std::move(*curve));
        }
      }
    }
  }
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
  return parsed.curves.size() == 1 ? one_curve_answer(parsed, limits)
                                    : two_curves_answer(parsed, limits);
}

}  // namespace bezier::api
