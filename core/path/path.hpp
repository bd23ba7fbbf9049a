#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "core/base/curve.hpp"

namespace bezier::path {

/// A run of consecutive segments of a path, each starting where the one before it ends:
/// the segments [first_segment, first_segment + segment_count) of its Path.
struct Subpath {
  std::size_t first_segment = 0;
  std::size_t segment_count = 0;
  /// The subpath ends exactly (bit for bit) where it starts, as a closepath command makes
  /// it end. A closed subpath encloses an area, and its last segment's end meets its first
  /// segment's start at a joint, not at an intersection.
  bool closed = false;
};

/// A path: Bézier segments in drawing order over all subpaths, and the subpaths that group
/// them. Invariants: every segment belongs to exactly one subpath, subpaths are listed in
/// order and each has at least one segment; inside a subpath, segment k + 1 starts exactly
/// at the end point of segment k.
struct Path {
  std::vector<core::Curve> segments;
  std::vector<Subpath> subpaths;
  /// When some segments stand for elliptical arcs of the path data (core/path/
  /// elliptical_arc.hpp): the largest distance within which such segments follow their arc
  /// (0 when every arc became nothing or an exact line); nullopt when the data had no arc.
  std::optional<double> arc_tolerance;
};

/// The segment that follows `segment` at its end point inside its subpath: the next one,
/// or for the last segment of a closed subpath its first; nullopt at the open end of a
/// subpath, and for a closed subpath of one segment (which meets itself, not a neighbour).
[[nodiscard]] std::optional<std::size_t> next_segment(const Path& path, std::size_t segment);

/// Whether segments i and j (i != j) share a joint: one follows the other in their subpath.
/// The point they share is then the end of one and the start of the other.
[[nodiscard]] bool adjacent(const Path& path, std::size_t i, std::size_t j);

/// The subpath that holds `segment` (precondition: segment < path.segments.size()).
[[nodiscard]] const Subpath& subpath_of(const Path& path, std::size_t segment);

}  // namespace bezier::path
