#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/base/work_budget.hpp"
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
  /// Segment pairs whose control boxes meet: the pairs searched, or settled without a
  /// search by a certified filter (joint_separation.hpp).
  std::int64_t candidate_pairs = 0;
  /// Work units charged in all: the box sweep, each pair's setup and search, and (one path)
  /// the segments' own self-intersection searches and their certification.
  std::int64_t work = 0;
  /// Search steps that certified the segments' own self-intersections
  /// (certified_self_intersections).
  std::int64_t certification_steps = 0;
};

/// Every intersection and overlap of two paths.
struct PathIntersectionResult {
  /// Sorted by (segment_t, t, segment_s, s); a contact at a joint appears once.
  std::vector<PathContact> intersections;
  /// Sorted by (segment_t, t_interval.lo, segment_s).
  std::vector<PathOverlap> overlaps;
  PathSearchStats stats;
  /// ok or tolerance_too_small (nothing is computed); work_cap_reached only from the
  /// overload without a budget.
  core::IntersectStatus status = core::IntersectStatus::ok;
};

/// Every intersection of a segment of `a` with a segment of `b`, each as the two-curve
/// search core::intersect reports it (guaranteed intervals, kind, overlaps), with the
/// segments that hold t and s. Only the segment pairs whose control boxes meet are
/// searched (meeting_boxes: a sweep, O(N log N + the pairs that meet));
/// the others cannot meet. A contact at a joint of either path, found on the segments on
/// both sides of it, is reported once, with the lower segment index (without_joint_copies).
/// `budget` bounds the whole call: the sweep (in work and in the memory of the pairs it
/// stores, meeting_boxes), a setup charge per pair searched (one step_cost of the two
/// degrees) and every search charge it. When it runs out (budget.exhausted()) the lists
/// hold what was found, unsorted, with joint copies. Precondition: finite coordinates.
[[nodiscard]] PathIntersectionResult intersect(const Path& a, const Path& b,
                                               const core::IntersectOptions& options,
                                               core::WorkBudget& budget);

/// The same with a budget of options.max_work units of its own, its running out reported
/// as status work_cap_reached.
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
  /// certified_self_intersections: the pairs within segments left as found for want of
  /// work units (core::CertifiedSelfIntersections::uncertified, summed).
  std::size_t uncertified_pairs = 0;
};

/// Every self-intersection of a path: each pair of different segments whose control boxes
/// meet, searched as two curves, and each segment against itself (core::self_intersections,
/// charged to the same budget; not called for a segment that
/// core::certainly_without_self_intersections clears, for which it would report and charge
/// nothing). Not intersections: the joint two
/// consecutive segments of a subpath share, and the start of a closed subpath meeting its
/// end (two consecutive segments still meet anywhere else, e.g. where a cubic loops back
/// across the line before it). A contact at a joint of other segments is reported once.
/// Two consecutive segments shown to meet only at their joint (meet_only_at_joint) are not
/// searched: the search would find that joint alone. Such a pair is charged the setup step
/// a searched pair is charged before its search.
/// Zero-length segments add nothing: their point is a joint of their neighbours. One
/// budget for the whole call, as for two paths; the pairs kept after the sweep (those
/// without a point segment) are a copy, charged to its memory as the sweep's are.
/// Precondition: finite coordinates.
[[nodiscard]] PathSelfIntersectionResult self_intersections(const Path& path,
                                                            const core::IntersectOptions& options,
                                                            core::WorkBudget& budget);

/// The same with a budget of options.max_work units of its own, its running out reported
/// as status work_cap_reached.
[[nodiscard]] PathSelfIntersectionResult self_intersections(const Path& path,
                                                            const core::IntersectOptions& options);

/// Every self-intersection of a path, certified: self_intersections(), then the pairs
/// within segments put in guaranteed intervals by core::certify_self_intersections (with
/// what the search left of `budget`, as a part of its own: a certification that falls
/// short reports its pairs as found, counted in uncertified_pairs, without exhausting the
/// budget) and added to `intersections` with segment_t = segment_s, all of them sorted
/// once by (segment_t, t, segment_s, s). `within_segments` still holds the search's
/// results (their overlaps). When the search runs out the budget is exhausted and nothing
/// is certified. The one call a layer above (the API, regions) makes for a path's
/// certified self-intersections.
[[nodiscard]] PathSelfIntersectionResult certified_self_intersections(
    const Path& path, const core::IntersectOptions& options, core::WorkBudget& budget);

}  // namespace bezier::path
