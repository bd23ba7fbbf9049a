#include "core/loop/loop_area.hpp"

#include <cmath>

#include "core/curve/area.hpp"

namespace bezier::core {

LoopAreaResult loop_area(const Curve& curve, const SelfIntersectionOptions& options) {
  WorkBudget budget(options.max_work);
  LoopAreaResult result = loop_area(curve, options, budget);
  if (budget.exhausted()) result.status = IntersectStatus::work_cap_reached;
  return result;
}

LoopAreaResult loop_area(const Curve& curve, const SelfIntersectionOptions& options,
                         WorkBudget& budget) {
  SelfIntersectionResult found = self_intersections(curve, options, budget);
  LoopAreaResult result;
  for (const SelfIntersection& pair : found.pairs) {
    const double signed_area = enclosed_area(curve, pair.t, pair.s);
    result.loops.push_back(
        {pair.t, pair.s, pair.point, std::fabs(signed_area), signed_area, pair.kind});
    result.area += std::fabs(signed_area);
  }
  result.closed = is_closed(curve);
  result.closed_area = closed_area(curve);
  result.overlaps = std::move(found.overlaps);
  result.status = found.status;
  result.stats = found.stats;
  return result;
}

}  // namespace bezier::core
