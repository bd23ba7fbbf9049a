#pragma once

#include <span>
#include <vector>

#include "core/base/curve.hpp"
#include "core/outline/outline_sink.hpp"
#include "core/outline/segment_cover.hpp"

namespace bezier::outline {

// The disks that cover the tight side of a piece of a segment (segment_cover.hpp, stroke.hpp):
// where the radius of curvature ρ is below R = r + ε/2 on one side, the stroke needs there
// every point B(t) + s N(t) with 0 <= s <= min(ρ(t), r) (N the unit normal towards that side),
// and the ribbon cannot hold them (its map folds where s > ρ).
//
// The piece is halved until a disk of radius R about one point c of each part holds the part,
// by one of two tests (u the unit roundoff; both keep a margin of 128 u (scale + R) for the
// rounding of the distances, scale the largest coordinate of the piece):
//
//  1. The hull test: with ℓ = max |P_i - c| over the part's control points (|B(t) - c| <= ℓ
//     on the part, which lies in their convex hull) and ρ_max an upper bound of ρ on the part
//     (infinite when none is found), min(ρ_max, r) + ℓ < R: every B(t) + s N(t) is within
//     s + ℓ of c. It holds a part as long as R - r = ε/2 only where ρ_max >= r, so next to an
//     end where ρ reaches R the parts shrink to a spread of ε/2.
//
//  2. The tangent-disk test, for c = B(t_c) at the part's middle. Where the curve turns to
//     the side throughout (κ of the side's sign, no zero of B'), by less than a quarter turn,
//     with 0 < ρ <= ρ_m:
//
//     Lemma. Every point x of such an arc lies in the closed disk of radius ρ_m tangent to the
//     arc at any other of its points y on the side of N(y): |x - y - ρ_m N(y)| <= ρ_m, that
//     is (x - y) · N(y) >= |x - y|^2 / (2 ρ_m).
//     Proof. Let x follow y (the other order is the same statement for the arc reversed and
//     mirrored in the normal line at y, which keeps N(y) and y + ρ_m N(y)). Take y = 0, the
//     tangent at y along e(0), N(y) = e(π/2), e(φ) = (cos φ, sin φ), and parametrise the
//     arc from y by its tangent's angle θ (increasing, since κ > 0 after mirroring):
//     B(θ) = ∫_0^θ ρ(φ) e(φ) dφ, θ in [0, Θ], Θ < π/2. With C = ρ_m e(π/2),
//     d/dθ |B - C|^2 = 2 ρ(θ) (B(θ) - C) · e(θ), and
//       (B(θ) - C) · e(θ) = ∫_0^θ ρ(φ) cos(θ - φ) dφ - ρ_m sin θ
//                        <= ρ_m ∫_0^θ cos(θ - φ) dφ - ρ_m sin θ = 0,
//     since 0 <= cos(θ - φ) for 0 <= φ <= θ <= π/2 and ρ <= ρ_m. So |B - C| never grows from
//     its value ρ_m at y. ∎
//
//     Then for t on the part, 0 <= s <= S(t) = min(ρ(t), r) <= S_m = min(ρ_m, r) and
//     D = B(t) - c (so (c - B(t)) · N(t) >= |D|^2 / (2 ρ_m) by the lemma, with x = c, y = B(t)):
//       |B(t) + s N(t) - c|^2 = |D|^2 - 2 s (c - B(t)) · N(t) + s^2
//                             <= |D|^2 (1 - s / ρ_m) + s^2 <= ℓ^2 (1 - s / ρ_m) + s^2,
//     convex in s, so at most max(ℓ^2, ℓ^2 (1 - S_m / ρ_m) + S_m^2) on [0, S_m]: the disk holds
//     the part when that is below R^2. Where ρ_m <= r it asks only ℓ < R; next to an end where
//     ρ reaches R it asks ℓ^2 (ρ_m - r) / ρ_m < R^2 - r^2 ≈ r ε, which for ρ_m within a few ε of
//     R lets ℓ reach about r: a disk holds a part as long as the stroke is wide instead of ε/2.
//
//     Certified on the part's control points (scaled by a power of two, exact), each Bernstein
//     coefficient with a bound of its error (the rounding of its own sums and products, and the
//     control points' distance from the exact piece's, which the blossoms of core::portion keep
//     within a few units of rounding of the segment's scale: taken as 16 n u scale):
//      - side · cross(B', B'') > 0: every coefficient (degree 2n - 3) beyond its error;
//      - the quarter turn: every hodograph control point h_i within 44° of one direction d
//        (d · h_i > 0.72 |h_i| beyond the errors), so every B'(t), a positive combination of
//        them, is in that convex cone, and the tangent's angle, monotone by the first
//        condition, stays within an interval shorter than π/2;
//      - ρ_m: the hull bound M1^3 / min(side · cross(B', B'')) (M1 the largest |h_i|), or,
//        where ρ is monotone on the part, the larger of its values at the ends (each from the
//        end's hodograph points, bounded up), whichever is smaller. dρ/dt has the sign of
//          Y = 3 (B' · B'') X - |B'|^2 X',   X = side · cross(B', B'')
//        (ρ = |B'|^3 / X), a polynomial of degree 4n - 6 whose coefficients, all beyond their
//        error and of one sign, show it monotone. Next to an end where ρ reaches R (a cusp
//        of the parallel curve, found to about 1e-12 in t) this keeps ρ_m that close to R.
//     The centre c is computed (within 4 u scale of the piece's B(1/2)), ℓ is increased by the
//     control points' and the centre's errors, and the disk must hold the part to within
//     R - (the centre's error) - the margin.
//
// A disk already drawn (about a zero of B', or for an earlier part) serves instead of a new
// one when the hull test holds with its centre. Near a zero of B' (where cross(B', B'')
// vanishes and no test 2 applies) the parts still shrink to a spread of ε/2, a few disks per
// halving.

/// Test 2 above for one part: whether the disk of radius sizes.reach about `centre` (the
/// computed B(1/2) of the part, within `centre_error` of the exact one) holds every
/// B(t) + s N(t), t in [0, 1], 0 <= s <= min(ρ(t), sizes.radius), N the unit normal towards
/// `side` (+1 left, -1 right), of the part whose computed control points `piece` are within
/// `point_error` of the exact ones; `margin` is kept free besides. False whenever a
/// certificate fails (the part does not turn to the side throughout, or turns by a quarter
/// turn or more, or the bound is not below the radius).
[[nodiscard]] bool tangent_disk_holds(std::span<const core::Point2> piece, core::Point2 centre,
                                      double point_error, double centre_error, double margin,
                                      double side, const CoverSizes& sizes);

/// Adds to `sink` the disks (circles of radius sizes.disk_radius >= R, stroke_shapes.hpp) that
/// cover the side `side` (+1 left, -1 right) of `segment` on [c0, c1], a piece where the side is
/// tight, as above; `centres` are the centres of the segment's disks so far (the new ones are
/// appended). Work is charged to `sink`; a part still failing both tests after 64 halvings
/// stops the sink with work_cap_reached.
void cover_tight_side(const core::Curve& segment, double c0, double c1, double side,
                      const CoverSizes& sizes, OutlineSink& sink,
                      std::vector<core::Point2>& centres);

}  // namespace bezier::outline
