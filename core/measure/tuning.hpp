#pragma once

#include <cstddef>

// The tuning constants of the measuring kernels' root isolation and nearest point, each with
// the reason for its value. They steer how the work is spent; none of them changes what is
// certified: every discarded piece and every compared distance carries its own rounding
// bound. Tolerances that define an answer (the tie tolerance of /nearest, the accuracy of
// /length) are in the headers that promise them (nearest.hpp, arc_length.hpp).

namespace bezier::core::measure_tuning {

// The Bernstein root isolation (interval_roots.hpp).

/// Subdivision stops at pieces of width 2^-40 and reports a still unresolved cluster once, at
/// the middle of its piece: 2^-40 is about 1e-12, below the 1e-10 to which /nearest and
/// /length promise a well-conditioned parameter, while distinct simple roots closer than
/// that are not separated by double-precision coefficients anyway (their p stays within its
/// rounding bound between them). It bounds the work on a multiple root to 40 levels.
inline constexpr int kMaxDepth = 40;

/// On [0, 1] the pieces of the first this many levels are halves of their parent (one
/// subdivision at 1/2, a third of the rounds of a portion from the coefficients, and no
/// evaluation of p at the piece's ends beyond the one at the split). Each halving adds at
/// most n u max|c| to a coefficient's rounding, which the sign test of a piece d levels
/// down allows (d n u max|c|, where that exceeds the bound of a portion, 3.02 n u max|c|):
/// down to this depth the test is at most four times looser than a portion's, and
/// isolating the roots of the polynomials /nearest and /bounds meet takes fewer levels;
/// deeper pieces (clusters of close roots) come from portions, whose tighter bound tells
/// closer roots apart. Each level costs a stack slot of n + 1 coefficients.
inline constexpr int kHalvedDepth = 12;

/// Polynomials of up to this many coefficients are evaluated and cut into pieces by code
/// unrolled for their size (one instantiation each): the (B - q) · B' of /nearest for
/// curves up to degree 12 and the hodograph coordinates of /bounds up to degree 24; beyond,
/// the loops run with the size known only at run time (slower), and the refinement of a
/// root evaluates by de Casteljau instead of the Horner form (interval_roots.hpp).
inline constexpr std::size_t kUnrolledSizes = 24;

/// The refinement of a root evaluates p by its Horner form from this degree on, by de
/// Casteljau's rounds below it: a Horner step costs about 3n operations after a preparation
/// of 3n, de Casteljau's n (n + 1) / 2 lerps, which for degree 4 and less is no more, and
/// then the last de Casteljau step that the Horner form needs is not taken either.
inline constexpr std::size_t kHornerFromDegree = 5;

/// Iterations of the bracketed Newton refinement of one root, after which it returns its
/// last iterate: Newton's steps reach the rounding of p in a few, and a step out of the
/// bracket is a bisection, so even by bisection alone 200 iterations bring the bracket to
/// one ulp of any root above 2^-148 (52 + log2(1/t) halvings of [0, 1]); the limit only
/// bounds the work on roots closer to 0 than that.
inline constexpr int kRefineIterations = 200;

// The nearest point (nearest.hpp).

/// Candidates whose rough distance is within this fraction of the coordinate scale of the
/// least rough distance are polished and compared with compensated evaluations; the others
/// cannot be the minimum nor tie with it. Polishing moves a root of the computed (B - q) · B'
/// by a rounding-level stretch, along which the distance changes by far less than 1e-6 of
/// the scale, and a rough distance (plain doubles, within a few n u of the scale) is
/// far closer than that to the compensated one; a larger margin only polishes more.
inline constexpr double kPolishMargin = 1e-6;

/// Newton steps of the polish on one candidate: each is kept only while it lowers the
/// compensated distance (or keeps it within a rounding and lowers |(B - q) · B'|), and from
/// a root already refined to the rounding of the computed polynomial one or two steps reach
/// the rounding of the compensated one; the limit only bounds the work where the steps keep
/// lowering by rounding-level amounts.
inline constexpr int kPolishIterations = 8;

// Arc length (arc_length.hpp).

/// A piece whose |B'| has a kink smoothed over a width w below this fraction of the piece's
/// length h is not graded toward it: the smoothing changes the integral by about
/// (w / h)^2 log(h / w), below 1e-14 of it (arc_length.cpp, grade_toward).
inline constexpr double kUngradedWidth = 1e-8;

/// Hodograph control points the speed evaluation keeps on the stack (degree 24 curves and
/// below); longer hodographs take a heap row.
inline constexpr std::size_t kSpeedInlinePoints = 24;

/// Below this sum of squared components, the speed is taken as a scaled length
/// (core::length) instead of the square root of the sum: above it the largest component
/// is at least 2^-481 / sqrt(3), so the squares the sum loses to underflow (below 2^-1022)
/// are under 2^-60 of it, far below a rounding.
inline constexpr double kPlainSquaredSpeed = 0x1p-960;

}  // namespace bezier::core::measure_tuning
