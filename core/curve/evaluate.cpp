#include "core/curve/evaluate.hpp"

#include <cassert>

#include "core/bernstein/casteljau_row.hpp"
#include "core/base/multiversion.hpp"

namespace bezier::core {

namespace {

template <class P>
P evaluate_row(std::span<const P> points, double t) {
  CasteljauRow<P> row(points);
  while (row.size() > 1) row.casteljau_step(t);
  return row.point(0);
}

}  // namespace

BEZIER_FMA_CLONES Point2 evaluate(const Curve& curve, double t) { return evaluate_row(curve.points(), t); }
BEZIER_FMA_CLONES Point3 evaluate(const Curve3& curve, double t) { return evaluate_row(curve.points(), t); }
BEZIER_FMA_CLONES double evaluate_coordinate(std::span<const double> coordinate, double t) {
  return evaluate_row(coordinate, t);
}

std::vector<double> uniform_parameters(int count) {
  assert(count >= 1);
  std::vector<double> ts(static_cast<std::size_t>(count));
  if (count == 1) return {0.0};
  // i / (count - 1) rather than i * step: one rounding, and the last value is exactly 1.
  const double last = count - 1;
  for (int i = 0; i < count; ++i) ts[static_cast<std::size_t>(i)] = i / last;
  return ts;
}

}  // namespace bezier::core
