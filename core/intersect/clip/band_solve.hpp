#pragma once

#include <optional>
#include <span>

#include "core/intersect/result.hpp"

namespace bezier::core {

/// A conservative interval around {t in [0,1] : lo <= p(t) <= hi} for a polynomial p of
/// degree 1, 2 or 3 given by its Bernstein coefficients: nullopt only when p certainly
/// avoids the band, otherwise an interval that certainly contains every t where p meets it.
///
/// Method: the boundary of the set is among the real roots of p(t) = lo and p(t) = hi.
///  - p monotone (monotone Bernstein coefficients, the usual case once pieces are small):
///    one root per level, by Halley's method from where the control polygon crosses it,
///    widened by 2^-32 and certified by one value of p beyond each end (a monotone p
///    that is outside the band there stays outside up to the end of [0, 1]).
///  - otherwise, degree <= 2: the roots in closed form (linear; the cancellation-free
///    quadratic formula, Numerical Recipes §5.6); segments between consecutive roots are
///    kept when p at their midpoint is in the band; the hull of the kept segments is
///    widened by 2^-32 and certified: on each excluded end [0, alpha] and [beta, 1], p's
///    Bernstein coefficients (a de Casteljau portion, with its rounding bound) must all lie
///    strictly below lo or all strictly above hi, which by the convex hull property proves p
///    avoids the band there.
///  - otherwise, degree 3: repeated convex-hull clips of p (below). The exact set from the
///    cubic's monotone stretches is tighter there but costs more than it saves: such
///    cubics come from large pieces, far from convergence.
///  - whenever a certificate fails: repeated convex-hull clips of p (bernstein::hull_clip),
///    conservative by construction.
/// real_roots_up_to_cubic (Viète / Cardano for cubics) is kept for callers that want the
/// roots themselves.
[[nodiscard]] std::optional<ParamInterval> kept_interval(std::span<const double> p, double lo,
                                                         double hi);

/// The same by convex-hull clipping alone, repeated on the kept piece while it shrinks by
/// more than 20 % (at most 3 times). Any degree.
[[nodiscard]] std::optional<ParamInterval> kept_interval_by_hulls(std::span<const double> p,
                                                                  double lo, double hi);

/// Real roots of c0 + c1 t + c2 t^2 + c3 t^3 = 0 in [lo, hi] (any of c1..c3 may be zero;
/// an identically zero polynomial has no isolated roots and gives none), ascending.
struct CubicRoots {
  double t[3] = {0.0, 0.0, 0.0};
  int count = 0;
};
[[nodiscard]] CubicRoots real_roots_up_to_cubic(double c0, double c1, double c2, double c3,
                                                double lo, double hi);

}  // namespace bezier::core
