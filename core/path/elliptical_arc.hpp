#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "core/base/curve.hpp"
#include "core/base/point.hpp"

namespace bezier::path {

// Elliptical arcs of SVG path data (the A and a commands) as cubic Bézier segments.
//
// The arc. SVG 2 §9.5.1 and its "Elliptical arc implementation notes" (SVG 2 Appendix
// "Implementation Notes", §B.2.3 to §B.2.5; SVG 1.1 Appendix F.6.2 to F.6.6 agree) define an
// arc by its end points, radii rx, ry, the rotation φ of the ellipse's x axis and two
// flags, and say how out-of-range parameters are read:
//   - end points equal: no arc at all (nothing is drawn);
//   - rx = 0 or ry = 0: a straight line to the end point;
//   - negative radii: their absolute values; φ is taken modulo 360 degrees;
//   - radii too small for an ellipse through both end points (Λ > 1 below): scaled up
//     uniformly, by √Λ, to the smallest ellipse that reaches (the centre is then the
//     chord's midpoint and the arc half the ellipse).
// Endpoint to centre parametrisation (B.2.4), written in the ellipse's unit coordinates so
// that nothing squares a radius (no overflow): with M the midpoint of the chord and
// (x', y') = R(-φ) (P_start - P_end) / 2, let d = (x' / rx, y' / ry) and m = |d| (Λ = m²).
// With ê = d / m, ê⊥ its counter-clockwise perpendicular, q = √(1 - m²) and s = +1 when
// the large-arc flag differs from the sweep flag, else -1, the ellipse's centre is
// C = M + R(φ) diag(rx, ry) (-s q ê⊥), and the start and end points are the images of the
// unit vectors u1 = m ê + s q ê⊥ and u2 = -m ê + s q ê⊥. The arc runs from angle θ1 of u1
// through Δθ, the angle from u1 to u2 taken in (0, 2π) when the sweep flag is 1 (angles
// increasing) and in (-2π, 0) when it is 0. This is the notes' formula (F.6.5.2) divided
// through by rx and ry.
//
// The cubics. The arc of the unit circle from α to α + δ (|δ| < 2π) is approximated by the
// cubic with control points
//   P0 = e(α), P1 = e(α) + k e'(α), P2 = e(α+δ) - k e'(α+δ), P3 = e(α+δ),
//   e(α) = (cos α, sin α), k = 4/3 tan(δ/4),
// which has the arc's end points and end tangents and passes through the arc's midpoint.
// Its error has a closed form (Goldapp, "Approximation of circular arcs by cubic
// polynomials", CAGD 8 (1991); Riškus, "Approximation of a cubic Bézier curve by circular
// arcs and vice versa", ITC 35 (2006)), derived here. Turn the arc to span -δ/2..δ/2; then
// f(t) = |B(t)|² - 1 is a polynomial of degree 6 in t with double roots at t = 0 and t = 1
// (|B| = 1 there, and B · B' = 0 since the end tangents are perpendicular to the radius),
// and at t = 1/2 (B(1/2) is on the circle by the choice of k, and f(t) = f(1 - t) by the
// mirror symmetry of the control points). Six roots fix f up to its leading coefficient:
//   f(t) = c t² (1 - t)² (1 - 2t)²,  c = |a3|² / 4,  a3 = P3 - 3 P2 + 3 P1 - P0
// (the t³ coefficient of B). With h = δ/4, a3 = (0, 6k cos 2h - 4 sin 2h) = (0, -8 sin³h /
// cos h), so c = 16 sin⁶h / cos²h. On [0, 1], t²(1 - t)²(1 - 2t)² = u²(1 - 4u) with
// u = t(1 - t) ∈ [0, 1/4] is largest at u = 1/6, where it is 1/108. Hence
//   0 <= |B(t)| - 1 <= √(1 + (4/27) sin⁶(δ/4) / cos²(δ/4)) - 1 =: ε(δ),
// and each point of the cubic is within ε(δ) of the circle; since |B| - 1 >= 0 and the
// cubic's direction from the centre sweeps the arc's angles, each point of the arc is as
// close to the cubic (the Hausdorff distance is at most ε(δ)). ε grows with |δ|.
// The ellipse is the image of the unit circle under the affine map A(p) = C + R(φ)
// diag(rx, ry) p, and so is each cubic (Bézier curves are affinely invariant); A stretches
// no distance by more than max(rx, ry). So each cubic of the ellipse's arc is within
// max(rx, ry) ε(δ) of the ellipse. The number of pieces n is the smallest with
// max(rx, ry) ε(|Δθ| / n) <= tolerance / 2 and |Δθ| / n <= π/2.
//
// Rounding. The bound above is for exact arithmetic on the ellipse with the centre and
// angles as computed in double precision (when the radii barely reach the end points the
// centre is ill-conditioned: q is the square root of a cancellation, so no double
// computation can pin the exact SVG centre closer than about √u times the radius). The
// sweep Δθ is taken from m and q directly, so it keeps its relative precision however small
// the chord is against the radii, and every control point is built from the start point
// (the start plus the image of a chord or a tangent of the unit circle), never through the
// centre, which for radii far larger than the chord lies far from the arc. So each control
// point takes a few dozen roundings, each at most u = 2^-53 times a few times the magnitude
// L = min(|C|∞ + max(rx, ry), max(|from|∞, |to|∞) + max(rx, ry) min(|Δθ|, 2)) (the
// ellipse's extent, or the end points' and the largest chord's or handle's, whichever is
// less). The other half of the tolerance covers them: the tolerance used is never below
// kArcToleranceFloor · L (2^-40 L, thousands of such roundings). An
// arc of a huge circle between near end points thus stays near its chord, as it should,
// while the tolerance the answer states is the one asked for. End points are the command's
// end points bit for bit, and consecutive cubics share their joint bit for bit.

/// One elliptical arc command, already made absolute.
struct EllipticalArc {
  core::Point2 from;
  core::Point2 to;
  double rx = 0.0;
  double ry = 0.0;
  double x_axis_rotation_degrees = 0.0;
  bool large_arc = false;
  bool sweep = false;
};

/// The relative floor of the tolerance an arc is drawn within (see the header comment).
inline constexpr double kArcToleranceFloor = 0x1p-40;
/// The default tolerance, relative to the arc's larger radius (after any scaling up).
inline constexpr double kDefaultArcRelativeTolerance = 1e-6;

enum class ArcStatus {
  ok,
  too_many_pieces,  ///< more cubics than the caller's limit (tolerance too fine for it)
  out_of_range,     ///< a control point beyond the double range
};

/// The segments an arc stands for, each within `tolerance` of the arc (Hausdorff distance).
struct ArcSegments {
  ArcStatus status = ArcStatus::ok;
  /// Empty for an arc whose end points are equal; one line for a zero radius; else cubics.
  std::vector<core::Curve> segments;
  /// The distance within which the segments follow the arc: 0 when nothing is drawn and for
  /// the line of a zero radius (exact), else max(asked, kArcToleranceFloor L), asked being
  /// `tolerance` or, when that is nullopt, kDefaultArcRelativeTolerance · max(rx, ry) (also
  /// for the one other line: a small arc whose half chord is below the least subnormal of
  /// the radii, the chord then being within radius · m² / 2 of it, far below any tolerance).
  double tolerance = 0.0;
};

/// ε(δ) above: the largest radial distance between the unit circle and the cubic
/// approximating its arc of angle δ (|δ| < 2π), for exact arithmetic.
[[nodiscard]] double circular_arc_cubic_error(double angle);

/// The arc as segments (see the header comment). Preconditions: finite inputs, tolerance
/// (when given) > 0. Never produces more than `max_pieces` segments: an arc needing more is
/// refused with too_many_pieces (and no segments). Time linear in the pieces made.
[[nodiscard]] ArcSegments arc_to_cubics(const EllipticalArc& arc, std::optional<double> tolerance,
                                        std::size_t max_pieces);

}  // namespace bezier::path
