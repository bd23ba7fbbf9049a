#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/path/path.hpp"

namespace bezier::path {

/// Why path data was refused.
enum class PathDataErrorKind {
  syntax,             ///< not SVG path data: `expected` says what the grammar wanted there
  out_of_range,       ///< a number, or a coordinate it leads to, beyond the double range
  too_many_segments,  ///< more segments than the caller's limit
};

/// Where and why parsing stopped. `offset` counts bytes from the start of the data; since
/// path data is ASCII and parsing stops at the first byte that is not, it is also the
/// offset in characters (and in UTF-16 code units) of the same place.
struct PathDataError {
  PathDataErrorKind kind = PathDataErrorKind::syntax;
  std::size_t offset = 0;
  /// For a syntax error, what the grammar expected at `offset` ("a number", "a command
  /// letter", ...); otherwise a short statement of the problem.
  std::string message;
};

/// A parsed path, or the first error (then `path` is empty).
struct PathDataParse {
  Path path;
  /// The segments that are the closing line of a Z (z), increasing.
  std::vector<std::size_t> closing_lines;
  std::optional<PathDataError> error;
};

/// Parses SVG path data (the `d` attribute; SVG 2, §9.3.9 "The grammar for path data",
/// https://www.w3.org/TR/SVG2/paths.html#PathDataBNF, which SVG 1.1 §8.3.9 agrees with
/// for these commands) into Bézier segments:
///
///   M m  start a subpath; further coordinate pairs are implicit L (l after m)
///   L l H h V v     a line: a segment of degree 1
///   C c S s         a cubic: degree 3; S's first control point is the reflection of the
///                   previous segment's second control point about the current point when
///                   that segment came from C, c, S or s, else the current point
///   Q q T t         a quadratic: degree 2; T's control point is the reflection of the
///                   previous segment's control point when that came from Q, q, T or t,
///                   else the current point (SVG 2 §9.5.2, §9.5.3)
///   A a             an elliptical arc: rx ry x-axis-rotation large-arc-flag sweep-flag x y,
///                   each flag the single character 0 or 1 ("a1 1 0 00 1 1" has flags 0 and
///                   0); cubic segments within `arc_tolerance` of the arc, a line for a zero
///                   radius, nothing when it ends where it starts (core/path/elliptical_arc.hpp,
///                   which follows SVG 2's arc implementation notes); Path::arc_tolerance
///                   states the largest distance the arcs' segments keep
///   Z z             close the subpath: a line back to its start when the current point is
///                   elsewhere (no segment when it is already there, except right after
///                   a moveto: `M1 1 Z` is a line of zero length, the zero-length subpath
///                   SVG 2 strokes as a dot under round and square caps,
///                   https://www.w3.org/TR/SVG2/painting.html#StrokeLinecapProperty); a
///                   command other than M after it starts the next subpath at the same
///                   start point
///
/// Lowercase commands are relative to the current point (a leading m to the origin). Any
/// command's arguments may repeat without repeating the letter. Numbers follow the SVG
/// grammar: an optional sign, digits with an optional fraction or a fraction alone, an
/// optional exponent (`1e-3`, `.5`, `-.5-.5` is two numbers, so is `.5.5`); arguments are
/// separated by whitespace and at most one comma, or by nothing where the next number's
/// sign or point ends the previous one. Commands are separated by optional whitespace.
/// Arcs are approximated by cubics: an exact ellipse is a rational curve, not a Bézier one.
///
/// Every segment drawn is kept, a zero-length one included, so that, arcs aside, segment k
/// is the k-th drawing command's (a closing line of Z counts; an arc draws as many segments
/// as its approximation takes). A subpath that draws nothing (`M1 1` alone, or an arc ending
/// where it starts with no Z after it) is left out. Data without any segment (empty, or
/// movetos only) is a path without segments. Parsing stops at the first error, which names
/// its offset and what was expected; more than `max_segments` segments is an error at the
/// command that draws the first one too many. `arc_tolerance` (> 0) is the absolute distance
/// each arc's cubics keep from it; nullopt means 1e-6 of each arc's larger radius. Time
/// linear in the length of the data plus the segments made.
[[nodiscard]] PathDataParse parse_svg_path_data(std::string_view data, std::size_t max_segments,
                                                std::optional<double> arc_tolerance = std::nullopt);

}  // namespace bezier::path
