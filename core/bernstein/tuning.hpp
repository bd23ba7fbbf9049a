#pragma once

// The tuning constants of the Bernstein layer, each with the reason for its value. None of
// them weakens a result: they bound iterations and choose what is computed ahead of time.

namespace bezier::core::bernstein_tuning {

/// Bisection steps on a bracketed root of a Bernstein polynomial on [0, 1] (bernstein_roots,
/// and collinear.cpp's inverse of a monotone position): the loop ends when the bracket is
/// one ulp wide, after about 53 + log2(1 / r) halvings for a root r; the limit binds only
/// for roots below 2^-147, which it leaves within 2^-200, and bounds the loop for any input.
inline constexpr int kBisectionSteps = 200;

/// The default subdivision depth of bernstein_roots: a cluster of roots still unresolved
/// on an interval of width 2^-40 is reported once at its midpoint and polished. Deeper
/// levels would split only clusters whose members the polynomial's rounding hardly tells
/// apart, at the cost of more intervals for each; shallower ones would report clusters that
/// bisection could still separate.
inline constexpr int kRootDepth = 40;

/// Newton steps that polish a root reported at the depth limit, and the largest step they
/// may take: from a midpoint within 2^-40 of a simple root, quadratic convergence reaches
/// the rounding in two or three steps; a step above 2^-30 means the iteration left the
/// cluster (a multiple root, a flat spot), and the midpoint is kept.
inline constexpr int kPolishSteps = 4;
inline constexpr double kPolishLargestStep = 0x1p-30;

/// Roots closer than this are reported once (the one where |p| is smallest): the same root
/// found from two neighbouring intervals differs by the polishing's error, far below it,
/// while distinct roots this close are beyond what the depth limit resolves anyway.
inline constexpr double kSameRoot = 0x1p-30;

/// Degrees up to which the L2 reduction (to degrees 2 and 3) and elevation (from degrees
/// 1 to 3) matrices are computed at compile time (degree.cpp): the API's default degree
/// limit, so a request within it solves no linear system for its fat curves; above it the
/// matrices are computed per call. Each degree more adds its tables to the binary.
inline constexpr int kTableDegree = 20;

/// Safety factor on the rounding bound of a monomial coefficient (significant_coefficient:
/// C(n, k) 2^k u of the magnitude): a coefficient above it is the curve's, not the
/// conversion's rounding, so a degree-elevated curve reads as its true degree; the factor
/// covers the bound's own looseness at little cost, since a true coefficient is far larger.
inline constexpr double kSignificantCoefficientFactor = 64;

}  // namespace bezier::core::bernstein_tuning
