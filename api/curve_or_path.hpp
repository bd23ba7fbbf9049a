#pragma once

#include <optional>
#include <string>
#include <variant>

#include "api/read_json.hpp"
#include "api/write_json.hpp"
#include "core/base/curve.hpp"
#include "core/path/path.hpp"
#include "core/path/svg_path_data.hpp"

namespace bezier::api {

/// What a route takes where the API lets a path stand for a curve: control points
/// {"points": [[x, y], ...]} or SVG path data {"path": "M0 0 C..."}.
using CurveOrPath = std::variant<core::Curve, path::Path>;

/// The request member `arc_tolerance` (at /arc_tolerance): the absolute distance within which
/// the cubics of a path's elliptical arcs follow them (core/path/elliptical_arc.hpp), a
/// finite number > 0; nullopt when absent (each arc then keeps 1e-6 of its larger radius).
/// A request with `arc_tolerance` and no `path` anywhere is refused at /arc_tolerance by
/// refuse_arc_tolerance_without_path.
std::optional<double> read_arc_tolerance(RequestReader& reader, const Json& request);
void refuse_arc_tolerance_without_path(RequestReader& reader, const Json& request, bool any_path);

/// `"arc_tolerance": d` when the path drew elliptical arcs (Path::arc_tolerance), the
/// tolerance the answer's arcs were drawn within; nothing otherwise. It comes first among
/// an answer's members in key order.
void write_arc_tolerance(JsonWriter& w, const std::optional<double>& arc_tolerance);

/// SVG path data (core/path/svg_path_data.hpp) as a path of at least one segment. A refusal
/// is recorded at `pointer` (the string's JSON Pointer); a pointer cannot reach inside a
/// string, so the message begins with the character offset where parsing stopped, then says
/// what was expected there ("offset 12: expected a number, found 'x'"). More segments than
/// limits().max_path_segments, or a segment above limits().max_degree, is a limit's refusal.
/// Elliptical arcs become cubics within `arc_tolerance` (read_arc_tolerance).
std::optional<path::Path> read_path(RequestReader& reader, const Json& value,
                                    const std::string& pointer,
                                    std::optional<double> arc_tolerance);

/// Whether read_parsed_path accepts path data that draws nothing (movetos alone, or empty).
enum class EmptyPath { refused, accepted };

/// read_path's parse, with what the parser records beside the path (the closing lines):
/// the same refusals, except that with EmptyPath::accepted data that draws no segment is a
/// path without segments.
std::optional<path::PathDataParse> read_parsed_path(RequestReader& reader, const Json& value,
                                                    const std::string& pointer,
                                                    std::optional<double> arc_tolerance,
                                                    EmptyPath empty);

/// The member `points` (a planar curve, RequestReader::curve2) or `path` (read_path) of the
/// object at `pointer`: exactly one of the two, else a refusal at `pointer`.
std::optional<CurveOrPath> read_curve_or_path(RequestReader& reader, const Json& object,
                                              const std::string& pointer,
                                              std::optional<double> arc_tolerance);

/// Whether `object` has a member `path` (null included: it is then refused as a path).
[[nodiscard]] bool has_path(const Json& object);

/// For the measuring routes (/length, /bounds, /nearest) with a request that has `path`:
/// the path (read_path at /path, arcs within the request's `arc_tolerance`), with `points`
/// beside it refused at /points and `interval` at /interval (a parameter interval is one
/// curve's).
std::optional<path::Path> read_request_path(RequestReader& reader, const Json& request);

/// A curve as a path of one segment (segment 0), or the path itself.
[[nodiscard]] path::Path as_path(CurveOrPath input);

}  // namespace bezier::api
