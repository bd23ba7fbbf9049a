#include "core/intersect/intersect.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <utility>

#include "core/numeric/min_max.hpp"
#include "core/intersect/collinear.hpp"
#include "core/intersect/common_arc.hpp"
#include "core/intersect/clip/fat_curve.hpp"
#include "core/intersect/high_order_contact.hpp"
#include "core/intersect/kind.hpp"
#include "core/intersect/merge.hpp"
#include "core/intersect/overlap.hpp"
#include "core/intersect/refine.hpp"
#include "core/intersect/search.hpp"
#include "core/intersect/work_cost.hpp"
#include "core/intersect/working_curve.hpp"

namespace bezier::core {

namespace {

/// n max |P_{i+1} - P_i|: the largest |f'| can be on [0, 1] (the hodograph's hull).
double hodograph_scale(const WorkingCurve& c) noexcept {
  double m = 0.0;
  for (std::size_t i = 0; i + 1 < c.x.size(); ++i) {
    const double dx = c.x[i + 1] - c.x[i], dy = c.y[i + 1] - c.y[i];
    m = max2(m, std::sqrt(dx * dx + dy * dy));  // working frame: no overflow
  }
  return c.degree * m;
}

/// What make_intersection needs of the pair besides the curves, computed once for all of
/// its contacts.
struct PairScales {
  WorkingFrame frame;
  double f_hodograph = 0.0, g_hodograph = 0.0;
};

PairScales pair_scales(const WorkingCurve& f, const WorkingCurve& g, WorkingFrame frame) noexcept {
  return {frame, hodograph_scale(f), hodograph_scale(g)};
}

/// The answer for one (t, s), with its kind judged from the derivatives there (pf, pg: f
/// and g at t and s with their tangents).
Intersection make_intersection(const PointAndTangent& pf, const PointAndTangent& pg,
                               const PairScales& scales, double t, double s, ParamInterval ti,
                               ParamInterval si) {
  Intersection x;
  x.t = t;
  x.s = s;
  x.t_interval = ti;
  x.s_interval = si;
  x.point = from_working({pf.point.x / 2 + pg.point.x / 2, pf.point.y / 2 + pg.point.y / 2},
                         scales.frame);
  x.kind = classify_intersection(pf.tangent, pg.tangent, scales.f_hodograph, scales.g_hodograph);
  return x;
}

Intersection make_intersection(const WorkingCurve& f, const WorkingCurve& g,
                               const PairScales& scales, double t, double s, ParamInterval ti,
                               ParamInterval si) {
  return make_intersection(evaluate_with_tangent(f, t), evaluate_with_tangent(g, s), scales, t, s,
                           ti, si);
}

void sort_result(IntersectionResult& r) {
  std::sort(r.intersections.begin(), r.intersections.end(),
            [](const Intersection& a, const Intersection& b) {
              return a.t != b.t ? a.t < b.t : a.s < b.s;
            });
  std::sort(r.overlaps.begin(), r.overlaps.end(), [](const Overlap& a, const Overlap& b) {
    return a.t_interval.lo != b.t_interval.lo ? a.t_interval.lo < b.t_interval.lo
                                              : a.s_interval.lo < b.s_interval.lo;
  });
}

bool control_boxes_disjoint(const Curve& f, const Curve& g) noexcept {
  const auto box = [](const Curve& c) {
    Point2 lo = c.front(), hi = c.front();
    for (const Point2 p : c.points()) {
      lo = {p.x < lo.x ? p.x : lo.x, p.y < lo.y ? p.y : lo.y};
      hi = {p.x > hi.x ? p.x : hi.x, p.y > hi.y ? p.y : hi.y};
    }
    return std::pair{lo, hi};
  };
  const auto [flo, fhi] = box(f);
  const auto [glo, ghi] = box(g);
  return fhi.x < glo.x || ghi.x < flo.x || fhi.y < glo.y || ghi.y < flo.y;
}

/// End points of f and g equal bit for bit: exact roots, unless they lie on an overlap,
/// which then reaches them exactly (its ends, pinned by Newton's method, may stop a
/// rounding short: t from 3e-27 instead of 0 on two curves sharing their first point, so
/// the answer would not contain that point: Overlap.AnOverlapReachesTheEndPointTheCurvesShare).
std::vector<ExactRoot> exact_end_roots(const Curve& f, const Curve& g,
                                       std::span<OverlapFinding> overlaps) {
  const Point2 f_ends[2] = {f.front(), f.back()}, g_ends[2] = {g.front(), g.back()};
  // Most pairs share no end point: no vector, no loop over the overlaps.
  if (!(f_ends[0] == g_ends[0] || f_ends[0] == g_ends[1] || f_ends[1] == g_ends[0] ||
        f_ends[1] == g_ends[1])) {
    return {};
  }
  std::vector<ExactRoot> roots;
  for (const int t : {0, 1}) {
    for (const int s : {0, 1}) {
      if (!(f_ends[t] == g_ends[s])) continue;
      const double rt = t, rs = s;
      bool on = false;
      for (OverlapFinding& o : overlaps) {
        if (!on_overlap(o, rt, rs)) continue;
        on = true;
        ParamInterval& ti = o.overlap.t_interval;
        ParamInterval& si = o.overlap.s_interval;
        ti = {std::min(ti.lo, rt), std::max(ti.hi, rt)};
        si = {std::min(si.lo, rs), std::max(si.hi, rs)};
      }
      if (!on) roots.push_back({rt, rs});
    }
  }
  return roots;
}

/// The certified high-order contacts in the searched ranges: exact roots when their
/// parameters are doubles, else resolved boxes one or two ulps wide around them.
void add_certified_contacts(std::span<const HighOrderContact> certified, ParamInterval t_range,
                            ParamInterval s_range, std::vector<ExactRoot>& exact,
                            std::vector<SearchCandidate>& candidates) {
  for (const HighOrderContact& c : certified) {
    if (t_range.hi < c.t.lo || c.t.hi < t_range.lo || s_range.hi < c.s.lo || c.s.hi < s_range.lo)
      continue;
    if (c.t.width() == 0.0 && c.s.width() == 0.0)
      exact.push_back({c.t.lo, c.s.lo});
    else
      candidates.push_back({c.t, c.s, true});
  }
}

/// Two single points (both curves of degree 0, or within rounding of one point): when they
/// are the same point, one degenerate intersection for every t and s (intervals [0, 1],
/// unresolved) goes into `result`; otherwise nothing does.
void add_coincident_point(const Curve& f, const Curve& g, IntersectionResult& result) {
  if (!(f.front() == g.front())) return;
  Intersection x;
  x.t_interval = x.s_interval = {0.0, 1.0};
  x.point = f.front();
  x.kind = IntersectionKind::degenerate;
  x.resolved = false;  // every t and s: the intervals are [0, 1]
  result.intersections.push_back(x);
}

/// Two curves on one line (collinear.hpp), neither a point: a one-dimensional problem. When
/// they are, `result` gets their overlaps and the touches inside t_range x s_range, sorted,
/// and the answer is true (the whole answer: no search follows); otherwise false and
/// `result` is left alone.
bool answer_collinear(const Curve& f, const Curve& g, const WorkingCurve& wf,
                      const WorkingCurve& wg, WorkingFrame frame, ParamInterval t_range,
                      ParamInterval s_range, double tolerance, IntersectionResult& result) {
  const auto line = collinear_intersections(wf, wg, exact_end_roots(f, g, {}));
  if (!line) return false;
  result.overlaps = line->overlaps;
  const PairScales scales = pair_scales(wf, wg, frame);
  for (const CollinearContact& c : line->touches) {
    if (!t_range.contains(c.t_estimate) || !s_range.contains(c.s_estimate)) continue;
    Intersection x = make_intersection(wf, wg, scales, c.t_estimate, c.s_estimate, c.t, c.s);
    // A curve within the line tolerance of a point touches with all of its parameter
    // range: resolved only when both ranges are narrower than the tolerance
    // (Intersect.TinyCurveIsNotReportedResolvedWithItsWholeInterval).
    x.resolved = c.t.width() < tolerance && c.s.width() < tolerance;
    result.intersections.push_back(x);
  }
  sort_result(result);
  return true;
}

/// The overlaps of two curves not on one line: an improper curve (one that traces its arc
/// more than once) overlaps the other along polynomial reparametrisations
/// (find_arc_overlaps); two proper ones only along an affine map (find_overlaps), asked
/// only when the first finds none.
std::vector<OverlapFinding> find_all_overlaps(const WorkingCurve& wf, const WorkingCurve& wg,
                                              ParamInterval t_range, ParamInterval s_range) {
  std::vector<OverlapFinding> overlaps = find_arc_overlaps(wf, wg, t_range, s_range);
  if (overlaps.empty()) overlaps = find_overlaps(wf, wg);
  return overlaps;
}

/// The exact roots the search is given: end points of f and g equal bit for bit
/// (exact_end_roots, which stretches an overlap through such a point onto it instead),
/// inside t_range x s_range. A point curve's parameter is free: one exact root at t = 0
/// (or s = 0; its interval is widened to [0, 1] at refinement) per end of the other curve
/// that is the point, whatever the point curve's range. The search alone can miss a point
/// lying exactly on an end (Collinear.PointAtAnEndIsAnExactRoot).
std::vector<ExactRoot> exact_roots_in(const Curve& f, const Curve& g, const WorkingCurve& wf,
                                      const WorkingCurve& wg, std::span<OverlapFinding> overlaps,
                                      ParamInterval t_range, ParamInterval s_range) {
  std::vector<ExactRoot> exact = exact_end_roots(f, g, overlaps);
  std::erase_if(exact, [&](const ExactRoot& r) {
    if (wf.is_point) return r.t != 0.0 || !s_range.contains(r.s);
    if (wg.is_point) return r.s != 0.0 || !t_range.contains(r.t);
    return !t_range.contains(r.t) || !s_range.contains(r.s);
  });
  return exact;
}

/// What the box search is asked (search.hpp): both curves, the method and its width, the
/// overlaps whose diagonals it skips, the ranges (a point curve's parameter free over
/// [0, 1]). For the clipping methods the fat-curve operators are built into op_f and op_g,
/// which the input points to and which must outlive it: degree
/// clamp(options.fat_curve_degree, 1, 3) for hybrid clipping; Bézier clipping bounds the
/// distance function itself, so no reduction (k >= n; a point curve, n = 0, still takes
/// k = 1, the operator's least degree: Intersect.BezierClippingAcceptsAPointCurve).
/// Subdivision takes none. No high-order contact finder is set.
SearchInput search_input(const WorkingCurve& wf, const WorkingCurve& wg,
                         std::span<const OverlapFinding> overlaps, const IntersectOptions& options,
                         ParamInterval t_range, ParamInterval s_range, FatCurveOperator& op_f,
                         FatCurveOperator& op_g) {
  SearchInput in;
  in.f = &wf;
  in.g = &wg;
  in.method = options.method;
  in.width = search_width(options.tolerance);
  in.overlaps = overlaps;
  in.t_free = wf.is_point;
  in.s_free = wg.is_point;
  in.t_range = wf.is_point ? ParamInterval{0.0, 1.0} : t_range;
  in.s_range = wg.is_point ? ParamInterval{0.0, 1.0} : s_range;
  if (options.method != IntersectMethod::subdivision) {
    const bool hybrid = options.method == IntersectMethod::hybrid;
    const int k = std::clamp(options.fat_curve_degree, 1, 3);
    op_f = fat_curve_operator(wf.degree, hybrid ? k : std::max(wf.degree, 1));
    op_g = fat_curve_operator(wg.degree, hybrid ? k : std::max(wg.degree, 1));
    in.op_f = &op_f;
    in.op_g = &op_g;
  }
  return in;
}

/// Each merged contact refined (refine.hpp) into an intersection appended to `result`, with
/// its point and kind, and the Newton iterations counted in result.stats. A refinement
/// starts only when the budget covers its most iterations, and is charged those it took;
/// the first one not covered ends the phase (the budget is then exhausted). A free
/// parameter (t_free, s_free: a point curve) keeps the interval [0, 1], so that
/// intersection is degenerate and not resolved; any other is resolved when its boxes all
/// reached the search width and both intervals are narrower than `tolerance`.
void add_refined_contacts(const WorkingCurve& wf, const WorkingCurve& wg, WorkingFrame frame,
                          std::span<const Contact> contacts, bool t_free, bool s_free,
                          double tolerance, WorkBudget& budget, IntersectionResult& result) {
  const KindTolerances kind_tol;
  const PairScales scales = contacts.empty() ? PairScales{frame} : pair_scales(wf, wg, frame);
  result.intersections.reserve(contacts.size());
  for (Contact c : contacts) {
    // A refinement starts only when the budget covers its most iterations.
    if (!budget.reserve(max_contact_cost(wf.degree, wg.degree))) break;
    if (t_free) c.t = {0.0, 1.0};
    if (s_free) c.s = {0.0, 1.0};
    const Refinement r = refine_contact(wf, wg, c, t_free, s_free, kind_tol.tangent_sine);
    result.stats.newton_iterations += r.iterations;
    // The point and the kind (two evaluations with tangents) cost less than one of the
    // iterations' charges, which every contact but an exact root's takes.
    budget.charge(r.iterations * newton_cost(wf.degree, wg.degree));
    Intersection x =
        r.f_at_t && r.g_at_s
            ? make_intersection(*r.f_at_t, *r.g_at_s, scales, r.t, r.s, c.t, c.s)
            : make_intersection(wf, wg, scales, r.t, r.s, c.t, c.s);
    if (t_free || s_free) x.kind = IntersectionKind::degenerate;
    // A curve handled as a point keeps the whole (or half) parameter interval: it is not
    // resolved then, whatever the other curve's box (Intersection's contract).
    x.resolved = c.resolved && c.t.width() < tolerance && c.s.width() < tolerance;
    result.intersections.push_back(x);
  }
}

}  // namespace

IntersectionResult intersect(const Curve& f, const Curve& g, const IntersectOptions& options,
                             WorkBudget& budget) {
  return intersect_in(f, g, {0.0, 1.0}, {0.0, 1.0}, options, budget);
}

IntersectionResult intersect(const Curve& f, const Curve& g, const IntersectOptions& options) {
  WorkBudget budget(options.max_work);
  IntersectionResult result = intersect(f, g, options, budget);
  if (budget.exhausted()) result.status = IntersectStatus::work_cap_reached;
  return result;
}

IntersectionResult intersect_in(const Curve& f, const Curve& g, ParamInterval t_range,
                                ParamInterval s_range, const IntersectOptions& options,
                                WorkBudget& budget) {
  IntersectionResult result;
  result.stats.method = options.method;
  if (!(options.tolerance >= kMinTolerance)) {
    result.status = IntersectStatus::tolerance_too_small;
    return result;
  }
  // Control-point bounding boxes apart (exact comparisons of the inputs): nothing to do.
  // Most pairs of random curves end here.
  if (control_boxes_disjoint(f, g)) return result;
  const WorkingFrame frame = working_frame(f, g);
  const WorkingCurve wf = to_working(f, frame), wg = to_working(g, frame);
  if (wf.is_point && wg.is_point) {
    add_coincident_point(f, g, result);
    return result;
  }
  // What comes before the search (the collinear case, the overlaps) is bounded by the
  // degrees: charged at once, and not started when the budget does not cover it.
  const std::int64_t spent_before = budget.spent();
  const bool covered = budget.spend(overlap_search_cost(wf.degree, wg.degree));
  result.stats.work = budget.spent() - spent_before;
  if (!covered) return result;
  if (!wf.is_point && !wg.is_point &&
      answer_collinear(f, g, wf, wg, frame, t_range, s_range, options.tolerance, result)) {
    return result;
  }
  std::vector<OverlapFinding> overlaps = find_all_overlaps(wf, wg, t_range, s_range);
  std::vector<ExactRoot> exact = exact_roots_in(f, g, wf, wg, overlaps, t_range, s_range);
  for (const OverlapFinding& o : overlaps) result.overlaps.push_back(o.overlap);

  FatCurveOperator op_f, op_g;
  SearchInput in = search_input(wf, wg, overlaps, options, t_range, s_range, op_f, op_g);
  HighOrderContactFinder high_order(f, g, wf, wg);
  if (!wf.is_point && !wg.is_point) in.contacts = &high_order;
  SearchOutput found = search(in, budget);
  add_certified_contacts(high_order.contacts(), t_range, s_range, exact, found.candidates);
  result.stats = found.stats;

  const MergedContacts merged = merge_candidates(found.candidates, exact, in.width, budget);
  add_refined_contacts(wf, wg, frame, merged.contacts, in.t_free, in.s_free, options.tolerance,
                       budget, result);
  result.stats.work = budget.spent() - spent_before;
  sort_result(result);
  return result;
}

}  // namespace bezier::core
