#pragma once

#include <bit>
#include <cstdint>

namespace bezier::core {

// What the two-curve search charges against IntersectOptions::max_work, in work units.
//
// A step's cost grows with the degrees and with the arithmetic: rebuilding a piece of degree n
// is de Casteljau's triangle, about (n + 1)^2 coordinate updates per piece, the implicit clip
// multiplies degree-n Bernstein polynomials ((n + 1)^2 products each), and compensated pieces
// do all of it in double-double. Counting steps alone lets the cost per step range over three
// orders of magnitude (a plain cubic step against a compensated degree-20 one), so a cap in
// steps either cut legitimate searches short or let pathological ones run for seconds.
// Charging each step by what it computes makes the spent units proportional to time: one unit
// is about one coordinate update of de Casteljau's algorithm in doubles. The multipliers are
// fitted to the worst and the heaviest ordinary requests of tests/bench/worst_case_inputs.hpp,
// so that every one that reaches the cap spends about the same time per unit: a plain step is
// cheap next to what the costly ones add.

/// Compensated (double-double) pieces cost this many times the plain ones: each update is
/// a two-product and two two-sums instead of one multiply-add.
inline constexpr std::int64_t kCompensatedFactor = 14;

/// A step's fixed part (popping the box, the bounding boxes, the fat line), in units.
inline constexpr std::int64_t kStepOverhead = 8;

/// One box step on pieces of degrees m and n: both pieces rebuilt and clipped.
[[nodiscard]] constexpr std::int64_t step_cost(int m, int n, bool compensated) noexcept {
  const std::int64_t a = m + 1, b = n + 1;
  const std::int64_t pieces = a * a + b * b;
  return kStepOverhead + (compensated ? kCompensatedFactor * pieces : pieces);
}

/// What a subdivision step adds to its step_cost: the separation test of both pieces
/// against both fat lines and the parallelism test, each a pass over both control
/// polygons with its own distances, and the halving into four boxes; measured as six
/// times the pieces' updates (on the 400-crossing grid, where it is most of the time).
[[nodiscard]] constexpr std::int64_t subdivision_test_cost(int m, int n) noexcept {
  const std::int64_t a = m + 1, b = n + 1;
  return 6 * (a * a + b * b);
}

/// Newton iterations cost this many times a plain piece's updates per curve: a residual
/// evaluated in double-double on each curve (half a compensated piece each), and the
/// tangents in doubles from the same pass.
inline constexpr std::int64_t kNewtonFactor = 4;

/// The test whether the curves coincide to within rounding on a compensated box at the
/// precision floor (overlap.hpp: f's compensated piece, then five points of f projected
/// onto g by Gauss-Newton steps with compensated residuals): the piece as one compensated
/// step, and each compensated evaluation of either curve as a Newton iteration's share
/// for one curve (below).
[[nodiscard]] constexpr std::int64_t coincidence_test_cost(int m, int n, int evaluations) noexcept {
  const std::int64_t a = m + 1, b = n + 1, c = (a > b ? a : b);
  return kCompensatedFactor * (a * a + b * b) + evaluations * kNewtonFactor * c * c;
}

/// One implicit ("fat parabola") clip of a piece of degree n: the squares and products of
/// its three degree-n distance polynomials, then the convex hull of a degree-2n
/// polynomial; measured at about 24 times the updates of rebuilding the piece.
[[nodiscard]] constexpr std::int64_t implicit_clip_cost(int n) noexcept {
  const std::int64_t a = n + 1;
  return 24 * a * a;
}

/// One implicit_cubic_clip of a piece of degree n: the Bezout matrix's entries and cofactors
/// along the piece (products of degree-n and degree-2n polynomials) and along the cubic, in
/// double-double arithmetic; measured against rebuilding a cubic piece, most of it
/// independent of n.
[[nodiscard]] constexpr std::int64_t implicit_cubic_clip_cost(int n) noexcept {
  const std::int64_t a = n + 1;
  return 400 * a * a + 6400;
}

/// One Newton iteration of the final refinement on curves of degrees m and n.
[[nodiscard]] constexpr std::int64_t newton_cost(int m, int n) noexcept {
  const std::int64_t a = m + 1, b = n + 1;
  return kStepOverhead + kNewtonFactor * (a * a + b * b);
}

/// Grouping k boxes into contacts (merge.hpp): the sort and the sweep through a segment
/// tree (box_components.hpp), about k log2 k visits of a few comparisons each.
inline constexpr std::int64_t kMergeVisitCost = 16;

[[nodiscard]] constexpr std::int64_t merge_cost(std::int64_t k) noexcept {
  return kMergeVisitCost * k * std::bit_width(static_cast<std::uint64_t>(k));
}

/// The most Newton iterations one contact's refinement takes (refine.hpp: the transversal
/// system, then the tangency system).
inline constexpr std::int64_t kMaxRefineIterations = 60;

/// The most a contact's refinement can cost: it is only started when the budget covers it.
[[nodiscard]] constexpr std::int64_t max_contact_cost(int m, int n) noexcept {
  return kMaxRefineIterations * newton_cost(m, n);
}

/// Storing a box the search reports (candidate_boxes), with the final separation test
/// that precedes it: a search that reports many (a column of boxes along a crossing that
/// doubles cannot decide) spends its time there and in the memory they take.
inline constexpr std::int64_t kCandidateCost = 32;

/// What intersect() does before the search, bounded by the degrees: the collinear test
/// (and the one-dimensional problem of two curves on one line), and the overlaps along an
/// affine map or a common arc. For proper curves the factorisation attempts stop at their
/// first filter and this covers them; an improper curve (or a degenerate one, most of its
/// control points equal) takes every candidate factor of its degree through division and
/// interpolation and costs a few times more, still bounded by the degree.
[[nodiscard]] constexpr std::int64_t overlap_search_cost(int m, int n) noexcept {
  const std::int64_t a = m + 1, b = n + 1;
  return 4 * (a * a * a + b * b * b);
}

}  // namespace bezier::core
