#pragma once

#include <optional>
#include <vector>

#include "core/numeric/small_array.hpp"
#include "core/intersect/overlap.hpp"
#include "core/intersect/result.hpp"
#include "core/intersect/working_curve.hpp"

namespace bezier::core {

/// An improperly parametrised curve written through its proper one: c(t) = h(p(t)) for
/// every t, with h a polynomial curve of degree d and p a polynomial of degree k >= 2,
/// n = d k. A polynomial curve has such a factorisation exactly when, over all real t, it
/// traces its point set more than once (Lüroth's theorem: the field R(x(t), y(t)) is R(p(t)) for some p,
/// and for a polynomial curve p can be taken polynomial); p is unique up to an affine map
/// of u, fixed here by p([0, 1]) = [0, 1], so h on [0, 1] is the arc c traces.
struct Factorisation {
  Coeffs hx, hy;  ///< h on [0, 1], Bernstein form, degree d
  Coeffs p;       ///< Bernstein form on [0, 1], degree k, range [0, 1]
};

/// The factorisation of c with the largest k, when c is improper (nullopt when proper).
/// The right factor p of each candidate degree k | n comes from the top k monomial
/// coefficients of c's dominant coordinate a: a = A_d (p + e)^d + O(p^(d-2)) for monic p,
/// so p + e is the truncated d-th root of a / A_d at infinity (Kozen & Landau,
/// "Polynomial decomposition algorithms", J. Symbolic Comput. 7, 1989). It goes on when
/// both coordinates divide by p down to constants (to within 1e-4 of their coefficients:
/// a filter, not a proof); h then comes from interpolating c at d + 1 points, p is refined
/// on the curve when h(p) nearly fits (Gauss-Newton; the root loses digits where the
/// power form cancels), and c = h(p) must hold to 1e-9 at 2n + 1 samples. Every use of a
/// factorisation verifies what it concludes on the curves themselves.
[[nodiscard]] std::optional<Factorisation> factorise(const WorkingCurve& c);

/// Two curves tracing one arc: f(t) = h(p(t)) and g(s) = h(q(s)) with h proper. Then
/// f(t) = g(s) on the arc exactly where p(t) = q(s) (apart from h's own crossings), an
/// algebraic curve of the parameter square, reported as overlaps: one per pair of pieces
/// where p and q are monotone whose ranges share more than a point.
struct CommonArc {
  Coeffs hx, hy;  ///< h, Bernstein form on [0, 1] (extended beyond it as a polynomial)
  double h_magnitude = 0.0;
  Coeffs p, q;  ///< Bernstein form on [0, 1]
  /// Boxes of the parameter square around pieces whose ranges share too little to be
  /// reported as overlaps (a point, or less than 2^-30 in t or s): the search looks there.
  std::vector<std::pair<ParamInterval, ParamInterval>> searched;
};

/// The overlaps of f and g when one of them is improper and both trace one arc
/// (OverlapFinding::arc set, shared by all). Every overlap's ends are pinned down by
/// Newton's method on f and g (each end is where an end or turning point of one curve
/// lies on the other), and every piece is verified on f and g themselves: points of f
/// along it, projected onto g, lie within overlap_tolerance of g, and the same with the
/// curves' roles exchanged. Empty when both curves are proper (find_overlaps covers them:
/// their parametrisations differ by an affine map), when they trace different arcs, or
/// when a verification fails. Only the pieces whose boxes meet t_window x s_window are
/// verified and reported (a search confined to that window needs no others: the one-curve
/// certification searches small boxes around each self-intersection).
[[nodiscard]] std::vector<OverlapFinding> find_arc_overlaps(const WorkingCurve& f,
                                                            const WorkingCurve& g,
                                                            ParamInterval t_window = {0.0, 1.0},
                                                            ParamInterval s_window = {0.0, 1.0});

/// The pieces an improper curve c = h(p) retraces: one overlap (t before s) per pair of
/// different pieces on which p is monotone whose ranges share more than a point, found and
/// verified as find_arc_overlaps does. Empty when c is proper.
[[nodiscard]] std::vector<OverlapFinding> find_self_arc_overlaps(const WorkingCurve& c);

/// True when every intersection in the box t x s is a point of the arc's overlaps: h is
/// injective on the hull of p(t) and q(s) (so f(t') = g(s') there forces p(t') = q(s')),
/// and the box avoids the arc's searched boxes.
[[nodiscard]] bool covered_by_arc(const CommonArc& arc, ParamInterval t, ParamInterval s);

/// True when (t, s) lies on the overlap (of this arc): inside its intervals to within
/// 2^-30, and p(t) = q(s) to within the accuracy of p and q (2^-24).
[[nodiscard]] bool on_arc_overlap(const CommonArc& arc, const Overlap& overlap, double t,
                                  double s);

}  // namespace bezier::core
