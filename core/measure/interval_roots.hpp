#pragma once

#include <span>

#include "core/numeric/small_array.hpp"

namespace bezier::core {

/// Which ends of [a, b] count: the critical points of /bounds lie in the open interval,
/// the candidates of /nearest in the closed one.
enum class IntervalEnds { open, closed };

/// The roots of a scalar polynomial in Bernstein form on [0, 1], c_0..c_n, that lie in
/// [a, b] (or (a, b)), ascending, each root once.
///
/// Isolation as in bernstein_roots (core/bernstein/roots.hpp), by subdivision of [a, b] with
/// Descartes' rule of signs on the Bernstein coefficients of each piece (Lane & Riesenfeld,
/// BIT 21, 1981): a piece is discarded only when its coefficients, each computed within its
/// rounding bound e = 3.02 n u max|c_i|, have one strict sign (then p has no root there, by
/// the convex hull property), so no root of the polynomial with the given coefficients is
/// lost except where |p| <= e throughout. A piece with exactly one sign change and p of
/// opposite signs at its ends holds exactly one root, which is refined by Newton's method
/// from where the piece's control polygon crosses zero, kept inside the sign bracket (a
/// step out of it is a bisection), until |p| is within the rounding bound e' of the
/// evaluation it uses, then one more Newton step: within about e' / |p'| of the root, as
/// closely as the rounded p determines it (or until the bracket is one ulp). The
/// evaluation is p's Horner form (core/bernstein/horner_form.hpp, O(n) a step, e' about
/// twice e; then one last Newton step from de Casteljau's rounds, which are exact at short
/// binary fractions) from degree measure_tuning::kHornerFromDegree up to
/// measure_tuning::kUnrolledSizes coefficients, de Casteljau's (e' = e) otherwise. The same sign tests as bisection, a few instead of 55 per root. An exact zero of p at a split
/// point is a root, and the pieces on either side leave that end out of their count.
/// A cluster still unresolved at width 2^-40 (a multiple root, a root where p rounds to
/// a tiny nonzero value at a split point) is reported at the middle of its piece.
/// Where p stays within e of zero the search may report several points a little apart,
/// each with an exact |p| within 2e (its piece's coefficients are within e of zero, and
/// within e of the exact ones). Near a multiple root |p| is no larger between two such
/// points, so p evaluates within 3e at their midpoint: consecutive points with that are one
/// flat stretch, chained (each point compared with the one before it, whether that one was
/// kept or not), and a stretch is one root, represented by its point with the smallest
/// computed |p|. `isolated` is false when such a flat stretch was met (a
/// double root is then within about sqrt(e / |p''|) of the reported t, a root of
/// multiplicity m within about (e / |p^(m)|)^(1/m)).
struct IntervalRoots {
  SmallArray<double> roots;
  bool isolated = true;
};

/// Which roots are wanted: every one, or only those where p rises through zero (a
/// minimum of a function whose derivative is p, as /nearest wants). With `rising`, a
/// one-root piece where p falls from positive to negative is left out unrefined; every
/// other root is reported as with `any` (exact zeros, clusters and flat stretches, whose
/// direction the signs do not settle).
enum class Crossings { any, rising };

/// Precondition: c non-empty, 0 <= a <= b <= 1.
[[nodiscard]] IntervalRoots interval_roots(std::span<const double> c, double a, double b,
                                           IntervalEnds ends, Crossings wanted = Crossings::any);

}  // namespace bezier::core
