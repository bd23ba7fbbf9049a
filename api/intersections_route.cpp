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
#include "core/evaluate.hpp"
#include "core/intersect/intersect.hpp"
#include "core/self_intersection.hpp"
#include "core/self_intersection_work_cost.hpp"

namespace bezier::api {

namespace {

struct IntersectionsRequest {
  std::vector<core::Curve> curves;
  core::IntersectOptions options;
};

nlohmann::json interval_json(core::ParamInterval iv) {
  return pair_json(iv.lo, iv.hi);
}

nlohmann::json intersection_json(const core::Intersection& x) {
  return {{"t", x.t},
          {"s", x.s},
          {"t_interval", interval_json(x.t_interval)},
          {"s_interval", interval_json(x.s_interval)},
          {"point", point_json(x.point)},
          {"kind", std::string(core::to_string(x.kind))},
          {"resolved", x.resolved}};
}

Reply work_cap_reply(std::int64_t steps, const Limits& limits) {
  return problem_reply(ProblemKind::work_cap,
                       "the intersection search took " + std::to_string(steps) +
                           " steps without finishing and ran out of the per-request work cap of " +
                           std::to_string(limits.max_work) +
                           " units (curves that retrace each other along a non-linear "
                           "reparametrisation, or touch to a high order, need unbounded work)");
}

Reply self_work_cap_reply(std::int64_t boxes, const Limits& limits) {
  return problem_reply(ProblemKind::work_cap,
                       "the self-intersection search examined " + std::to_string(boxes) +
                           " parameter boxes without finishing and ran out of the per-request "
                           "work cap of " +
                           std::to_string(limits.max_work) +
                           " units (a curve that retraces part of itself, other than a line or "
                           "a palindrome, needs unbounded work)");
}

Reply two_curves_answer(const IntersectionsRequest& request, const Limits& limits) {
  const core::IntersectionResult r =
      core::intersect(request.curves[0], request.curves[1], request.options);
  if (r.status == core::IntersectStatus::work_cap_reached)
    return work_cap_reply(r.stats.iterations, limits);
  if (r.status == core::IntersectStatus::tolerance_too_small) {
    return validation_reply({{"/tolerance", "below what doubles can guarantee"}});
  }
  nlohmann::json intersections = nlohmann::json::array();
  for (const core::Intersection& x : r.intersections) intersections.push_back(intersection_json(x));
  nlohmann::json overlaps = nlohmann::json::array();
  for (const core::Overlap& o : r.overlaps) {
    overlaps.push_back({{"t_interval", interval_json(o.t_interval)},
                        {"s_interval", interval_json(o.s_interval)},
                        {"reversed", o.reversed}});
  }
  nlohmann::json stats = {{"method", std::string(core::to_string(r.stats.method))},
                          {"iterations", r.stats.iterations},
                          {"work", r.stats.work},
                          {"clipping_steps", r.stats.clipping_steps},
                          {"subdivisions", r.stats.subdivisions},
                          {"candidate_boxes", r.stats.candidate_boxes},
                          {"compensated_steps", r.stats.compensated_steps},
                          {"newton_iterations", r.stats.newton_iterations},
                          {"max_depth", r.stats.max_depth}};
  if (r.stats.method == core::IntersectMethod::hybrid)
    stats["fat_curve_degree"] = request.options.fat_curve_degree;
  return json_reply({{"intersections", std::move(intersections)},
                     {"overlaps", std::move(overlaps)},
                     {"tolerance", request.options.tolerance},
                     {"stats", std::move(stats)}});
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
  if (!(w > 0) || budget <= 0) return {x, 0, 0};
  core::IntersectOptions local = options;
  local.max_work = budget;
  const core::IntersectionResult r =
      core::intersect_in(curve, curve, {std::max(0.0, pair.t - w), std::min(1.0, pair.t + w)},
                         {std::max(0.0, pair.s - w), std::min(1.0, pair.s + w)}, local);
  if (r.status != core::IntersectStatus::ok || r.intersections.size() != 1)
    return {x, r.stats.work, r.stats.iterations};
  return {r.intersections.front(), r.stats.work, r.stats.iterations};
}

Reply one_curve_answer(const IntersectionsRequest& request, const Limits& limits) {
  const core::Curve& curve = request.curves[0];
  core::SelfIntersectionOptions options;
  options.max_work = core::self_intersection_box_budget(limits.max_work, curve.degree());
  const core::SelfIntersectionResult r = core::self_intersections(curve, options);
  if (r.status == core::SelfIntersectionStatus::work_cap_reached)
    return self_work_cap_reply(r.stats.work, limits);
  // The certification searches share what the self-intersection search left of the budget;
  // a pair they cannot certify within it is reported as found, unresolved.
  const std::int64_t search_units = r.stats.work * core::self_intersection_box_cost(curve.degree());
  std::int64_t certification_work = 0, certification_steps = 0;
  nlohmann::json intersections = nlohmann::json::array();
  for (const core::SelfIntersection& pair : r.pairs) {
    const CertifiedPair c = certified_pair(curve, pair, request.options,
                                           limits.max_work - search_units - certification_work);
    certification_work += c.work;
    certification_steps += c.steps;
    intersections.push_back(intersection_json(c.intersection));
  }
  nlohmann::json overlaps = nlohmann::json::array();
  for (const core::SelfOverlap& o : r.overlaps) {
    // The pieces run the same way when B(t_lo) is B(s_lo), backwards when it is B(s_hi).
    const core::Point2 a = core::evaluate(curve, o.t_lo);
    const double same = core::length(a - core::evaluate(curve, o.s_lo));
    const double opposite = core::length(a - core::evaluate(curve, o.s_hi));
    overlaps.push_back({{"t_interval", pair_json(o.t_lo, o.t_hi)},
                        {"s_interval", pair_json(o.s_lo, o.s_hi)},
                        {"reversed", opposite < same}});
  }
  return json_reply({{"intersections", std::move(intersections)},
                     {"overlaps", std::move(overlaps)},
                     {"tolerance", request.options.tolerance},
                     {"stats",
                      {{"method", core::method_name(r.stats.method)},
                       {"work", r.stats.work},
                       {"max_depth", r.stats.max_depth},
                       {"newton_iterations", r.stats.newton_iterations},
                       {"certification_iterations", certification_steps}}}});
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
  if (!reader.ok()) return validation_reply(reader.take_errors());
  return parsed.curves.size() == 1 ? one_curve_answer(parsed, limits)
                                    : two_curves_answer(parsed, limits);
}

}  // namespace bezier::api
