#include "core/self_intersect/certify.hpp"

#include <algorithm>
#include <cstddef>

#include "core/intersect/intersect.hpp"
#include "core/self_intersect/tuning.hpp"

namespace bezier::core {

namespace {

/// One pair's certification, charged to `budget`; `uncertified` counts it when the budget
/// did not cover it.
Intersection certified_pair(const Curve& curve, const SelfIntersection& pair,
                            const IntersectOptions& options, WorkBudget& budget,
                            std::int64_t& steps, std::size_t& uncertified) {
  Intersection x;
  x.t = pair.t;
  x.s = pair.s;
  x.t_interval = {pair.t, pair.t};
  x.s_interval = {pair.s, pair.s};
  x.point = pair.point;
  x.kind = pair.kind;
  x.resolved = false;
  const double w = std::min(self_intersect_tuning::kCertifyHalfWidth, (pair.s - pair.t) / 4);
  if (!(w > 0)) return x;
  if (!budget.reserve(1)) {  // nothing left: reported as found
    ++uncertified;
    return x;
  }
  // A part of its own: an earlier pair's running out must not hide whether this one did.
  WorkBudget part = budget.share();
  const IntersectionResult r =
      intersect_in(curve, curve, {std::max(0.0, pair.t - w), std::min(1.0, pair.t + w)},
                   {std::max(0.0, pair.s - w), std::min(1.0, pair.s + w)}, options, part);
  budget.settle(part);
  steps += r.stats.iterations;
  if (part.exhausted()) ++uncertified;
  if (part.exhausted() || r.status != IntersectStatus::ok || r.intersections.size() != 1) return x;
  return r.intersections.front();
}

}  // namespace

CertifiedSelfIntersections certify_self_intersections(const Curve& curve,
                                                      std::span<const SelfIntersection> pairs,
                                                      const IntersectOptions& options,
                                                      WorkBudget& budget) {
  CertifiedSelfIntersections out;
  const std::int64_t spent_before = budget.spent();
  for (const SelfIntersection& pair : pairs) {
    out.intersections.push_back(
        certified_pair(curve, pair, options, budget, out.steps, out.uncertified));
  }
  out.work = budget.spent() - spent_before;
  return out;
}

CertifiedSelfIntersectionResult certified_self_intersections(const Curve& curve,
                                                             const IntersectOptions& options,
                                                             WorkBudget& budget) {
  CertifiedSelfIntersectionResult out;
  out.found = self_intersections(curve, SelfIntersectionOptions{}, budget);
  if (budget.exhausted()) return out;
  // The certification may fall short (its pairs are then reported as found, counted in
  // `uncertified`) without making the search's answer incomplete: it spends a part of its
  // own, whose running out is not the budget's.
  WorkBudget part = budget.share();
  out.certified = certify_self_intersections(curve, out.found.pairs, options, part);
  budget.charge(part.spent());
  return out;
}

}  // namespace bezier::core
