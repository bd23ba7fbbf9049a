#pragma once

#include <cstddef>
#include <optional>

#include "core/base/point.hpp"
#include "core/outline/outline_sink.hpp"

namespace bezier::outline {

// The stroke's pieces that are not ribbons (stroke.hpp): disks (round joins and caps, and the
// disks that cover the tight side of a curve), and the polygons of SVG 2's miter and bevel
// joins and square caps (SVG 2 §13.5 "Stroke shape", https://www.w3.org/TR/SVG2/painting.html#StrokeShape).
// Every contour runs counter-clockwise (y up): winding number 1 inside, 0 outside.

/// The fewest cubics n >= 4 whose circle of radius `radius` (the construction below) stays
/// within `tolerance` of the true circle: radius ε(2π / n) <= tolerance, ε the radial error
/// of one cubic arc (core/path/elliptical_arc.hpp, circular_arc_cubic_error; Goldapp 1991).
/// Precondition: radius > 0, tolerance > 0 and at least 1e-12 of radius.
[[nodiscard]] std::size_t circle_pieces(double radius, double tolerance);

/// The circle about `centre` as `pieces` cubic arcs, counter-clockwise from angle 0: the arc
/// from α to α + δ (δ = 2π / pieces) has control points c + R e(α), c + R (e(α) + k e'(α)),
/// c + R (e(α + δ) - k e'(α + δ)), c + R e(α + δ), k = 4/3 tan(δ / 4). Each cubic lies
/// outside the circle or on it, within radius ε(δ) of it (Goldapp: |B(t) - c| - R is in
/// [0, R ε(δ)]), and its distance from c grows with the angle swept, so the contour winds once
/// about every point of the open disk and about no point farther than R (1 + ε(δ)) from c.
[[nodiscard]] Contour circle(core::Point2 centre, double radius, std::size_t pieces);

/// The polygon SVG 2 adds at a joint for a miter or bevel join, on the outer side of the turn
/// from unit direction t0 (arriving) to t1 (leaving) at `point`, half width w: with n0, n1 the
/// outer unit normals (to the right of travel for a left turn, y up), the bevel is the triangle
/// point, point + w n0, point + w n1; the miter adds the tip where the two outer edges meet,
/// point + w (n0 + n1) / (1 + t0 · t1), when the miter ratio 1 / sin(θ / 2) (θ the angle
/// between the segments, π minus the turn) is at most `miter_limit`: that is
/// miter_limit^2 (1 + t0 · t1) >= 2. nullopt when the polygon has no area (no turn, or a
/// half turn, where SVG 2's bevel is a line).
[[nodiscard]] std::optional<Contour> join_polygon(core::Point2 point, core::Point2 t0,
                                                  core::Point2 t1, double w, bool miter,
                                                  double miter_limit);

/// SVG 2's square cap at the open end `point` of a subpath whose unit direction pointing out
/// of the path there is `outward`: the rectangle point ± w n, point ± w n + w outward
/// (n the normal), half width w.
[[nodiscard]] Contour square_cap(core::Point2 point, core::Point2 outward, double w);

}  // namespace bezier::outline
