#pragma once

#include <cstddef>

// The tuning constants of two-curve intersection, each with the reason for its value: the
// search's, the clipping methods' (clip/), the refinement's, and the thresholds of the
// degenerate cases (collinear curves, overlaps, common arcs). Most steer how the work is
// spent (when to clip, when to halve, when to stop an iteration); none of them weakens what
// is certified: every test carries its own error bound. The work each step is charged is in
// work_cost.hpp; the tolerances a caller sets or that define an answer (the search width,
// the overlap tolerance, the kind thresholds) are in options.hpp, overlap.hpp and kind.hpp.

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

/// The cubic's own implicit equation (implicit_cubic_clip.hpp) is tried on a box when the
/// fat parabola kept at least this fraction of the piece: pieces that run so close together
/// that the parabola's cubic term hides the gap. Where the parabola narrows the piece the
/// box is near a crossing or a contact, and halving does better than the costlier clip.
inline constexpr double kCubicClipAfterParabolaKept = 0.9;
/// Where the cubic clip kept as much itself (the pieces meet, or come together at a common
/// end, where no implicit band parts them), it is tried again on that box's descendants
/// only once they are this fraction of its width: four levels of halving later.
inline constexpr double kCubicClipRetryWidth = 1.0 / 16;

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

/// The Krawczyk test certifies a root within the radius it is given (half the tolerance,
/// rounded down to a power of two); it is used only for radii in this window: above 2^-2 the
/// box is most of the parameter square and the test's linearisation is too coarse to pay
/// off, below 2^-52 the radius is under one ulp of a parameter near 1 and the test could not
/// shrink the box.
inline constexpr double kKrawczykSmallestRadius = 0x1p-52;
inline constexpr double kKrawczykLargestRadius = 0x1p-2;

/// Relative slack on every Krawczyk bound assembled from rounded sums and products of
/// nonnegative terms: a handful of roundings of at most u = 2^-53 each, far below 2^-40.
inline constexpr double kKrawczykSlack = 1 + 0x1p-40;

/// Boxes the search holds on the stack before its stack spills to the heap (the depth of a
/// typical search stays below it).
inline constexpr std::size_t kSearchStackInline = 32;

// The clipping methods (clip/).

/// A piece is a point for the search (is_point_like, and fat_line's choice of line) when
/// all its control points lie within this many times its error bound of the first: its
/// chord is then noise, and a line drawn along it would point anywhere.
inline constexpr double kPointLikeErrors = 4;
/// A clip is noise (is_noisy) when this many times its error margins exceed the spread of
/// the distances they bound: the margins then take so much of the band that the clip tells
/// more about rounding than about the curves, and compensated pieces (or halving) tell more.
inline constexpr double kNoiseRatio = 4;
/// The implicit clip's parabola is straight (no implicit form) when twice its signed area
/// is below this many ulps of its squared size: the rounding of the area is a few ulps of
/// it, so the form's coefficients would be rounding.
inline constexpr double kStraightParabolaUlps = 64;
/// The band solver's cubic degenerates to a quadratic (and that to a line) when its leading
/// coefficient is below this fraction of the largest: the closed forms divide by it, and
/// below 2^-40 the quotients lose more digits than the polishing restores.
inline constexpr double kLeadingCoefficient = 0x1p-40;
/// The band solver looks for roots of the distance polynomial this far outside [0, 1], so a
/// root just outside, moved across the end by rounding, still splits the interval there.
inline constexpr double kRootWindow = 0x1p-20;
/// Widening of the closed-form interval before it is certified: well above the error of a
/// polished simple root (a few ulps), small enough to keep quadratic convergence (a clip can
/// still shrink an interval by a factor 2^31).
inline constexpr double kRootPad = 0x1p-32;
/// Halley steps on the distance cubic from where its control polygon crosses the level,
/// and the step that ends them: the iteration converges cubically, so three steps from the
/// polygon's crossing reach the rounding, and after a step below 2^-40 the error, of order
/// its cube, is below the last bit.
inline constexpr int kHalleySteps = 3;
inline constexpr double kHalleyConverged = 0x1p-40;
/// The band solver's hull clip (kept_interval_by_hulls) clips again while a pass keeps less
/// than this fraction of the interval (the rule of kBezierClipKeptFraction, for the same
/// reason), at most kBandClipPasses times: each pass portions the polynomial anew, and the
/// search clips the box again anyway, with fresh pieces.
inline constexpr double kBandClipKeptFraction = 0.8;
inline constexpr int kBandClipPasses = 3;

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
/// A step below this, with the curves' tangents at least kSeparatedSine apart, ends the
/// refinement early: at such a well-conditioned root Newton's error after a step h is
/// O(h^2), so the iterate is already exact to the last bit.
inline constexpr double kEarlyConverged = 0x1p-40;
inline constexpr double kSeparatedSine = 0x1p-10;
/// Steps that grow again after this many iterations mean stagnation at the floor of the
/// residual's accuracy (or a clamped step) and end the refinement; before it, a growing step
/// is Newton's method still finding its basin.
inline constexpr int kStagnationAfter = 8;

// The Krawczyk test (krawczyk.hpp).

/// rho above this leaves the box to the clipping: the certificate needs rho < 1, and a
/// contraction this strong makes Newton's iterates and the tight box reliable.
inline constexpr double kMaxRho = 0.5;
/// Newton steps before the test: from where the chords cross, O(width^2) from the root on a
/// box of at most kKrawczykWidth, quadratic convergence reaches the rounding in three or four
/// steps. The test certifies whatever they reach: fewer steps only make it fail more often.
inline constexpr int kNewtonIterations = 4;

// Gauss-Newton on a curve's parameter (gauss_newton.hpp).

/// A step larger than this ends the iteration: the callers start within about 1e-9 of the
/// answer, so such a step means r' nearly vanishes here, where the iteration is unreliable.
inline constexpr double kGaussNewtonLargestStep = 0x1p-20;

// Two curves on one line (collinear.hpp).

/// Ranges closer than this (in units of the line's parameter, about 1 over the common
/// extent) touch rather than overlap: far above the rounding of the positions along the
/// line, far below any overlap worth reporting.
inline constexpr double kTouch = 0x1p-40;

// Overlaps by linear reparametrisation (overlap.hpp) and along common arcs (common_arc.hpp).

/// Overlaps shorter than this in t or s are left to the search, which reports such a piece
/// as one contact. Far above the error of the refined end points, so a longer overlap is no
/// artefact of rounding; the value decides when a very short overlap is reported as a
/// contact instead.
inline constexpr double kShortestOverlap = 0x1p-30;
/// How far outside an overlap's intervals (and, linear, off its map) a pair (t, s) still
/// lies on it (on_overlap): the overlap's ends are refined to well within this.
inline constexpr double kOnOverlapSlack = 0x1p-30;
/// How far beyond a box the map's image may reach and still cover it (covered_by_overlap):
/// a few ulps of the parameters' rounding, with room.
inline constexpr double kCoverSlack = 0x1p-40;
/// Points of f projected onto g by coincide_at_precision (evenly spaced, both ends
/// included): a polynomial piece of degree <= 4 that agrees at 5 points is the same piece,
/// and beyond it the box is at the precision floor, where every piece is nearly straight.
inline constexpr int kCoincidenceSamples = 5;
/// Gauss-Newton's step limit and default convergence when a point known to lie on a curve
/// is projected onto it (locate_on_curve, coincide_at_precision): quadratic convergence
/// from a close guess reaches 2^-60, below the last bit of a parameter, in a handful of
/// steps; the limit only bounds a projection that does not converge.
inline constexpr int kProjectionSteps = 30;
inline constexpr double kProjectionConverged = 0x1p-60;
/// How far the approximations of h, p and q (about 1e-10 of the curves' size for the
/// degrees accepted) may put a point of u, h's parameter: the coverage test widens the
/// ranges of p and q by this much.
inline constexpr double kArcSlack = 0x1p-24;
/// The candidate filters' relative tolerance: far above the rounding of monomial
/// coefficients of degree 20 (2^20 u), far below any curve that is not improper.
inline constexpr double kArcFilter = 1e-6;
/// The relative step of the forward-difference Jacobian when a common factor is refined on
/// the curve (refined_on_curve): about sqrt(u), which balances the difference's truncation
/// error (of order the step) against its rounding error (of order u / step).
inline constexpr double kFactorJacobianStep = 0x1p-27;
/// The division filter's tolerance (is_polynomial_in): a factor of a degree-20 curve whose
/// power form cancels a lot leaves remainders near 2e-5 of its coefficients, while generic
/// curves of degree 20 leave at least 2e-4, and those of lower degree more.
inline constexpr double kDivisionFilter = 1e-4;
/// A factor whose interpolated h misses the curve by more than this (relative) is wrong,
/// not inaccurate: it is not refined.
inline constexpr double kRefineBelow = 1e-2;
/// Factors of higher degree than this are not refined (a degree-20 curve through a factor
/// of degree 10 would take ten interpolations per Gauss-Newton step).
inline constexpr std::size_t kRefineDegree = 5;
/// How well h(p) must fit the curve (relative to its magnitude) for a factorisation: a
/// true factor, refined, fits to the interpolation's rounding (about 1e-12 at degree 20);
/// a curve within 1e-6 of an improper one (say a wave 1e-6 wide on it) is not one.
inline constexpr double kFactorFit = 1e-9;
/// Gauss-Newton steps on a common arc (refine_turn's turning point, piece_lies_on's
/// projections), from guesses within about 1e-9: two or three steps converge, so eight
/// bound the work of the samples of a piece that does not lie on the other curve.
inline constexpr int kArcNewtonSteps = 8;
/// piece_lies_on's projections stop at steps of 2^-50: the residual is then compared with
/// coincidence_tolerance, far above what the last few bits of the parameter change.
inline constexpr double kArcSampleConverged = 0x1p-50;
/// Changes of p or q (whose ranges are about [0, 1]) below this are rounding, not turns.
inline constexpr double kTurnNoise = 0x1p-40;
/// Roots of p' (or q') within this of 0, of 1 or of the previous turn do not split p into
/// monotone pieces: a piece that short is far below the shortest overlap reported
/// (kShortestOverlap), so splitting there would only add pieces.
inline constexpr double kTurnSeparation = 0x1p-40;
/// The interpolation nodes' parameters are found to this accuracy: h interpolated through
/// them is then as good as p itself.
inline constexpr double kNodeAccuracy = 0x1p-44;
/// A preimage under p or q found to this accuracy starts Newton's method on the curves,
/// well inside its reach; the curves' own Newton steps give the last bits.
inline constexpr double kPreimageAccuracy = 0x1p-32;
/// Gauss-Newton steps that refine a factor p on the curve (refined_on_curve): the right
/// factor from the power form starts about 1e-5 off at degree 20, and quadratic convergence
/// brings it to the rounding in two or three steps (a step that does not reduce the misfit
/// ends it earlier).
inline constexpr int kFactorRefineSteps = 3;

// High-order contacts (high_order_contact.hpp).

/// Contacts of order 1 (crossings) and 2 (ordinary tangencies) are the search's: they
/// converge there, and their answers stay those of the search and refinement.
inline constexpr int kLeastCertifiedOrder = 3;
/// The highest order tried. Bezout bounds it by n m for proper curves (9 for cubics); the
/// exact terms grow with it (order 16 of two degree-4 curves is a few thousand exact
/// products), and higher orders need degrees beyond what such contacts come from.
inline constexpr int kMaxContactOrder = 16;
/// Only boxes at most this wide try a contact: a contact of order k >= 3 sends the search to
/// double-double pieces in boxes about u^(1/k) wide (2^-17 at order 3, 2^-10 at order 5),
/// and wider boxes whose tests rounding decides are not near one.
inline constexpr double kContactTryWidth = 0x1p-6;
/// Nor boxes narrower than this: an ordinary tangency (order 2), the common near-tangent
/// case, goes to double-double pieces only in boxes about u^(1/2) wide (2^-26) or less,
/// where proposing would only cost.
inline constexpr double kContactLeastWidth = 0x1p-24;
/// A box proposes the simplest rationals in itself widened by margins from
/// max(its width, kContactFirstMargin) up to kContactTryWidth, growing by
/// kContactMarginGrowth: the contact lies somewhere on the stretch where the curves agree to
/// within rounding (about u^(1/k) long), not necessarily in the box. Five margins at most.
inline constexpr double kContactFirstMargin = 0x1p-24;
inline constexpr double kContactMarginGrowth = 16.0;
/// Distinct pairs of rationals tried (each a double precheck) per call: the boxes of one
/// contact's stretch propose the same simplest rationals, so a few find it; a tangency at
/// irrational parameters proposes new ones at every level, and this bounds what it spends.
inline constexpr int kContactAttempts = 32;
/// Boxes that may propose per call: each costs a few hundred flops even when its proposals
/// were tried already, and the first boxes near a contact (at most kContactTryWidth wide)
/// propose it.
inline constexpr int kContactCalls = 64;
/// Largest denominator of a proposed parameter: contacts built at rational parameters have
/// small ones; 256 keeps the exact coefficients (b^n) small.
inline constexpr int kMaxContactDenominator = 256;
/// The double precheck: f and g at the proposed parameters, in the working frame (magnitude
/// about 1), closer than this in each coordinate, and the sine of the angle between their
/// tangents below it. At a true contact of order >= 2 both agree to within the rounding of
/// the parameters and the evaluations (about 1e-15).
inline constexpr double kContactPrecheck = 0x1p-30;
/// The least half-width of an isolating box worth reporting: narrower ones keep nothing
/// from the search (and the inward rounding of the box needs a few ulps of room).
inline constexpr double kLeastIsolation = 0x1p-40;

}  // namespace bezier::core::intersect_tuning
