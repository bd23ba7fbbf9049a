#include "core/outline/control_points.hpp"

#include <algorithm>

namespace bezier::outline {

core::Point2 point_at_by_casteljau(std::span<const core::Point2> p, double u) {
  ControlPoints q(p.size(), ControlPoints::Uninitialized{});
  std::copy(p.begin(), p.end(), q.begin());
  for (std::size_t k = p.size() - 1; k > 0; --k)
    for (std::size_t i = 0; i < k; ++i) q[i] = core::lerp(q[i], q[i + 1], u);
  return q[0];
}

}  // namespace bezier::outline
