#pragma once

#include <span>
#include <vector>

#include "core/base/curve.hpp"

namespace bezier::outline {

// Where a curve's derivative vanishes, and the direction of travel there: what the parallel
// curve (offset.hpp) and the stroke (stroke.hpp) take as the tangent where B' = 0.

/// The unit tangent of the curve with control points p at u = 0 (from the right, at_start) or
/// u = 1 (from the left): the direction of the first derivative that is not zero (to 1e-12 of
/// the control points' scale), times side^(k - 1) for the k-th, side = -1 at u = 1, since
/// B'(u0 + ε) ≈ ε^(k-1) / (k-1)! B^(k)(u0): the direction of travel next to the end. A curve
/// that is one point has no direction; (1, 0) is returned for it.
[[nodiscard]] core::Point2 end_tangent(std::span<const core::Point2> p, bool at_start);

/// The zeros of B' inside (0, 1), ascending: roots of x' (or of y' when x' is identically
/// zero) where the other coordinate of B' vanishes too, to 1e-9 of the hodograph's scale; and
/// the minima of |B'| (roots of B' · B'') where |B'| is below half end_tangent's threshold
/// (1e-12 n of the largest control point) and no root of the first kind is within 1e-6:
/// there B' is zero to within the rounding of its own evaluation, although x' may have no
/// real root (a cusp whose control points are rounded off it), and offset.hpp takes it as a
/// zero (the curve whose derivative vanishes there differs from B by less than 1e-12 of the
/// scale in position).
[[nodiscard]] std::vector<double> stationary_points(const core::Curve& curve);

}  // namespace bezier::outline
