// POST /nearest (api/openapi.yaml): for each target, the point of a planar or space curve of any
// degree nearest to it on a parameter interval (the global minimum of the distance).
//
// Request:  {"points": [[x, y], ...] or [[x, y, z], ...], "targets": [[x, y], ...],
//            "interval": [a, b]}
//   targets   1 to max_t_values points of the curve's dimension, finite.
//   interval  optional, 0 <= a <= b <= 1, default [0, 1].
// Answer:   {"degree", "interval": [a, b],
//            "results": [{"distance", "point", "t", "target", "ties": [t, ...]}]}
//   one result per target, in order: t the smallest parameter attaining the least distance
//   over [a, b] (ends included), B(t), the distance, and the other parameters that tie with
//   it to 1e-12 relative (core/measure/nearest.hpp).
// With {"path": SVG path data} instead of points (2-D targets, no interval): the
// nearest point of the whole path,
//   {"results": [{"distance", "point", "segment", "t", "target",
//                 "ties": [{"segment", "t"}, ...]}], "segment_count"}
//   the least distance over every segment; the lowest segment (then the smallest t)
//   attaining it, the others that tie with it to the same tolerance in `ties`, a joint
//   once (on the lower segment).
// A path's elliptical arcs are cubics within "arc_tolerance" (a request field, > 0; default
// 1e-6 of each arc's larger radius), and the answer then begins with "arc_tolerance": the
// distance they keep (api/curve_or_path.hpp).
// Errors: 422 validation problems with JSON Pointers; 422 work-cap problem when targets
// times the cost of one target's search (on a path: on every segment) exceeds
// limits.max_work.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "api/curve_or_path.hpp"
#include "api/parameter_interval.hpp"
#include "api/read_json.hpp"
#include "api/read_targets.hpp"
#include "api/routes.hpp"
#include "api/write_json.hpp"
#include "core/curve/evaluate.hpp"
#include "core/measure/nearest.hpp"

namespace bezier::api {

namespace {

// {"degree", "interval", "results": [{"distance", "point", "t", "target", "ties"}]}, members
// in key order (the text a document of the answer would dump to).
template <class P>
Reply nearest_answer(const core::BasicCurve<P>& curve, const std::vector<P>& targets,
                     ParameterInterval interval) {
  JsonWriter w;
  w.begin_object();
  w.key("degree").value(curve.degree());
  w.key("interval").pair(interval.a, interval.b);
  w.key("results").begin_array();
  for (const P& target : targets) {
    const core::NearestPoint<P> found = core::nearest(curve, target, interval.a, interval.b);
    w.begin_object();
    w.key("distance").value(found.distance);
    write_point(w.key("point"), found.point);
    w.key("t").value(found.t);
    write_point(w.key("target"), target);
    w.key("ties").begin_array();
    for (const double t : found.ties) w.value(t);
    w.end_array();
    w.end_object();
  }
  w.end_array();
  w.end_object();
  return json_reply(std::move(w));
}

template <class P>
Reply read_and_answer(RequestReader& reader, const core::BasicCurve<P>& curve,
                      const Json& request, const std::optional<ParameterInterval>& interval) {
  std::optional<std::vector<P>> targets;
  if (const auto* value = reader.required(request, "targets", "")) {
    targets = read_targets<P>(reader, *value, ", the curve's dimension");
  }
  if (!reader.ok()) return reader.refusal();
  const std::int64_t work = static_cast<std::int64_t>(targets->size()) * core::nearest_work(curve.degree());
  if (work > reader.limits().max_work) {
    return problem_reply(ProblemKind::work_cap,
                         std::to_string(targets->size()) + " targets on a curve of degree " +
                             std::to_string(curve.degree()) + " need about " + std::to_string(work) +
                             " work units, above the cap of " + std::to_string(reader.limits().max_work) +
                             ": send fewer targets per request");
  }
  return nearest_answer(curve, *targets, *interval);
}

/// A point of a path at the least distance: on `segment` at `t`.
struct PathCandidate {
  std::size_t segment = 0;
  double t = 0.0;
  double distance = 0.0;
  core::Point2 point;
};

// {"arc_tolerance"?, "results": [{"distance", "point", "segment", "t", "target", "ties"}],
//  "segment_count"}, members in key order.
Reply path_nearest_answer(const path::Path& p, const std::vector<core::Point2>& targets) {
  double path_scale = 0.0;
  for (const core::Curve& segment : p.segments) path_scale = std::max(path_scale, core::scale(segment));
  JsonWriter w;
  w.begin_object();
  write_arc_tolerance(w, p.arc_tolerance);
  w.key("results").begin_array();
  for (const core::Point2 target : targets) {
    std::vector<PathCandidate> candidates;
    double least = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < p.segments.size(); ++k) {
      const core::NearestPoint<core::Point2> found = core::nearest(p.segments[k], target, 0.0, 1.0);
      candidates.push_back({k, found.t, found.distance, found.point});
      for (const double t : found.ties) {
        candidates.push_back({k, t, found.distance, core::evaluate(p.segments[k], t)});
      }
      least = std::min(least, found.distance);
    }
    // The tolerance core::nearest ties its own candidates with, over the whole path.
    const double scale = std::max(path_scale, core::max_abs_coordinate(target));
    const double tolerance =
        std::max(1e-12 * least, 8 * std::numeric_limits<double>::epsilon() / 2 * scale);
    std::erase_if(candidates, [&](const PathCandidate& c) { return c.distance > least + tolerance; });
    // A joint attains the distance at t = 1 of one segment and t = 0 of the next: once.
    std::erase_if(candidates, [&](const PathCandidate& c) {
      if (c.t != 0.0) return false;
      return std::any_of(candidates.begin(), candidates.end(), [&](const PathCandidate& d) {
        return d.t == 1.0 && path::next_segment(p, d.segment) == c.segment && d.segment < c.segment;
      });
    });
    std::erase_if(candidates, [&](const PathCandidate& c) {
      if (c.t != 1.0) return false;
      return std::any_of(candidates.begin(), candidates.end(), [&](const PathCandidate& d) {
        return d.t == 0.0 && path::next_segment(p, c.segment) == d.segment && d.segment < c.segment;
      });
    });
    const PathCandidate& best = candidates.front();
    w.begin_object();
    w.key("distance").value(least);
    write_point(w.key("point"), best.point);
    w.key("segment").value(static_cast<std::int64_t>(best.segment));
    w.key("t").value(best.t);
    write_point(w.key("target"), target);
    w.key("ties").begin_array();
    for (std::size_t i = 1; i < candidates.size(); ++i) {
      w.begin_object();
      w.key("segment").value(static_cast<std::int64_t>(candidates[i].segment));
      w.key("t").value(candidates[i].t);
      w.end_object();
    }
    w.end_array();
    w.end_object();
  }
  w.end_array();
  w.key("segment_count").value(static_cast<std::int64_t>(p.segments.size()));
  w.end_object();
  return json_reply(std::move(w));
}

Reply read_path_and_answer(RequestReader& reader, const Json& request) {
  const std::optional<path::Path> p = read_request_path(reader, request);
  std::optional<std::vector<core::Point2>> targets;
  if (const auto* value = reader.required(request, "targets", "")) {
    targets = read_targets<core::Point2>(reader, *value, ", the curve's dimension");
  }
  if (!reader.ok()) return reader.refusal();
  std::int64_t per_target = 0;
  for (const core::Curve& segment : p->segments) per_target += core::nearest_work(segment.degree());
  const std::int64_t work = static_cast<std::int64_t>(targets->size()) * per_target;
  if (work > reader.limits().max_work) {
    return problem_reply(ProblemKind::work_cap,
                         std::to_string(targets->size()) + " targets on a path of " +
                             std::to_string(p->segments.size()) + " segments need about " +
                             std::to_string(work) + " work units, above the cap of " +
                             std::to_string(reader.limits().max_work) +
                             ": send fewer targets or a shorter path per request");
  }
  return path_nearest_answer(*p, *targets);
}

}  // namespace

Reply nearest_route(const nlohmann::json& request, const Limits& limits) {
  RequestReader reader(limits);
  reader.reject_unknown_fields(request, {"points", "path", "arc_tolerance", "targets", "interval"},
                               "");
  if (has_path(request)) return read_path_and_answer(reader, request);
  refuse_arc_tolerance_without_path(reader, request, false);
  const auto curve = reader.request_curve(request);
  const auto interval = read_parameter_interval(reader, request);
  if (!curve) {
    // The targets' dimension is the curve's: without a curve, only their presence is checked.
    if (RequestReader::optional(request, "targets") == nullptr) {
      reader.fail("/targets", "required field is missing");
    }
    return reader.refusal();
  }
  return std::visit([&](const auto& c) { return read_and_answer(reader, c, request, interval); },
                    *curve);
}

}  // namespace bezier::api
