#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "core/intersect/result.hpp"

namespace bezier::core {

/// A closed axis-aligned rectangle of the parameter plane: t x s.
struct ClosedBox {
  ParamInterval t;
  ParamInterval s;
};

/// The connected components of the boxes' intersection graph: box i and box j are joined
/// when they meet (closed: touching counts), and the relation is closed transitively.
/// The answer holds, for each box, a label shared by the boxes of its component and by no
/// other (the index of one of them).
///
/// Method: a sweep in t with a segment tree over the boxes' s end points, after Imai and
/// Asano ("Finding the connected components and a maximum clique of an intersection graph
/// of rectangles in the plane", J. Algorithms 4, 1983). A box enters at its t.lo and meets
/// every box stored that has not ended (t.hi >= the sweep's t) and whose s interval meets
/// its own: the ones stored at the tree nodes above its canonical nodes and the ones below
/// them. Boxes stored at one node that are all still open meet each other, so a node keeps
/// only the one that ends last; a subtree whose open boxes are known to be in one
/// component is marked so and answers with one of them. Each insertion visits O(log k)
/// nodes and marks O(log k) nodes as mixed, each visit to a mixed subtree unmarks it, so
/// the whole is O(k log k) time and O(k) memory, whatever the number of meeting pairs
/// (a column of k boxes sharing one t interval meets in k^2 / 2 pairs).
/// Its cost in work units is merge_cost (work_cost.hpp).
[[nodiscard]] std::vector<std::size_t> box_components(std::span<const ClosedBox> boxes);

}  // namespace bezier::core
