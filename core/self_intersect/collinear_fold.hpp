#pragma once

#include <optional>
#include <span>
#include <vector>

#include "core/base/point.hpp"
#include "core/base/work_budget.hpp"
#include "core/self_intersect/self_intersection.hpp"

namespace bezier::core {

/// The line a collinear curve runs along: B(t) = origin + x(t) direction.
struct CollinearFrame {
  Point2 origin;
  /// From P_0 to the control point farthest from it; zero when every point equals P_0.
  Point2 direction;
};

/// The frame when every control point lies within `dist_tol` of the line through P_0 and
/// the control point farthest from P_0 (all points equal: direction zero); nullopt when the
/// curve is not collinear at that tolerance. A curve that thin is a segment traversed back
/// and forth as far as double precision can tell, and its self-intersections are continua.
/// Expects coordinates below 2^500 in magnitude (squared lengths must not overflow);
/// self_intersections() scales extreme inputs by a power of two first.
[[nodiscard]] std::optional<CollinearFrame> collinear_frame(std::span<const Point2> points,
                                                            double dist_tol);

/// The same for a cubic's four control points (the same computation).
[[nodiscard]] std::optional<CollinearFrame> collinear_frame(std::span<const Point2, 4> points,
                                                            double dist_tol);

/// Self-overlaps of a collinear curve, in four phases. Along the line B is the scalar
/// Bernstein polynomial x(t) = Σ x_i b_i(t), x_i = (P_i - origin)·direction / |direction|^2
/// (line coordinates). Its sign runs: the coefficients of x' (x_{i+1} - x_i) subdivided until
/// they share a sign (variation diminishing property, Farin §5.5). Its monotone pieces:
/// between runs of opposite signs a turning point, located by bisection on x'; roots of even
/// multiplicity do not turn the curve and are skipped. Its retraced pieces: two monotone
/// pieces whose ranges of x overlap by more than dist_tol retrace each other there, and the
/// overlap's parameter intervals are the preimages of the common range (bisection). Every
/// pair of pieces is reported, in order of t. A point curve (direction zero) is one overlap
/// [0,1] x [0,1].
/// Each subdivision step of the sign runs is charged collinear_fold_step_cost(n)
/// (work_cost.hpp) to `budget`; when a step does not fit in what is left the budget is
/// exhausted and nothing is returned.
[[nodiscard]] std::vector<Overlap> collinear_self_overlaps(std::span<const Point2> points,
                                                           const CollinearFrame& frame,
                                                           double dist_tol, WorkBudget& budget);

}  // namespace bezier::core
