#include "core/curve/polar.hpp"

#include <cassert>

#include "core/bernstein/casteljau_row.hpp"
#include "core/base/multiversion.hpp"

namespace bezier::core {

namespace {

template <class P>
BasicCurve<P> casteljau_rounds(const BasicCurve<P>& curve, std::span<const double> us) {
  assert(static_cast<int>(us.size()) <= curve.degree());
  CasteljauRow<P> row(curve.points());
  for (const double u : us) row.casteljau_step(u);
  std::vector<P> points;
  points.reserve(row.size());
  for (std::size_t i = 0; i < row.size(); ++i) points.push_back(row.point(i));
  return BasicCurve<P>(std::move(points));
}

}  // namespace

BEZIER_FMA_CLONES Curve polar(const Curve& curve, std::span<const double> us) { return casteljau_rounds(curve, us); }
BEZIER_FMA_CLONES Curve3 polar(const Curve3& curve, std::span<const double> us) { return casteljau_rounds(curve, us); }

}  // namespace bezier::core
