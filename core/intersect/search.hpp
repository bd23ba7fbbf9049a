#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/base/work_budget.hpp"
#include "core/intersect/clip/fat_curve.hpp"
#include "core/intersect/overlap.hpp"
#include "core/intersect/result.hpp"
#include "core/intersect/working_curve.hpp"

namespace bezier::core {

class HighOrderContactFinder;

/// A box t x s of the parameter square that may hold an intersection.
struct SearchCandidate {
  ParamInterval t;
  ParamInterval s;
  /// False for a box left at the precision floor (compensated pieces could not decide)
  /// before reaching the search width.
  bool resolved = true;
};

/// What the search needs: the curves in their working frame, the method and its
/// operators (built once per call), the overlaps whose diagonals hold nothing else, and
/// which curve is a single point (its parameter is then free: every t is a solution).
struct SearchInput {
  const WorkingCurve* f = nullptr;
  const WorkingCurve* g = nullptr;
  IntersectMethod method = IntersectMethod::hybrid;
  double width = 0x1p-42;  ///< boxes narrower than this in t and s are done (search_width)
  const FatCurveOperator* op_f = nullptr;  ///< fat curves of f's pieces (hybrid)
  const FatCurveOperator* op_g = nullptr;  ///< fat curves of g's pieces (hybrid)
  std::span<const OverlapFinding> overlaps;
  bool t_free = false;
  bool s_free = false;
  /// The part of the parameter square searched (default all of it).
  ParamInterval t_range{0.0, 1.0};
  ParamInterval s_range{0.0, 1.0};
  /// Certifies high-order contacts near boxes that go to double-double pieces, and drops
  /// the boxes their isolating boxes cover (high_order_contact.hpp); none when null.
  HighOrderContactFinder* contacts = nullptr;
};

struct SearchOutput {
  std::vector<SearchCandidate> candidates;
  /// The search's counts (its work is in the budget it charged, not in stats.work).
  IntersectStats stats;
};

/// Every box of [0,1]^2 that may hold an intersection, narrowed to the search width, by
/// the chosen method. Boxes are kept on an explicit stack; each step reserves its cost
/// (work_cost.hpp) from `budget` and the search stops at the first step it does not cover
/// (the budget is then exhausted; the candidates found so far are returned).
///
///  - hybrid: clip the pieces in turn against each other's fat line with fat curves;
///    when a clip keeps more than half of its interval, halve both intervals (after Lou & Liu 2012).
///    Boxes narrower than 2^-4 first try the Krawczyk test (krawczyk.hpp), which proves a
///    transversal crossing unique and returns it in a box of half the search width, or
///    proves the box empty, in one step.
///  - bezier-clipping: the same with the convex hull of the distance function; when a clip
///    keeps more than 80 % (removes less than 20 %), halve the wider interval
///    (Sederberg & Nishita 1990, §4).
///  - subdivision: drop the box when its pieces are separated (bounding boxes, fat lines),
///    otherwise halve both intervals.
///
/// In all three, when the primary test fails on pieces that run nearly parallel (the sine
/// of the angle between their chords below 1/16: a tangency, or curves that follow each
/// other), the implicit "fat parabola" clip (implicit_clip.hpp) is tried before halving
/// (by the hybrid method once the box is at most 1/4 wide); without it, contacts of
/// order 3 keep a tube of boxes alive at every level.
///
/// Every piece carries an error bound and every test includes it, so no box holding an
/// intersection is ever dropped. When the bounds dominate a test (a tangency: the curves
/// stay within rounding of each other), the box switches to compensated pieces
/// (double-double, in a frame centred on the box); when even those cannot decide, the box
/// is returned unresolved. Boxes covered by an overlap are dropped (covered_by_overlap,
/// covered_by_arc), and so are boxes inside a certified high-order contact's isolating box
/// (input.contacts, which each box about to go to double-double pieces may first propose).
[[nodiscard]] SearchOutput search(const SearchInput& input, WorkBudget& budget);

}  // namespace bezier::core
