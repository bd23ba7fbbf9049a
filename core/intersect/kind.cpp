#include "core/intersect/kind.hpp"

#include <cmath>

namespace bezier::core {

double sine_between(Point2 a, Point2 b) noexcept {
  // Working-frame vectors: no overflow or harmful underflow in the squares.
  const double la = std::sqrt(dot(a, a)), lb = std::sqrt(dot(b, b));
  if (!(la > 0 && lb > 0)) return 0.0;
  // Normalise first: the cross product of unnormalised vectors may underflow.
  return std::fabs(cross(a / la, b / lb));
}

IntersectionKind classify_intersection(Point2 df, Point2 dg, double df_scale, double dg_scale,
                                       const KindTolerances& tol) noexcept {
  if (!(std::sqrt(dot(df, df)) > tol.zero_derivative * df_scale) ||
      !(std::sqrt(dot(dg, dg)) > tol.zero_derivative * dg_scale)) {
    return IntersectionKind::degenerate;
  }
  return sine_between(df, dg) <= tol.tangent_sine ? IntersectionKind::tangent
                                                  : IntersectionKind::transversal;
}

}  // namespace bezier::core
