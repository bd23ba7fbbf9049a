#include "core/region/segment_piece.hpp"

#include <cstddef>
#include <utility>
#include <vector>

#include "core/base/multiversion.hpp"
#include "core/bernstein/casteljau_row.hpp"

namespace bezier::region {

BEZIER_FMA_CLONES core::Curve exact_portion(const core::Curve& curve, double a, double b) {
  const int n = curve.degree();
  std::vector<core::Point2> points;
  points.reserve(static_cast<std::size_t>(n) + 1);
  if (n == 0) {
    points.push_back(curve.front());
    return core::Curve(std::move(points));
  }
  for (int i = 0; i <= n; ++i) {
    core::CasteljauRow<core::Point2> row(curve.points());
    for (int j = 0; j < n; ++j) row.casteljau_step(j < n - i ? a : b);
    points.push_back(row.point(0));
  }
  return core::Curve(std::move(points));
}

}  // namespace bezier::region
