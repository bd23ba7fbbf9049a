#pragma once

// The tuning constants of self-intersection, each with the reason for its value. The work
// each stage is charged is in work_cost.hpp; the tolerances a caller chooses (the distance
// tolerance, the budget, the deepest level) are SelfIntersectionOptions.

namespace bezier::core::self_intersect_tuning {

// The curve's scale (self_intersection.cpp).

/// Curves whose largest coordinate lies in [kSmallestUnscaled, kLargestUnscaled] are worked
/// on as given; others are scaled by a power of two (exact) to [1, 2) first. The inner loops
/// square lengths (sqrt(v·v), not the slower overflow-safe hypot), which neither overflows
/// nor underflows within 2^±300 for the degrees the API takes.
inline constexpr double kSmallestUnscaled = 0x1p-300;
inline constexpr double kLargestUnscaled = 0x1p300;

// The search (search.hpp).

/// Cone angles (radians) are compared with this margin, so that rounding in the control
/// points cannot make two touching tangent cones look disjoint: the angles come from atan2
/// of differences of control points, good to a few ulps of pi, far below it.
inline constexpr double kConeMargin = 1e-9;

/// A Newton root found for a box whose tangent cones are disjoint belongs to that box when
/// it lies inside it or at most this far outside (in parameter): a few ulps of 1, the
/// rounding of the root itself.
inline constexpr double kRootSlack = 0x1p-50;

// Refinement (refine.hpp).

/// Newton steps below this (in parameter, t in [0, 1]) mean the iteration has converged:
/// a few ulps of 1, and one more quadratic step then lands at rounding level.
inline constexpr double kConvergedStep = 0x1p-50;

/// A double point is resolved when its uncertainty is below this fraction of its
/// parameter separation (is_resolved_double_point). The linearised uncertainty
/// underestimates how far the noise reaches next to a cusp, where F grows only like
/// (v - u)^3 along the anti-diagonal, so that noise "roots" there can have estimates within
/// a small factor of v - u: hence the wide margin. Real loops of area 1e-12 of their
/// curve's size have v - u of order 1e-3 and estimates of order 1e-10, far inside it.
inline constexpr double kResolvedFraction = 0x1p-10;

// Clean-up of the pairs (self_intersection.cpp).

/// Crossings found twice (from neighbouring boxes) agree to a few ulps; distinct
/// transversal pairs this close in both parameters do not occur above the resolution of
/// the search, so candidates this close in t and s are one pair.
inline constexpr double kMergeCrossings = 1e-10;
/// Tangential contacts are located less sharply (to about half the digits when the
/// branches' curvatures agree) and from clusters of boxes: merged at this distance.
inline constexpr double kMergeContacts = 1e-7;

/// Sine of the angle between the tangents below which a pair counts as tangent: about
/// sqrt(u), the precision to which a double root's tangent directions can be matched.
inline constexpr double kTangentSine = 1e-7;

/// A tangent shorter than this times n scale(curve) counts as zero (the pair's kind is then
/// degenerate): |B'| can be up to 2 n scale, and next to a simple zero of B' it grows like
/// the parameter's distance from it, so this is a cusp located to 1e-12 in parameter.
inline constexpr double kZeroTangent = 1e-12;

/// The polish of a crossing (mixed-precision Newton steps): at most this many steps, each
/// at least halving the one before, so from the search's root (within its uncertainty of
/// the double point) quadratic convergence reaches the noise floor well within them.
inline constexpr int kPolishSteps = 6;
/// The polish stays within reach of its start: this many times the start's uncertainty
/// (anything farther is another root, or none), but at least kPolishReachMin (some
/// hundred ulps, so that a well-conditioned pair can still move by rounding) and at most
/// kPolishReachMax, so that at an ill-conditioned pair (a large uncertainty) the steps cannot
/// slide along the branches to another point.
inline constexpr double kPolishReachFactor = 16.0;
inline constexpr double kPolishReachMin = 0x1p-40;
inline constexpr double kPolishReachMax = 0x1p-20;

/// A parameter within this of 0 (or 1) is tried at the end exactly: a loop closing at an
/// end point is found by Newton to within its uncertainty of it, which for a resolved pair
/// is far below this; a pair farther from the end than this is not at it.
inline constexpr double kNearEnd = 0x1p-20;

/// Improper curves B = h(p(t)): the parameters t with p(t) = u are the roots of p - u, and
/// an end of [0, 1] within this of the level counts as a root too. u comes from h's pairs
/// (about 1e-10 off), so a root just outside [0, 1] shows as |p - u| of that order at the
/// end; the polish on B then settles it.
inline constexpr double kLevelEndSlack = 0x1p-30;

// Collinear curves (collinear_fold.hpp).

/// Intervals of x' (x the coordinate along the curve's line) narrower than this are left
/// undecided, a root of x' inside: a turning point is then bracketed by the gap between two
/// sign runs, some hundred ulps of 1 at most, where bisection on x' locates it.
inline constexpr double kNarrowestSignRun = 0x1p-40;

// Certification (certify.hpp).

/// The boxes in which a pair is certified have half-width at most this (and at most a
/// quarter of s - t, which keeps them off the diagonal): far wider than the pair's
/// uncertainty, so the box holds it, and narrow, so that another pair in it is rare (the
/// pair is then reported as found, not certified).
inline constexpr double kCertifyHalfWidth = 0x1p-20;

}  // namespace bezier::core::self_intersect_tuning
