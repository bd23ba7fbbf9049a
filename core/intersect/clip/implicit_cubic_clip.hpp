#pragma once

#include "core/intersect/clip/clip.hpp"
#include "core/intersect/working_curve.hpp"

namespace bezier::core {

/// Clip of x against the exact implicit equation of a cubic piece `other`, for cubics that
/// run so close together that a fat parabola (implicit_clip.hpp) cannot part them.
///
/// The fat parabola bounds a cubic by a band of its cubic term, about c w^3 at width w, so
/// two cubics a distance d apart along their whole length stay unparted until the boxes are
/// about d^(1/3) wide: thousands of boxes for d near 1e-11 of their size. A cubic's own
/// implicit equation has no such term: with L_ij(p) = C(3,i) C(3,j) cross(P_i - p, P_j - p)
/// (affine in p), the Bezout matrix
///     M(p) = [[L32, L31, L30], [L31, L30 + L21, L20], [L30, L20, L10]]
/// has det M(p) = 0 at every point of the cubic (Sederberg, "Implicit and parametric curves
/// and surfaces for CAGD", 1983; Sederberg, Anderson & Goldman, "Implicit representation of
/// parametric curves and surfaces", 1984), so J(t) = det M(x(t)), a polynomial of degree 3n
/// in Bernstein form (the entries at x's control points, then products of polynomials), is
/// zero wherever x meets `other`, and a distance d away it is about d |grad det M|.
///
/// The band. Points of the true `other` lie within e_o = sqrt(2) other.error of the stored
/// cubic Q, and points of the true x within e_x = sqrt(2) x.error of the stored piece X. For
/// q on either curve and |e| <= e, M(q + e) = M(q) + E with |E_ij| <= C(3,i) C(3,j)
/// |P_j - P_i| e (L_ij moves by C C cross(P_j - P_i, e)). Expanding det(M + E) by columns,
/// the terms with one column of E sum to grad det M(q) . e (Jacobi's formula: the cofactors
/// times the entries' slopes), bounded by the largest Bernstein coefficients of grad det M
/// along the curve; the terms with two or three columns of E are bounded by Hadamard's
/// inequality, with column norms bounded over the hull where q lies (|P_i - q| at most the
/// distance to the hull's farthest vertex). det M = 0 on Q, so where x meets `other`,
/// |J(t)| <= band_o + band_x + e_J, e_J bounding the rounding of J's coefficients. The
/// entries, cofactors and J are computed in double-double arithmetic in the scaled Bernstein
/// basis (products are convolutions without weights), each operation's rounding tracked: J
/// cancels to about the gap times the products that form it, which doubles would bury
/// below gaps near 1e-11 of the curves' size. Keeping the t where J can be in [-band, band]
/// (the convex hull clip) is conservative. A degenerate cubic (all control points on a
/// line, or a quadratic raised in degree) has det M small or zero everywhere: J stays in the
/// band and the clip keeps everything, which is sound.
/// `noisy`: the band, all of it rounding, is a quarter of J's spread or more.
/// Precondition: other.degree() == 3; x of any degree.
[[nodiscard]] Clip implicit_cubic_clip(const Piece& x, const Piece& other);

}  // namespace bezier::core
