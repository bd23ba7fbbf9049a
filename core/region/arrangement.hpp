#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "core/base/curve.hpp"
#include "core/base/point.hpp"
#include "core/base/work_budget.hpp"
#include "core/intersect/result.hpp"
#include "core/path/path.hpp"

namespace bezier::region {

/// Which operand of a boolean operation a piece of boundary comes from.
enum class Operand : std::uint8_t { a = 0, b = 1 };

/// One piece of an operand's segment between two vertices of the arrangement.
struct ArrangementEdge {
  Operand source = Operand::a;
  /// The segment in its operand's path.
  std::size_t segment = 0;
  /// The piece is the segment on [t0, t1], t0 < t1.
  double t0 = 0.0;
  double t1 = 1.0;
  /// The vertices at t0 and at t1 (they may be the same vertex for a piece that loops).
  std::size_t from = 0;
  std::size_t to = 0;
  /// The exact piece (Arrangement::exact) with its end points replaced by the vertices'
  /// points, so that every edge through a vertex meets it at the same double. Each end moves
  /// by at most the vertex's merge radius (a contact's own interval, or kVertexMergeRel of
  /// scale).
  core::Curve piece = core::Curve({core::Point2{}});
  /// Where the exact piece differs from `piece` (bit for bit): its place in
  /// Arrangement::snapped_exacts; kNotSnapped where the vertices' points are its own end
  /// points, so that one curve serves as both. (Kept apart from the edge, which the passes
  /// over all edges then read in fewer cache lines.)
  static constexpr std::size_t kNotSnapped = static_cast<std::size_t>(-1);
  std::size_t snapped_exact = kNotSnapped;
  /// The coincident group holding the edge.
  std::size_t group = 0;

  ArrangementEdge() = default;
  /// Every member given, for emplace_back (which builds an aggregate from parentheses only
  /// from C++20 on, and clang only from version 16).
  ArrangementEdge(Operand of, std::size_t in_segment, double from_t, double to_t,
                  std::size_t from_vertex, std::size_t to_vertex, core::Curve curve,
                  std::size_t snapped, std::size_t in_group)
      : source(of), segment(in_segment), t0(from_t), t1(to_t), from(from_vertex),
        to(to_vertex), piece(std::move(curve)), snapped_exact(snapped), group(in_group) {}
};

/// Edges that are the same point set: pieces of shared boundary (an overlap reported by the
/// intersection search, between the operands or within one), or a single edge.
struct CoincidentGroup {
  /// The edge that stands for the group: the first one of operand a if there is one.
  std::size_t representative = 0;
  /// The group's edges, in increasing order, are Arrangement::group_members
  /// [first_member, first_member + member_count) (Arrangement::group_edges).
  std::size_t first_member = 0;
  std::size_t member_count = 0;
  /// For each operand, the number of its edges in the group that run the representative's
  /// way minus those that run against it: what crossing the group from its right to its
  /// left adds to that operand's winding number.
  std::array<int, 2> multiplicity{0, 0};
};

/// Both operands' boundaries cut at every contact into edges that meet only at vertices.
struct Arrangement {
  std::vector<core::Point2> vertices;
  std::vector<ArrangementEdge> edges;
  /// The exact pieces of the edges whose ends were moved to their vertices' points
  /// (ArrangementEdge::snapped_exact).
  std::vector<core::Curve> snapped_exacts;
  std::vector<CoincidentGroup> groups;
  /// Every group's edges, group after group (one list for all, not one per group).
  std::vector<std::size_t> group_members;
  /// The largest absolute control-point coordinate of both operands (1 when both are empty
  /// or at the origin): the unit of every relative distance.
  double scale = 1.0;
  /// Work units spent (core/intersect/work_cost.hpp's unit).
  std::int64_t work = 0;
  /// ok, or work_cap_reached (the arrangement is then incomplete and must not be used).
  core::IntersectStatus status = core::IntersectStatus::ok;

  /// The edge's piece as core::portion(segment, t0, t1) gives it: the de Casteljau (blossom)
  /// piece, unchanged.
  [[nodiscard]] const core::Curve& exact(const ArrangementEdge& edge) const {
    return edge.snapped_exact == ArrangementEdge::kNotSnapped ? edge.piece
                                                              : snapped_exacts[edge.snapped_exact];
  }

  /// The edges of group g, in increasing order.
  [[nodiscard]] std::span<const std::size_t> group_edges(std::size_t g) const {
    return std::span<const std::size_t>(group_members).subspan(groups[g].first_member,
                                                               groups[g].member_count);
  }
};

/// The arrangement of the boundaries of a and b (b may be null: the arrangement of a alone).
///
/// Contacts: one certified search over both paths as one (path::self_intersections on the
/// segments of a followed by those of b), which reports every contact between two segments
/// of a, of b, and of a with b (transversal, tangent, degenerate: each with guaranteed
/// parameter intervals), every overlap (parameter ranges on both segments, same or
/// opposite direction), and each segment's own crossings and retraced pieces.
///
/// Vertices: every segment end and every contact is an event (a segment, a parameter, a
/// point and a merge radius: kVertexMergeRel * scale, plus for a contact the distance its
/// parameter interval spans on the segment, bounded by the interval width times the
/// segment's speed bound n max|P_{i+1} - P_i|). The two events of one contact (and the
/// corresponding ends of an overlap) are one vertex; events whose points lie within the sum
/// of their radii are one vertex (transitively, so a cluster of nearby crossings becomes one
/// vertex on every edge through it). A vertex's point is a segment end point when it holds
/// one (the first in segment order), so that the joints of the input stay exactly where
/// they are; otherwise the point of its first contact.
///
/// Edges: each segment is cut at its events' parameters in increasing order; consecutive
/// cuts at the same vertex are one cut unless the piece between them is more than the
/// vertex's size (a loop); zero-length segments are left out of the search and give no
/// edge (a single point adds no boundary). The pieces of the two segments
/// of one overlap are one coincident group piece by piece in their order along it (the k-th
/// of one with the k-th of the other, when both are cut at the same vertices in that order;
/// otherwise a piece with the one piece of the other that runs between the same two vertices
/// the same way, a loop with none), and so are two edges
/// between the same two vertices whose points at t = k/8 (k = 1..7, matched along their
/// common direction) are within kRayClearanceRel * scale of each other: a lens thinner than
/// the side-winding rays can resolve (two crossings a few ulps off a tangency) has no area
/// worth a contour, and its two sides are told apart only as one edge.
///
/// The contact search charges `budget` (as path::self_intersections spends it); when it runs
/// out the status is work_cap_reached and the arrangement must not be used.
/// Precondition: finite coordinates; every subpath closed.
[[nodiscard]] Arrangement build_arrangement(const path::Path& a, const path::Path* b,
                                            core::WorkBudget& budget);

}  // namespace bezier::region
