#include "core/region/segment_piece.hpp"

#include <algorithm>
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
  // Control point i takes n - i rounds with a, then i with b. The rows after the rounds
  // with a are shared: after k of them, `row_a` is what every control point i <= n - k has
  // gone through, so each control point i starts from a copy of the row after n - i rounds
  // (its i + 1 entries) and the same arithmetic follows. Built from n down to 0 and
  // reversed in place at the end.
  core::CasteljauRow<core::Point2> row_a(curve.points());
  for (int k = 0; k <= n; ++k) {
    if (k > 0) row_a.casteljau_step(a);
    const int i = n - k;
    core::CasteljauRow<core::Point2> row = row_a;
    for (int j = 0; j < i; ++j) row.casteljau_step(b);
    points.push_back(row.point(0));
  }
  std::reverse(points.begin(), points.end());
  return core::Curve(std::move(points));
}

}  // namespace bezier::region
