#pragma once

#include "core/intersect/result.hpp"
#include "core/intersect/working_curve.hpp"

namespace bezier::core {

/// What the Krawczyk test proved about a box X = T x S of the parameter square.
struct KrawczykResult {
  enum class Verdict {
    inconclusive,  ///< nothing proved: the box goes on being clipped
    no_root,       ///< f(t) != g(s) everywhere on X
    one_root,      ///< X holds exactly one root, and it lies in t x s below
  };
  Verdict verdict = Verdict::inconclusive;
  ParamInterval t;  ///< one_root: [y_t - radius, y_t + radius], inside X
  ParamInterval s;  ///< one_root: [y_s - radius, y_s + radius], inside X
};

/// The Krawczyk operator (R. Krawczyk, "Newton-Algorithmen zur Bestimmung von Nullstellen
/// mit Fehlerschranken", Computing 4, 1969; R. E. Moore, "A test for existence of solutions
/// to nonlinear systems", SIAM J. Numer. Anal. 14, 1977) for F(t, s) = f(t) - g(s) on X.
///
/// J(X), an interval matrix holding the Jacobian [f'(t), -g'(s)] for every (t, s) in X, comes
/// from the hulls of the pieces' hodographs (f_piece is f on T, g_piece is g on S, both fast
/// pieces in the working frame, with their error bounds). C is the inverse of J(X)'s
/// midpoint, and B >= |I - C J| entrywise for every J in J(X), every rounding included.
/// With K(Z, y) = y - C F(y) + (I - C J(X)) (Z - y) for a box Z inside X and y in Z:
///  - rho = ||B||_inf < 1 makes every matrix of J(X) regular, so F is injective on the convex
///    X (F(a) - F(b) is the mean of J along the segment, a matrix of J(X), times a - b):
///    at most one root in X;
///  - a root in X lies in K(X, y0) for any y0 in X (the mean value theorem), so K(X, y0)
///    disjoint from X proves there is none;
///  - K(Y, y) inside Y proves a root in Y (Brouwer's fixed point theorem on the continuous
///    map z -> z - C F(z), which sends Y into K(Y, y)).
/// The tight box Y = y +- radius is centred on a Newton iterate y (in doubles, from y0: where
/// the chords of the pieces cross, or the centre of X; y is rounded to a multiple of 2^-52 so
/// that y +- radius is exact). F(y) is
/// evaluated by de Casteljau in doubles on the whole working curves, with the bound
/// frame_error + lerp_levels_error_bound(n, magnitude) per curve. Verdict one_root needs rho <= 1/2 and Y
/// inside X; a root within `radius` of X's boundary, a tangency (J(X) nearly singular) or a
/// box too wide for J(X) to be nearly constant stay inconclusive.
/// Preconditions: both curves of degree >= 1 (not single points), radius a power of two
/// in [2^-52, 2^-2].
[[nodiscard]] KrawczykResult krawczyk(const WorkingCurve& f, const WorkingCurve& g,
                                      const Piece& f_piece, const Piece& g_piece, ParamInterval t,
                                      ParamInterval s, double radius);

}  // namespace bezier::core
