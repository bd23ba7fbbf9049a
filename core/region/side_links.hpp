#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "core/region/arrangement.hpp"

namespace bezier::region {

/// A group whose two sides are another group's: the winding numbers on its left and right
/// are that group's (left and right swapped when `flipped`).
struct SideLink {
  std::size_t group = 0;
  bool flipped = false;
};

/// The links of one group: at most one at each of its two vertices.
struct GroupLinks {
  std::array<SideLink, 2> link;
  std::size_t count = 0;
  [[nodiscard]] const SideLink* begin() const noexcept { return link.data(); }
  [[nodiscard]] const SideLink* end() const noexcept { return link.data() + count; }
};

/// For each coincident group of the arrangement, the groups that share its sides through a
/// vertex where the boundary merely passes: links[g] lists them (each link appears from both
/// of its groups; a group has two ends, so at most two links).
///
/// Why the sides are shared. A group is one point set, an arc from vertex u to vertex v (its
/// representative's `from` and `to`) that meets the rest of the arrangement only at u and v
/// (arrangement.hpp: edges meet only at vertices, and coincide only inside a group). So the
/// points just left of it, all along it, lie in one face of the arrangement, and so do the
/// points just right of it; near v they are the two sides of the arc's end there. When v is
/// the end of exactly two groups, G and H (each of them ending there once, neither of them a
/// loop from v to v), a small disc about v holds no other boundary: G's and H's arcs split it
/// into two sectors, each of them inside one face. Walking G towards v and then H away from
/// v, the left side stays the left side; so G's left face is H's left face when one of them
/// arrives at v and the other leaves it, and H's right face when both arrive or both leave
/// (flipped). Winding numbers are constant on a face, so the winding numbers on the sides of
/// H follow exactly from those of G: a certified ray for one group of a chain of such
/// vertices decides the whole chain (side_winding.hpp).
///
/// Conservative: a vertex with a group that is a loop, or with a group whose edges do not
/// all join the representative's two vertices, links nothing there. O(E + V).
[[nodiscard]] std::vector<GroupLinks> side_links(const Arrangement& arrangement);

}  // namespace bezier::region
