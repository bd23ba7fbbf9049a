#pragma once

#include <optional>
#include <span>

#include "core/intersect/result.hpp"

namespace bezier::core {

/// A conservative interval around {t in [0,1] : lo <= p(t) <= hi} for a polynomial p of
/// degree 1, 2 or 3 given by its Bernstein coefficients: nullopt only when p certainly
/// avoids the band, otherwise an interval that certainly contains every t where p meets it.
///
/// Method: the boundary of the set is among the real roots of p(t) = lo and p(t) = hi, found
/// in closed form (linear; the cancellation-free quadratic formula, Numerical Recipes §5.6;
/// Viète's trigonometric / Cardano's formula for cubics, each root polished by Newton's
/// method). Segments between consecutive roots are kept when p at their midpoint is in the
/// band; the hull of the kept segments is widened by 2^-32. Rounding can misplace a root or
/// miss a pair of nearly double ones, so the result is then certified: on each excluded end
/// [0, alpha] and [beta, 1], p's Bernstein coefficients (a de Casteljau portion, with its
/// rounding bound) must all lie strictly below lo or all strictly above hi, which by the
/// convex hull property proves p avoids the band there. If a certificate fails, the interval
/// comes from repeated convex-hull clips of p (bernstein::hull_clip) instead, which are
/// conservative by construction.
[[nodiscard]] std::optional<ParamInterval> kept_interval(std::span<const double> p, double lo,
                                                        double hi);

/// The same by convex-hull clipping alone, repeated on the kept piece while it shrinks by
/// more than 20 % (at most 8 times). Any degree.
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
