#include "core/path/path_intersections.hpp"

#include <algorithm>
#include <tuple>
#include <utility>

#include "core/intersect/intersect.hpp"
#include "core/intersect/work_cost.hpp"
#include "core/path/joint_copies.hpp"
#include "core/path/segment_boxes.hpp"
#include "core/self_intersect/work_cost.hpp"

namespace bezier::path {

namespace {

std::vector<Box> boxes_of(const Path& path) {
  std::vector<Box> boxes;
  boxes.reserve(path.segments.size());
  for (const core::Curve& segment : path.segments) boxes.push_back(control_box(segment));
  return boxes;
}

bool is_point(const core::Curve& segment) {
  return std::all_of(segment.points().begin(), segment.points().end(),
                     [&](core::Point2 p) { return p == segment.front(); });
}

void add_stats(core::IntersectStats& sum, const core::IntersectStats& s) {
  sum.iterations += s.iterations;
  sum.work += s.work;
  sum.clipping_steps += s.clipping_steps;
  sum.subdivisions += s.subdivisions;
  sum.candidate_boxes += s.candidate_boxes;
  sum.compensated_steps += s.compensated_steps;
  sum.newton_iterations += s.newton_iterations;
  sum.max_depth = std::max(sum.max_depth, s.max_depth);
}

void sort_results(std::vector<PathContact>& contacts, std::vector<PathOverlap>& overlaps) {
  std::sort(contacts.begin(), contacts.end(), [](const PathContact& p, const PathContact& q) {
    return std::tuple(p.segment_t, p.intersection.t, p.segment_s, p.intersection.s) <
           std::tuple(q.segment_t, q.intersection.t, q.segment_s, q.intersection.s);
  });
  std::sort(overlaps.begin(), overlaps.end(), [](const PathOverlap& p, const PathOverlap& q) {
    return std::tuple(p.segment_t, p.overlap.t_interval.lo, p.segment_s) <
           std::tuple(q.segment_t, q.overlap.t_interval.lo, q.segment_s);
  });
}

/// The start of both searches: the segment pairs whose control boxes meet (found by
/// `sweep`), the stats with the method asked and the sweep's work, and the status that ends
/// the search before any pair when not ok: tolerance_too_small (checked first, nothing is
/// swept) or work_cap_reached (the sweep stopped at its limit).
struct SweptPairs {
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  PathSearchStats stats;
  core::IntersectStatus status = core::IntersectStatus::ok;

  /// A result (PathIntersectionResult, PathSelfIntersectionResult) that starts from these
  /// stats and status.
  template <class Result>
  [[nodiscard]] Result start() const {
    Result out;
    out.stats = stats;
    out.status = status;
    return out;
  }
};

template <class Sweep>
SweptPairs swept_pairs(const core::IntersectOptions& options, Sweep&& sweep) {
  SweptPairs out;
  out.stats.pairs.method = options.method;
  if (!(options.tolerance >= core::kMinTolerance)) {
    out.status = core::IntersectStatus::tolerance_too_small;
    return out;
  }
  MeetingBoxes meeting = sweep();
  out.stats.work = meeting.work;
  if (!meeting.complete) {
    out.status = core::IntersectStatus::work_cap_reached;
    return out;
  }
  out.pairs = std::move(meeting.pairs);
  return out;
}

/// The two-curve searches of the pairs (first segment of path_t, second of path_s) that
/// shares one budget, adding what they find and cost to the lists and stats.
core::IntersectStatus search_pairs(const Path& path_t, const Path& path_s,
                                   const std::vector<std::pair<std::size_t, std::size_t>>& pairs,
                                   const core::IntersectOptions& options,
                                   std::vector<PathContact>& contacts,
                                   std::vector<PathOverlap>& overlaps, PathSearchStats& stats) {
  for (const auto& [i, j] : pairs) {
    const core::Curve& f = path_t.segments[i];
    const core::Curve& g = path_s.segments[j];
    // Each search sets up its working frame and pieces before its first step: charged as
    // one plain step of the two degrees.
    stats.work += core::step_cost(f.degree(), g.degree(), false);
    if (stats.work > options.max_work) return core::IntersectStatus::work_cap_reached;
    core::IntersectOptions local = options;
    local.max_work = options.max_work - stats.work;
    const core::IntersectionResult r = core::intersect(f, g, local);
    ++stats.candidate_pairs;
    stats.work += r.stats.work;
    add_stats(stats.pairs, r.stats);
    for (const core::Intersection& x : r.intersections) contacts.push_back({i, j, x});
    for (const core::Overlap& o : r.overlaps) overlaps.push_back({i, j, o});
    if (r.status != core::IntersectStatus::ok) return r.status;
  }
  return core::IntersectStatus::ok;
}

}  // namespace

PathIntersectionResult intersect(const Path& a, const Path& b,
                                 const core::IntersectOptions& options) {
  const SweptPairs swept = swept_pairs(
      options, [&] { return meeting_boxes(boxes_of(a), boxes_of(b), options.max_work); });
  auto out = swept.start<PathIntersectionResult>();
  if (out.status != core::IntersectStatus::ok) return out;
  out.status = search_pairs(a, b, swept.pairs, options, out.intersections, out.overlaps,
                            out.stats);
  out.intersections = without_joint_copies(std::move(out.intersections), a, b, false);
  sort_results(out.intersections, out.overlaps);
  return out;
}

PathSelfIntersectionResult self_intersections(const Path& path,
                                              const core::IntersectOptions& options) {
  const SweptPairs swept =
      swept_pairs(options, [&] { return meeting_boxes(boxes_of(path), options.max_work); });
  auto out = swept.start<PathSelfIntersectionResult>();
  if (out.status != core::IntersectStatus::ok) return out;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (const auto& [i, j] : swept.pairs) {
    if (!is_point(path.segments[i]) && !is_point(path.segments[j])) pairs.emplace_back(i, j);
  }
  out.status = search_pairs(path, path, pairs, options, out.intersections, out.overlaps,
                            out.stats);
  // A segment against itself: a line (or a point) has no self-intersection.
  for (std::size_t k = 0; k < path.segments.size() && out.status == core::IntersectStatus::ok;
       ++k) {
    const core::Curve& segment = path.segments[k];
    if (segment.degree() < 2 || is_point(segment)) continue;
    core::SelfIntersectionOptions self_options;
    self_options.max_work =
        core::self_intersection_box_budget(options.max_work - out.stats.work, segment.degree());
    if (self_options.max_work <= 0) {
      out.status = core::IntersectStatus::work_cap_reached;
      break;
    }
    core::SelfIntersectionResult r = core::self_intersections(segment, self_options);
    out.stats.work += r.stats.work * core::self_intersection_box_cost(segment.degree());
    if (r.status == core::IntersectStatus::work_cap_reached) {
      out.status = core::IntersectStatus::work_cap_reached;
    }
    if (!r.pairs.empty() || !r.overlaps.empty()) out.within_segments.push_back({k, std::move(r)});
  }
  out.intersections = without_joint_copies(std::move(out.intersections), path, path, true);
  sort_results(out.intersections, out.overlaps);
  return out;
}

}  // namespace bezier::path
