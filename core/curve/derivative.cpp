#include "core/curve/derivative.hpp"

#include <cassert>

#include "core/bernstein/casteljau_row.hpp"
#include "core/base/multiversion.hpp"

namespace bezier::core {

namespace {

template <class P>
BasicCurve<P> hodograph_k(const BasicCurve<P>& curve, int k) {
  assert(k >= 0);
  CasteljauRow<P> row(curve.points());
  for (int i = 0; i < k; ++i) row.hodograph_step();
  typename BasicCurve<P>::Points points(row.size());
  for (std::size_t i = 0; i < row.size(); ++i) points[i] = row.point(i);
  return BasicCurve<P>(std::move(points));
}

template <class P>
std::vector<P> hodograph_values(const BasicCurve<P>& curve, double t, int order) {
  assert(order >= 0);
  std::vector<P> values;
  values.reserve(static_cast<std::size_t>(order));
  CasteljauRow<P> hodograph(curve.points());
  for (int k = 1; k <= order; ++k) {
    hodograph.hodograph_step();
    CasteljauRow<P> row = hodograph;
    while (row.size() > 1) row.casteljau_step(t);
    values.push_back(row.point(0));
  }
  return values;
}

}  // namespace

BEZIER_FMA_CLONES Curve derivative(const Curve& curve, int k) { return hodograph_k(curve, k); }
BEZIER_FMA_CLONES Curve3 derivative(const Curve3& curve, int k) { return hodograph_k(curve, k); }

BEZIER_FMA_CLONES std::vector<Point2> derivatives_at(const Curve& curve, double t, int order) {
  return hodograph_values(curve, t, order);
}
BEZIER_FMA_CLONES std::vector<Point3> derivatives_at(const Curve3& curve, double t, int order) {
  return hodograph_values(curve, t, order);
}

}  // namespace bezier::core
