#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/intersect/options.hpp"
#include "core/intersect/result.hpp"
#include "core/path/path.hpp"
#include "core/path/path_contact.hpp"
#include "core/self_intersect/self_intersection.hpp"

namespace bezier::path {

/// What a path search cost.
struct PathSearchStats {
  /// The two-curve searches' stats summed over the segment pairs searched (method as asked).
  core::IntersectStats pairs;
  /// Segment pairs whose control boxes meet: the pairs searched.
  std::int64_t candidate_pairs = 0;
  /// Work units spent in all: the box sweep, each pair's setup and search, and (one path)
  /// the segments' own self-intersection searches.
  std::int64_t work = 0;
};

/// Every intersection and overlap of two paths.
struct PathIntersectionResult {
  /// Sorted by (segment_t, t, segment_s, s); a contact at a joint appears once.
  std::vector<PathContact> intersections;
  /// Sorted by (segment_t, t_interval.lo, segment_s).
  std::vector<PathOverlap> overlaps;
  PathSearchStats stats;
  /// ok, work_cap_reached (the lists then hold what was found) or tolerance_too_small.
  core::IntersectStatus status = core::IntersectStatus::ok;
};

/// Every intersection of a segment of `a` with a segment of `b`, each as the two-curve
/// search core::intersect reports it (guaranteed intervals, kind, overlaps), with the
/// segments that hold t and s. Only the segment pairs whose control boxes meet are
/// searched (meeting_boxes: a sweep, O(N log N + the pairs that meet));
/// the others cannot meet. A contact at a joint of either path, found on the segments on
/// both sides of it, is reported once, with the lower segment index (without_joint_copies).
/// options.max_work bounds the whole call: the sweep, a setup charge per pair searched
/// (one step_cost of the two degrees) and every search share it; running out gives
/// work_cap_reached. Precondition: finite coordinates.
[[nodiscard]] PathIntersectionResult intersect(const Path& a, const Path& b,
                                               const core::IntersectOptions& options);

/// One segment's own self-intersections (t < s on that segment).
struct SegmentSelfIntersections {
  std::size_t segment = 0;
  core::SelfIntersectionResult result;
};

/// The self-intersections of one path.
struct PathSelfIntersectionResult {
  /// Contacts between two different segments, segment_t < segment_s, sorted by
  /// (segment_t, t, segment_s, s).
  std::vector<PathContact> intersections;
  std::vector<PathOverlap> overlaps;
  /// The segments that cross or retrace themselves, in order, with core::self_intersections'
  /// results (pairs without guaranteed intervals: the caller may certify them).
  std::vector<SegmentSelfIntersections> within_segments;
  PathSearchStats stats;
  core::IntersectStatus status = core::IntersectStatus::ok;
};

/// Every self-intersection of a path: each pair of different segments whose control boxes
/// meet, searched as two curves, and each segment against itself (core::self_intersections,
/// the box budget from what is left of options.max_work). Not intersections: the joint two
/// consecutive segments of a subpath share, and the start of a closed subpath meeting its
/// end (two consecutive segments still meet anywhere else, e.g. where a cubic loops back
/// across the line before it). A contact at a joint of other segments is reported once.
/// Zero-length segments add nothing: their point is a joint of their neighbours. One work
/// budget for the whole call, as for two paths. Precondition: finite coordinates.
[[nodiscard]] PathSelfIntersectionResult self_intersections(const Path& path,
                                                            const core::IntersectOptions& options);

}  // namespace bezier::path
