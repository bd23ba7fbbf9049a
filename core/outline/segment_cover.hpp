#pragma once

#include <cstddef>

#include "core/base/curve.hpp"
#include "core/outline/outline_sink.hpp"

namespace bezier::outline {

/// The sizes one segment's cover is built with (stroke.hpp): r the half width, R = r + ε/2 the
/// radius the cover reaches (ε the stroke's tolerance), the tolerance of each offset fit and
/// circle, the pieces of each disk, and the distance below which two chain ends are rounding.
struct CoverSizes {
  double radius = 0.0;        ///< r
  double reach = 0.0;         ///< R
  double fit_tolerance = 0.0; ///< offsets' tolerance
  /// The disks' radius: R and a little more (stroke.cpp), so that a circle crosses the
  /// parallel curves that end on it instead of touching them, a contact of high order that
  /// /stroke's simplify could not always decide.
  double disk_radius = 0.0;
  std::size_t circle_pieces = 4;  ///< cubics per circle
  double snap = 0.0;
};

/// Adds to `sink` contours that together cover, with winding numbers >= 0 that are positive
/// only within R + fit_tolerance of the segment, every point B(t) + s N(t) (t in [0, 1],
/// N the unit left normal) with |s| <= r and s κ(t) <= 1 (the points whose nearest point on
/// the segment may be B(t), see stroke.hpp), and a disk about each interior zero of B'.
///
/// The segment is cut at the zeros of B' and at the cusps of its parallel curves at ±R (where
/// the radius of curvature ρ = 1 / |κ| equals R, offset_cusps.hpp), so that on each piece
/// each side is either loose (ρ >= R on that side: the map (t, s) -> B(t) + s N(t) has
/// Jacobian |B'| (1 - s κ) >= 0 for s up to R) or tight (ρ < R, decided at the piece's middle).
/// Each piece gives one contour, counter-clockwise: the right edge forward and the left edge
/// backward, joined by
/// the normal segments at the piece's ends (at a cut inside the segment, two lines meeting at
/// B there, so that the two pieces' normal segments at a cut overlap exactly), where a loose
/// side's edge is its parallel curve at
/// distance R (offset.hpp, within fit_tolerance; fitted once for the whole segment, whose
/// cubics are cut at the same cusps, and a cubic that straddles a cut of the other side split
/// there by its fit's linear correspondence of parameters) and a tight side's edge is the piece itself
/// (its control points; for degree above 3, its fit at distance 0). A tight side is covered by
/// disks of radius R instead: the piece is halved until on each part P, with c = P(1/2) and
/// ℓ = max |P_i - c| (so |B(t) - c| <= ℓ on P, convex hull), ρ_max an upper bound of ρ on P
/// (|B'|^3 / |cross(B', B'')| with |B'| <= the first hodograph's largest control point and
/// |cross| >= the least Bernstein coefficient of cross(B', B''), all of one sign on a tight
/// side), min(ρ_max, r) + ℓ < R: then every point B(t) + s N(t) with 0 <= s <= min(ρ(t), r) is
/// within min(ρ_max, r) + ℓ < R of c, inside the disk about c. A disk of the segment already
/// drawn (about a zero of B', or for an earlier part) serves instead of a new one when the
/// same test holds with its centre for c.
///
/// The count of disks: where ρ_max is well below r a part may be as long as R - ρ_max; next
/// to an end where ρ reaches R, or a zero of B' (where the bound of ρ is lost because
/// cross(B', B'') vanishes there too), the parts shrink geometrically to a spread of ε/2,
/// a few disks per halving; a curve whose ρ stays within about ε/2 of r over a long stretch
/// needs about its length / ε disks, and may be refused by the segment limit.
///
/// Work is charged to `sink` (de Casteljau coordinate updates), and so are the contours'
/// segments; a part still failing the test after 64 halvings stops with work_cap_reached.
void cover_segment(const core::Curve& segment, const CoverSizes& sizes, OutlineSink& sink);

}  // namespace bezier::outline
