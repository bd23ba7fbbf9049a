#include "core/cubic/canonical_form.hpp"

#include <cassert>
#include <cmath>

#include "core/numeric/expansion.hpp"

namespace bezier::core {

std::optional<Point2> canonical_point(const CubicPredicates& pred) {
  if (pred.sign.d1 == 0) return std::nullopt;
  // + 0.0 turns a -0 quotient into +0.
  Point2 q{pred.x_num / pred.d1 + 0.0, pred.y_num / pred.d1 + 0.0};
  // Where a coordinate is known exactly, report it exactly: d2 = d1 (x − 3) and
  // I(1) = d1 (1 − y), so d2 = 0 puts x at 3 and an inflection at t = 1 puts y at 1.
  if (pred.sign.d2 == 0) q.x = 3.0;
  if (pred.sign.i1 == 0) q.y = 1.0;
  if (!(std::isfinite(q.x) && std::isfinite(q.y))) return std::nullopt;
  return q;
}

std::optional<Point2> canonical_point(std::span<const Point2, 4> p) {
  return canonical_point(cubic_predicates(p));
}

std::optional<Point2> canonical_point(const Curve& cubic) {
  assert(cubic.degree() == 3);
  return canonical_point(std::span<const Point2, 4>(cubic.points().data(), 4));
}

CubicType canonical_region(Point2 q) {
  assert(std::isfinite(q.x) && std::isfinite(q.y));
  const double x = q.x, y = q.y;
  if (x == 3.0 && y == 0.0) return CubicType::quadratic;
  // The edge polynomials, exact in expansion arithmetic (products of doubles are exact).
  const Expansion ex(x), ey(y);
  const Expansion xx = ex * x;
  const int cusp_side = (xx - ex * 2.0 + ey * 4.0 - Expansion(3.0)).sign();  // x² − 2x + 4y − 3
  if (cusp_side == 0 && x <= 1.0) return CubicType::cusp;
  if (y > 1.0) return CubicType::single_inflection;
  if (y == 1.0) return x < 1.0 ? CubicType::double_inflection : CubicType::single_inflection;
  // Below y = 1 from here on.
  if (cusp_side > 0) return x <= 1.0 ? CubicType::double_inflection : CubicType::arch;
  if (cusp_side == 0) return CubicType::arch;  // the cusp edge beyond x = 1: cusp at t > 1
  // Below the cusp edge: the unbounded curve has a loop; is it on [0,1]?
  if (x <= 0.0) {
    const int start_side = (xx - ex * 3.0 + ey * 3.0).sign();  // x² − 3x + 3y
    if (start_side < 0) return CubicType::arch;
    return start_side == 0 ? CubicType::loop_at_start : CubicType::loop;
  }
  if (x <= 1.0) {
    // y >= (√(3(4x − x²)) − x) / 2  <=>  2y + x >= 0 and (2y + x)² >= 12x − 3x²,
    // and the latter is 4 (x² + xy + y² − 3x) >= 0.
    const bool upper_branch = (ey * 2.0 + ex).sign() >= 0;
    const int end_side = (xx + ex * y + ey * y - ex * 3.0).sign();
    if (!upper_branch || end_side < 0) return CubicType::arch;
    return end_side == 0 ? CubicType::loop_at_end : CubicType::loop;
  }
  return CubicType::arch;
}

}  // namespace bezier::core
