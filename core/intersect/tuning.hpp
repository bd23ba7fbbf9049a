#pragma once

// The tuning constants of two-curve intersection, each with the reason for its value. They
// steer how the search spends its work (when to clip, when to halve, when to switch
// method); none of them changes what is certified: every test carries its own error bound.
// The work each step is charged is in work_cost.hpp; tolerances that define an answer
// (overlap, kind) are in overlap.hpp and kind.hpp.

namespace bezier::core::intersect_tuning {

// The search (search.hpp).

/// Boxes wider than this are never declared "coincident to within rounding": a contact of
/// order 3 reaches its precision floor near 1e-8 (double-precision local coordinates hold
/// the curves' gap c d^3 down to about u |f'| d), while wider coincident boxes are
/// near-coincidences along an arc (improper overlaps, the same point set traced along a
/// non-linear reparametrisation, are found before the search: common_arc.hpp), which the
/// search must not report as one contact; they run into the work cap instead.
inline constexpr double kFloorWidth = 0x1p-20;

/// The sine of the angle between two pieces' chords is below this: they run nearly parallel,
/// and the implicit clip is worth its cost (a few hundred flops for cubics).
inline constexpr double kParallelSine = 1.0 / 16;

/// In the hybrid method the implicit clip waits until the box is at most this wide: on the
/// first, large boxes nearly parallel chords are common and mean little (halving separates
/// such pieces for a fraction of the clip's cost), while the tube it prevents only forms
/// around a contact. (Bézier clipping, which halves only one interval at a time, still
/// needs it on wide boxes to resolve a tangency.)
inline constexpr double kImplicitClipWidth = 0.25;

/// A clip that keeps more than this fraction of its interval has not done enough: the box
/// is split instead of clipped again. The hybrid method halves both intervals once a clip
/// keeps more than half (halving then gains more than the clip); Bézier clipping halves the
/// wider interval once a clip removes less than 20 % of it (Sederberg & Nishita 1990, §4).
inline constexpr double kHybridKeptFraction = 0.5;
inline constexpr double kBezierClipKeptFraction = 0.8;

/// When rounding decides even on compensated pieces and one piece is more than this many
/// times longer than the other, the longer one is halved: its fat line is the blunt one.
inline constexpr double kUnevenPieces = 8;

/// Boxes narrower than this in t and s (hybrid, fast pieces) try the Krawczyk test
/// (krawczyk.hpp) before they are clipped: at a transversal crossing the Jacobian varies by
/// O(width) over the box, so the test usually succeeds and replaces the last few clips.
/// (Newton's method starts from where the chords cross, from which it converges on boxes
/// this wide.)
inline constexpr double kKrawczykWidth = 0x1p-4;

// Newton refinement of a contact (refine.hpp).

/// Steps below this (in parameter) end the iteration: a few ulps of 1/2.
inline constexpr double kConverged = 0x1p-54;
/// Iteration limits of the refinement (transversal: Newton on f(t) - g(s); tangency: Newton
/// on cross(f', g') = 0, (f - g) . f' = 0). Both converge quadratically from a box of the
/// search width on a regular root, where kConverged ends them after a handful of steps; the
/// limits, far above that, only bound the work where Newton's method does not converge (a
/// root of higher order, a start outside its basin).
inline constexpr int kTransversalIterations = 40;
inline constexpr int kTangencyIterations = 20;

// The Krawczyk test (krawczyk.hpp).

/// rho above this leaves the box to the clipping: the certificate needs rho < 1, and a
/// contraction this strong makes Newton's iterates and the tight box reliable.
inline constexpr double kMaxRho = 0.5;
/// Newton steps before the test: from where the chords cross, O(width^2) from the root on a
/// box of at most kKrawczykWidth, quadratic convergence reaches the rounding in three or four
/// steps. The test certifies whatever they reach: fewer steps only make it fail more often.
inline constexpr int kNewtonIterations = 4;

}  // namespace bezier::core::intersect_tuning
