#pragma once

#include <cstdint>

#include "core/outline/control_points.hpp"

namespace bezier::outline {

/// Whether a curve is "loose" at the distance `reach` (R) on both sides throughout: B' has no
/// zero and the radius of curvature exceeds R everywhere (R |κ| < 1), so that neither
/// parallel curve at ±R has a cusp and the stroke's cover needs no root search
/// (segment_cover.hpp). h1 and h2 are the control points of the curve's first and second
/// hodographs (B' and B''), in the units of `reach` (any common scale).
///
/// The bound. On a parameter interval J, let m be the least projection of the control points
/// of B' restricted to J on the direction of B' at J's middle, and M2 the largest length of
/// those of B'' restricted to J. B' and B'' on J lie in their control points' hulls, so where
/// m > 0, |B'| >= m on J (no zero of B'), |B''| <= M2, and
///   |κ| = |cross(B', B'')| / |B'|^3 <= |B''| / |B'|^2 <= M2 / m^2,
/// so R M2 < m^2 gives R |κ| < 1 on J. The test is made on [0, 1], and where it fails there,
/// on the halves, then the quarters, then the eighths (each part's control points by de
/// Casteljau's algorithm): true when every part of one of these passes. False decides
/// nothing (the caller searches the roots).
///
/// Rounding: the restricted control points (de Casteljau steps with weights in [0, 1]) are
/// within a few units of rounding, times the degree, of the exact ones times the largest
/// control point of the whole hodograph (a few n u M1 and n u M2; n at most the service's
/// degree limit, 20 by default), so m is lowered by 64 u M1 and M2 raised by 64 u M2 of the
/// whole before the comparison, whose own few roundings the factor 1 - 1e-9 covers. The
/// parts' ends are binary fractions, exact; the second split, at a / b rounded, moves a
/// part's start by a few units of rounding in t, a gap between parts over which R |κ|
/// changes by far less than the factor's margin (|B'| >= m > 0 on both sides of it).
///
/// Work: at most 15 tests; `work` (when given) is increased by the de Casteljau coordinate
/// updates of the parts' control points, 2 (k + 1)^2 per part and hodograph of k + 1 points.
[[nodiscard]] bool loose_everywhere(const ControlPoints& h1, const ControlPoints& h2,
                                    double reach, std::int64_t* work = nullptr);

}  // namespace bezier::outline
