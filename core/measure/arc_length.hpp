#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/base/curve.hpp"
#include "core/base/work_budget.hpp"

namespace bezier::core {

/// Tuning of arc_length. The defaults are the API's contract (POST /length in api/openapi.yaml).
struct ArcLengthOptions {
  /// Target relative accuracy: the result's error_bound is at most this times the length.
  double relative_tolerance = 1e-12;
  /// The budget (work units) of arc_length() without a WorkBudget: its own, its running out
  /// reported as tolerance_met false. A cusp costs about two pieces per binary digit of its
  /// distance to the nearest split point, a smooth piece a few: this covers thousands of
  /// pieces at every degree the API takes, far more than any curve needs once split at the
  /// minima of |B'| (see arc_length).
  std::int64_t max_work = 100000000;
};

/// One piece of the final partition of [a, b], with its length by its rule (K7 or P15).
struct LengthPiece {
  double a = 0.0;
  double b = 0.0;
  double length = 0.0;
};

struct ArcLength {
  /// The interval [a, b] measured.
  double a = 0.0;
  double b = 0.0;
  /// ∫_a^b |B'(t)| dt.
  double length = 0.0;
  /// The bound the computation met (see arc_length): Σ over pieces of |K7 - G3| or
  /// |P15 - K7| plus the rounding of the integrand and of the sums.
  double error_bound = 0.0;
  /// Whether error_bound <= relative_tolerance * length was reached. false when the budget
  /// ran out first (budget.exhausted() then says so) or the piece with the largest estimate
  /// was too narrow to halve in doubles; length and error_bound are still honest.
  bool tolerance_met = true;
  /// The partition of [a, b], in increasing t (empty when a = b): what
  /// parameter_at_length inverts.
  std::vector<LengthPiece> pieces;
};

/// The work units (core/intersect/work_cost.hpp's unit) one evaluation of |B'| costs on a
/// curve of degree n: |B'|^2 is a polynomial of degree d = 2n - 2, d (d + 1) / 2 updates
/// of de Casteljau's triangle (at least one).
[[nodiscard]] constexpr std::int64_t speed_evaluation_cost(int degree) noexcept {
  const std::int64_t d = 2 * static_cast<std::int64_t>(degree) - 2;
  const std::int64_t updates = d * (d + 1) / 2;
  return updates > 1 ? updates : 1;
}

/// The work units of adding up the pieces' lengths and estimates after a step, per piece:
/// two compensated additions (Neumaier), each a few floating-point operations.
inline constexpr std::int64_t kLengthSumCostPerPiece = 4;

/// The arc length of B on [a, b], ∫_a^b |B'(t)| dt, for any degree, 2-D or 3-D, to the
/// relative tolerance asked for (the API asks 1e-12; looser tolerances cost less).
///
/// The integrand |B'| = sqrt(S) with S = B' · B', a polynomial of degree 2n - 2 (its
/// Bernstein coefficients are products of hodograph points, bernstein_product.hpp). It is
/// analytic wherever S > 0, with branch points at the complex zeros of S; a Gauss rule
/// converges slowly only where such a zero comes near the real axis, which is where S has
/// a zero (a cusp: |B'| behaves like |t - t0|) or a small minimum. So [a, b] is first split
/// at every minimum of |B'| in (a, b) (a root of S' where it rises through zero; at most
/// n - 1 of them, found by the certified Bernstein root finder), and graded toward a small
/// one: a near-zero of |B'| then sits at a piece end, where Gauss nodes cluster, and a
/// maximum of |B'|, where S > 0, is left inside its piece. Each piece is then integrated
/// by nested rules that reuse their nodes: the 3-point Gauss rule G3, its 7-point Kronrod
/// extension K7 (Kronrod 1965) and the 15-point Patterson extension P15 of K7 (Patterson
/// 1968), exact for polynomials of degree 5, 11 and 23. A piece starts with K7 and the
/// estimate |K7 - G3|; the piece with the largest estimate is extended to P15 (8 more
/// evaluations, estimate |P15 - K7|) and, once extended, halved (its halves by P15), until
///   Σ estimates + rounding <= relative_tolerance * length.
/// Each estimate is the difference between the value returned and a rule of about half its
/// degree: for an analytic integrand the lower rule's error decays like ρ^-6 (G3) or
/// ρ^-12 (K7), the returned one's like ρ^-12 (K7) or ρ^-24 (P15) (ρ the piece's Bernstein
/// ellipse parameter), so where the two agree to the tolerance the value returned is far
/// more accurate than the bound claims. This is the standard a posteriori estimate, not an
/// interval-arithmetic proof; the splitting and the adaptive halving keep it in its
/// asymptotic regime, and the tests check it against closed forms and reference
/// quadrature at tolerances from 1e-2 to 1e-12. A loose tolerance is met by K7 alone on
/// most pieces of a smooth curve: 7 evaluations of |B'| per piece.
/// The rounding term: |B'(t)| is evaluated by de Casteljau on the hodograph h_0..h_{n-1}
/// (within 3.01 n u Σ_i ||h_i||_1 b_i(t) per coordinate, Higham §5.1) and the square root
/// of the sum of squares (within 3 u of the length), so the integral carries at most
/// 2 (3.01 n + 3) u ∫_a^b Σ_i ||h_i||_1 b_i(t) dt (computed in closed form), plus 20 u of
/// the length for the rules' weighted sums and the compensated total.
///
/// Compared with kurbo's arclen (a fixed 8- or 16-point Legendre rule whose error is
/// estimated from the control polygon, recursing on halves, with an absolute accuracy) and
/// lib2geom's length (the control polygon against the chord, subdividing until they agree,
/// which converges only linearly at a cusp): this is relative, splits where the integrand
/// is not smooth, and reports the bound it met.
///
/// Work: each rule's evaluations of |B'| (speed_evaluation_cost each) and each sum over the
/// pieces (kLengthSumCostPerPiece a piece) are charged to `budget`; an extension or a
/// halving that does not fit in what is left is not made, the budget is then exhausted and
/// the result has tolerance_met false. (Finding the minima of |B'| is bounded by the degree
/// and not charged.)
///
/// Precondition: 0 <= a <= b <= 1, finite control points. a = b gives 0 exactly. Invariant
/// under translation, uniform scaling and reversal up to rounding.
[[nodiscard]] ArcLength arc_length(const Curve& curve, double a, double b,
                                   const ArcLengthOptions& options, WorkBudget& budget);
[[nodiscard]] ArcLength arc_length(const Curve3& curve, double a, double b,
                                   const ArcLengthOptions& options, WorkBudget& budget);

/// The same with a budget of options.max_work units of their own.
[[nodiscard]] ArcLength arc_length(const Curve& curve, double a, double b,
                                   const ArcLengthOptions& options = {});
[[nodiscard]] ArcLength arc_length(const Curve3& curve, double a, double b,
                                   const ArcLengthOptions& options = {});

/// The parameter t in [a, b] (a, b the interval `measured` was computed on) with
/// length(a, t) = `length`: the piece of `measured` holding that length is found by its
/// cumulative lengths, then t by Newton's method on F(t) = length(a, t) - length with
/// F' = |B'(t)|, safeguarded: the bracket [lo, hi] shrinks with the sign of F at every
/// iterate, and a step that leaves it, or a zero |B'|, is replaced by bisection, so t never
/// leaves [a, b] and the iteration converges (quadratically where |B'| > 0) in at most 200
/// steps. length(piece start, t) is P15 on [piece start, t], a part of a piece whose rule
/// (K7 or P15) met the tolerance. Precondition: 0 <= length; a length above the total
/// gives b.
[[nodiscard]] double parameter_at_length(const Curve& curve, const ArcLength& measured,
                                         double length);
[[nodiscard]] double parameter_at_length(const Curve3& curve, const ArcLength& measured,
                                         double length);

}  // namespace bezier::core
