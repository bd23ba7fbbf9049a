#include "core/intersect/kind.hpp"

#include <cmath>

namespace bezier::core {

double sine_between(Point2 a, Point2 b) noexcept {
  const double la = length(a), lb = length(b);
  if (!(la > 0 && lb > 0)) return 0.0;
  // Normalise first: the cross product of unnormalised vectors may underflow.
  return std::fabs(cross(a / la, b / lb));
}

IntersectionKind classify_intersection(Point2 df, Point2 dg, double df_scale, double dg_scale,
                                       const KindTolerances& tol) noexcept {
  if (!(length(df) > tol.zero_derivative * df_scale) || !(length(dg) > tol.zero_derivative * dg_scale)) {
    return IntersectionKind::degenerate;
  }
  return sine_between(df, dg) <= tol.tangent_sine ? IntersectionKind::tangent
                                                  : IntersectionKind::transversal;
}

}  // namespace bezier::core
