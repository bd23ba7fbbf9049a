#include "core/curve/polar.hpp"

#include <cassert>
#include <utility>

#include "core/bernstein/casteljau_row.hpp"
#include "core/base/multiversion.hpp"

namespace bezier::core {

namespace {

template <class P>
BasicCurve<P> casteljau_rounds(const BasicCurve<P>& curve, std::span<const double> us) {
  assert(static_cast<int>(us.size()) <= curve.degree());
  CasteljauRow<P> row(curve.points());
  for (const double u : us) row.casteljau_step(u);
  typename BasicCurve<P>::Points points(row.size());
  for (std::size_t i = 0; i < row.size(); ++i) points[i] = row.point(i);
  return BasicCurve<P>(std::move(points));
}

/// portion(): control point i takes n - i rounds with a, then i with b. After k rounds
/// with a, `row_a` is the row every control point i <= n - k has gone through, so control
/// point i starts from a copy of the row after n - i of them and the same arithmetic
/// follows. Built from i = n down to 0.
template <class P>
BasicCurve<P> shared_row_portion(const BasicCurve<P>& curve, double a, double b) {
  const int n = curve.degree();
  if (n == 0) return curve;
  typename BasicCurve<P>::Points points(static_cast<std::size_t>(n) + 1);
  CasteljauRow<P> row_a(curve.points());
  for (int k = 0; k <= n; ++k) {
    if (k > 0) row_a.casteljau_step(a);
    CasteljauRow<P> row = row_a;
    for (int j = 0; j < n - k; ++j) row.casteljau_step(b);
    points[static_cast<std::size_t>(n - k)] = row.point(0);
  }
  return BasicCurve<P>(std::move(points));
}

}  // namespace

BEZIER_FMA_CLONES Curve polar(const Curve& curve, std::span<const double> us) { return casteljau_rounds(curve, us); }
BEZIER_FMA_CLONES Curve3 polar(const Curve3& curve, std::span<const double> us) { return casteljau_rounds(curve, us); }

BEZIER_FMA_CLONES Curve portion(const Curve& curve, double a, double b) {
  return shared_row_portion(curve, a, b);
}
BEZIER_FMA_CLONES Curve3 portion(const Curve3& curve, double a, double b) {
  return shared_row_portion(curve, a, b);
}

}  // namespace bezier::core
