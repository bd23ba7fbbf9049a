#pragma once

#include <cstddef>
#include <vector>

#include "core/base/work_budget.hpp"
#include "core/region/arrangement.hpp"
#include "core/region/side_winding.hpp"

namespace bezier::region {

/// What decide_around_vertices found.
enum class VertexSectorStatus { ok, undecided, work_cap_reached };

/// Decides the side windings of the groups not yet `known` from those of their neighbours
/// around a common vertex, where no ray could (side_winding.hpp: a face thinner than the
/// ray clearance, such as the sliver between near-tangent curves that cross a few times
/// within 1e-8 of each other, leaves every ray from its edges' middles too close to another
/// edge).
///
/// Why it is exact. Around a vertex v, the groups ending there (each group's representative
/// edge, once at each of its ends at v) are ordered counter-clockwise by their germs at v
/// (edge_germ.hpp: tangent angle, then turn), the order chain_contours follows to build the
/// result's contours. Two germs consecutive in that order bound a sector of a small disc
/// about v that holds no other boundary (edges meet only at vertices and coincide only
/// within a group, arrangement.hpp), so the sector lies in one face and has one winding
/// number per operand. The sector counter-clockwise after a group's germ is the group's left
/// side when the group leaves v and its right side when it arrives at v; the sector
/// clockwise before a germ is its right side when it leaves, its left when it arrives. So a
/// known group gives its neighbour's side on the common sector, and the neighbour's other
/// side differs by its multiplicity (side_winding.hpp: crossing a group from right to left
/// adds it). Conservative: no sector is used between two germs that tie (ccw_angle 0: the
/// order is not decided), nor at a vertex that an edge of a group reaches while its
/// representative does not (the representative's germs would not be all of the boundary
/// there).
///
/// Passes over all vertices until nothing changes; each pass charges one unit per group end
/// (budget.spend). A group left unknown whose multiplicity is 0 for both operands (edges that
/// cancel, such as a piece and its retrace squeezed into one group) separates nothing: its
/// two sides are one face, so it is given equal sides (all zero), which no operation keeps.
/// undecided when some other group stays unknown.
[[nodiscard]] VertexSectorStatus decide_around_vertices(const Arrangement& arrangement,
                                                        std::vector<SideWindings>& windings,
                                                        std::vector<char>& known,
                                                        core::WorkBudget& budget);

}  // namespace bezier::region
