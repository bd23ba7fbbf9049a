#pragma once

#include "core/intersect/clip/clip.hpp"
#include "core/intersect/clip/fat_curve.hpp"

namespace bezier::core {

/// Clip of x against the "fat parabola" of `other`, for pieces that run close together.
///
/// A fat line bounds `other` by a band of width ~ kappa w^2 around its chord; where two
/// curves touch with equal curvature (a contact of order 3) they stay within c d^3 of each
/// other, so the band keeps a tube of O(w^(-1/3)) boxes alive at every width w. Here
/// `other` is bounded by a parabola instead: Q, its L2-best degree-2 approximation (op2,
/// with reduce/elevate for other's degree), and delta, the largest distance between
/// other's control points and Q's elevated back (so |other(u) - Q(u)| <= delta). The
/// parabola through Q is the zero set of the implicit quadratic
///   I(p) = D1(p)^2 - 4 D0(p) D2(p),  D_i(p) = cross(Q_j - p, Q_k - p), (i, j, k) cyclic,
/// (the barycentric coordinates of Q(u) are the Bernstein polynomials, and B1^2 = 4 B0 B2;
/// Sederberg, "Implicit and parametric curves and surfaces for CAGD", PhD thesis, 1983).
/// Every point of `other` satisfies |I| <= |D| Gamma delta + ||H|| delta^2 / 2 (Taylor's
/// formula of the quadratic I around Q(u), with |grad I| <= |D| Gamma on Q, D the doubled
/// area of Q's control triangle, Gamma and ||H|| from its edge lengths). J(t) = I(x(t)) is a
/// polynomial of degree 2n whose Bernstein coefficients come from the D_i at x's control
/// points (D_i is affine) and the product formula; the part of x's domain where J can be in
/// that band is found by the convex hull clip. All rounding and the pieces' error bounds are
/// included, so the clip is conservative. Returns kept = [0, 1] (no information) when
/// `other` is straight (Q degenerate) or of degree 1.
[[nodiscard]] Clip implicit_clip(const Piece& x, const Piece& other, const FatCurveOperator& op2);

}  // namespace bezier::core
