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
/// Fit (Tiller and Hanson's construction, 1984, with the handle lengths by least squares):
/// the cubic has the ends O(t0), O(t1) and end tangents along ±T there (the sign of 1 - d κ
/// on the piece: O turns back between cusps), and its two handle lengths minimise
/// Σ |C(u_j) - O(t0 + u_j (t1 - t0))|^2 over the interior samples u_j = j / K of the bound
/// below (at least 16), each handle at least 0 (a negative one would start the cubic against
/// O's direction of travel and fold it back beside its end: next to a cusp of O, where O's
/// speed vanishes, the unconstrained least squares can prefer that hook; it is set to 0 and
/// the other handle fitted alone). Then the bound is computed, and a piece whose bound
/// exceeds the tolerance is split (in t) into parts, two or more as the sampled error
/// exceeds what the tolerance allows (the error of a fit falls about as the fifth power of
/// the length), and each is fitted again.
///
/// The bound. With the linear correspondence u -> t = t0 + u (t1 - t0), the Hausdorff
/// distance is at most max_u |e(u)|, e(u) = C(u) - O(t(u)) (each point of one is that close
/// to a point of the other). On K uniform samples u_j, between two of them
///   |e(u)| <= max(|e(u_j)|, |e(u_{j+1})|) + h^2 / 8 max |e''|,  h = 1 / K,
/// (the linear interpolant of e plus its remainder). O_p (the piece's parallel curve in u) is
/// B_p + d N, so e'' = (C'' - B_p'') - d N'': |e''| <= max |C'' - B_p''| + |d| max |N''|, the
/// first the largest distance between the control points of C'' (a line) and B_p'' (the
/// second hodograph), both raised to the degree max(1, n - 2) (convex hull; the two nearly
/// cancel, since C follows O). For the piece B_p (de Casteljau, local parameter u) with
/// M_k >= |B_p^(k)| (the largest control point of its k-th hodograph: convex hull) and
/// m <= |B_p'| (the least projection of B_p's first hodograph's control points on the
/// direction of B_p'(1/2), when positive), the turning rate ω = cross(B_p', B_p'') / |B_p'|^2
/// gives N'' = -ω' T - ω^2 N, so
///   |N''| <= |ω'| + ω^2,  |ω| <= M_1 M_2 / m^2,  |ω'| <= M_1 M_3 / m^2 + 2 M_1^2 M_2^2 / m^4.
/// O is sampled once per fit, at K from three times the bound of |d N''| (C'' - B_p'' is
/// about d N''), and again only when the fitted cubic's bound of |e''| needs a larger K; K
/// keeps the remainder at most a quarter of the tolerance. Where m is not positive (B'
/// vanishes on or near the piece), the bound is the sum of the radii of two balls about
/// O(t0): the cubic is within its control points' largest distance from O(t0), and O within
/// max |B_p(u) - B_p(0)| + |d| θ, θ the angle spanned by the nonzero control points of the
/// first hodograph (the normal turns by at most θ, |N(u) - N(0)| <= θ), when θ < π.
/// Evaluations and de Casteljau steps are in doubles, on the curve scaled by a power of two
/// (exact) so that its coordinates and |d| are at most about 1 and the squared distances the
/// bound compares neither overflow nor underflow at the tolerances accepted; the bound adds
/// 64 n u S for their rounding (S the largest coordinate plus |d|). The samples' distances
/// are compared squared, and the square root taken of the largest only.
///
/// Segment count. The ends, end tangents and cusps are exact, and the handles minimise the
/// squared distance at the samples; this does not reach the sixth order of the geometric
/// Hermite cubic (de Boor, Höllig and Sabin, "High accuracy geometric Hermite interpolation",
/// CAGD 4, 1987), which R. Levien's fit ("Parallel curves of cubic Béziers", 2022) attains by
/// matching the piece's signed area and moment: at tight tolerances this makes more cubics
/// than Levien's, and fewer than a fixed subdivision (no measured comparison is claimed here:
/// counts against other libraries belong in BENCHMARKS.md beside their command).
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
/// piece still fails the tolerance after 40 halvings (the budget is then exhausted).
bool offset_interval(const core::Curve& curve, double a, double b, double d, double tolerance,
                     core::WorkBudget& budget, std::vector<OffsetCubic>& out);

}  // namespace bezier::outline
