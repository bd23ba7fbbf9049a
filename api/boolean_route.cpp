// POST /boolean (api/openapi.yaml, DESIGN.md §8): union, intersection, difference, xor of
// two regions, or simplify of one, as contours made of pieces of the input segments.
//
// Request:  {"op": "union" | "intersection" | "difference" | "xor" | "simplify",
//            "a": operand, "b": operand, "arc_tolerance"}
//   operand  {"path": SVG path data, "fill_rule"} or {"curves": [[[x, y], ...], ...],
//            "fill_rule"} (api/read_region.hpp); "b" is required except with "simplify",
//            which refuses it.
//   arc_tolerance  optional, > 0, when an operand has "path": the distance within which
//            the operands' elliptical arcs become cubics (api/curve_or_path.hpp).
// Answer:
//   {"arc_tolerance"?: when an operand's path had elliptical arcs, the largest distance of
//            their cubics from them (the operation is the cubics'),
//    "area": the result's area (>= 0, 0 when empty),
//    "contours": [{"area" (signed: > 0 outer, counter-clockwise with y up; < 0 hole),
//                  "orientation": "ccw" | "cw", "segments": [first, end)}],
//    "path": the contours as SVG path data ("" when empty; null when a segment has degree 4
//            or more, which path data cannot write),
//    "segments": [{"degree", "points", "segment", "source": "a" | "b", "t": [t0, t1]}],
//    "stats": {"work"}}
//   Each segment is the piece of segment `segment` of its source operand between t0 and t1
//   (t0 > t1: run backwards), its interior control points exactly core::portion's and its
//   ends the contour's shared vertices (core/region/boolean.hpp). Segments are numbered as
//   the operand's region numbers them: in drawing order, the line that closes an open
//   subpath for filling counted after that subpath's last segment.
// Errors: 422 validation problems with JSON Pointers; 422 work-cap problem when the
// operation needs more than limits.max_work work units; 422 at "" when no ray could decide
// the side windings of an edge (boundaries within about 2^-40 of scale of a vertex
// everywhere; see core/region/side_winding.hpp).

#include <algorithm>
#include <array>
#include <charconv>
#include <optional>
#include <string>
#include <utility>

#include "api/curve_or_path.hpp"
#include "api/read_json.hpp"
#include "api/read_region.hpp"
#include "api/routes.hpp"
#include "api/write_json.hpp"
#include "core/region/boolean.hpp"

namespace bezier::api {

namespace {

constexpr std::array<std::string_view, 5> kOperationNames = {"union", "intersection",
                                                             "difference", "xor", "simplify"};
constexpr std::array<region::BooleanOperation, 5> kOperations = {
    region::BooleanOperation::union_, region::BooleanOperation::intersection,
    region::BooleanOperation::difference, region::BooleanOperation::xor_,
    region::BooleanOperation::simplify};

void append_number(double v, std::string& out) {
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  out.append(buffer, ec == std::errc() ? end : buffer);
}

void append_point(core::Point2 p, std::string& out) {
  append_number(p.x, out);
  out += ' ';
  append_number(p.y, out);
}

/// The contours as SVG path data: "M" at each contour's start, "L", "Q" or "C" per segment
/// with its control points after the first, "Z" (which adds no segment: the last segment
/// ends exactly at the start). Numbers in the shortest form that reads back to the same
/// double, so the data parses back to the same segments. nullopt when a segment has degree
/// 4 or more.
std::optional<std::string> path_data(const region::BooleanResult& result) {
  std::string out;
  for (const region::ResultContour& c : result.contours) {
    if (!out.empty()) out += ' ';
    out += 'M';
    append_point(result.segments[c.first_segment].curve.front(), out);
    for (std::size_t k = c.first_segment; k < c.end_segment; ++k) {
      const core::Curve& curve = result.segments[k].curve;
      const int n = curve.degree();
      if (n > 3) return std::nullopt;
      out += n == 1 ? " L" : n == 2 ? " Q" : " C";
      for (int i = 1; i <= n; ++i) {
        if (i > 1) out += ' ';
        append_point(curve[i], out);
      }
    }
    out += " Z";
  }
  return out;
}

Reply answer(const region::BooleanResult& result, std::optional<double> arc_tolerance) {
  // {"arc_tolerance"?, "area", "contours": [{"area", "orientation", "segments"}], "path", "segments":
  //  [{"degree", "points", "segment", "source", "t"}], "stats": {"work"}}, members in key
  // order (the text a document of the answer would dump to).
  JsonWriter w;
  w.begin_object();
  write_arc_tolerance(w, arc_tolerance);
  w.key("area").value(result.area);
  w.key("contours").begin_array();
  for (const region::ResultContour& c : result.contours) {
    w.begin_object();
    w.key("area").value(c.area);
    w.key("orientation").value(c.area > 0 ? "ccw" : "cw");
    w.key("segments").begin_array();
    w.value(static_cast<std::int64_t>(c.first_segment));
    w.value(static_cast<std::int64_t>(c.end_segment));
    w.end_array();
    w.end_object();
  }
  w.end_array();
  const std::optional<std::string> data = path_data(result);
  if (data) {
    w.key("path").value(std::string_view(*data));
  } else {
    w.key("path").null();
  }
  w.key("segments").begin_array();
  for (const region::ResultSegment& s : result.segments) {
    w.begin_object();
    w.key("degree").value(s.curve.degree());
    write_points(w.key("points"), s.curve.points());
    w.key("segment").value(static_cast<std::int64_t>(s.segment));
    w.key("source").value(s.source == region::Operand::a ? "a" : "b");
    w.key("t").pair(s.t0, s.t1);
    w.end_object();
  }
  w.end_array();
  w.key("stats").begin_object();
  w.key("work").value(result.work);
  w.end_object();
  w.end_object();
  return json_reply(std::move(w));
}

}  // namespace

Reply boolean_route(const nlohmann::json& request, const Limits& limits) {
  RequestReader reader(limits);
  reader.reject_unknown_fields(request, {"op", "a", "b", "arc_tolerance"}, "");
  const std::optional<double> arc_tolerance = read_arc_tolerance(reader, request);
  std::optional<region::BooleanOperation> op;
  if (const Json* value = reader.required(request, "op", "")) {
    const auto name = reader.one_of(*value, "/op",
                                    {kOperationNames[0], kOperationNames[1], kOperationNames[2],
                                     kOperationNames[3], kOperationNames[4]});
    for (std::size_t k = 0; name && k < kOperationNames.size(); ++k) {
      if (*name == kOperationNames[k]) op = kOperations[k];
    }
  }
  std::optional<region::Region> a, b;
  if (const Json* value = reader.required(request, "a", "")) {
    if (value->is_object()) {
      reader.reject_unknown_fields(*value, {kRegionFields[0], kRegionFields[1], kRegionFields[2]}, "/a");
    }
    a = read_region(reader, *value, "/a", arc_tolerance);
  }
  const Json* b_value = RequestReader::optional(request, "b");
  if (op == region::BooleanOperation::simplify) {
    if (b_value != nullptr) reader.fail("/b", "simplify takes one operand, \"a\"");
  } else if (op) {
    if (const Json* value = reader.required(request, "b", "")) {
      if (value->is_object()) {
        reader.reject_unknown_fields(*value, {kRegionFields[0], kRegionFields[1], kRegionFields[2]}, "/b");
      }
      b = read_region(reader, *value, "/b", arc_tolerance);
    }
  }
  const auto operand_has_path = [&](std::string_view key) {
    const Json* value = RequestReader::optional(request, key);
    return value != nullptr && value->is_object() && has_path(*value);
  };
  refuse_arc_tolerance_without_path(reader, request, operand_has_path("a") || operand_has_path("b"));
  if (!reader.ok()) return reader.refusal();
  core::WorkBudget budget(limits.max_work);
  const region::BooleanResult result =
      *op == region::BooleanOperation::simplify
          ? region::simplify(*a, budget)
          : region::boolean_operation(*op, *a, *b, budget);
  if (budget.exhausted()) {
    return problem_reply(ProblemKind::work_cap,
                         "the boolean operation spent " + std::to_string(result.work) +
                             " work units without finishing, beyond the per-request work cap of " +
                             std::to_string(limits.max_work) + " units");
  }
  if (result.status == region::BooleanStatus::unresolved) {
    return problem_reply(ProblemKind::validation,
                         "the operands' boundaries come so close to their vertices that no "
                         "ray could decide which side of an edge is inside",
                         {{"", "the boolean operation could not be decided for these operands"}});
  }
  std::optional<double> arcs_followed = a->path.arc_tolerance;
  if (b && b->path.arc_tolerance) {
    arcs_followed = std::max(arcs_followed.value_or(0.0), *b->path.arc_tolerance);
  }
  return answer(result, arcs_followed);
}

}  // namespace bezier::api
