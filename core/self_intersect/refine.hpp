#pragma once

#include <cmath>
#include <span>

#include "core/base/interval.hpp"
#include "core/base/point.hpp"

namespace bezier::core {

// The functions here expect coordinates of moderate magnitude (within about 2^±300):
// self_intersections() scales other input by a power of two (exact), and lengths are then
// sqrt(v·v) instead of the slower overflow-safe hypot.

/// |v| = sqrt(v·v), for coordinates of moderate magnitude (no overflow protection).
[[nodiscard]] inline double norm(Point2 v) noexcept {
  return std::sqrt(dot(v, v));
}

/// B(t), B'(t) and B''(t) of the curve with control points `points` (degree n >= 1;
/// B'' is zero for n = 1).
struct CurveJet {
  Point2 point;
  Point2 d1;
  Point2 d2;
};

/// The jet by one de Casteljau pass: the last three rows r_0..r_2 and q_0, q_1 give
/// B'' = n (n-1) (r_2 - 2 r_1 + r_0), B' = n (q_1 - q_0) and B = (1-t) q_0 + t q_1
/// (Farin, "Curves and Surfaces for CAGD", 5th ed., §5.3). Plain (uncompensated) rounds,
/// no allocation for n < 32 (this sits in the inner loop of every Newton step); the point is
/// bit for bit the plain de Casteljau value. Any finite t.
[[nodiscard]] CurveJet curve_jet(std::span<const Point2> points, double t);

/// A closed parameter box u x v for a refinement to stay in.
struct ParameterBox {
  ParamInterval u;
  ParamInterval v;
};

/// Outcome of refining a parameter pair (u, v) with B(u) = B(v) in mind.
struct PairRefinement {
  double u = 0.0;
  double v = 0.0;
  /// |B(v) - B(u)| at (u, v), in input units.
  double residual = 0.0;
  /// Whether the iteration converged (last step below a few ulps of the parameters)
  /// inside the box it was given.
  bool converged = false;
  int iterations = 0;
};

/// Newton's method on F(u, v) = B(v) - B(u) = 0, Jacobian J = [-B'(u), B'(v)]: each step
/// solves -B'(u) du + B'(v) dv = -F by Cramer's rule. Quadratic convergence at a transversal
/// double point (B'(u), B'(v) not parallel) until the steps reach the noise floor that
/// `rounding` (the rounding level of F, input units) sets: rounding * ||J^-1||, see
/// double_point_uncertainty. Converged means a step at most max(2^-50, 4 * that floor): the
/// error left after it is of order step^2, and the stepped pair is returned (with the
/// residual before the step). Otherwise the iterate with the smallest |F| is returned. Stops
/// unconverged after `max_iterations`, on a singular Jacobian or a non-finite value, or when
/// an iterate leaves `box`. F vanishes on the whole diagonal u = v too, which is why callers
/// keep u < v by the box and check the result with double_point_uncertainty.
[[nodiscard]] PairRefinement refine_double_point(std::span<const Point2> points, double u0,
                                                 double v0, ParameterBox box, double rounding,
                                                 int max_iterations = 24);

/// How far rounding errors of size `rounding` (input units) in F(u, v) = B(v) - B(u) can
/// move a double point (u, v): rounding * ||J^-1|| with J = [-B'(u), B'(v)], i.e.
/// rounding * sqrt(2) * max(|B'(u)|, |B'(v)|) / |cross(B'(u), B'(v))| (infinite when J is
/// singular). A pair whose uncertainty is not well below s - t cannot be told apart from a
/// point of the diagonal: near a cusp, |F| stays below rounding level for s - t up to about
/// (rounding / |B'''|)^(1/3), and those "roots" are numerical noise, not loops.
[[nodiscard]] double double_point_uncertainty(std::span<const Point2> points, double u, double v,
                                              double rounding);

/// How far apart the parameters u < v are, the way the trivial zeros of F lie: v - u on an
/// open curve; on a closed one (P_0 = P_n: t = 0 and t = 1 are the same point, and F also
/// vanishes at (0, 1), the seam) the shorter way round, min(v - u, 1 - (v - u)).
[[nodiscard]] inline double parameter_separation(double u, double v, bool closed) noexcept {
  const double d = v - u;
  return closed ? std::fmin(d, 1.0 - d) : d;
}

/// Whether a double point (u, v), u < v, is resolved: its uncertainty at rounding level
/// `rounding` is below parameter_separation(u, v, closed) times kResolvedFraction (1/1024,
/// tuning.hpp: why the margin is so wide), so that rounding could not move it onto the
/// diagonal (nor, on a closed curve, onto the seam's trivial pair (0, 1)).
[[nodiscard]] bool is_resolved_double_point(std::span<const Point2> points, double u, double v,
                                            double rounding, bool closed);

/// The touching point of a tangential self-contact: Newton's method on
///   G(u, v) = (F·B'(v), cross(B'(u), B'(v))) = 0,   F = B(v) - B(u),
/// i.e. B(v) is the foot of the perpendicular from B(u) to the other branch and the two
/// tangents are parallel there (an extremum of the distance between the branches).
/// Why not Newton on F: at a tangency the double point is a double root of F, where Newton
/// converges linearly and to about half the digits, and |F|^2 has a degenerate (quartic)
/// minimum along the common tangent. G has a simple root there whenever the two branches
/// have different curvature: its Jacobian
///   [[-B'(u)·B'(v), B'(v)·B'(v) + F·B''(v)], [cross(B''(u), B'(v)), cross(B'(u), B''(v))]]
/// is then regular, so convergence is quadratic. At a near miss it converges to the closest
/// approach instead, and the residual |F| tells the two apart. Iterates are clamped to
/// `box`; stops after `max_iterations`.
[[nodiscard]] PairRefinement refine_self_contact(std::span<const Point2> points, double u0,
                                                 double v0, ParameterBox box,
                                                 int max_iterations = 40);

}  // namespace bezier::core
