#pragma once

#include <span>

#include "core/base/point.hpp"

namespace bezier::core {

/// Exact signs of the polynomials that classify a planar cubic (see CubicPredicates).
/// Each is -1, 0 or +1.
struct CubicSigns {
  int d1 = 0;
  int d2 = 0;
  int d3 = 0;
  int d2_plus_2d3 = 0;  ///< d2 + 2 d3
  int i1 = 0;           ///< I(1) = d1 + d2 + d3
  int disc = 0;         ///< d2² − 4 d1 d3
  int l0 = 0;           ///< d2² − 3 d1 d3
  int l1 = 0;           ///< d2² + d2 d3 + d3² − 3 d1 d3
};

/// The invariants of a cubic B(t) = Σ C(3,i) (1−t)^(3−i) t^i P_i from which its type,
/// inflections, cusp and double point follow, with their signs decided exactly.
///
/// Power form: B(t) = P0 + 3 a t + 3 b t² + c t³ with a = P1 − P0, b = P2 − 2 P1 + P0,
/// c = P3 − 3 P2 + 3 P1 − P0. Then B'(t) × B''(t) = 18 I(t), the inflection polynomial
///     I(t) = d1 + d2 t + d3 t²,   d1 = a × b,  d2 = a × c,  d3 = b × c
/// (the t³ term c × c vanishes; cf. Skia's SkFindCubicInflections, and Loop & Blinn,
/// "Resolution independent curve rendering using programmable graphics hardware",
/// SIGGRAPH 2005, §4, whose d1, d2, d3 are these in reverse order and scale). They are
/// computed from the differences u = P1 − P0, v = P2 − P0, w = P3 − P0:
///     d1 = u × v,   d2 = u × w − 3 u × v,   d3 = 3 u × v − 2 u × w + v × w.
///
/// The degree-4 predicates, derived from B'(t) = 0 and B(s) = B(t):
///   - disc = d2² − 4 d1 d3, the discriminant of I: < 0 the unbounded curve has a loop,
///     = 0 a cusp (at t = −d2 / (2 d3)), > 0 two real inflections (serpentine).
///   - With a loop, its parameters s, t are the roots of d3 z² + d2 z + l0 / d3, so
///     s + t = −d2 / d3 and l0 = d2² − 3 d1 d3 = d3² s t, l1 = d2² + d2 d3 + d3² − 3 d1 d3
///     = d3² (1 − s)(1 − t): l0 = 0 when the loop closes at t = 0, l1 = 0 when at t = 1.
///   - d2 + 2 d3 compares the vertex −d2 / (2 d3) of I (the cusp, the loop's midpoint) with 1.
///
/// In the Stone–DeRose canonical coordinates (x, y) of P3 (the affine image with P0, P1,
/// P2 at (0,0), (0,1), (1,1); x = (u × w) / d1, y = ((P1 − P2) × w) / d1) these are the
/// edges of the regions, multiplied out by d1 (M. Stone, T. DeRose, "A geometric
/// characterization of parametric cubic curves", ACM TOG 8(3), 1989; Pomax, "A Primer on
/// Bézier Curves", §"Canonical form"):
///     d2 = d1 (x − 3),  d3 = d1 (3 − x − y),  I(1) = d1 (1 − y),  d2 + 2 d3 = d1 (3 − x − 2y),
///     disc = d1² (x² − 2x + 4y − 3)         cusp edge  y = (−x² + 2x + 3) / 4
///     l0   = d1² (x² − 3x + 3y)             loop at start  y = (−x² + 3x) / 3
///     l1   = d1² (x² + xy + y² − 3x)        loop at end  y = (√(3(4x − x²)) − x) / 2
/// so deciding these signs is deciding on which side of each edge the canonical point lies,
/// without dividing by d1 (which vanishes when P0, P1, P2 are collinear).
///
/// Exactness: a floating-point evaluation with a rigorous a-priori error bound decides each
/// sign when the value is clearly away from zero; otherwise the polynomial is evaluated
/// exactly with expansion arithmetic (core/numeric/expansion.hpp) on the inputs scaled by a power of
/// two. The signs are exact for all inputs whose nonzero coordinates lie within a factor of
/// 2^400 (about 1e120) of the largest one; `exact` reports whether that held (beyond it a
/// tiny coordinate may lose bits to underflow in the exact path). Invariances: translation
/// leaves every value unchanged, a linear map with matrix A multiplies the d's by det A and
/// the degree-4 values by (det A)².
struct CubicPredicates {
  /// Approximations of d1, d2, d3 and of the canonical numerators x_num = u × w and
  /// y_num = (P1 − P2) × w, all times one common positive power of two (1 unless the input
  /// needed rescaling): only ratios and signs carry meaning. Their signs agree with `sign`.
  double d1 = 0.0;
  double d2 = 0.0;
  double d3 = 0.0;
  double x_num = 0.0;
  double y_num = 0.0;
  /// Approximations of disc, l0, l1 at the square of that scale.
  double disc = 0.0;
  double l0 = 0.0;
  double l1 = 0.0;
  CubicSigns sign;
  /// True when every sign is certainly exact (see above).
  bool exact = true;
};

/// The predicates of the cubic with control points p[0..3]. Precondition: finite coordinates.
/// Cost: about 100 floating-point operations; the exact fallback (rare: only for inputs on
/// or within rounding of an edge, or with coordinate differences outside 2^±200) allocates.
[[nodiscard]] CubicPredicates cubic_predicates(std::span<const Point2, 4> p);

/// The same with the filter skipped: every sign from exact expansion arithmetic. For tests
/// and for comparing the two paths.
[[nodiscard]] CubicPredicates cubic_predicates_exact(std::span<const Point2, 4> p);

}  // namespace bezier::core
