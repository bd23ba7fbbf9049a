#include "core/path/path_intersections.hpp"

#include <algorithm>
#include <tuple>
#include <utility>

#include "core/intersect/intersect.hpp"
#include "core/intersect/work_cost.hpp"
#include "core/self_intersect/certify.hpp"
#include "core/path/joint_copies.hpp"
#include "core/path/joint_separation.hpp"
#include "core/path/segment_boxes.hpp"

namespace bezier::path {

namespace {

std::vector<core::Rect> boxes_of(const Path& path) {
  std::vector<core::Rect> boxes;
  boxes.reserve(path.segments.size());
  for (const core::Curve& segment : path.segments) boxes.push_back(control_box(segment));
  return boxes;
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

/// The segment pairs whose control boxes meet, found by `sweep` (empty when the budget ran
/// out during the sweep).
template <class Sweep>
std::vector<std::pair<std::size_t, std::size_t>> swept_pairs(core::WorkBudget& budget,
                                                             Sweep&& sweep) {
  MeetingBoxes meeting = sweep();
  if (budget.exhausted()) return {};
  return std::move(meeting.pairs);
}

/// The two-curve searches of the pairs (first segment of path_t, second of path_s) that
/// share `budget`, adding what they find and cost to the lists and stats; stops when the
/// budget runs out. A pair for which `settled(i, j)` is true is not searched: the caller's
/// filter has shown that the search would add nothing.
template <class Settled>
void search_pairs(const Path& path_t, const Path& path_s,
                  const std::vector<std::pair<std::size_t, std::size_t>>& pairs,
                  const core::IntersectOptions& options, core::WorkBudget& budget,
                  std::vector<PathContact>& contacts, std::vector<PathOverlap>& overlaps,
                  PathSearchStats& stats, Settled&& settled) {
  for (const auto& [i, j] : pairs) {
    const core::Curve& f = path_t.segments[i];
    const core::Curve& g = path_s.segments[j];
    // Each search sets up its working frame and pieces before its first step: charged as
    // one plain step of the two degrees. A filter's test reads the same control points a
    // few times and is charged the same.
    if (!budget.spend(core::step_cost(f.degree(), g.degree(), false))) return;
    ++stats.candidate_pairs;
    if (settled(i, j)) continue;
    const core::IntersectionResult r = core::intersect(f, g, options, budget);
    add_stats(stats.pairs, r.stats);
    for (const core::Intersection& x : r.intersections) contacts.push_back({i, j, x});
    for (const core::Overlap& o : r.overlaps) overlaps.push_back({i, j, o});
    if (budget.exhausted()) return;
  }
}

/// A result (PathIntersectionResult, PathSelfIntersectionResult) with the method asked and,
/// when the tolerance is too small, that status.
template <class Result>
Result started(const core::IntersectOptions& options) {
  Result out;
  out.stats.pairs.method = options.method;
  if (!(options.tolerance >= core::kMinTolerance)) {
    out.status = core::IntersectStatus::tolerance_too_small;
  }
  return out;
}

}  // namespace

PathIntersectionResult intersect(const Path& a, const Path& b,
                                 const core::IntersectOptions& options, core::WorkBudget& budget) {
  auto out = started<PathIntersectionResult>(options);
  if (out.status != core::IntersectStatus::ok) return out;
  const std::int64_t spent_before = budget.spent();
  const auto pairs =
      swept_pairs(budget, [&] { return meeting_boxes(boxes_of(a), boxes_of(b), budget); });
  search_pairs(a, b, pairs, options, budget, out.intersections, out.overlaps, out.stats,
               [](std::size_t, std::size_t) { return false; });
  out.stats.work = budget.spent() - spent_before;
  if (budget.exhausted()) return out;
  out.intersections = without_joint_copies(std::move(out.intersections), a, b, false);
  sort_results(out.intersections, out.overlaps);
  return out;
}

PathIntersectionResult intersect(const Path& a, const Path& b,
                                 const core::IntersectOptions& options) {
  core::WorkBudget budget(options.max_work);
  PathIntersectionResult out = intersect(a, b, options, budget);
  if (budget.exhausted()) out.status = core::IntersectStatus::work_cap_reached;
  return out;
}

namespace {

/// What the search of one path reads of each segment, gathered in one pass over the
/// segments: its control box, whether it is a single point (core::is_point), and the
/// segment that follows it in its subpath (next_segment; kNone when there is none), each the
/// same as computed where it is used.
struct SegmentFacts {
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::vector<core::Rect> boxes;
  std::vector<char> point;
  std::vector<std::size_t> next;
};

SegmentFacts segment_facts(const Path& path) {
  const std::size_t n = path.segments.size();
  SegmentFacts facts;
  facts.boxes.resize(n);
  facts.point.resize(n);
  core::Rect* const boxes = facts.boxes.data();
  char* const point = facts.point.data();
  for (std::size_t k = 0; k < n; ++k) {
    const core::Rect box = control_box(path.segments[k]);
    boxes[k] = box;
    // core::is_point read off the box: every control point equal to the first (by value)
    // exactly when each coordinate's least and greatest value are equal (finite coordinates).
    point[k] = box.min == box.max ? 1 : 0;
  }
  // next_segment, subpath by subpath: the following segment, and for a closed subpath of
  // more than one segment its first after its last.
  facts.next.assign(n, SegmentFacts::kNone);
  for (const Subpath& sub : path.subpaths) {
    if (sub.segment_count == 0) continue;
    const std::size_t last = sub.first_segment + sub.segment_count - 1;
    for (std::size_t k = sub.first_segment; k < last; ++k) facts.next[k] = k + 1;
    if (sub.closed && sub.segment_count > 1) facts.next[last] = sub.first_segment;
  }
  return facts;
}

/// self_intersections() before its contacts are sorted.
PathSelfIntersectionResult unsorted_self_intersections(const Path& path,
                                                       const core::IntersectOptions& options,
                                                       core::WorkBudget& budget) {
  auto out = started<PathSelfIntersectionResult>(options);
  if (out.status != core::IntersectStatus::ok) return out;
  const std::int64_t spent_before = budget.spent();
  const SegmentFacts facts = segment_facts(path);
  const auto swept = swept_pairs(budget, [&] { return meeting_boxes(facts.boxes, budget); });
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  pairs.reserve(swept.size());
  for (const auto& [i, j] : swept) {
    if (facts.point[i] != 0 || facts.point[j] != 0) continue;
    // The copy is charged as the sweep's pairs are.
    if (!budget.charge_memory(kStoredPairBytes)) break;
    pairs.emplace_back(i, j);
  }
  // Two segments that follow each other share their joint, so their boxes always meet; a
  // pair whose only common point is that joint (meet_only_at_joint) has nothing to report
  // (the search would find the joint alone, which is not an intersection).
  const auto settled = [&](std::size_t i, std::size_t j) {
    if (facts.next[i] == j) return meet_only_at_joint(path.segments[i], path.segments[j]);
    if (facts.next[j] == i) return meet_only_at_joint(path.segments[j], path.segments[i]);
    return false;
  };
  search_pairs(path, path, pairs, options, budget, out.intersections, out.overlaps, out.stats,
               settled);
  // A segment against itself: a line (or a point) has no self-intersection.
  const core::SelfIntersectionOptions own_options;
  for (std::size_t k = 0; k < path.segments.size() && !budget.exhausted(); ++k) {
    const core::Curve& segment = path.segments[k];
    if (segment.degree() < 2 || facts.point[k] != 0) continue;
    // A segment shown to have nothing to report is not searched: the search would report
    // nothing and charge nothing for it.
    if (core::certainly_without_self_intersections(segment, own_options)) continue;
    core::SelfIntersectionResult r = core::self_intersections(segment, own_options, budget);
    if (budget.exhausted()) break;
    if (!r.pairs.empty() || !r.overlaps.empty()) out.within_segments.push_back({k, std::move(r)});
  }
  out.stats.work = budget.spent() - spent_before;
  if (budget.exhausted()) return out;
  out.intersections = without_joint_copies(std::move(out.intersections), path, path, true);
  return out;
}

}  // namespace

PathSelfIntersectionResult self_intersections(const Path& path,
                                              const core::IntersectOptions& options,
                                              core::WorkBudget& budget) {
  PathSelfIntersectionResult out = unsorted_self_intersections(path, options, budget);
  if (out.status == core::IntersectStatus::ok && !budget.exhausted()) {
    sort_results(out.intersections, out.overlaps);
  }
  return out;
}

PathSelfIntersectionResult certified_self_intersections(const Path& path,
                                                        const core::IntersectOptions& options,
                                                        core::WorkBudget& budget) {
  PathSelfIntersectionResult out = unsorted_self_intersections(path, options, budget);
  if (out.status != core::IntersectStatus::ok || budget.exhausted()) return out;
  // The certification spends what the search left, as a part of its own: falling short
  // leaves pairs as found (uncertified_pairs), not the answer incomplete.
  core::WorkBudget part = budget.share();
  for (const SegmentSelfIntersections& within : out.within_segments) {
    const core::CertifiedSelfIntersections c = core::certify_self_intersections(
        path.segments[within.segment], within.result.pairs, options, part);
    out.stats.certification_steps += c.steps;
    out.uncertified_pairs += c.uncertified;
    for (const core::Intersection& x : c.intersections) {
      out.intersections.push_back({within.segment, within.segment, x});
    }
  }
  budget.charge(part.spent());
  out.stats.work += part.spent();
  sort_results(out.intersections, out.overlaps);
  return out;
}

PathSelfIntersectionResult self_intersections(const Path& path,
                                              const core::IntersectOptions& options) {
  core::WorkBudget budget(options.max_work);
  PathSelfIntersectionResult out = self_intersections(path, options, budget);
  if (budget.exhausted()) out.status = core::IntersectStatus::work_cap_reached;
  return out;
}

}  // namespace bezier::path
