#include "core/curve/subdivide.hpp"

#include <utility>

#include "core/bernstein/casteljau_row.hpp"
#include "core/base/multiversion.hpp"

namespace bezier::core {

namespace {

template <class P>
Split<P> split_triangle(const BasicCurve<P>& curve, double t) {
  CasteljauRow<P> row(curve.points());
  const std::size_t n = row.size() - 1;
  typename BasicCurve<P>::Points left(n + 1);
  typename BasicCurve<P>::Points right(n + 1);
  left[0] = row.point(0);
  right[n] = row.point(n);
  for (std::size_t k = 1; k <= n; ++k) {
    row.casteljau_step(t);
    left[k] = row.point(0);
    right[n - k] = row.point(n - k);
  }
  return {BasicCurve<P>(std::move(left)), BasicCurve<P>(std::move(right))};
}

}  // namespace

BEZIER_FMA_CLONES Split<Point2> subdivide(const Curve& curve, double t) { return split_triangle(curve, t); }
BEZIER_FMA_CLONES Split<Point3> subdivide(const Curve3& curve, double t) { return split_triangle(curve, t); }

}  // namespace bezier::core
