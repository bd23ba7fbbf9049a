#pragma once

#include <cstdint>

// The tuning constants of the outline kernels (flattening), each with the reason for its
// value. They steer how the work is spent; none of them weakens what is certified: a chord is
// kept only when its distance bound (chord_error.hpp) is within the tolerance.

namespace bezier::outline::outline_tuning {

/// Midpoint-rule cells per degree for the integral of the flattening density
/// (flatten.hpp): the density is smooth except for square-root kinks at inflections, and
/// the integral only chooses the count and the places of the vertices (every chord is then
/// verified), so a few cells per possible inflection or turn of the curve suffice; a
/// degree-n curve has at most 2n - 4 inflections and n - 1 turns of its hodograph.
inline constexpr int kDensityCellsPerDegree = 16;

/// Halvings the chord-error branch and bound (chord_error.hpp) may make for one chord. Each
/// halving of a piece of parameter width w brings its hull bound within O(w^2) of the
/// curve's true distance there, so closing the bracket to kChordResolution takes a few
/// dozen near a flat maximum; a bracket still open leaves its upper bound, which is still
/// certified (the chord may then be judged too long: a vertex more, never an error).
inline constexpr int kChordBoundHalvings = 64;

/// Width of the bracket [lower, upper] of a chord's distance the branch and bound closes to,
/// as a fraction of the tolerance: well inside kChordSlack, so the march (flatten.cpp) reads
/// a chord's distance closely enough to tell whether it is within the slack of the tolerance.
inline constexpr double kChordResolution = 2e-3;

/// A chord is long enough when its distance is within this fraction of the tolerance: its
/// parameter step is then within about half of it of the longest (the distance grows with
/// the square of the step), so the polyline has at most about that fraction more vertices
/// than the greedy one.
inline constexpr double kChordSlack = 1e-2;

/// Tries inside the bracket of the longest chord from one vertex (a certified end, an end
/// too far) before the certified end is taken: the march alternates the secant of the
/// distance with halving the bracket, which narrows it to a sixteenth or better, while the
/// estimate and the square law make the first tries land close where the curvature varies
/// smoothly.
inline constexpr int kMarchTries = 8;

/// The longer chords the march tries once a chord is long enough: steps kProbeFactor,
/// kProbeFactor^2, ... kProbeFactor^kProbes times its step. Where the curve turns back
/// through an inflection, or bends little after a bend, a longer chord can be within the
/// tolerance again (the distance need not grow with the step), which is where the greedy
/// polyline's farthest chord goes; these tries reach up to about twice the step for three
/// checks more a vertex.
inline constexpr double kProbeFactor = 1.26;
inline constexpr int kProbes = 3;

/// Rounding margin of the chord bound in units of n u S (n the degree, u the unit roundoff,
/// S the largest coordinate): the piece's control points come from two de Casteljau
/// subdivisions and a change of frame in doubles, each within a few n u S of the exact
/// value, and the polyline's vertices are evaluated separately (within one rounding): a chord
/// is accepted only when its bound plus this margin is within the tolerance.
inline constexpr double kRoundingMarginUnits = 64.0;

/// Work units (core/intersect/work_cost.hpp: about one coordinate update of de Casteljau's
/// algorithm each) of the fixed part of a chord check: the frame, the heap of pieces.
inline constexpr std::int64_t kChordCheckOverhead = 16;

}  // namespace bezier::outline::outline_tuning
