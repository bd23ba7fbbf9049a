#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "core/base/enum_names.hpp"
#include "core/base/work_budget.hpp"
#include "core/outline/outline_sink.hpp"
#include "core/path/path.hpp"

namespace bezier::outline {

// The outline of a stroked path (DESIGN.md §9, SVG 2 §13.5 "Stroke shape",
// https://www.w3.org/TR/SVG2/painting.html#StrokeShape): closed contours whose region under the
// nonzero fill rule is the set of points the stroke paints.
//
// Round joins and caps: the stroke is S = {p : dist(p, path) < r}, r = width / 2. With ε the
// tolerance and R = r + ε/2, the outline's region F satisfies
//     {p : dist(p, path) < r}  ⊆  F  ⊆  {p : dist(p, path) <= r + ε},
// so every point farther than ε from S's boundary is in F exactly when its distance to the
// path is below r (a point outside S at distance > ε from its boundary has dist > r + ε:
// along the segment to its nearest path point, dist falls at rate 1 and reaches r at a
// boundary point). The inner inclusion must be exact, not within ε: a point deep inside S (the
// middle of two overlapping strokes) may be at distance r - ε/10 from the path.
//
// Why. The outline is a union of contours, each winding >= 0 about every point and > 0 only
// within R + ε/2 <= r + ε of the path, so the nonzero region of the union is the union of the
// contours' positive sets, within {dist <= r + ε}. They cover {dist < r}: let p have distance
// s < r and q = B(t*) a nearest point (segment B).
//  - t* at an end of a subpath, at a joint that is not smooth (below), or where B'(t*) = 0: p
//    is in the disk of radius R about q, a contour of its own (round joins and caps,
//    stroke_shapes.hpp; a disk is added at every interior zero of B' whatever the join).
//  - otherwise p - q is normal to B at t*, so p = B(t*) + s N(t*) (N the unit left normal, s
//    signed, |s| < r), and the second-order condition of a minimum of |p - B(t)|^2,
//    |B'|^2 - (p - B) · B'' >= 0, is 1 - s κ(t*) >= 0 (κ the signed curvature): p is not
//    beyond the centre of curvature. The runs below cover exactly these points: on a side
//    where the radius of curvature ρ stays >= R, by the map Φ(t, s) = B(t) + s N(t) for
//    0 <= ±s <= R, whose Jacobian |B'| (1 - s κ) is >= 0; on a side where ρ < R (the tight
//    inner side of a bend, where the parallel curve at R folds into a swallowtail and its
//    folded part would wind -1), not by the folded map but by disks of radius R, each holding
//    every B(t) + s N(t) with 0 <= s <= min(ρ(t), r) for t in its part (segment_cover.hpp).
//
// Runs. Consecutive segments whose joint is smooth, and the stretches of each segment between
// its zeros of B', are joined into runs, each run one domain D = {(t, s) : lo(t) <= s <= hi(t)}
// over its parameters (hi = R where the left side is loose and 0 where it is tight, lo = -R or
// 0 likewise; never both 0) mapped by Φ, continuous across the run's smooth joints. A run's
// contour is the image of D's boundary: the right edge (the parallel curve at -R where loose,
// the curve itself where tight, a step along the normal where that changes) forward, the
// normal segment at the run's end, the left edge backward, the normal segment at its start.
// Where Φ is continuous with Jacobian >= 0 on D (a disk, or an annulus for a closed subpath
// all of whose joints are smooth and that has no zero of B', whose boundary is two contours:
// the right edge forward and the left edge backward), the winding number of the image of ∂D
// about a point off it is the number of its preimages in D, counted with the sign of the
// Jacobian (the degree of Φ): >= 0 everywhere, and >= 1 at every p above, which has a
// preimage with 1 - s κ >= 1 - r / R > 0. Runs break at zeros of B' (where N turns by a half
// turn), at joints that are not smooth (where a join's disk or polygon covers the wedge
// between the two normals) and at the ends of an open subpath (caps). One contour per side of
// a closed smooth subpath, one per run otherwise: no disk, polygon or closing line is spent
// where the ribbons already meet.
//
// Smooth joints. The joint from segment A to segment B is smooth when the directions there
// agree to the snap: T_A(1) · T_B(0) > 0 and R |cross(T_A(1), T_B(0))| <= snap / 4 (the
// unit tangents from the first nonzero derivative, tangent_limits.hpp), B' does not vanish at
// either side, and neither parallel curve has a cusp exactly at the joint (ρ != R there).
// Then the normals differ by an angle θ with R |N_A - N_B| <= R θ < snap / 2: the far edges'
// ends meet within the snap (append_to_chain moves one control point onto the other end,
// by at most snap), and the join adds nothing the run does not hold: whatever the join, SVG 2
// fills at a joint only points q + s n with n between the two outer normals and
// s <= r / cos(θ/2) (the miter tip, the farthest), which the run covers as follows. Rotate
// in the argument only (not in the computation) the normal of B on a short parameter interval
// [0, δ] by the angle back to N_A, decreasing to 0 at δ: the map is then continuous across
// the joint; its Jacobian is |B'| (1 - s κ) - s α' with |α'| ~ θ / δ, positive for δ large
// against R θ / (|B'| (1 - R |κ|)), which is positive since ρ > R at the joint; and its far
// edges move by at most R θ < snap / 2 from the parallel curves. The contour is thus a
// homotopy, through curves within fit_tolerance + snap <= ε/2 of exact far edges at R, of
// the boundary of a continuous map with Jacobian >= 0 whose image holds the wedge at the
// joint to radius R, so the degree argument above holds at p with dist(p, path) < r as at
// any other point of the ribbons (a miter's tip reaches beyond r by r (1 / cos(θ/2) - 1) <
// r θ^2 / 4, far below rounding). (θ at such joints is of
// the size of the rounding of the input: a curve drawn tangent-continuous, as fonts and
// splines are, has its joints' control points collinear up to the rounding of their
// coordinates.)
//
// The far edges are the parallel curves fitted within 0.49 ε (offset.hpp: the bound is for a
// linear correspondence of parameters, so the fitted contour is a homotopy of the exact one
// through curves within 0.49 ε of it), and where two fitted pieces meet with a gap (at most
// 0.01 ε: rounding, or a smooth joint's angle) one control point is moved onto the other's
// end; the disks have radius R + 0.005 ε (so that their circles cross the parallel curves
// ending on them rather than touch them) and are circles of cubics outside the exact circle
// by at most 0.485 ε (Goldapp's bound). So every contour stays within R + ε/2 = r + ε of the
// path. The margin R - r = ε/2 is what keeps the points at distance < r of the path inside
// after the far edges move by up to ε/2: the winding about p changes only where a contour
// passes within ε/2 of p, and the exact far edge is at distance R from the curve where p's
// own preimage is at s < r. That step is argued here, not certified: a fitted edge could in
// principle pass within ε/2 of a point that another part of the same run holds; the tests
// (tests/core/outline/stroke_test.cpp) check the inclusions with the exact winding numbers of
// core/region at random and chosen points.
//
// Miter and bevel joins, butt and square caps: SVG 2's polygons (stroke_shapes.hpp), with the
// segments' ribbons and disks as above (their far edges at R, so within ε of SVG 2's shape);
// miter tips and square caps are exact.
//
// Degenerate input as SVG renderers draw it: a segment whose control points all coincide is
// left out (the joint is between its neighbours); a subpath of such segments only is a dot: a
// disk (round cap), a square of side `width` along the axes (square cap: SVG 2's "direction
// along the positive x-axis"), nothing (butt). The direction at an end where B' = 0 is the
// first nonzero derivative's (tangent_limits.hpp). A subpath is closed when it ends exactly
// where it starts (path::Subpath::closed): a join there, no caps. (SVG closes a subpath
// only with Z; a path that returns to its start without Z is taken as closed here, since
// core/path does not record a Z that draws nothing. `M x y Z` is a closing line of zero
// length in core/path, so it is a dot.)
//
// The error bound: each point of the outline where it bounds the region is within ε of the
// exact stroke's boundary (the far edges and circles are within ε/2 of curves at distance
// R = r + ε/2 from the path; polygons, miter tips and square caps are exact), and the region
// holds the exact stroke: the Hausdorff distance between the two regions is at most ε, and
// the region is never smaller.

/// SVG 2's stroke-linejoin values this service draws.
enum class LineJoin { miter, round, bevel };
/// SVG 2's stroke-linecap values.
enum class LineCap { butt, round, square };

inline constexpr core::EnumNames<LineJoin::bevel> kLineJoinNames{"miter", "round", "bevel"};
inline constexpr core::EnumNames<LineCap::square> kLineCapNames{"butt", "round", "square"};

struct StrokeStyle {
  double width = 1.0;  ///< > 0
  LineJoin join = LineJoin::miter;
  /// SVG 2's stroke-miterlimit (>= 1): the largest miter length / stroke width; beyond it a
  /// miter join is drawn as a bevel.
  double miter_limit = 4.0;
  LineCap cap = LineCap::butt;
};

struct StrokeOutline {
  StrokeStatus status = StrokeStatus::ok;
  /// Closed contours, each counter-clockwise where it has a sense (y up); empty when the
  /// status is not ok.
  std::vector<Contour> contours;
  std::size_t segment_count = 0;
};

/// The outline of `path` stroked with `style`, within `tolerance` (ε above; absolute, in the
/// coordinates' units). Work (de Casteljau coordinate updates, as offset.hpp charges them)
/// is charged to `budget` (status work_cap_reached when it runs out); an outline of more than `max_segments` segments is refused
/// as soon as the count passes it (the disks' and polygons' counts before they are built).
/// Preconditions: finite coordinates, width > 0, miter_limit >= 1, tolerance >= 1e-9 of the
/// largest of the coordinates' scale and the width.
[[nodiscard]] StrokeOutline stroke(const path::Path& path, const StrokeStyle& style,
                                   double tolerance, core::WorkBudget& budget,
                                   std::size_t max_segments);

}  // namespace bezier::outline
