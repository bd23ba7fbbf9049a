// POST /segments (api/openapi.yaml): the Bézier segments SVG path data stands for, as every
// route taking a path reads it (api/curve_or_path.hpp, core/path/svg_path_data.hpp), so that
// a client needs no parser of its own.
//
// Request:  {"path": SVG path data, "arc_tolerance": d}   (arc_tolerance optional, > 0)
// Answer:   {"arc_tolerance"? (when the data has elliptical arcs: the distance their cubics
//            keep), "segment_count",
//            "segments": [{"closing", "degree", "points", "subpath"}],
//            "subpaths": [{"closed", "first_segment", "segment_count"}]}
//   segments   in drawing order over all subpaths (the numbering every answer about a path
//              uses); `closing` for the closing line a Z adds, `subpath` the index of the
//              subpath holding it.
//   subpaths   the runs of consecutive segments, `closed` when one ends exactly where it
//              starts.
// Data that draws nothing (movetos alone) answers no segments. The work is linear in the
// data and the segments made, both bounded by the body limit and max_path_segments: no
// work cap.
// Errors: 422 validation problems with JSON Pointers (path data refused at /path with the
// character offset, as on every path route).

#include <cstdint>

#include "api/curve_or_path.hpp"
#include "api/read_json.hpp"
#include "api/routes.hpp"
#include "api/write_json.hpp"

namespace bezier::api {

Reply segments_route(const nlohmann::json& request, const Limits& limits) {
  RequestReader reader(limits);
  reader.reject_unknown_fields(request, {"path", "arc_tolerance"}, "");
  const std::optional<double> arc_tolerance = read_arc_tolerance(reader, request);
  std::optional<path::PathDataParse> parse;
  if (const Json* data = reader.required(request, "path", "")) {
    parse = read_parsed_path(reader, *data, "/path", arc_tolerance, EmptyPath::accepted);
  }
  if (!reader.ok()) return reader.refusal();
  const path::Path& p = parse->path;

  // Members in key order (the text a document of the answer would dump to).
  JsonWriter w;
  w.begin_object();
  write_arc_tolerance(w, p.arc_tolerance);
  w.key("segment_count").value(static_cast<std::int64_t>(p.segments.size()));
  w.key("segments").begin_array();
  std::size_t closing = 0;
  for (std::size_t s = 0; s < p.subpaths.size(); ++s) {
    const path::Subpath& sub = p.subpaths[s];
    for (std::size_t k = sub.first_segment; k < sub.first_segment + sub.segment_count; ++k) {
      const bool is_closing = closing < parse->closing_lines.size() && parse->closing_lines[closing] == k;
      if (is_closing) ++closing;
      w.begin_object();
      w.key("closing").value(is_closing);
      w.key("degree").value(p.segments[k].degree());
      write_points(w.key("points"), p.segments[k].points());
      w.key("subpath").value(static_cast<std::int64_t>(s));
      w.end_object();
    }
  }
  w.end_array();
  w.key("subpaths").begin_array();
  for (const path::Subpath& sub : p.subpaths) {
    w.begin_object();
    w.key("closed").value(sub.closed);
    w.key("first_segment").value(static_cast<std::int64_t>(sub.first_segment));
    w.key("segment_count").value(static_cast<std::int64_t>(sub.segment_count));
    w.end_object();
  }
  w.end_array();
  w.end_object();
  return json_reply(std::move(w));
}

}  // namespace bezier::api
