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

/// The zeros of B' inside (0, 1): roots of x' (or of y' when x' is identically zero) where the
/// other coordinate of B' vanishes too, to 1e-9 of the hodograph's scale; ascending.
[[nodiscard]] std::vector<double> stationary_points(const core::Curve& curve);

}  // namespace bezier::outline
