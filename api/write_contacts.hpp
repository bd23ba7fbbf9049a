#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "api/write_json.hpp"
#include "core/intersect/result.hpp"
#include "core/path/path_contact.hpp"
#include "core/path/path_intersections.hpp"

namespace bezier::api {

// The JSON of what /intersections and /loop-area report where curves or paths meet: the
// segment pair of a path's contact, and overlaps (pieces two curves, or one curve with
// itself, share).

/// The segments of a path's contact: the one that holds t and the one that holds s.
struct SegmentPair {
  std::size_t t = 0;
  std::size_t s = 0;
};

/// "segments": [t, s].
void write_segments(JsonWriter& w, SegmentPair segments);

/// Whether an overlap's answer has `reversed` (its pieces run in opposite directions):
/// /intersections' overlaps have it, /loop-area's (a curve's retraced pieces) do not.
enum class OverlapDirection { written, left_out };

/// An overlap {"reversed"?, "s_interval", "segments"?, "t_interval"}, members in key
/// order; `segments` for an overlap of paths.
void write_overlap(JsonWriter& w, const core::Overlap& overlap, OverlapDirection direction,
                   std::optional<SegmentPair> segments = std::nullopt);

/// The overlaps of paths, each with its `segments`: those between two segments, then (for a
/// path with itself) the pieces each segment retraces of itself.
void write_path_overlaps(JsonWriter& w, const std::vector<path::PathOverlap>& between,
                              const std::vector<path::SegmentSelfIntersections>& within,
                              OverlapDirection direction);

}  // namespace bezier::api
