#pragma once

#include <optional>

#include "core/intersect/merge.hpp"
#include "core/intersect/working_curve.hpp"

namespace bezier::core {

/// The best estimate of a contact's (t, s) and how it was found.
struct Refinement {
  double t = 0.0;
  double s = 0.0;
  int iterations = 0;            ///< Newton iterations in all
  bool tangency_system = false;  ///< found by the tangency system, not by f(t) = g(s)
  /// f and g at (t, s) with their tangents, when Newton's method on f(t) = g(s) converged:
  /// from its last compensated evaluation, one step (at most 2^-40) before (t, s), the points
  /// moved along the tangents by that step. The linearisation is off by O(step^2), far below
  /// an ulp, so the points are as accurate as the compensated evaluation (about half an
  /// ulp), more than a plain evaluation at (t, s) (a few ulps), and need none.
  std::optional<PointAndTangent> f_at_t, g_at_s;
};

/// Refines a contact to full double precision, inside its intervals.
///
/// An exact end-point root is returned as it is. Otherwise Newton's method on
/// F(t, s) = f(t) - g(s) = 0 from the centre of the contact, with f and g evaluated to
/// double-double accuracy (compensated de Casteljau, compensated_point.hpp; so the estimate is as accurate as the root's conditioning allows in
/// double precision, even where f and g nearly cancel) and the Jacobian [f', -g'] in
/// doubles; it converges quadratically at a transversal root. At a tangency the Jacobian is
/// singular (f' x g' = 0) and this crawls, so when it ends where the sine of the angle is
/// below `tangent_sine`, Newton's method on the tangency system
///   f'(t) x g'(s) = 0,   (f(t) - g(s)) · f'(t) = 0
/// takes over: its Jacobian has determinant |f'|^5 lambda^2 (kappa_f - kappa_g) (lambda =
/// |g'| / |f'|), regular at a tangency where the curvatures differ, so it converges
/// quadratically to the contact (or, for a near miss, to the closest approach). When t (or
/// s) is free (a curve collapsed to a point), only the other parameter is solved for, by
/// Gauss-Newton on |f(t) - g(s)|^2. Every iterate is clamped to the contact's intervals.
[[nodiscard]] Refinement refine_contact(const WorkingCurve& f, const WorkingCurve& g,
                                        const Contact& contact, bool t_free, bool s_free,
                                        double tangent_sine);

}  // namespace bezier::core
