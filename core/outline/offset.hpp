#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/base/curve.hpp"
#include "core/base/work_budget.hpp"

namespace bezier::outline {

/// One cubic of a parallel curve: it stands for O on [t0, t1] of its source curve.
struct OffsetCubic {
  double t0 = 0.0;
  double t1 = 0.0;
  std::array<core::Point2, 4> points;
  /// The certified bound of the Hausdorff distance between this cubic and O on [t0, t1].
  double error_bound = 0.0;
};

struct CurveOffset {
  /// In order of t; consecutive cubics share their end point except across a zero of B'
  /// (where the normal turns by a half turn and O jumps by 2 |d|). Empty when the budget
  /// ran out.
  std::vector<OffsetCubic> cubics;
};

/// The parallel curve O(t) = B(t) + d N(t) of a planar Bézier curve of any degree n >= 1 (N
/// the unit left normal, y up; where B'(t) = 0, N is the limit of the tangent's normal from
/// the side of the piece) as cubics within `tolerance` of it, both ways.
///
/// Pieces. B is cut at the cusps of O (offset_cusps.hpp: the radius of curvature is |d| on
/// d's side) and at the zeros of B' inside (0, 1) (roots of x' where y' vanishes too, to
/// 1e-9 of the hodograph's scale), so that on each piece O' = |B'| (1 - d κ) T keeps its
/// direction sign: each cusp of O is the end of a cubic.
///
/// Fit. The cubic has the ends O(t0), O(t1) and end tangents along ±T there (the sign of
/// 1 - d κ on the piece: O turns back between cusps); its two handle lengths are chosen in
/// turn by:
/// 1. R. Levien's parallel-curve fit ("Parallel curves of cubic Béziers", 2022;
///    area_moment_fit.hpp): the handles for which the cubic's signed area and first moment
///    in the chord frame equal those of O on the piece (6-point Gauss-Legendre quadrature of
///    ∫ y dx and ∫ x y dx with O' = |B'| (1 - d κ) T), the roots of a quartic, each a
///    candidate in turn. Matching the ends, tangents, area and moment reaches the sixth
///    order of the geometric Hermite cubic (de Boor, Höllig and Sabin, "High accuracy
///    geometric Hermite interpolation", CAGD 4, 1987): halving a piece divides the error
///    by about 64.
/// 2. Where no candidate passes the bound (no root with both handles >= 0, near a cusp of
///    O, or a piece too long for one cubic), Tiller and Hanson's construction (1984) with
///    the handles by least squares: they minimise Σ |C(u_j) - O(t0 + u_j (t1 - t0))|^2
///    over the interior samples u_j = j / K of the bound below, each handle at least 0 (a
///    negative one would start the cubic against O's direction of travel and fold it back
///    beside its end: next to a cusp of O, where O's speed vanishes, the unconstrained
///    least squares can prefer that hook; it is set to 0 and the other fitted alone).
/// The first cubic whose bound is within the tolerance is kept; otherwise the piece is
/// split (in t) into parts, two or more as the sampled error exceeds what the tolerance
/// allows (assuming the error falls as the fifth power of the length, which overestimates
/// the parts a sixth-order fit needs), and each is fitted again.
///
/// The bound. A fit only proposes a cubic; this bound decides. Let u = ψ(t) be any
/// continuous map of [0, 1] onto itself with ψ(0) = 0, ψ(1) = 1 (t the piece's parameter,
/// u the cubic's); then the Hausdorff distance is at most max_t |e(t)|, e(t) = C(ψ(t)) -
/// O(t): each O(t) is that close to C(ψ(t)), and each C(u) is C(ψ(t)) for some t (ψ is
/// onto). O is sampled at the K + 1 uniform t_j = j / K, and ψ is linear between the nodes
/// ψ(t_j) = u_j, each u_j in [0, 1] near the foot of O(t_j) on C (Gauss-Newton steps from
/// the previous two nodes' extrapolation; the area-and-moment cubic follows O geometrically
/// but not in parameter, so the linear correspondence u = t would overstate its distance many
/// times), and |e(t_j)| = |C(u_j) - O(t_j)| is evaluated there. Between two samples e is
/// smooth and
///   |e(t)| <= max(|e(t_j)|, |e(t_{j+1})|) + h^2 / 8 max |e''|,  h = 1 / K,
/// (the linear interpolant of e plus its remainder, by the interpolation kernel, which is
/// positive). There ψ' = s_j = (u_{j+1} - u_j) / h and ψ'' = 0, and O = B_p + d N, so
///   e'' = (s_j^2 C''(ψ(t)) - B_p''(t)) - d N''(t).
/// The first term is linear in t for n <= 3 (C'' is linear in u, ψ in t, B_p'' of degree
/// n - 2), so its largest norm is at the two samples, where it is computed; for n > 3 its
/// distance from that linear function is at most M_3 h / 2 more (|B_p'''| <= M_3). For the
/// piece B_p (de Casteljau, local parameter t) with M_k >= |B_p^(k)| (the largest control
/// point of its k-th hodograph: convex hull) and m <= |B_p'| (the least projection of B_p's
/// first hodograph's control points on the direction of B_p'(1/2), when positive), the
/// turning rate ω = cross(B_p', B_p'') / |B_p'|^2 gives N'' = -ω' T - ω^2 N, so
/// (normal_turning.hpp, θ the angle from B_p' to B_p'', φ the golden ratio)
///   |N''| <= |ω'| + ω^2 <= M_3 / m + (|sin 2θ| + sin^2 θ) M_2^2 / m^2 <= M_3 / m + φ M_2^2 / m^2.
/// K is chosen first for a remainder within 0.9 of the tolerance with |e''| estimated at 1.4
/// times the bound of |d N''| above (where the cubic follows O, the sampled first term is
/// about a third of that bound), at least 4; where the samples are inside the tolerance and
/// the remainder alone fails, O is sampled again at the K the remainder needs in the room the
/// samples leave (twice at most, the second time at least a quarter denser). K only spends
/// work: the bound holds for every K.
/// Zeros of B' at the ends. Where an end of the interval being fitted (a cut above, or an
/// end of offset_interval's [a, b]) has |B'| below end_tangent's threshold (1e-12 n of the
/// control points' scale, tangent_limits.hpp: the frame there takes the limit tangent), B' is
/// taken to vanish there exactly: the zeros stationary_points finds are within rounding of
/// B''s zeros, and what B' is next to them is rounding, not direction. On a piece with that
/// end, B_p' = t^i (1 - t)^j Q (i, j >= 1 at such ends; the piece's first or last hodograph
/// control point set to zero and the factor divided out, q_i = g_i k / (k - i) for (1 - t),
/// q_i = g_{i+1} k / (i + 1) for t, again while Q's end point is below 1e-9 of its largest:
/// a zero of higher order), so that inside the piece N is Q's normal, and at the end its
/// limit. The turning bounds above are then Q's: M_1, M_2, M_3 the largest control points of
/// Q and its first two hodographs, m the least projection of Q's on the direction of Q(1/2)
/// (with m -> 0 from B_p' itself, the bound would grow without limit next to the zero and
/// the piece be split forever). The end frames' tangents come from end_tangent (the first
/// derivative above the threshold); the bound adds |d| |T - Q/|Q|| at each such end, the
/// distance between the end sample and Q's limit.
///
/// Straight curves. Where the control points are collinear (decided exactly,
/// straight_curve.hpp), B' is parallel to their line and N is constant between zeros of B':
/// the parallel curve of an interval [a, b] without a zero inside is the segment from B(a) to
/// B(b) moved by d N (N the left normal of the direction of travel: ± one unit direction of
/// the line for the whole curve, the sign that of the chord B(b) - B(a) where it is longer
/// than 1e-12 of the curve's size, else of the start frame's limit tangent). The answer is
/// that segment as straight cubics (handles at their thirds), cut where it passes B at
/// another zero of B' or end of the curve, the parameter there by bisection: the runs'
/// segments along one side, which overlap where the curve goes back over itself, then
/// coincide in whole pieces with the same ends (/stroke's simplify needs them equal, not
/// 1e-16 apart). Each cubic's bound is the largest distance of its part's control points
/// from its segment and of B at the part's ends from the segment's ends (B's values lie in
/// the control points' hull, and the distance to a segment is convex; the segment lies on
/// B's values by continuity): rounding only. At a reversal (a zero of B' where B turns
/// back) O jumps by 2 |d| to the other side: the next interval's cubic starts there. Where a
/// bound exceeds the tolerance (a cut rounded so far that B turns back inside), the fit above
/// decides. A
/// curve that is one point (all control points equal) is one point of the answer, moved by
/// d along end_tangent's convention (1, 0), as a line of zero length is.
///
/// Where m is not positive (B' vanishes on or near the piece), the cubic is the least
/// squares one and the bound is the sum of the radii of two balls about O(t0): the cubic is
/// within its control points' largest distance from O(t0), and O within max |B_p(u) -
/// B_p(0)| + |d| θ, θ the angle spanned by the nonzero control points of the first
/// hodograph (the normal turns by at most θ, |N(u) - N(0)| <= θ), when θ < π.
/// Evaluations and de Casteljau steps are in doubles (the cubic's points at the u_j in
/// Bernstein form), on the curve scaled by a power of two (exact) so that its coordinates
/// and |d| are at most about 1 and the squared distances the bound compares neither
/// overflow nor underflow at the tolerances accepted; the bound adds 64 n u S for their
/// rounding (S the largest coordinate plus |d|). The samples' distances are compared
/// squared, and the square root taken of the largest only.
///
/// Segment count. The fit is of the sixth order where O is smooth, so most pieces need one
/// cubic (counts against other libraries belong in BENCHMARKS.md beside their command).
///
/// Work (units of one de Casteljau coordinate update) is charged to `budget` for the cuts and
/// every fit and bound; when it runs out (budget.exhausted()) there are no cubics.
/// Precondition: finite coordinates, tolerance > 1e-9 of the coordinates' scale and |d|.
[[nodiscard]] CurveOffset offset_curve(const core::Curve& curve, double d, double tolerance,
                                       core::WorkBudget& budget);

/// The fit above on one parameter interval [a, b] of `curve` (0 <= a < b <= 1) on which O
/// has no cusp and B' no zero inside (a piece of offset_curve, or one the caller cut the
/// same way, as the stroke does where one side is loose): its cubics, in order of t, are
/// appended to `out`. The ends O(a), O(b) are computed from the whole curve (B and B' there),
/// so the cubics of two intervals meeting at a t where B' is not zero share their end point
/// bit for bit. Work is charged to `budget`; false (nothing appended) when it runs out or a
/// piece still fails the tolerance after 60 levels of splitting (the budget is then exhausted).
bool offset_interval(const core::Curve& curve, double a, double b, double d, double tolerance,
                     core::WorkBudget& budget, std::vector<OffsetCubic>& out);

/// offset_interval at d and at -d on the same [a, b] (the two sides of a stroke's segment
/// where neither has a cusp inside): the cubics of the side at d are appended to `plus`,
/// those at -d to `minus`, each exactly (bit for bit) those offset_interval gives for its
/// side, with the same work charged. The two sides share what does not depend on the sign of
/// d: the scaled curve, the piece's hodographs and bounds, the end frames, the sample count,
/// and, for the first fit of [a, b], the evaluations of B, B' and B'' at its samples and
/// at the chord moments' quadrature nodes; for a curve of degree at most 3, the two first
/// candidates' bounds walk their samples in one loop, each side's arithmetic its own (kept
/// when both hold); a side whose first fit fails is split on its own.
/// False when the budget runs out or a piece fails as in offset_interval (nothing appended
/// to `minus`; `plus` may hold its side's cubics).
bool offset_interval_sides(const core::Curve& curve, double a, double b, double d,
                           double tolerance, core::WorkBudget& budget,
                           std::vector<OffsetCubic>& plus, std::vector<OffsetCubic>& minus);

}  // namespace bezier::outline
