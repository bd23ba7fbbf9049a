// POST /length (api/openapi.yaml): the arc length of a planar or space curve of any degree on a
// parameter interval, and the parameters at given lengths.
//
// Request:  {"points": [[x, y], ...] or [[x, y, z], ...], "interval": [a, b],
//            "at_lengths": [l, ...]}   (interval and at_lengths optional)
//   interval    0 <= a <= b <= 1, default [0, 1].
//   at_lengths  1 to max_t_values numbers, each in [0, length] (a value above the length by
//               more than its error bound is refused at its pointer).
// Answer:   {"degree", "error_bound", "interval": [a, b], "length",
//            "parameters": [{"length", "point", "t"}] (with at_lengths, in their order)}
//   length       ∫_a^b |B'(t)| dt within 1e-12 relative; error_bound the bound it met
//                (core/measure/arc_length.hpp).
//   parameters   the t in [a, b] with length(a, t) = l, and B(t).
// With {"path": SVG path data} instead of points (no interval): the length of the
// whole path, the sum of its segments' (each measured as above),
//   {"error_bound": Σ, "length": Σ, "parameters": [{"length", "point", "segment", "t"}],
//    "segment_count", "segment_lengths": [...]}
//   parameters   the segment holding length l from the path's start (the first one whose
//                cumulative length reaches l) and its t there.
// The quadratures (every segment's, for a path) are charged to the work cap as they evaluate
// (core/measure/arc_length.hpp).
// A path's elliptical arcs are cubics within "arc_tolerance" (a request field, > 0; default
// 1e-6 of each arc's larger radius), and the answer then begins with "arc_tolerance": the
// distance they keep (api/curve_or_path.hpp).
// Errors: 422 validation problems with JSON Pointers; 422 work-cap problem when the
// quadrature does not reach its accuracy within the work cap (or with pieces as narrow as
// doubles allow).

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "api/curve_or_path.hpp"
#include "api/parameter_interval.hpp"
#include "api/read_json.hpp"
#include "api/routes.hpp"
#include "api/write_json.hpp"
#include "core/curve/evaluate.hpp"
#include "core/measure/arc_length.hpp"

namespace bezier::api {

namespace {

std::string format_number(double v) {
  std::string out;
  append_json_number(v, out);
  return out;
}

/// Refuses, each at its pointer, every length of `at_lengths` beyond `length` by more than
/// its error bound: up to there a length is the end (a client may send back the length it
/// was given). `what` names what was measured.
void refuse_lengths_beyond(RequestReader& reader, const std::vector<double>& at_lengths, double length,
                           double error_bound, const char* what) {
  for (std::size_t i = 0; i < at_lengths.size(); ++i) {
    if (at_lengths[i] > length + error_bound) {
      reader.fail(pointer_to("/at_lengths", i),
                  std::string("beyond the length of ") + what + " (" + format_number(length) + ")");
    }
  }
}

/// Why a quadrature stopped short of its accuracy: the work cap, or its worst piece as narrow
/// as doubles allow.
std::string not_met_because(const core::WorkBudget& budget, const Limits& limits) {
  return budget.exhausted() ? "within the per-request work cap of " +
                                  std::to_string(limits.max_work) + " units"
                            : "with pieces as narrow as doubles allow";
}

template <class P>
Reply length_answer(RequestReader& reader, const core::BasicCurve<P>& curve,
                    ParameterInterval interval, const std::optional<std::vector<double>>& at_lengths) {
  core::WorkBudget budget = request_budget(reader.limits());
  const core::ArcLength measured =
      core::arc_length(curve, interval.a, interval.b, core::ArcLengthOptions{}, budget);
  if (!measured.tolerance_met) {
    return problem_reply(ProblemKind::work_cap,
                         "the arc length did not reach its 1e-12 relative accuracy " +
                             not_met_because(budget, reader.limits()) + " (error bound " +
                             format_number(measured.error_bound) + " for length " +
                             format_number(measured.length) + ")");
  }
  if (at_lengths) {
    refuse_lengths_beyond(reader, *at_lengths, measured.length, measured.error_bound, "the curve on the interval");
    if (!reader.ok()) return reader.refusal();
  }
  // {"degree", "error_bound", "interval", "length", "parameters"?: [{"length", "point", "t"}]},
  // members in key order (the text a document of the answer would dump to).
  JsonWriter w;
  w.begin_object();
  w.key("degree").value(curve.degree());
  w.key("error_bound").value(measured.error_bound);
  w.key("interval").pair(interval.a, interval.b);
  w.key("length").value(measured.length);
  if (at_lengths) {
    w.key("parameters").begin_array();
    for (const double l : *at_lengths) {
      const double t = core::parameter_at_length(curve, measured, l);
      w.begin_object();
      w.key("length").value(l);
      write_point(w.key("point"), core::evaluate(curve, t));
      w.key("t").value(t);
      w.end_object();
    }
    w.end_array();
  }
  w.end_object();
  return json_reply(std::move(w));
}

Reply path_length_answer(RequestReader& reader, const path::Path& p,
                         const std::optional<std::vector<double>>& at_lengths) {
  std::vector<core::ArcLength> measured;
  measured.reserve(p.segments.size());
  double total = 0.0, error_bound = 0.0;
  core::WorkBudget budget = request_budget(reader.limits());
  for (std::size_t k = 0; k < p.segments.size(); ++k) {
    measured.push_back(core::arc_length(p.segments[k], 0.0, 1.0, core::ArcLengthOptions{}, budget));
    if (budget.exhausted()) {
      return problem_reply(ProblemKind::work_cap,
                           "the arc lengths of the path's first " + std::to_string(k + 1) +
                               " segments took " + std::to_string(budget.spent()) +
                               " work units, beyond the per-request work cap of " +
                               std::to_string(reader.limits().max_work) +
                               " units: send a shorter path per request");
    }
    if (!measured.back().tolerance_met) {
      return problem_reply(ProblemKind::work_cap,
                           "the arc length of segment " + std::to_string(k) +
                               " did not reach its 1e-12 relative accuracy " +
                               not_met_because(budget, reader.limits()));
    }
    total += measured.back().length;
    error_bound += measured.back().error_bound;
  }
  if (at_lengths) {
    refuse_lengths_beyond(reader, *at_lengths, total, error_bound, "the path");
    if (!reader.ok()) return reader.refusal();
  }
  // {"arc_tolerance"?, "error_bound", "length", "parameters"?: [{"length", "point",
  //  "segment", "t"}], "segment_count", "segment_lengths"}, members in key order.
  JsonWriter w;
  w.begin_object();
  write_arc_tolerance(w, p.arc_tolerance);
  w.key("error_bound").value(error_bound);
  w.key("length").value(total);
  if (at_lengths) {
    w.key("parameters").begin_array();
    for (const double l : *at_lengths) {
      // The first segment whose cumulative length reaches l (the last one for l beyond the
      // rounded total), and the rest of l on it.
      std::size_t k = 0;
      double before = 0.0;
      while (k + 1 < measured.size() && before + measured[k].length < l) {
        before += measured[k].length;
        ++k;
      }
      const double local = std::max(0.0, l - before);
      const double t = core::parameter_at_length(p.segments[k], measured[k], local);
      w.begin_object();
      w.key("length").value(l);
      write_point(w.key("point"), core::evaluate(p.segments[k], t));
      w.key("segment").value(static_cast<std::int64_t>(k));
      w.key("t").value(t);
      w.end_object();
    }
    w.end_array();
  }
  w.key("segment_count").value(static_cast<std::int64_t>(p.segments.size()));
  w.key("segment_lengths").begin_array();
  for (const core::ArcLength& m : measured) w.value(m.length);
  w.end_array();
  w.end_object();
  return json_reply(std::move(w));
}

std::optional<std::vector<double>> read_at_lengths(RequestReader& reader, const Json& request) {
  if (const auto* value = RequestReader::optional(request, "at_lengths")) {
    return reader.numbers(*value, "/at_lengths", 0.0, std::numeric_limits<double>::max());
  }
  return std::nullopt;
}

}  // namespace

Reply length_route(const nlohmann::json& request, const Limits& limits) {
  RequestReader reader(limits);
  reader.reject_unknown_fields(request, {"points", "path", "arc_tolerance", "interval", "at_lengths"}, "");
  if (has_path(request)) {
    const std::optional<path::Path> p = read_request_path(reader, request);
    const auto at_lengths = read_at_lengths(reader, request);
    if (!reader.ok()) return reader.refusal();
    return path_length_answer(reader, *p, at_lengths);
  }
  refuse_arc_tolerance_without_path(reader, request, false);
  const auto curve = reader.request_curve(request);
  const auto interval = read_parameter_interval(reader, request);
  const auto at_lengths = read_at_lengths(reader, request);
  if (!reader.ok()) return reader.refusal();
  return std::visit([&](const auto& c) { return length_answer(reader, c, *interval, at_lengths); },
                    *curve);
}

}  // namespace bezier::api
