#include "core/self_intersect/certify.hpp"

#include <algorithm>

#include "core/intersect/intersect.hpp"
#include "core/self_intersect/tuning.hpp"

namespace bezier::core {

namespace {

/// One pair's certification and what it cost.
struct CertifiedPair {
  Intersection intersection;
  std::int64_t work = 0;
  std::int64_t steps = 0;
  bool out_of_work = false;
};

CertifiedPair certified_pair(const Curve& curve, const SelfIntersection& pair,
                             const IntersectOptions& options, std::int64_t budget) {
  Intersection x;
  x.t = pair.t;
  x.s = pair.s;
  x.t_interval = {pair.t, pair.t};
  x.s_interval = {pair.s, pair.s};
  x.point = pair.point;
  x.kind = pair.kind;
  x.resolved = false;
  const double w = std::min(self_intersect_tuning::kCertifyHalfWidth, (pair.s - pair.t) / 4);
  if (!(w > 0)) return {x, 0, 0, false};
  if (budget <= 0) return {x, 0, 0, true};
  IntersectOptions local = options;
  local.max_work = budget;
  const IntersectionResult r =
      intersect_in(curve, curve, {std::max(0.0, pair.t - w), std::min(1.0, pair.t + w)},
                   {std::max(0.0, pair.s - w), std::min(1.0, pair.s + w)}, local);
  if (r.status != IntersectStatus::ok || r.intersections.size() != 1) {
    return {x, r.stats.work, r.stats.iterations, r.status == IntersectStatus::work_cap_reached};
  }
  return {r.intersections.front(), r.stats.work, r.stats.iterations, false};
}

}  // namespace

CertifiedSelfIntersections certify_self_intersections(const Curve& curve,
                                                      std::span<const SelfIntersection> pairs,
                                                      const IntersectOptions& options,
                                                      std::int64_t budget) {
  CertifiedSelfIntersections out;
  for (const SelfIntersection& pair : pairs) {
    const CertifiedPair c = certified_pair(curve, pair, options, budget - out.work);
    out.work += c.work;
    out.steps += c.steps;
    out.out_of_work = out.out_of_work || c.out_of_work;
    out.intersections.push_back(c.intersection);
  }
  return out;
}

}  // namespace bezier::core
