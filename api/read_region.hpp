#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "api/read_json.hpp"
#include "core/region/region.hpp"

namespace bezier::api {

/// The members of an operand object that read_region reads; a route lists them among its
/// known fields (RequestReader::reject_unknown_fields) with its own.
inline constexpr std::string_view kRegionFields[] = {"path", "curves", "fill_rule"};

/// A region operand (DESIGN.md §8) from the object at `pointer`:
///   {"path": "<SVG path data>", "fill_rule": "nonzero" | "evenodd"}, or
///   {"curves": [[[x, y], ...], ...], "fill_rule": ...}
/// exactly one of `path` and `curves` (null is refused, not taken for absent); `fill_rule`
/// optional (default "nonzero"), anything else (null included) refused at
/// <pointer>/fill_rule.
///   path    SVG path data (read_path; "" or data that draws nothing is the empty region);
///           every open subpath is closed for filling (region::region_from_path); its
///           elliptical arcs become cubics within `arc_tolerance` (nullopt: the parser's
///           default), and the region's path.arc_tolerance says what they kept.
///   curves  0 to limits().max_path_segments curves of degree 1 to limits().max_degree
///           (RequestReader::curve2 each); each starts exactly at the end of the one before,
///           except after a curve that closed its chain (ended where the chain started);
///           a curve that breaks this is refused at <pointer>/curves/k; a last open chain
///           is closed by a line (region::region_from_curves).
/// Every problem is recorded at its pointer; nullopt when any was.
std::optional<region::Region> read_region(RequestReader& reader, const Json& object,
                                          const std::string& pointer,
                                          std::optional<double> arc_tolerance);

}  // namespace bezier::api
