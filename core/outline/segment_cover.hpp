#pragma once

#include <cstddef>
#include <vector>

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

/// The sizes of a stroke of half width r at tolerance ε (stroke.hpp's budget of ε): R = r +
/// ε/2, each offset fit within 0.49 ε, the disks of radius R + 0.005 ε in circles within
/// 0.485 ε, and chain ends closer than 0.01 ε taken as one point.
[[nodiscard]] CoverSizes cover_sizes(double half_width, double tolerance);

/// One stretch of a segment between its zeros of B' (or its ends): the two edges of its
/// cover, each an open chain in order of t (stroke.cpp joins the stretches of consecutive
/// segments into contours). `left` is the side s = +R, `right` the side s = -R.
struct StretchEdges {
  Contour left;
  Contour right;
  core::Point2 start, end;  ///< B at the stretch's ends
};

/// What cover_segment gives for one segment.
struct SegmentCover {
  /// In order of t; more than one where B' vanishes inside the segment.
  std::vector<StretchEdges> stretches;
  /// A cusp of a parallel curve at ±R (the radius of curvature equals R) at t = 0 or t = 1:
  /// the ribbon's Jacobian vanishes at that end, so the joint there is not smooth.
  bool cusp_at_start = false;
  bool cusp_at_end = false;
};

/// The edges of the region that covers, with winding numbers >= 0 that are positive only
/// within R + fit_tolerance of the segment, every point B(t) + s N(t) (t in [0, 1], N the
/// unit left normal) with |s| <= r and s κ(t) <= 1 (the points whose nearest point on the
/// segment may be B(t), see stroke.hpp); the disks this needs are added to `sink` (about each
/// interior zero of B', and on the tight sides).
///
/// Each side is cut at the zeros of B' and at the cusps of its parallel curve at ±R (where
/// the radius of curvature ρ = 1 / |κ| equals R, offset_cusps.hpp), so that on each piece
/// the side is either loose (ρ >= R on that side: the map (t, s) -> B(t) + s N(t) has
/// Jacobian |B'| (1 - s κ) >= 0 for s from 0 to ±R) or tight (ρ < R, decided at the piece's
/// middle). Where loose_everywhere (loose_curve.hpp) proves R |κ| < 1 and B' != 0 on the
/// whole segment (R M2 < m^2 on the segment or on each of its halves, quarters or eighths: M2
/// the largest control point of B'' there, m the least projection of B''s on the direction
/// of B' at the part's middle, |κ| <= |B''| / |B'|^2), there is neither a cusp nor a zero of
/// B' and both sides are loose throughout, decided without the root searches.
///
/// A loose side's edge is its parallel curve at distance R (offset.hpp's offset_interval,
/// within fit_tolerance, on that side's pieces only); a tight side's edge is the piece itself
/// (its control points; for degree above 3, its fit at distance 0), and between a loose and
/// a tight piece the edge steps along the normal at the cut, a line between B + R N and B
/// there. The region of a stretch is then the image of the staircase domain
/// {(t, s) : lo(t) <= s <= hi(t)} (hi = R where the left side is loose and 0 where it is
/// tight; lo = -R or 0 likewise for the right side; never both 0, since the two sides are
/// not tight at once), whose Jacobian is >= 0 throughout.
///
/// A tight side is covered by disks of radius R instead (tight_side_cover.hpp): the piece is
/// halved until a disk about a point c of each part holds every B(t) + s N(t) of the part
/// with 0 <= s <= min(ρ(t), r), by the hull test (min(ρ_max, r) + max |P_i - c| < R, ρ_max an
/// upper bound of ρ on the part) or, where the part turns to the side by less than a quarter
/// turn, by the tangent-disk test (the part lies in the disk of radius ρ_max tangent to it at
/// each of its points), which lets a disk hold a part about as long as the stroke is wide,
/// also next to an end where ρ reaches R. A disk of the segment already drawn (about a zero
/// of B', or for an earlier part) serves instead of a new one when the hull test holds with
/// its centre.
///
/// The count of disks: a few per quarter turn of the tight side or per length r of it;
/// next to a zero of B' (where cross(B', B'') vanishes, so neither a bound of ρ nor the
/// tangent-disk test applies) the parts shrink geometrically to a spread of ε/2, a few disks
/// per halving.
///
/// `out` is replaced: its stretches' entries are reused, with the room of their chains, for
/// the segment's stretches in order (a caller that keeps its covers from one stroke to the
/// next allocates no chain twice), and cut to their count.
///
/// Work is charged to `sink` (de Casteljau coordinate updates), and so are the disks'
/// segments; false when the sink stopped (a part still failing the test after 64 halvings
/// stops with work_cap_reached).
bool cover_segment(const core::Curve& segment, const CoverSizes& sizes, OutlineSink& sink,
                   SegmentCover& out);

}  // namespace bezier::outline
