#pragma once

// The boolean operations on regions (DESIGN.md §8): union, intersection, difference, xor of
// two regions, and simplify of one.
//
// The layer's contract. A region is a path whose subpaths are all closed, with a fill rule:
// the points p whose winding number w(p) has w != 0 (nonzero) or w odd (evenodd). The result
// of an operation is a set of contours with these promises:
//  1. The right region: a point p farther than 1e-9 of scale from both operands' boundaries
//     is inside the result (winding number 1 of the result's contours; 0 outside) exactly
//     when op(p in a, p in b) holds. Outer contours run counter-clockwise (y up), holes
//     clockwise.
//  2. Made of the inputs: every result segment is a piece of one input segment between two
//     of its parameters, the de Casteljau (blossom, core::portion) sub-curve, with its source
//     operand, segment index and [t0, t1] (t0 > t1 when the piece runs backwards). Its
//     interior control points are exactly the piece's; its two end points are the vertices
//     it joins, each within the vertex's merge radius of the piece's own end (the contact's
//     located interval, at least kVertexMergeRel of scale). A piece of boundary a and b share
//     is taken once, from a.
//  3. Clean: contours are closed and consecutive segments meet exactly (the end of one is the
//     start of the next, the same double, the last's end the first's start); contours do not
//     cross themselves or each other (they may touch at vertices); no contour has zero area;
//     no segment has zero length.
//  4. Bounded: one work budget for the whole operation (core/intersect/work_cost.hpp's unit);
//     running out gives work_cap_reached, never a hang.
//  5. Empty is an answer: no contours, area 0.
//
// Method (the classical arrangement approach, e.g. Margalit & Knott 1989 for polygons, here
// on curves with certified contacts):
//  - arrangement.hpp: both boundaries cut at every contact (crossings, tangencies, vertices on
//    edges, overlaps in either direction, self-contacts of either operand and within one
//    segment), contacts closer than their located intervals merged into one vertex the same
//    way on every edge; pieces of shared boundary grouped, and so are two edges between the
//    same vertices that stay within kRayClearanceRel of scale (a lens thinner than rounding).
//  - side_winding.hpp: for each group, both operands' winding numbers on its two sides, from
//    a ray cast across the arrangement with every crossing decided clearly (else another ray);
//    one ray for each chain of groups that share their sides through vertices where only two
//    groups end (side_links.hpp), the rest of the chain taking the same windings exactly.
//  - the group is a boundary of the result where op(fill_a(w_a), fill_b(w_b)) differs between
//    its sides, directed so that the inside is on its left; taken once, as its representative
//    edge (the first of a).
//  - contour_chain.hpp: kept edges chained into contours, choosing at vertices by the order of
//    the edges around it (edge_germ.hpp: tangent angle, then turn).
//  - contours whose |area| is at most 2^-80 scale^2 (zero to rounding) are dropped.
// What is not certified: the order of edges leaving a vertex with tangents within
// kTangentTieAngle and equal turn (contacts of order three and up) is taken from floating
// point; a region whose every ray is unclear (kTurns) gives status unresolved.

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/base/curve.hpp"
#include "core/base/work_budget.hpp"
#include "core/intersect/result.hpp"
#include "core/path/path.hpp"
#include "core/region/arrangement.hpp"
#include "core/region/fill_rule.hpp"
#include "core/region/region.hpp"

namespace bezier::region {

enum class BooleanOperation {
  union_,        ///< in a or in b
  intersection,  ///< in a and in b
  difference,    ///< in a and not in b
  xor_,          ///< in exactly one
  simplify,      ///< in a (b is ignored): a's region as simple contours
};

/// Whether a point in a (in_a) and in b (in_b) is in the result of `op`.
[[nodiscard]] constexpr bool keeps(BooleanOperation op, bool in_a, bool in_b) noexcept {
  switch (op) {
    case BooleanOperation::union_: return in_a || in_b;
    case BooleanOperation::intersection: return in_a && in_b;
    case BooleanOperation::difference: return in_a && !in_b;
    case BooleanOperation::xor_: return in_a != in_b;
    case BooleanOperation::simplify: return in_a;
  }
  return false;
}

/// One segment of a result contour.
struct ResultSegment {
  Operand source = Operand::a;
  std::size_t segment = 0;
  /// The piece of the source segment from t0 to t1 (t0 > t1: traversed backwards).
  double t0 = 0.0;
  double t1 = 1.0;
  /// core::portion(source segment, t0, t1) with its ends at the result's vertices.
  core::Curve curve = core::Curve({core::Point2{}});

  ResultSegment() = default;
  /// Every member given, for emplace_back (which builds an aggregate from parentheses only
  /// from C++20 on, and clang only from version 16).
  ResultSegment(Operand of, std::size_t in_segment, double from_t, double to_t,
                core::Curve piece)
      : source(of), segment(in_segment), t0(from_t), t1(to_t), curve(std::move(piece)) {}
};

struct ResultContour {
  /// The contour's segments: [first_segment, end_segment) of BooleanResult::segments.
  std::size_t first_segment = 0;
  std::size_t end_segment = 0;
  /// Signed area (Green's theorem), counter-clockwise positive: positive for an outer
  /// contour, negative for a hole.
  double area = 0.0;
};

enum class BooleanStatus {
  ok,
  work_cap_reached,  ///< the budget ran out; no result
  unresolved,        ///< a side's winding could not be decided or the kept edges did not chain
};

struct BooleanResult {
  std::vector<ResultSegment> segments;
  std::vector<ResultContour> contours;
  /// The sum of the contours' areas: the result region's area.
  double area = 0.0;
  std::int64_t work = 0;
  BooleanStatus status = BooleanStatus::ok;
};

/// The result of `op` on a and b (b ignored by simplify). Every phase charges `budget`, which
/// the call shares with its caller's other work (a stroke's simplify takes what the stroke
/// left); when it runs out (budget.exhausted()) the status is work_cap_reached and there is
/// no result. `work` is what this call charged.
/// Preconditions: finite coordinates (a Region's subpaths are closed).
[[nodiscard]] BooleanResult boolean_operation(BooleanOperation op, const Region& a,
                                              const Region& b, core::WorkBudget& budget);

/// simplify of one operand.
[[nodiscard]] BooleanResult simplify(const Region& a, core::WorkBudget& budget);

/// The same with a budget of max_work units of their own (tests, benchmarks, fuzzers).
[[nodiscard]] BooleanResult boolean_operation(BooleanOperation op, const Region& a,
                                              const Region& b, std::int64_t max_work);
[[nodiscard]] BooleanResult simplify(const Region& a, std::int64_t max_work);

}  // namespace bezier::region
